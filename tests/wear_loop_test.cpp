// The wear loop (wear/wear_loop.h): the identities it must keep (worn volume = k_E x dissipated
// energy, no wear without slip, symmetry), its lifetime limits, its convergence in the tolerance, and
// the regression values of the shipped wear cases.
#include "wear/wear_loop.h"

#include <gtest/gtest.h>

#include <spdlog/fmt/fmt.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "lib/io/case.h"
#include "lib/numeric.h"
#include "tests/log_capture.h"
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
    EXPECT_EQ(r.contact.normal_solver, pass == 0 ? "hertz" : "semi-hertz");
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
  EXPECT_EQ(life.ended_by, "revolutions");
  EXPECT_GT(steps, 5);
  EXPECT_LT(worst, 1e-12) << "over " << steps << " steps";
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
  EXPECT_EQ(life.ended_by, "revolutions");
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
    table += fmt::format("{:.0e}, {:.0e}, {}, {}, {:.9e}, {:.2e}\n", rtol, rtol * 1e-6, r.steps, r.rhs_evals,
                         max_depth_m(m, r.state), error);
  }
  std::cout << table << "reference: " << reference.steps << " steps\n";
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LT(errors[k], errors[k - 1]) << table;
  EXPECT_LT(errors.back(), 1e-5) << table;
}

// The depth limit ends the life where it is reached, located by root finding and not overshot:
// adaptive (on ARKODE's dense output) and fixed-depth (exactly on the Euler line).
TEST(WearLoop, DepthLimitIsLocated) {
  for (const std::string method : {"adaptive", "fixed-depth"}) {
    WearCase c = paper_wear(20);
    c.wear.limits = WearLimits{3e-5, 0, true};
    c.wear.stepping.method = method;
    c.wear.stepping.max_depth_step_m = 7e-6;
    c.wear.snapshots_revolutions.clear();
    const WearModel m = make_wear_model(c);
    WearCache cache;
    const LifeResult life = run_life(m, c, LifeStart{}, LifeHooks{}, cache);
    EXPECT_EQ(life.ended_by, "max_depth") << method << ": " << life.message;
    EXPECT_NEAR(max_depth_m(m, life.state) / 3e-5, 1.0, 1e-9) << method;
    EXPECT_LT(life.N, c.wear.revolutions);
  }
}

// Fixed stepping by depth: no update wears more than max_depth_step_m; by revolutions, every step is
// step_revolutions but the last. Both reach the adaptive run's depth within their first-order error.
TEST(WearLoop, FixedSteppingRespectsItsStepAndAgreesWithAdaptive) {
  WearCase c = paper_wear(20);
  const double N = 2e7;
  const LifeResult adaptive = run_to(c, N);
  const WearModel m = make_wear_model(c);
  const double depth = max_depth_m(m, adaptive.state);

  c.wear.stepping.method = "fixed-depth";
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

  c.wear.stepping.method = "fixed-revolutions";
  c.wear.stepping.step_revolutions = N / 64;
  const LifeResult by_revolutions = run_to(c, N);
  EXPECT_EQ(by_revolutions.steps, 64);
  EXPECT_NEAR(max_depth_m(m, by_revolutions.state) / depth, 1.0, 0.03);
}

// Step control on the shipped case to its end (the contact reaching the roller's edge): strips enter
// and leave the contact as it widens, and f is only piecewise smooth; the control must not chatter
// (few rejected steps) nor stall (few steps).
TEST(WearLoop, StepControlCopesOnTheShippedCase) {
  const rollwear_test::ExpectWarnings warnings;  // the contact reaching the edge warns
  const WearCase c = paper_wear(80);
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const LifeResult life = run_life(m, c, LifeStart{}, LifeHooks{}, cache);
  EXPECT_TRUE(life.ended_by == "edge" || life.ended_by == "max_depth") << life.message;
  EXPECT_LT(life.steps, 200) << life.message;
  EXPECT_LE(life.rejected, life.steps / 10 + 1) << life.message;
}

// Both bodies wear, each with its own coefficient: each spreads the same dissipated energy over its own
// circumference, so each body's volume rate is its k_E x the energy rate (to rounding), and with the
// same k_E the path's depth per roller revolution is the roller's x R1/R2 (the strips' depths are the
// same per unit circumference; the map to each body's nodes differs, so the areas are compared).
TEST(WearLoop, BothBodiesWearWithTheirOwnCoefficients) {
  WearCase c = paper_wear();
  WearLaw path;
  path.law = "energy";
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
  kth.law = "kth";
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
TEST(WearLoop, BodyWornThroughEndsTheLife) {
  const WearModel m = make_wear_model(paper_wear(20));
  const contact::Profile& p = m.profiles.body1;
  const double width_m = p.y_m(p.y_m.size() - 1) - p.y_m(0);
  Eigen::VectorXd state = initial_state(m);
  state(m.n1 / 2) = 0.99 * width_m - p.z_m(m.n1 / 2);  // deep, but not through
  WearCache cache;
  try {
    normal_state(m, state, cache);
  } catch (const WornThrough& e) {
    ADD_FAILURE() << "0.99 of the width: " << e.what();
  } catch (const std::exception&) {  // the contact of such a profile may fail otherwise: not this test's
  }
  state(m.n1 / 2) = 1.01 * width_m - p.z_m(m.n1 / 2);
  try {
    normal_state(m, state, cache);
    ADD_FAILURE() << "no throw";
  } catch (const WornThrough& e) {
    EXPECT_NE(std::string(e.what()).find("body 1 is worn through"), std::string::npos) << e.what();
  }
}

TEST(WearLoop, PressureLimitAlreadyExceededEndsTheLifeAtTheStart) {
  WearCase c = paper_wear();
  c.wear.limits.max_pressure_Pa = 1e9;
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const LifeResult life = run_life(m, c, LifeStart{}, LifeHooks{}, cache);
  EXPECT_EQ(life.ended_by, "max_pressure") << life.message;
  EXPECT_EQ(life.N, 0);
  EXPECT_EQ(life.steps, 0);
  // a limit below p0's fall: the worn contact's p0 falls through 1.1 GPa, never exceeding it again
  c.wear.limits.max_pressure_Pa = 1.2e9;
  c.wear.revolutions = 1e7;
  c.wear.snapshots_revolutions.clear();
  const WearModel m2 = make_wear_model(c);
  WearCache cache2;
  EXPECT_EQ(run_life(m2, c, LifeStart{}, LifeHooks{}, cache2).ended_by, "revolutions");
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
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_TRUE(a.state == b.state);  // bit for bit
  EXPECT_LT(reuse.counters.tangential_solves, afresh.counters.tangential_solves);
  std::cout << "tangential solves: " << reuse.counters.tangential_solves << " with reuse, "
            << afresh.counters.tangential_solves << " without\n";
}

// ---- regression: the shipped wear cases after a few revolutions ----
// Goldens in tests/data/golden/<case>.txt: 'key value' lines. Regenerate after an intended change with
//   ROLLWEAR_UPDATE_GOLDENS=1 ./build/release/tests/rollwear_tests --gtest_filter='WearGolden.*'
// and commit the files with the reason. Tolerance: 1e-9 relative (the runs are deterministic; the
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
  v["steps"] = static_cast<double>(life.steps);
  return v;
}

TEST(WearGolden, PaperWear) {
  const WearCase c = read_wear_case((kSource / "cases" / "paper-wear.yaml").string());
  const LifeResult life = run_to(c, 1e7);
  check_golden("paper-wear", wear_values(make_wear_model(c), life));
}

TEST(WearGolden, StartStopWear) {
  const WearCase c = read_wear_case((kSource / "cases" / "start-stop-wear.yaml").string());
  const LifeResult life = run_to(c, 1e7);
  check_golden("start-stop-wear", wear_values(make_wear_model(c), life));
}

}  // namespace
}  // namespace wear
