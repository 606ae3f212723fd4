// The wear loop (wear/wear_loop.h): the identities it must keep (worn volume = k_E x dissipated
// energy, no wear without slip, symmetry), its lifetime limits, its convergence in the tolerance, and
// the regression values of the shipped wear cases.
#include "wear/wear_loop.h"

#include <gtest/gtest.h>

#include <spdlog/fmt/fmt.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "lib/io/case.h"
#include "lib/numeric.h"
#include "tests/log_capture.h"
#include "tests/temp_dir.h"
#include "wear/profile_update.h"
#include "wear/wear_output.h"

namespace wear {
namespace {
using contact::kPi;

namespace fs = std::filesystem;
const fs::path kSource = ROLLWEAR_SOURCE_DIR;

// the shipped case on a coarser grid (the identities hold on any grid)
WearCase paper_wear(int n = 40) {
  WearCase c = read_wear_case((kSource / "cases" / "paper-wear.yaml").string());
  c.contact.solver.nx = c.contact.solver.ny = n;
  return c;
}

double k_E_of(const WearModel& m) {
  return archard_energy_coefficient_m3_per_J(m.law1->archard_k, m.law1->hardness_Pa, m.mu);
}

// the worn state after N revolutions of the case (no limit besides the budget)
LifeResult run_to(const WearCase& c, double N, const LifeHooks& hooks = {}) {
  WearCase k = c;
  k.wear.revolutions = N;
  k.wear.snapshots_revolutions.clear();
  k.wear.limits = WearLimits{0, 0, false};
  const WearModel m = make_wear_model(k);
  WearCache cache;
  return run_life(m, k, LifeStart{}, hooks, cache);
}

// Identity (docs/physics.md §6): the volume worn per revolution, 2 pi R_w sum_i w_i dh_i/dN after mapping and
// smoothing, equals k_E x the energy dissipated per revolution, to rounding, on the unworn and on a
// worn (semi-Hertzian) geometry.
TEST(WearLoop, VolumeRateEqualsEnergyRateTimesCoefficient) {
  const WearCase c = paper_wear();
  const WearModel m = make_wear_model(c);
  WearCache cache;
  Eigen::VectorXd state = initial_state(m);
  for (int pass = 0; pass < 2; ++pass) {
    const WearRate r = wear_rate(m, state, cache);
    const double volume_rate = 2 * kPi * m.Rx1_m * profile_area_m2(r.dstate_dN.head(m.n1).array(), m.profiles.body1.y_m);
    EXPECT_NEAR(volume_rate / (k_E_of(m) * r.energy_per_revolution_J), 1.0, 1e-13) << "pass " << pass;
    EXPECT_GT(r.energy_per_revolution_J, 0);
    EXPECT_EQ(r.contact.normal_solver,
              pass == 0 ? contact::NormalSolverKind::Hertz : contact::NormalSolverKind::SemiHertz);
    // the energy per revolution is the steady power times a revolution's time, 2 pi R / V
    EXPECT_NEAR(r.energy_per_revolution_J / (r.contact.power_W * 2 * kPi * m.Rx1_m / m.speed_m_per_s), 1.0, 1e-12);
    state.head(m.n1) = 4e6 * r.dstate_dN.head(m.n1);  // a worn crown (about 10 um deep)
  }
}

// Identity over a whole run: the worn volume from the depths and k_E x the dissipated energy, both
// integrated by the same Runge-Kutta weights, agree to rounding at the end of every step.
TEST(WearLoop, WornVolumeEqualsCoefficientTimesEnergyAtEveryStep) {
  WearCase c = paper_wear();
  c.wear.revolutions = 3e7;
  c.wear.snapshots_revolutions = {1e7};
  const WearModel m = make_wear_model(c);
  WearCache cache;
  double worst = 0;
  long steps = 0;
  LifeHooks hooks;
  hooks.on_step = [&](const LifeStep& s) {
    const double volume = worn_volume_m3(m, *s.state, 1), energy = dissipated_energy_J(m, *s.state);
    worst = std::max(worst, std::abs(volume / (k_E_of(m) * energy) - 1));
    ++steps;
    return true;
  };
  const LifeResult life = run_life(m, c, LifeStart{}, hooks, cache);
  EXPECT_EQ(life.ended_by, LifeEnd::Revolutions);
  EXPECT_GT(steps, 5);
  EXPECT_LT(worst, 1e-12) << "over " << steps << " steps";
}

// The pressure fields on the grid are left out where the duty cycle reads only the strips (steady,
// consistent, pure xi, Archard per strip: the closed form); the rate on a worn (semi-Hertzian) crown is
// the same to the bit as with the fields filled. With lateral creepage the march reads them: kept.
TEST(WearLoop, PressureFieldsOnlyWhereTheDutyCycleReadsThem) {
  const WearCase c = paper_wear();
  const WearModel skip = make_wear_model(c);
  EXPECT_FALSE(skip.normal_options.pressure_fields);
  WearModel full = skip;
  full.normal_options.pressure_fields = true;
  WearCache a, b;
  Eigen::VectorXd state = initial_state(skip);
  state.head(skip.n1) = 4e6 * wear_rate(skip, state, a).dstate_dN.head(skip.n1);  // a worn crown
  const WearRate r_skip = wear_rate(skip, state, a), r_full = wear_rate(full, state, b);
  EXPECT_EQ(r_skip.contact.normal_solver, contact::NormalSolverKind::SemiHertz);
  EXPECT_TRUE(r_skip.dstate_dN == r_full.dstate_dN);
  EXPECT_EQ(r_skip.contact.power_W, r_full.contact.power_W);
  EXPECT_EQ(r_skip.contact.edge_limit_m, r_full.contact.edge_limit_m);

  WearCase lateral = c;
  lateral.contact.kinematics.eta = contact::constant_history(1e-4);
  EXPECT_TRUE(make_wear_model(lateral).normal_options.pressure_fields);
}

// Pure rolling (no creepage, no spin) with the Heathcote slip off: no slip, no dissipation, no wear,
// exactly; with the Heathcote slip on, the crown's varying rolling radius slips and wears.
TEST(WearLoop, PureRollingWearsNothingWithoutHeathcoteSlip) {
  WearCase c = paper_wear();
  c.contact.kinematics.xi = contact::constant_history(0.0);
  c.contact.profiles->heathcote_slip = false;
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const WearRate r = wear_rate(m, initial_state(m), cache);
  EXPECT_EQ(r.dstate_dN.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(r.energy_per_revolution_J, 0.0);
  const LifeResult life = run_to(c, 1e9);
  EXPECT_EQ(life.ended_by, LifeEnd::Revolutions);
  EXPECT_EQ(max_depth_m(m, life.state), 0.0);

  c.contact.profiles->heathcote_slip = true;
  const WearModel with = make_wear_model(c);
  WearCache cache2;
  EXPECT_GT(wear_rate(with, initial_state(with), cache2).dstate_dN.maxCoeff(), 0.0);
}

// A case symmetric about y = 0 (symmetric crown on a flat path, pure xi) stays symmetric while it wears.
TEST(WearLoop, SymmetricCaseStaysSymmetric) {
  const WearCase c = paper_wear();
  const LifeResult life = run_to(c, 5e7);
  const WearModel m = make_wear_model(c);
  const Eigen::VectorXd h = life.state.head(m.n1);
  const Eigen::VectorXd mirrored = h.reverse();
  const double depth = h.maxCoeff();
  EXPECT_GT(depth, 3e-5);
  EXPECT_LT((h - mirrored).cwiseAbs().maxCoeff(), 1e-9 * depth);
  // the profile's nodes are symmetric too, so the mirror is the same node set
  EXPECT_LT((m.profiles.body1.y_m + m.profiles.body1.y_m.reverse()).abs().maxCoeff(), 1e-15);
}

// Convergence study: the worn depth after N revolutions converges as the tolerance tightens (rtol,
// with atol = rtol x 1 um, the scale of the depth); against a run at rtol 1e-8 the error falls with the
// tolerance (the table is in docs/wear-loop.md).
TEST(WearLoop, WearAfterNRevolutionsConvergesAsToleranceTightens) {
  WearCase c = paper_wear(20);
  const double N = 5e7;
  c.wear.stepping.rtol = 1e-8;
  c.wear.stepping.atol_m = 1e-14;
  const LifeResult reference = run_to(c, N);
  const WearModel m = make_wear_model(c);
  const double depth_ref = max_depth_m(m, reference.state);
  std::vector<double> errors;
  std::string table = "rtol, atol_m, steps, rhs evals, max depth (m), max |h - h_ref| / max h_ref\n";
  for (double rtol : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5}) {
    c.wear.stepping.rtol = rtol;
    c.wear.stepping.atol_m = rtol * 1e-6;
    const LifeResult r = run_to(c, N);
    const double error = (r.state.head(m.n1) - reference.state.head(m.n1)).cwiseAbs().maxCoeff() / depth_ref;
    errors.push_back(error);
    table += fmt::format("{:.0e}, {:.0e}, {}, {}, {:.9e}, {:.2e}\n", rtol, rtol * 1e-6, r.counters.steps, r.counters.rhs_evals,
                         max_depth_m(m, r.state), error);
  }
  std::cout << table << "reference: " << reference.counters.steps << " steps\n";
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LT(errors[k], errors[k - 1]) << table;
  EXPECT_LT(errors.back(), 1e-5) << table;
}

// The depth limit ends the life where it is reached, located by root finding and not overshot:
// adaptive (on ARKODE's dense output) and fixed-depth (exactly on the Euler line).
TEST(WearLoop, DepthLimitIsLocated) {
  for (const std::string method : {"adaptive", "fixed-depth"}) {
    WearCase c = paper_wear(20);
    c.wear.limits = WearLimits{3e-5, 0, true};
    c.wear.stepping.method = parse_stepping_method(method);
    c.wear.stepping.max_depth_step_m = 7e-6;
    c.wear.snapshots_revolutions.clear();
    const WearModel m = make_wear_model(c);
    WearCache cache;
    const LifeResult life = run_life(m, c, LifeStart{}, LifeHooks{}, cache);
    EXPECT_EQ(life.ended_by, LifeEnd::MaxDepth) << method << ": " << life.message;
    EXPECT_NEAR(max_depth_m(m, life.state) / 3e-5, 1.0, 1e-9) << method;
    EXPECT_LT(life.N, c.wear.revolutions);
  }
}

// A reference life with the exact theory (solver.tangential: exact, steady duty cycle, one exact steady
// solve per wear-rate evaluation) runs to its revolutions, its creep force within the steady-force
// difference between the theories (docs/exact-theory.md §7) of the consistent scheme's, on the unworn
// contact and on the consistent life's worn crown (the same geometry for both). Measured on 20, 40,
// 80 cells a side: Fx ratio 1.002, 0.980, 0.969 unworn and 1.123, 1.037, 1.013 on the worn crown
// (the coarsest grid resolves the worn contact poorly: hence 40 here). The wear follows the dissipated
// energy, the creep work (docs/exact-theory.md §4, "Dissipation"): energy per revolution 1.016, 0.994, 0.982
// unworn and 1.160, 1.058, 1.029 on the worn crown; worn volume after 3e7 revolutions 1.116, 1.095, 1.072.
TEST(WearLoop, ExactTheoryLifeRunsAndAgreesInForce) {
  constexpr double kForceDifference = 0.05;  // the theories' steady Fx differ by 2 to 4 % here (measured above)
  WearCase c = paper_wear(40);
  // the simplified theory's, as measured above (the shipped default, the relaxed model, is fitted to the exact
  // theory; its three 1e7-revolution Euler steps leave a crown of up to 8 patches, on which it is not judged here)
  c.contact.solver.tangential = contact::TangentialScheme::Consistent;
  c.wear.stepping.method = IntegratorOptions::Method::FixedStep;
  c.wear.stepping.step_revolutions = 1e7;
  WearCase e = c;
  e.contact.solver.tangential = contact::TangentialScheme::Exact;
  const WearModel mc = make_wear_model(c), me = make_wear_model(e);
  const LifeResult lc = run_to(c, 3e7), le = run_to(e, 3e7);
  ASSERT_EQ(le.ended_by, LifeEnd::Revolutions) << le.message;
  ASSERT_EQ(lc.ended_by, LifeEnd::Revolutions) << lc.message;
  for (const bool end : {false, true}) {
    WearCache cc, ce;
    const WearRate rc = wear_rate(mc, end ? lc.state : initial_state(mc), cc);
    const WearRate re = wear_rate(me, end ? lc.state : initial_state(me), ce);  // the same geometry
    EXPECT_NEAR(re.contact.Fx_N / rc.contact.Fx_N, 1, kForceDifference) << (end ? "end" : "start");
    EXPECT_GT(re.energy_per_revolution_J, 0);
    std::printf("%s: exact/consistent Fx %.5f, energy per revolution %.5f\n", end ? "end" : "start",
                re.contact.Fx_N / rc.contact.Fx_N, re.energy_per_revolution_J / rc.energy_per_revolution_J);
  }
  const double Vc = profile_area_m2(lc.state.head(mc.n1).array(), mc.profiles.body1.y_m);
  const double Ve = profile_area_m2(le.state.head(me.n1).array(), me.profiles.body1.y_m);
  EXPECT_GT(Ve, 0);
  std::printf("exact/consistent worn volume after 3e7 revolutions: %.5f\n", Ve / Vc);
}

// Fixed stepping by depth: no update wears more than max_depth_step_m; by revolutions, every step is
// step_revolutions but the last. Both reach the adaptive run's depth within their first-order error.
TEST(WearLoop, FixedSteppingRespectsItsStepAndAgreesWithAdaptive) {
  WearCase c = paper_wear(20);
  const double N = 2e7;
  const LifeResult adaptive = run_to(c, N);
  const WearModel m = make_wear_model(c);
  const double depth = max_depth_m(m, adaptive.state);

  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = depth / 50;
  double largest = 0;
  Eigen::VectorXd previous = initial_state(m);
  LifeHooks hooks;
  hooks.on_step = [&](const LifeStep& s) {
    largest = std::max(largest, (s.state->head(m.n1) - previous.head(m.n1)).cwiseAbs().maxCoeff());
    previous = *s.state;
    return true;
  };
  const LifeResult fixed = run_to(c, N, hooks);
  EXPECT_LE(largest, depth / 50 * (1 + 1e-12));
  EXPECT_NEAR(max_depth_m(m, fixed.state) / depth, 1.0, 0.03);

  c.wear.stepping.method = IntegratorOptions::Method::FixedStep;
  c.wear.stepping.step_revolutions = N / 64;
  const LifeResult by_revolutions = run_to(c, N);
  EXPECT_EQ(by_revolutions.counters.steps, 64);
  EXPECT_NEAR(max_depth_m(m, by_revolutions.state) / depth, 1.0, 0.03);
}

// Step control on the shipped case to its end (the contact reaching the roller's edge): strips enter
// and leave the contact as it widens, and f is only piecewise smooth; the control must not chatter
// (few rejected steps) nor stall (few steps).
// The contact reaching the edge is the life's expected end: reported once at info level, no warning
// (the test's log capture fails a test that warns).
TEST(WearLoop, StepControlCopesOnTheShippedCase) {
  const WearCase c = paper_wear(80);
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const LifeResult life = run_life(m, c, LifeStart{}, LifeHooks{}, cache);
  EXPECT_EQ(life.ended_by, LifeEnd::Edge) << life.message;
  EXPECT_LT(life.counters.steps, 200) << life.message;
  EXPECT_LE(life.counters.rejected, life.counters.steps / 10 + 1) << life.message;
}

// Both bodies wear, each with its own coefficient: each spreads the same dissipated energy over its own
// circumference, so each body's volume rate is its k_E x the energy rate (to rounding), and with the
// same k_E the path's depth per roller revolution is the roller's x R1/R2 (the strips' depths are the
// same per unit circumference; the map to each body's nodes differs, so the areas are compared).
TEST(WearLoop, BothBodiesWearWithTheirOwnCoefficients) {
  WearCase c = paper_wear();
  WearLaw path;
  path.law = WearLawKind::Energy;
  path.k_E_m3_per_J = 2e-14;
  c.wear.body2 = path;
  const WearModel m = make_wear_model(c);
  ASSERT_GT(m.n2, 0);
  WearCache cache;
  const WearRate r = wear_rate(m, initial_state(m), cache);
  const double area1 = profile_area_m2(r.dstate_dN.segment(0, m.n1).array(), m.profiles.body1.y_m);
  const double area2 = profile_area_m2(r.dstate_dN.segment(m.n1, m.n2).array(), m.profiles.body2.y_m);
  EXPECT_NEAR(2 * kPi * m.Rx1_m * area1 / (k_E_of(m) * r.energy_per_revolution_J), 1.0, 1e-13);
  EXPECT_NEAR(2 * kPi * m.Rx2_m * area2 / (2e-14 * r.energy_per_revolution_J), 1.0, 1e-13);
  EXPECT_NEAR(area2 / area1, 2e-14 / k_E_of(m) * m.Rx1_m / m.Rx2_m, 1e-13 * area2 / area1);
  // life counted in the roller's revolutions; the path's worn volume in the report
  const LifeResult life = run_to(c, 1e7);
  EXPECT_GT(worn_volume_m3(m, life.state, 2), 0);
  EXPECT_NEAR(worn_volume_m3(m, life.state, 2) / worn_volume_m3(m, life.state, 1), 2e-14 / k_E_of(m), 1e-9);
}

// The KTH map with the same K in every region is Archard with that K (docs/wear-laws.md): the loop
// fed with the steady per-cell fields gives Archard's wear rate to rounding.
TEST(WearLoop, KthWithOneCoefficientIsArchard) {
  WearCase c = paper_wear();
  const WearModel archard = make_wear_model(c);
  WearLaw kth;
  kth.law = WearLawKind::Kth;
  kth.hardness_Pa = c.wear.body1->hardness_Pa;
  kth.kth.K_mild_slow = kth.kth.K_severe = kth.kth.K_mild_fast = kth.kth.K_catastrophic = c.wear.body1->archard_k;
  c.wear.body1 = kth;
  const WearModel by_map = make_wear_model(c);
  WearCache a, b;
  const Eigen::VectorXd ra = wear_rate(archard, initial_state(archard), a).dstate_dN.head(archard.n1);
  const Eigen::VectorXd rb = wear_rate(by_map, initial_state(by_map), b).dstate_dN.head(by_map.n1);
  EXPECT_GT(ra.maxCoeff(), 0);
  EXPECT_LT((ra - rb).cwiseAbs().maxCoeff(), 1e-12 * ra.maxCoeff());
}

// A limit already passed at the start ends the life there, and says which: the unworn crown's p0 is
// 1192 MPa, above a 1 GPa limit.
// A body worn deeper than it is wide (a life without a depth limit, stress finding 13) is not a profile
// any more: normal_state throws WornThrough, which run_life takes as the end of the life at its last
// accepted step (as for UnresolvedContact), instead of the profile check's "looks like millimetres".
// A body worn deeper than it is wide (docs/stress-suite.md, finding 13) ends a life run without a depth
// limit at its last accepted step, status failed (WornThrough). The roller here is concave, its deepest
// point (z = width - 50 nm) at the centre where it wears, on a crowned path that keeps the contact there:
// the first 50 nm of wear wear it through. Its contact is the paper case's (gap curvature 1/0.25 - 1/1).
TEST(WearLoop, BodyWornThroughEndsTheLife) {
  WearCase c = paper_wear(20);
  constexpr double kWidth_m = 0.020, kGrooveRadius_m = 1.0, kMargin_m = 5e-8;
  contact::Profile roller;
  roller.source = "a concave roller, 20 mm wide";
  roller.y_m = Eigen::ArrayXd::LinSpaced(401, -kWidth_m / 2, kWidth_m / 2);
  roller.z_m = (kWidth_m - kMargin_m) - roller.y_m.square() / (2 * kGrooveRadius_m);
  c.contact.profiles->profiles.body1 = roller;
  c.contact.profiles->profiles.body2 = contact::crowned_profile(0.25, 0.030);
  c.contact.solver.normal = contact::NormalChoice::SemiHertz;
  c.wear.limits = WearLimits{0, 0, false};
  c.wear.revolutions = 1e8;
  c.wear.snapshots_revolutions.clear();
  const WearModel m = make_wear_model(c);
  double last_N = -1;
  Eigen::VectorXd last_state;
  LifeHooks hooks;
  hooks.on_step = [&](const LifeStep& s) {
    last_N = s.N;
    last_state = *s.state;
    return true;
  };
  WearCache cache;
  const rollwear_test::ExpectWarnings warnings;  // the life's failure is a warning
  const LifeResult life = run_life(m, c, LifeStart{}, hooks, cache);
  EXPECT_EQ(life.ended_by, LifeEnd::Failed) << life.message;
  EXPECT_EQ(life.failure, LifeFailure::WornThrough) << life.message;
  EXPECT_EQ(warnings.count(), 1);
  ASSERT_GT(last_N, 0) << "no step accepted before the body wore through: " << life.message;
  EXPECT_EQ(life.N, last_N);
  EXPECT_TRUE(life.state == last_state) << "the state is not the last accepted step's";
  EXPECT_LE(max_depth_m(m, life.state), kMargin_m);  // not through yet there
}

TEST(WearLoop, PressureLimitAlreadyExceededEndsTheLifeAtTheStart) {
  WearCase c = paper_wear();
  c.wear.limits.max_pressure_Pa = 1e9;
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const LifeResult life = run_life(m, c, LifeStart{}, LifeHooks{}, cache);
  EXPECT_EQ(life.ended_by, LifeEnd::MaxPressure) << life.message;
  EXPECT_EQ(life.N, 0);
  EXPECT_EQ(life.counters.steps, 0);
  // a limit below p0's fall: the worn contact's p0 falls through 1.1 GPa, never exceeding it again
  c.wear.limits.max_pressure_Pa = 1.2e9;
  c.wear.revolutions = 1e7;
  c.wear.snapshots_revolutions.clear();
  const WearModel m2 = make_wear_model(c);
  WearCache cache2;
  EXPECT_EQ(run_life(m2, c, LifeStart{}, LifeHooks{}, cache2).ended_by, LifeEnd::Revolutions);
}

// The reuse of solves at an unchanged profile (WearCache) is a skip that changes nothing: the same life
// bit for bit, with fewer tangential solves.
TEST(WearLoop, ReusingUnchangedProfilesChangesNothing) {
  WearCase c = paper_wear(20);
  c.wear.revolutions = 3e7;
  c.wear.snapshots_revolutions.clear();
  const WearModel m = make_wear_model(c);
  WearCache reuse, afresh;
  afresh.reuse = false;
  const LifeResult a = run_life(m, c, LifeStart{}, LifeHooks{}, reuse);
  const LifeResult b = run_life(m, c, LifeStart{}, LifeHooks{}, afresh);
  EXPECT_EQ(a.N, b.N);
  EXPECT_EQ(a.counters.steps, b.counters.steps);
  EXPECT_TRUE(a.state == b.state);  // bit for bit
  EXPECT_LT(reuse.counters.tangential_solves, afresh.counters.tangential_solves);
  std::cout << "tangential solves: " << reuse.counters.tangential_solves << " with reuse, "
            << afresh.counters.tangential_solves << " without\n";
}

// ---- regression: the shipped wear cases after a few revolutions ----
// Goldens in tests/data/golden/<case>.txt: 'key value' lines. The shipped cases run the default tangential
// model, the relaxed one; <case>-consistent.txt hold the simplified theory's (tangential: consistent), which
// did not move when the default changed. After an intended change of the relaxed model, regenerate its
// goldens and the start-stop life's converged reference with one command,
//   scripts/update-relaxed-goldens
// and commit the files with the reason (the consistent goldens: ROLLWEAR_UPDATE_GOLDENS=1 with
// --gtest_filter='WearGolden.*Consistent'). Tolerance: 1e-9 relative (the runs are deterministic; the
// margin covers another compiler's rounding).

void check_golden(const std::string& name, const std::map<std::string, double>& values) {
  const fs::path p = kSource / "tests" / "data" / "golden" / (name + ".txt");
  if (std::getenv("ROLLWEAR_UPDATE_GOLDENS")) {
    std::ofstream out(p);
    out << "# " << name << ": written by WearGolden (tests/wear_loop_test.cpp)\n";
    for (const auto& [k, v] : values) out << k << " " << fmt::format("{:.17g}", v) << "\n";
    GTEST_SKIP() << "golden written: " << p;
  }
  std::ifstream in(p);
  ASSERT_TRUE(in) << p << " missing: regenerate it (see tests/wear_loop_test.cpp)";
  std::string comment;
  std::getline(in, comment);
  std::map<std::string, double> golden;
  std::string key;
  double v = 0;
  while (in >> key >> v) golden[key] = v;
  ASSERT_EQ(golden.size(), values.size()) << p;
  for (const auto& [k, expected] : golden) {
    ASSERT_TRUE(values.count(k)) << k;
    EXPECT_NEAR(values.at(k), expected, 1e-9 * std::abs(expected) + 1e-30) << name << ": " << k;
  }
}

// the depth at y = 0, +-2, +-4 mm, the maximum depth and the worn volume after N revolutions
std::map<std::string, double> wear_values(const WearModel& m, const LifeResult& life) {
  std::map<std::string, double> v;
  v["revolutions"] = life.N;
  v["max_depth_m"] = max_depth_m(m, life.state);
  v["worn_volume_m3"] = worn_volume_m3(m, life.state, 1) + worn_volume_m3(m, life.state, 2);
  v["dissipated_J"] = dissipated_energy_J(m, life.state);
  const contact::Profiles worn = worn_profiles(m, life.state);
  const contact::Profile& p = m.n1 > 0 ? worn.body1 : worn.body2;
  const contact::Profile& p0 = m.n1 > 0 ? m.profiles.body1 : m.profiles.body2;
  for (double y_mm : {-4.0, -2.0, 0.0, 2.0, 4.0})
    v[fmt::format("depth_at_{}mm_m", y_mm)] =
        contact::profile_z(p, y_mm * 1e-3) - contact::profile_z(p0, y_mm * 1e-3);
  v["steps"] = static_cast<double>(life.counters.steps);
  return v;
}

// 'key value' lines of a file of tests/data ('#' comments)
std::map<std::string, double> stored_values(const fs::path& p) {
  std::ifstream in(p);
  EXPECT_TRUE(in) << p << " missing";
  std::map<std::string, double> stored;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string key;
    double v = 0;
    if (words >> key >> v) stored[key] = v;
  }
  return stored;
}

WearCase with_scheme(WearCase c, const std::string& scheme) {
  c.contact.solver.tangential = contact::parse_tangential_scheme(scheme);
  return c;
}

// The relaxed model's wear after 1e7 revolutions against the exact theory's: the goal is the steady-force target
// (2 %) carried into the energy and the volume worn, which are proportional to the force. It is met: the relaxed
// goldens are within 0.1 % of the exact theory's, the simplified theory's 3.1 % below (measured, below). It was
// missed (-6.2 %) until the model took the worn contact's shape (lib/tangential/relaxed_shape.h): on the crown
// worn for 1e7 revolutions (a/b = 0.037, its band flattened) the springs' one flexibility undercounted the
// strips' forces (Fx -3.9 % of the exact theory's, tests/relaxed_worn_test.cpp; now +0.5 %), and their
// distribution of the power over the strips put the wear too near the crown's centre (the exact theory's per-strip
// power is the springs' times about 1 / a_j on thin contacts): the contact widened more slowly. The tests hold the
// measured gaps, so that a change of the model that moves them is seen, the target, and the reference's convergence.
constexpr double kRelaxedWearTarget = 0.02;
constexpr double kGapTolerance = 5e-4;  // the quoted gaps are rounded to 0.01 %

// the exact reference's own check: first order in the cell size, (v80 - v40) / (v160 - v80) near 2
void expect_first_order(const std::map<std::string, double>& exact, const std::string& key) {
  const double ratio = (exact.at(key + "_80") - exact.at(key + "_40")) / (exact.at(key + "_160") - exact.at(key + "_80"));
  EXPECT_NEAR(ratio, 2.0, 0.2) << key << ": the exact wear is not first order in the cell size";
}

// The independent reference of the paper-wear goldens: the same life to 1e7 revolutions with Kalker's exact
// theory (tangential: exact) on 40, 80 and 160 cells a side (tests/data/reference/paper-wear-exact.txt, made by
// ROLLWEAR_UPDATE_EXACT_REFERENCES=1 rollwear_tests --gtest_filter='WearGolden.PaperWear', 6.8 min at load 9; it does
// not move with the relaxed model). The exact theory's dissipation, the creep work of its forces, converges at
// first order in the cell (docs/exact-theory.md §4), so the reference is Richardson's 2 v(160) - v(80).
std::map<std::string, double> paper_wear_exact_reference(const WearCase& c) {
  const fs::path p = kSource / "tests" / "data" / "reference" / "paper-wear-exact.txt";
  if (std::getenv("ROLLWEAR_UPDATE_EXACT_REFERENCES")) {
    std::ofstream out(p);
    out << "# paper-wear (cases/paper-wear.yaml) after 1e7 revolutions with tangential: exact on n x n cells, and\n"
           "# Richardson's extrapolation from 80 and 160 (first order in the cell size). Made by\n"
           "#   ROLLWEAR_UPDATE_EXACT_REFERENCES=1 build/release/tests/rollwear_tests --gtest_filter='WearGolden.PaperWear'\n";
    std::map<std::string, double> v[3];
    const int cells[3] = {40, 80, 160};
    for (int k = 0; k < 3; ++k) {
      WearCase e = with_scheme(c, "exact");
      e.contact.solver.nx = e.contact.solver.ny = cells[k];
      v[k] = wear_values(make_wear_model(e), run_to(e, 1e7));
      for (const char* key : {"dissipated_J", "worn_volume_m3", "max_depth_m"})
        out << key << "_" << cells[k] << " " << fmt::format("{:.17g}", v[k].at(key)) << "\n";
    }
    for (const char* key : {"dissipated_J", "worn_volume_m3", "max_depth_m"})
      out << key << "_extrapolated " << fmt::format("{:.17g}", 2 * v[2].at(key) - v[1].at(key)) << "\n";
  }
  return stored_values(p);
}

// Moved when the relaxed model became the default (paper-wear on 80 x 80 after 1e7 revolutions), against the
// exact theory's (40, 80, 160 cells: 238630, 252235, 259260 J; extrapolated 266286 J, 1.47936e-8 m^3):
//   dissipated energy  relaxed 249672 J (-6.24 %), consistent (the old golden) 258051 J (-3.09 %)
//   worn volume        relaxed 1.38707e-8 m^3 (-6.24 %), consistent 1.43361e-8 m^3 (-3.09 %)
// and again with the worn contact's shape (relaxed_shape.h): relaxed 266375 J and 1.47986e-8 m^3 (+0.03 %); the
// maximum depth 1.77546e-5 m against the exact 1.81004e-5 m (-1.91 %; it was +1.36 %: the wear less concentrated);
// and again with the strip weights fading with the saturation level (relaxed_shape.h): relaxed 265753 J and
// 1.47641e-8 m^3 (-0.20 %), the maximum depth 1.79172e-5 m (-1.01 %); and again with the exact theory's power
// made trapezoidal (its sum the creep work, docs/exact-theory.md §4): the exact reference on 40, 80, 160 cells
// 273511, 269874, 268132 J, extrapolated 266389 J, 1.47994e-8 m^3, maximum depth 1.81051e-5 m (+0.04 %, +0.04 %,
// +0.03 % from the upwind power's): relaxed -0.24 %, consistent -3.13 %.
TEST(WearGolden, PaperWear) {
  const WearCase c = read_wear_case((kSource / "cases" / "paper-wear.yaml").string());
  ASSERT_EQ(c.contact.solver.tangential, contact::TangentialScheme::Relaxed);
  const LifeResult life = run_to(c, 1e7);
  const std::map<std::string, double> v = wear_values(make_wear_model(c), life);
  check_golden("paper-wear", v);
  if (std::getenv("ROLLWEAR_UPDATE_GOLDENS")) return;  // being rewritten: the pairing below reads the new one
  const std::map<std::string, double> exact = paper_wear_exact_reference(c);
  const std::map<std::string, double> consistent =
      stored_values(kSource / "tests" / "data" / "golden" / "paper-wear-consistent.txt");
  std::string table;
  for (const char* key : {"dissipated_J", "worn_volume_m3"}) {
    expect_first_order(exact, key);
    const double ref = exact.at(std::string(key) + "_extrapolated");
    const double relaxed_error = v.at(key) / ref - 1, consistent_error = consistent.at(key) / ref - 1;
    table += fmt::format("{}: relaxed {:.6g} ({:+.2f} % from the exact theory's {:.6g}; target {:.0f} %), consistent "
                         "{:.6g} ({:+.2f} %)\n",
                         key, v.at(key), 100 * relaxed_error, ref, 100 * kRelaxedWearTarget, consistent.at(key),
                         100 * consistent_error);
    EXPECT_NEAR(relaxed_error, -0.0024, kGapTolerance) << table;
    EXPECT_LT(std::abs(relaxed_error), kRelaxedWearTarget) << table;
    EXPECT_NEAR(consistent_error, -0.0313, kGapTolerance) << table;
  }
  std::cout << table;
}

TEST(WearGolden, PaperWearConsistent) {  // the simplified theory's golden, as before the default changed
  const WearCase c = with_scheme(read_wear_case((kSource / "cases" / "paper-wear.yaml").string()), "consistent");
  const LifeResult life = run_to(c, 1e7);
  check_golden("paper-wear-consistent", wear_values(make_wear_model(c), life));
}

// Moved when the relaxed model became the default (start-stop-wear, 40 x 40, after 1e7 revolutions): its duty
// cycle is steady running but for the start and the stop (0.9 m rolled at 1.8 m/s against start-ups of a few
// mm), so its wear per revolution is paper-wear's steady one (on 40 x 40 cells), and the same exact reference
// applies (266286 J, 1.47936e-8 m^3):
//   dissipated energy  relaxed 249534 J (-6.29 %), consistent (the old golden) 258105 J (-3.07 %)
//   worn volume        relaxed 1.38630e-8 m^3 (-6.29 %), consistent 1.43392e-8 m^3 (-3.07 %)
// and with the worn contact's shape (relaxed_shape.h): relaxed 266123 J, 1.47846e-8 m^3 (-0.06 %); with the strip
// weights fading with the saturation level: 265506 J, 1.47503e-8 m^3 (-0.29 %); against the exact reference with
// the trapezoidal power (266389 J, 1.47994e-8 m^3): relaxed -0.33 %, consistent -3.11 %.
TEST(WearGolden, StartStopWear) {
  const WearCase c = read_wear_case((kSource / "cases" / "start-stop-wear.yaml").string());
  ASSERT_EQ(c.contact.solver.tangential, contact::TangentialScheme::Relaxed);
  const LifeResult life = run_to(c, 1e7);
  const std::map<std::string, double> v = wear_values(make_wear_model(c), life);
  check_golden("start-stop-wear", v);
  if (std::getenv("ROLLWEAR_UPDATE_GOLDENS")) return;
  const std::map<std::string, double> exact =
      stored_values(kSource / "tests" / "data" / "reference" / "paper-wear-exact.txt");
  const std::map<std::string, double> consistent =
      stored_values(kSource / "tests" / "data" / "golden" / "start-stop-wear-consistent.txt");
  std::string table;
  for (const char* key : {"dissipated_J", "worn_volume_m3"}) {
    const double ref = exact.at(std::string(key) + "_extrapolated");
    const double relaxed_error = v.at(key) / ref - 1, consistent_error = consistent.at(key) / ref - 1;
    table += fmt::format("{}: relaxed {:.6g} ({:+.2f} % from the exact theory's steady {:.6g}; target {:.0f} %), "
                         "consistent {:.6g} ({:+.2f} %)\n",
                         key, v.at(key), 100 * relaxed_error, ref, 100 * kRelaxedWearTarget, consistent.at(key),
                         100 * consistent_error);
    EXPECT_NEAR(relaxed_error, -0.0033, kGapTolerance) << table;
    EXPECT_LT(std::abs(relaxed_error), kRelaxedWearTarget) << table;
    EXPECT_NEAR(consistent_error, -0.0311, kGapTolerance) << table;
  }
  std::cout << table;
}

TEST(WearGolden, StartStopWearConsistent) {  // the simplified theory's golden, as before the default changed
  const WearCase c = with_scheme(read_wear_case((kSource / "cases" / "start-stop-wear.yaml").string()), "consistent");
  const LifeResult life = run_to(c, 1e7);
  check_golden("start-stop-wear-consistent", wear_values(make_wear_model(c), life));
}

// ---- the shipped cases' lives against converged references ----
//
// Reference: the fixed-depth life (explicit Euler, each step wearing d at the fastest node), first
// order in d, extrapolated (Richardson) from d and d/2: L_ref = 2 L(d/2) - L(d). Its own error is about
// |L(d/2) - L(d)| before the extrapolation and far below that after it (paper-wear: L(4e-8), L(2e-8),
// L(1e-8) and L(5e-9) differ by 834, 412 and 202 revolutions, first order; the extrapolations from
// (2e-8, 1e-8) and (1e-8, 5e-9) agree within 9e-8). Every limit is located by root finding in both
// modes, so the adaptive life converges to the same life (docs/wear-loop.md, "Convergence of the life").

constexpr double kShippedLifeRtol = 3e-3;  // the shipped tolerances' life against the reference (0.3 %)

// the life of the case with fixed-depth steps of d_m, ended by the edge limit
double fixed_depth_life(WearCase c, double d_m) {
  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = d_m;
  c.wear.stepping.max_steps = 10000000;
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const LifeResult life = run_life(m, c, LifeStart{}, LifeHooks{}, cache);
  EXPECT_EQ(life.ended_by, LifeEnd::Edge) << "fixed-depth " << d_m << ": " << life.message;
  return life.N;
}

LifeResult shipped_life(const WearCase& c) {
  const WearModel m = make_wear_model(c);
  WearCache cache;
  return run_life(m, c, LifeStart{}, LifeHooks{}, cache);
}

// Defect: the edge limit was 0 once reached (no sign change), so the life ended at the end of the step
// that reached it, 1.2 % long, and did not converge as the tolerance tightened. Now the life converges,
// as rtol and atol_m tighten together (atol_m = rtol x max_depth_m), to the fixed-depth life, and the
// shipped tolerances' life agrees with it within 0.3 %. The README quotes that life.
// The convergence as the tolerance tightens is shown on the simplified theory (tangential: consistent), whose
// rate is smooth in the worn state; the relaxed model's (the shipped case's) has kinks where the saturation
// level crosses a row of its table (linear interpolation), and its adaptive lives converge more slowly
// (measured: 2.4e-3, 2.1e-4, 2.0e-4, 2.9e-5 at rtol 1e-3 ... 1e-6): it is held to the shipped tolerance.
void expect_life_converges(const WearCase& c, const std::string& label) {
  const double coarse = fixed_depth_life(c, 4e-8), fine = fixed_depth_life(c, 2e-8);
  const double reference = 2 * fine - coarse;
  std::string table = fmt::format("{}: fixed-depth 4e-8 m: {:.10g}, 2e-8 m: {:.10g}, extrapolated {:.10g} revolutions\n"
                                  "rtol, atol_m, steps, life, |life / reference - 1|\n",
                                  label, coarse, fine, reference);
  EXPECT_LT(std::abs(fine - coarse) / reference, 2e-5) << table;
  std::vector<double> errors;
  for (double rtol : {1e-3, 1e-4, 1e-5, 1e-6}) {
    WearCase k = c;
    k.wear.stepping.rtol = rtol;
    k.wear.stepping.atol_m = rtol * c.wear.limits.max_depth_m;
    const LifeResult life = shipped_life(k);
    EXPECT_EQ(life.ended_by, LifeEnd::Edge) << life.message;
    errors.push_back(std::abs(life.N / reference - 1));
    table += fmt::format("{:.0e}, {:.0e}, {}, {:.10g}, {:.2e}\n", rtol, k.wear.stepping.atol_m, life.counters.steps,
                         life.N, errors.back());
  }
  std::cout << table;
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LT(errors[k], errors[k - 1]) << table;
  EXPECT_LT(errors.back(), 1e-5) << table;  // rtol 1e-6
}

TEST(WearLife, PaperWearConsistentConvergesToTheFixedDepthLife) {
  expect_life_converges(with_scheme(read_wear_case((kSource / "cases" / "paper-wear.yaml").string()), "consistent"),
                        "consistent");
}

TEST(WearLife, PaperWearConvergesToTheFixedDepthLife) {
  const WearCase c = read_wear_case((kSource / "cases" / "paper-wear.yaml").string());
  const double coarse = fixed_depth_life(c, 4e-8), fine = fixed_depth_life(c, 2e-8);
  const double reference = 2 * fine - coarse;
  std::string table = fmt::format("fixed-depth 4e-8 m: {:.10g}, 2e-8 m: {:.10g}, extrapolated {:.10g} revolutions\n"
                                  "rtol, atol_m, steps, life, |life / reference - 1|\n",
                                  coarse, fine, reference);
  // the extrapolation's own error: far below the first-order error of the finer run (the relaxed model with the
  // worn contact's shape: L(4e-8), L(2e-8), L(1e-8) = 91730265.6, 91732865.4, 91734199.7, first order; the
  // extrapolations from (4e-8, 2e-8) and (2e-8, 1e-8) agree within 8e-7): the finer run within 5e-5
  EXPECT_LT(std::abs(fine - coarse) / reference, 5e-5) << table;

  const LifeResult shipped = shipped_life(c);
  const double shipped_error = std::abs(shipped.N / reference - 1);
  table += fmt::format("shipped (rtol {:.0e}, atol_m {:.0e}): {} steps, {:.10g}, {:.2e}\n", c.wear.stepping.rtol,
                       c.wear.stepping.atol_m, shipped.counters.steps, shipped.N, shipped_error);
  std::cout << table;
  EXPECT_EQ(shipped.ended_by, LifeEnd::Edge) << shipped.message;
  EXPECT_LT(shipped_error, kShippedLifeRtol) << table;

  // the README's headline: the shipped life as the program prints it, rounded
  std::ifstream in(kSource / "README.md");
  const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const WearModel m = make_wear_model(c);
  const std::string life_text = fmt::format("after {:.2f}e7 revolutions", shipped.N / 1e7);
  const std::string depth_text = fmt::format("at a depth of {:.0f} µm", max_depth_m(m, shipped.state) * 1e6);
  EXPECT_NE(readme.find(life_text), std::string::npos) << "README.md does not say '" << life_text << "'";
  EXPECT_NE(readme.find(depth_text), std::string::npos) << "README.md does not say '" << depth_text << "'";
}

// The edge limit is a signed, continuous function of the state: negative inside, positive past the
// edge. At the life's end it has just changed sign (located to the root finder's tolerance in N: its
// value there is a few revolutions' change of it at most), and the last accepted step before was inside.
TEST(WearLife, EdgeLimitIsLocatedInBothModes) {
  for (const std::string method : {"adaptive", "fixed-depth"}) {
    WearCase c = paper_wear(40);
    c.wear.stepping.method = parse_stepping_method(method);
    c.wear.stepping.max_depth_step_m = 2e-6;
    c.wear.limits.max_depth_m = 0;
    c.wear.snapshots_revolutions.clear();
    const WearModel m = make_wear_model(c);
    WearCache cache;
    double last_g = 0, last_N = 0, slope = 0;
    LifeHooks hooks;
    hooks.on_step = [&](const LifeStep& s) {
      const double g = s.contact.edge_limit_m;
      if (s.N > last_N && last_N > 0) slope = (g - last_g) / (s.N - last_N);
      last_g = g;
      last_N = s.N;
      return true;
    };
    const LifeResult life = run_life(m, c, LifeStart{}, hooks, cache);
    ASSERT_EQ(life.ended_by, LifeEnd::Edge) << method << ": " << life.message;
    EXPECT_LT(last_g, 0) << method << ": the last accepted step is inside the overlap";
    EXPECT_GT(slope, 0) << method;
    const double g_end = life.contact.edge_limit_m;
    EXPECT_GE(g_end, 0) << method << ": the end is on the far side of the root";
    EXPECT_LE(g_end, 10 * slope) << method << ": more than 10 revolutions past the root (g " << g_end
                                 << " m, dg/dN " << slope << " m)";
    EXPECT_GT(life.N, last_N) << method;
  }
}

// The start-stop case's life against its stored reference (tests/data/reference/start-stop-wear.txt for the
// shipped case, the relaxed model; start-stop-wear-consistent.txt for tangential: consistent): fixed-depth
// 2e-8 and 1e-8 m, extrapolated (23 s with consistent, about 30 s with relaxed: too slow to run here;
// regenerate with scripts/update-relaxed-goldens, or for consistent with
//   ROLLWEAR_UPDATE_REFERENCES=1 build/release/tests/rollwear_tests --gtest_filter='WearLife.StartStop*Consistent*'
// ). The cheap check made here: a fixed-depth life with 4e-7 m steps, first order with an error below
// 2e-3 (10 x the error of the 4e-8 m life, 5e-5), agrees with both.
void check_start_stop_reference(const WearCase& c, const std::string& file) {
  const fs::path p = kSource / "tests" / "data" / "reference" / file;
  if (std::getenv("ROLLWEAR_UPDATE_REFERENCES")) {
    const double coarse = fixed_depth_life(c, 2e-8), fine = fixed_depth_life(c, 1e-8);
    std::ofstream out(p);
    out << "# start-stop-wear (tangential: " << contact::to_string(c.contact.solver.tangential)
        << "): the life (revolutions) with fixed-depth steps of 2e-8 and 1e-8 m, and their\n"
           "# Richardson extrapolation (first order), the reference of WearLife.StartStopWear* in\n"
           "# tests/wear_loop_test.cpp (made as said there).\n";
    out << fmt::format("life_fixed_depth_2e-8 {:.17g}\nlife_fixed_depth_1e-8 {:.17g}\nlife_reference {:.17g}\n", coarse,
                       fine, 2 * fine - coarse);
    GTEST_SKIP() << "reference written: " << p;
  }
  const std::map<std::string, double> stored = stored_values(p);
  ASSERT_TRUE(stored.count("life_reference")) << p;
  const double reference = stored.at("life_reference");
  const LifeResult shipped = shipped_life(c);
  ASSERT_EQ(shipped.ended_by, LifeEnd::Edge) << shipped.message;
  const double euler = fixed_depth_life(c, 4e-7);
  constexpr double kEulerError = 2e-3;
  EXPECT_LT(std::abs(shipped.N / reference - 1), kShippedLifeRtol) << shipped.N << " against " << reference;
  EXPECT_LT(std::abs(euler / reference - 1), kEulerError) << euler << " against " << reference;
  EXPECT_LT(std::abs(shipped.N / euler - 1), kShippedLifeRtol + kEulerError) << shipped.N << " against " << euler;
  std::cout << fmt::format("start-stop-wear ({}): shipped {:.10g} ({:.2e}), fixed-depth 4e-7 m {:.10g} ({:.2e}), "
                           "reference {:.10g}\n",
                           contact::to_string(c.contact.solver.tangential), shipped.N, shipped.N / reference - 1, euler,
                           euler / reference - 1, reference);
}

TEST(WearLife, StartStopWearAgreesWithItsConvergedReference) {
  check_start_stop_reference(read_wear_case((kSource / "cases" / "start-stop-wear.yaml").string()),
                             "start-stop-wear.txt");
}

TEST(WearLife, StartStopWearConsistentAgreesWithItsConvergedReference) {
  check_start_stop_reference(
      with_scheme(read_wear_case((kSource / "cases" / "start-stop-wear.yaml").string()), "consistent"),
      "start-stop-wear-consistent.txt");
}

// One struct holds the life's counters, and a resumed life starts from the checkpoint's: stopped at a
// step and resumed (fixed stepping repeats the uninterrupted run to rounding), the life ends with the
// same steps, rejected steps and evaluations of f as the uninterrupted one, and its solves count both
// parts (the fresh cache of the resumed part solves its start once more: one normal and one tangential
// solve). The report's message names the step the limit was reached in, which is `steps`.
TEST(WearLoop, ResumedLifeCountsTheWholeLife) {
  WearCase c = paper_wear(20);
  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = 1e-6;
  c.wear.limits.max_depth_m = 3e-5;
  const WearModel m = make_wear_model(c);
  WearCache whole_cache;
  const LifeResult whole = run_life(m, c, LifeStart{}, LifeHooks{}, whole_cache);
  ASSERT_EQ(whole.ended_by, LifeEnd::MaxDepth) << whole.message;
  ASSERT_GT(whole.counters.steps, 10);
  EXPECT_NE(whole.message.find(fmt::format("in step {}", whole.counters.steps)), std::string::npos)
      << whole.message << " (steps " << whole.counters.steps << ")";

  LifeHooks stop_at;
  const long stop_step = whole.counters.steps / 2;
  stop_at.on_step = [&](const LifeStep& s) { return s.step < stop_step; };
  WearCache first_cache;
  const LifeResult first = run_life(m, c, LifeStart{}, stop_at, first_cache);
  ASSERT_EQ(first.ended_by, LifeEnd::Stopped) << first.message;
  ASSERT_EQ(first.counters.steps, stop_step);
  WearCache second_cache;  // a new process
  const LifeResult resumed =
      run_life(m, c, LifeStart{first.N, first.state, first.next_step, first.counters}, LifeHooks{}, second_cache);
  ASSERT_EQ(resumed.ended_by, LifeEnd::MaxDepth) << resumed.message;
  EXPECT_EQ(resumed.N, whole.N);
  EXPECT_EQ(resumed.counters.steps, whole.counters.steps);
  EXPECT_EQ(resumed.counters.rejected, whole.counters.rejected);
  EXPECT_EQ(resumed.counters.rhs_evals, whole.counters.rhs_evals);
  EXPECT_EQ(resumed.counters.normal_solves, whole.counters.normal_solves + 1);
  EXPECT_EQ(resumed.counters.tangential_solves, whole.counters.tangential_solves + 1);
  EXPECT_EQ(resumed.message, whole.message);
  // the life's counters count this life's solves, not the cache's
  EXPECT_EQ(whole.counters.normal_solves, whole_cache.counters.normal_solves);
}

// LifeEnd's words are the report's, each read back to itself; an unknown word is refused.
TEST(WearLoop, LifeEndWordsReadBack) {
  for (LifeEnd e : {LifeEnd::NotRun, LifeEnd::MaxDepth, LifeEnd::MaxPressure, LifeEnd::Edge, LifeEnd::Revolutions,
                    LifeEnd::MaxSteps, LifeEnd::Stopped, LifeEnd::Failed})
    EXPECT_EQ(parse_life_end(to_string(e)), e) << to_string(e);
  EXPECT_EQ(to_string(LifeResult{}.ended_by), "not_run");
  EXPECT_THROW(parse_life_end("edge reached"), std::invalid_argument);
}

}  // namespace
}  // namespace wear

namespace wear {
namespace {

class WearOutput : public rollwear_test::TempDirTest {};

// A resumed run's summary.csv starts from the file's own text up to the checkpoint's step, byte for byte
// (read by lib/csv_reader.h): comments and header as written, no row after that step.
TEST_F(WearOutput, SummaryUpToKeepsTheFileTextToTheCheckpointStep) {
  const std::string head = "# case: x\n# revolutions of body1 (R 0.02 m); one row per accepted step\nstep,revolutions\n";
  const std::string rows = "0,0\n1,1e+06\n2,2.5e+06\n";
  const std::filesystem::path p = dir_ / "summary.csv";
  std::ofstream(p) << head << rows << "3,4e+06\n4,5e";  // a row torn by the kill
  EXPECT_EQ(summary_up_to(p, 2), head + rows);
  EXPECT_EQ(summary_up_to(p, 0), head + "0,0\n");
  EXPECT_THROW(summary_up_to(p, 7), std::runtime_error);  // the summary ends before the checkpoint
  std::ofstream(p) << head << "0,0\nx,1\n";
  try {
    summary_up_to(p, 1);
    ADD_FAILURE() << "a row without a step number must be refused";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), p.string() + ":5: expected a step number, got 'x'");
  }
  EXPECT_THROW(summary_up_to(dir_ / "none.csv", 0), std::runtime_error);
}

// The checkpoint holds its numbers in hexadecimal floats: read back, every one is the number written, to the bit
// (subnormals, -0, values %g would round), its named blocks included (the cam's rate and warm starts); a torn or
// malformed block is refused naming its line.
TEST_F(WearOutput, CheckpointRoundTripsEveryNumberToTheBit) {
  Checkpoint c;
  c.case_hash = 0x0123456789abcdefULL;
  c.start.N = 1.0 / 3.0 * 1e11;
  c.start.next_step = std::nextafter(2.0, 3.0);
  c.start.counters.steps = 89;
  c.start.counters.tangential_solves = 181;
  c.snapshots_written = 3;
  c.wall_s = 0.1;
  c.start.state = Eigen::VectorXd::LinSpaced(7, -1, 1) / 7.0;
  c.start.state(3) = -0.0;
  c.blocks.push_back({"rate", Eigen::VectorXd::Constant(5, 4.9406564584124654e-324)});
  c.blocks.push_back({"warm_starts", Eigen::VectorXd::LinSpaced(4, 1e-7, 3e-7) / 3.0});
  c.blocks.push_back({"empty", Eigen::VectorXd()});
  const fs::path p = dir_ / "checkpoint.txt";
  std::ofstream(p) << checkpoint_text(c);
  const Checkpoint r = read_checkpoint(p);
  const auto bits_equal = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    // (an empty vector's data() is null, which memcmp may not take)
    return a.size() == b.size() && (a.size() == 0 || std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0);
  };
  EXPECT_EQ(r.case_hash, c.case_hash);
  EXPECT_EQ(r.start.N, c.start.N);
  EXPECT_EQ(r.start.next_step, c.start.next_step);
  EXPECT_EQ(r.start.counters.steps, 89);
  EXPECT_EQ(r.start.counters.tangential_solves, 181);
  EXPECT_EQ(r.wall_s, c.wall_s);
  EXPECT_TRUE(bits_equal(r.start.state, c.start.state));
  ASSERT_EQ(r.blocks.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(r.blocks[k].name, c.blocks[k].name);
    EXPECT_TRUE(bits_equal(r.blocks[k].values, c.blocks[k].values)) << c.blocks[k].name;
  }
  // the wear loop's checkpoint has no block
  c.blocks.clear();
  std::ofstream(p) << checkpoint_text(c);
  EXPECT_TRUE(read_checkpoint(p).blocks.empty());
  // a block torn by a kill, or not of its form
  c.blocks.push_back({"rate", Eigen::VectorXd::Ones(3)});
  const std::string text = checkpoint_text(c);
  std::ofstream(p) << text.substr(0, text.find("block rate 3\n") + 16);
  EXPECT_THROW(read_checkpoint(p), std::runtime_error);
  std::string bad = text;
  bad.replace(bad.find("block rate 3"), 12, "block rate");
  std::ofstream(p) << bad;
  try {
    read_checkpoint(p);
    ADD_FAILURE() << "a block without its count must be refused";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("expected 'block NAME COUNT', got 'block rate'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wear
