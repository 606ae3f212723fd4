// Wear laws (docs/physics.md §6, wear/wear_law.h): the energy law against its formula and its volume
// balance, Archard as the energy law with k_E = K/(H mu) on the paper's steady case (and the power
// error a naive p |s| sum on classic FASTSIM carries), the KTH map's regions, the USFD function's
// branches, convention and unit conversion on hand-computed cells, zero creepage, and the errors.
#include "wear/wear_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/steady.h"
#include "tests/test_text.h"

namespace wear {
namespace {
using contact::kPi;
using rollwear_test::message_of;

using contact::ContactPatch;
using contact::Creepages;
using contact::TangentialScheme;
using contact::TangentialSolution;

constexpr double kRounding = 1e-13;  // relative: a few hundred additions and products in double

const contact::Bodies kPaperBodies{{0.020, 0.500}, {0.025, contact::kFlat}};
const contact::ElasticPair kSteel{{210e9, 0.28}, {210e9, 0.28}};

// the paper's case (docs/physics.md §1-2, tests/steady_test.cpp): F = 1500 N, mu 0.3, V 1 m/s
ContactPatch paper_patch(int n) { return contact::solve_normal_hertz(kPaperBodies, kSteel, 1500, {n, n}); }

TangentialSolution paper_steady(const ContactPatch& p, Creepages c, TangentialScheme scheme = TangentialScheme::Consistent) {
  return contact::solve_steady(p, contact::make_tangential_problem(p, kSteel, c, 0.3, 1.0), scheme);
}

// one duty cycle of steady rolling: the solution held for duration_s
DutyCycle steady_duty(const ContactPatch& p, const TangentialSolution& s, double duration_s, double R_w) {
  DutyCycle d;
  d.worn_radius_m = R_w;
  d.mu = 0.3;
  d.strip_energy_J_per_m = s.strip_power_W_per_m * duration_s;
  d.stretches.push_back(cell_fields(p, s, 0.3, 1.0, duration_s));
  return d;
}

WearLaw energy_law(double k_E) {
  WearLaw w;
  w.law = WearLawKind::Energy;
  w.k_E_m3_per_J = k_E;
  return w;
}
WearLaw archard_law(double K, double H) {
  WearLaw w;
  w.law = WearLawKind::Archard;
  w.archard_k = K;
  w.hardness_Pa = H;
  return w;
}

// a 1 x 1 grid holding one cell, without a power field (the cell means stand in for it), mu 0.3
CellFields one_cell(double p, double tx, double ty, double sx, double sy, double dx, double V, double T) {
  auto a = [](double v) { return Eigen::ArrayXXd::Constant(1, 1, v); };
  return {a(p), a(tx), a(ty), a(sx), a(sy), Eigen::ArrayXXd(), 0.3, dx, V, T};
}

// ---- energy law ----

TEST(WearLaw, EnergyLawDepthIsKETimesEnergyOverCircumference) {
  // dh = k_E E_l / (2 pi R_w), docs/physics.md §6
  Eigen::ArrayXd E(4);
  E << 0.0, 1.0, 2.5, 40.0;  // J/m
  const double k_E = 2e-13, R_w = 0.02;
  const Eigen::ArrayXd h = depth_from_energy(E, k_E, R_w);
  ASSERT_EQ(h.size(), 4);
  EXPECT_EQ(h(0), 0.0);
  EXPECT_NEAR(h(1) / (2e-13 / (2 * kPi * 0.02)), 1, 1e-15);
  EXPECT_NEAR(h(2) / 3.978873577297384e-12, 1, 1e-12);  // 2e-13 * 2.5 / (0.04 pi), by hand
  EXPECT_NEAR(h(3) / (16 * h(2)), 1, 1e-15);
  // the dispatcher gives the same
  DutyCycle d;
  d.worn_radius_m = R_w;
  d.strip_energy_J_per_m = E;
  EXPECT_TRUE((depth_per_duty_cycle(energy_law(k_E), d) == h).all());
}

TEST(WearLaw, WornVolumeEqualsKETimesDissipatedEnergy) {
  // sum_j dh_j dy 2 pi R_w = k_E sum_j E_l(y_j) dy, to rounding, before any smoothing
  const ContactPatch p = paper_patch(80);
  const TangentialSolution s = paper_steady(p, {1e-3, 4e-4, 0.6});
  const double T = 3600, R_w = 0.02, k_E = 1.5e-13, dy = p.grid.dy_m;
  const DutyCycle d = steady_duty(p, s, T, R_w);
  for (const WearLaw& law : {energy_law(k_E), archard_law(k_E * 6e9 * 0.3, 6e9)}) {
    const Eigen::ArrayXd h = depth_per_duty_cycle(law, d);
    const double volume = h.sum() * dy * 2 * kPi * R_w;
    EXPECT_NEAR(volume / (k_E * s.power_W * T), 1, kRounding) << to_string(law.law);
    EXPECT_NEAR(volume / (k_E * d.strip_energy_J_per_m.sum() * dy), 1, kRounding) << to_string(law.law);
  }
}

TEST(WearLaw, EnergyLawReadsSatranStripEnergy) {
  // a Satran run from rest: the worn volume is k_E times the run's dissipated energy
  contact::TransientCase tc;
  tc.bodies = kPaperBodies;
  tc.materials = kSteel;
  tc.mu = 0.3;
  tc.inputs.xi = contact::constant_history(1e-3);
  tc.inputs.normal_load_N = contact::constant_history(1500);
  tc.settings.grid = {20, 20};
  tc.settings.t_end_s = 2e-3;  // 2 mm rolled at 1 m/s: past the start-up (2 a = 0.46 mm)
  const contact::TransientResult r = contact::run_transient(tc);
  DutyCycle d;
  d.worn_radius_m = 0.02;
  d.strip_energy_J_per_m = r.strip_energy_J_per_m;
  const Eigen::ArrayXd h = depth_per_duty_cycle(energy_law(1e-13), d);
  const double volume = h.sum() * r.grid.dy_m * 2 * kPi * 0.02;
  ASSERT_GT(r.dissipated_J, 0);
  EXPECT_NEAR(volume / (1e-13 * r.dissipated_J), 1, 1e-12);  // dissipated_J summed step by step
}

// ---- Archard ----

TEST(WearLaw, ArchardEnergyCoefficientIsKOverHardnessTimesMu) {
  EXPECT_NEAR(archard_energy_coefficient_m3_per_J(1e-4, 6e9, 0.3) / 5.555555555555556e-14, 1, 1e-15);
}

TEST(WearLaw, ArchardWithZeroFrictionHasNoEnergyEquivalent) {
  const std::string m = message_of([] { archard_energy_coefficient_m3_per_J(1e-4, 6e9, 0.0); });
  EXPECT_NE(m.find("mu = 0 has no energy equivalent"), std::string::npos) << m;
  // the dispatcher reports it too
  DutyCycle d;
  d.worn_radius_m = 0.02;
  d.strip_energy_J_per_m = Eigen::ArrayXd::Ones(3);
  d.mu = 0;
  const std::string m2 = message_of([&] { depth_per_duty_cycle(archard_law(1e-4, 6e9), d); });
  EXPECT_NE(m2.find("no energy equivalent"), std::string::npos) << m2;
}

TEST(WearLaw, ArchardIsEnergyLawWithKOverHMuOnPaperCase) {
  // docs/physics.md §6: Archard = energy law with k_E = K/(H mu), on the same energy-consistent P_l
  const ContactPatch p = paper_patch(80);
  const TangentialSolution s = paper_steady(p, {1e-3, 0, 0});
  const double K = 1e-4, H = 6e9, T = 10, R_w = 0.02;
  const DutyCycle d = steady_duty(p, s, T, R_w);
  const Eigen::ArrayXd archard = depth_per_duty_cycle(archard_law(K, H), d);
  const Eigen::ArrayXd energy = depth_per_duty_cycle(energy_law(K / (H * 0.3)), d);
  ASSERT_GT(archard.maxCoeff(), 0);
  for (int j = 0; j < 80; ++j) EXPECT_NEAR(archard(j), energy(j), kRounding * energy.maxCoeff()) << "strip " << j;
  // and the total is K/(H mu) times the closed-form energy P T (P = 0.159884 W, docs/steady-solver.md)
  constexpr double kGridTol = 5e-4;  // 80 x 80: P within 0.007 % of the closed form
  EXPECT_NEAR(archard.sum() * p.grid.dy_m * 2 * kPi * R_w / (K / (H * 0.3) * 0.1598843 * T), 1, kGridTol);
}

// A naive Archard sum, K/H sum p |s| dx dy, on classic FASTSIM's cell fields inherits its power
// error (docs/physics.md §5: P 19 % low at 80 x 80); the energy route on the consistent scheme does not.
// The same naive sum on the consistent scheme's cell means is off too, the other way (+4.5 %).
TEST(WearLaw, NaivePSlipSumOnClassicFastsimShowsItsPowerError) {
  const ContactPatch p = paper_patch(80);
  const TangentialSolution consistent = paper_steady(p, {1e-3, 0, 0});
  const TangentialSolution classic = paper_steady(p, {1e-3, 0, 0}, TangentialScheme::Classic);
  auto p_slip_sum = [&](const TangentialSolution& s) {  // sum p |s| dx dy, W/mu
    double sum = 0;
    for (int j = 0; j < 80; ++j)
      for (int i = 0; i < 80; ++i)
        sum += p.pressure_Pa(i, j) * std::hypot(s.slip_x_m_per_s(i, j), s.slip_y_m_per_s(i, j));
    return sum * p.grid.dx_m * p.grid.dy_m;
  };
  // the energy route's p |s| integral is P / mu
  const double reference = consistent.power_W / 0.3;
  const double naive_classic = p_slip_sum(classic) / reference - 1;
  const double naive_consistent = p_slip_sum(consistent) / reference - 1;
  RecordProperty("naive_classic_error", std::to_string(naive_classic));
  RecordProperty("naive_consistent_error", std::to_string(naive_consistent));
  std::printf("naive sum p|s| dx dy against P/mu (80 x 80): classic %+.2f %%, consistent cell means %+.2f %%\n",
              100 * naive_classic, 100 * naive_consistent);
  EXPECT_NEAR(naive_classic, -0.19, 0.02);     // measured -19.9 %: the power error of docs/physics.md §5
  EXPECT_NEAR(naive_consistent, 0.045, 0.005);  // measured +4.5 %: cell-mean product (WearLawKth below)
}

// ---- KTH wear map ----

TEST(WearLawKth, RegionsFollowPressureOverHardnessAndSlipSpeed) {
  // Jendel 2002: p/H > 0.8 catastrophic; else |s| < 0.2 mild, 0.2 .. 0.7 severe, > 0.7 mild
  const KthWearMap m;
  EXPECT_EQ(kth_region(m, 0.5, 0.1), KthRegion::MildSlow);
  EXPECT_EQ(kth_region(m, 0.5, 0.2), KthRegion::Severe);  // boundary: severe from 0.2
  EXPECT_EQ(kth_region(m, 0.5, 0.5), KthRegion::Severe);
  EXPECT_EQ(kth_region(m, 0.5, 0.7), KthRegion::Severe);  // through 0.7
  EXPECT_EQ(kth_region(m, 0.5, 0.71), KthRegion::MildFast);
  EXPECT_EQ(kth_region(m, 0.8, 0.1), KthRegion::MildSlow);  // catastrophic above 0.8 only
  EXPECT_EQ(kth_region(m, 0.81, 0.1), KthRegion::Catastrophic);
  EXPECT_EQ(kth_region(m, 0.81, 0.5), KthRegion::Catastrophic);
  EXPECT_EQ(kth_region(m, 0.81, 5.0), KthRegion::Catastrophic);
  EXPECT_EQ(kth_coefficient(m, 0.5, 0.1), m.K_mild_slow);
  EXPECT_EQ(kth_coefficient(m, 0.5, 0.5), m.K_severe);
  EXPECT_EQ(kth_coefficient(m, 0.5, 1.0), m.K_mild_fast);
  EXPECT_EQ(kth_coefficient(m, 0.9, 1.0), m.K_catastrophic);
}

TEST(WearLawKth, SingleCellDepthByHand) {
  // p = 1 GPa, H = 2 GPa (p/H 0.5), |s| = |(0.3, 0.4)| = 0.5 m/s: severe, K = 35e-4;
  // dx = 10 um, V = 2 m/s: dh = K/H p |s| dx/V = 35e-4 / 2e9 * 1e9 * 0.5 * 1e-5 / 2 = 4.375e-9 m
  const CellFields f = one_cell(1e9, -2e8, 0, 0.3, 0.4, 1e-5, 2.0, 1.0);
  const Eigen::ArrayXd h = kth_depth_per_passage(f, KthWearMap{}, 2e9);
  EXPECT_NEAR(h(0) / 4.375e-9, 1, 1e-15);
  // per duty cycle: V T / (2 pi R_w) passages; T = 1 s, R_w = 0.05 m
  WearLaw w;
  w.law = WearLawKind::Kth;
  w.hardness_Pa = 2e9;
  DutyCycle d;
  d.worn_radius_m = 0.05;
  d.stretches = {f};
  EXPECT_NEAR(depth_per_duty_cycle(w, d)(0) / (4.375e-9 * 2.0 / (2 * kPi * 0.05)), 1, 1e-14);
  // sliding at standstill still wears per duty cycle (K/H p |s| dx T / (2 pi R_w))
  d.stretches = {one_cell(1e9, -2e8, 0, 0.3, 0.4, 1e-5, 0.0, 1.0)};
  EXPECT_NEAR(depth_per_duty_cycle(w, d)(0) / (35e-4 / 2e9 * 1e9 * 0.5 * 1e-5 / (2 * kPi * 0.05)), 1, 1e-14);
}

WearLaw uniform_kth(double K, double H) {
  WearLaw w;
  w.law = WearLawKind::Kth;
  w.hardness_Pa = H;
  w.kth.K_mild_slow = w.kth.K_severe = w.kth.K_mild_fast = w.kth.K_catastrophic = K;
  return w;
}

TEST(WearLawKth, UniformCoefficientIsArchardStripByStrip) {
  // one K for every region: with the cells' dissipated power, (p |s|) = D/mu, KTH is Archard through
  // the energy law to rounding, strip by strip (combined creepages: slip direction varies)
  const ContactPatch p = paper_patch(80);
  const TangentialSolution s = paper_steady(p, {1e-3, 4e-4, 0.6});
  const DutyCycle d = steady_duty(p, s, 1.0, 0.02);
  const Eigen::ArrayXd kth = depth_per_duty_cycle(uniform_kth(1e-4, 6e9), d);
  const Eigen::ArrayXd archard = depth_per_duty_cycle(archard_law(1e-4, 6e9), d);
  ASSERT_GT(archard.maxCoeff(), 0);
  constexpr double kCellSum = 1e-12;  // 80 cells summed per strip, against the march's strip total
  for (int j = 0; j < 80; ++j) EXPECT_NEAR(kth(j), archard(j), kCellSum * archard.maxCoeff()) << "strip " << j;
}

// Without a power field (Satran snapshots), (p |s|) is the product of the cell means, which is
// biased at first order in dx: measured on the paper's case, pure xi = 1e-3.
TEST(WearLawKth, CellMeanProductIsHighAtFirstOrder) {
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const int n = 40 * (k + 1);
    const ContactPatch p = paper_patch(n);
    DutyCycle d = steady_duty(p, paper_steady(p, {1e-3, 0, 0}), 1.0, 0.02);
    const double reference = depth_per_duty_cycle(uniform_kth(1e-4, 6e9), d).sum();
    d.stretches[0].power_W_per_m2.resize(0, 0);
    err[k] = depth_per_duty_cycle(uniform_kth(1e-4, 6e9), d).sum() / reference - 1;
  }
  RecordProperty("cell_mean_error_40", std::to_string(err[0]));
  RecordProperty("cell_mean_error_80", std::to_string(err[1]));
  EXPECT_NEAR(err[0], 0.090, 0.01);   // measured +9.0 % at 40 x 40
  EXPECT_NEAR(err[1], 0.045, 0.005);  // +4.5 % at 80 x 80
  EXPECT_NEAR(err[0] / err[1], 2, 0.1);  // first order
}

// ---- USFD ----

TEST(WearLawUsfd, BranchesAndConventionAtTheBreakpoints) {
  const UsfdWearFunction f;
  // published branches where they hold: 5.3 x, 55.0, 61.9 x - 4778.7 (ug/(m mm^2), x in N/mm^2)
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 0.0), 0.0, 1e-15);
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 5.0), 26.5, 1e-12);
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 10.0), 53.0, 1e-12);
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 40.0), 55.0, 1e-12);
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 100.0), 1411.3, 1e-9);
  EXPECT_EQ(usfd_region(f, 5.0), UsfdRegion::Mild);
  EXPECT_EQ(usfd_region(f, 40.0), UsfdRegion::Severe);
  EXPECT_EQ(usfd_region(f, 100.0), UsfdRegion::Catastrophic);
  // convention at 10.4: 55.0 from x = 55/5.3 = 10.377 on (the published mild branch reaches 55.12)
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 10.39), 55.0, 1e-12);
  // convention at 77.2: the published function drops to 61.9 * 77.2 - 4778.7 = -0.02; here it
  // stays 55.0 until the catastrophic branch passes it at (55 + 4778.7)/61.9 = 78.089
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 77.2), 55.0, 1e-12);
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 78.0), 55.0, 1e-12);
  EXPECT_EQ(usfd_region(f, 78.0), UsfdRegion::Severe);
  EXPECT_NEAR(usfd_wear_rate_ug_per_m_mm2(f, 78.2), 61.9 * 78.2 - 4778.7, 1e-9);
  EXPECT_EQ(usfd_region(f, 78.2), UsfdRegion::Catastrophic);
  // continuous and non-decreasing on a fine sweep
  double prev = 0;
  for (int k = 0; k <= 200000; ++k) {
    const double x = k * 1e-3, w = usfd_wear_rate_ug_per_m_mm2(f, x);
    ASSERT_GE(w, prev) << "x = " << x;
    ASSERT_LE(w - prev, 61.9 * 1e-3 + 1e-9) << "jump at x = " << x;
    prev = w;
  }
}

TEST(WearLawUsfd, SingleCellUnitConversionByHand) {
  // |tau| = |(180, 240)| MPa = 300 N/mm^2, |s| = 0.01 m/s, V = 1 m/s: T gamma/A = 3 N/mm^2, mild,
  // W = 5.3 * 3 = 15.9 ug/(m mm^2); dx = 0.1 mm: W dx = 1.59e-3 ug/mm^2 = 1.59e-6 kg/m^2;
  // / 7850 kg/m^3 = 2.025477707e-10 m per passage
  CellFields f = one_cell(1e9, 180e6, 240e6, -0.006, -0.008, 1e-4, 1.0, 1.0);
  const Eigen::ArrayXd h = usfd_depth_per_passage(f, UsfdWearFunction{}, 7850);
  EXPECT_NEAR(h(0) / 2.025477707006369e-10, 1, 1e-13);
  // the same through the cell's dissipated power D = |tau| |s| = 3e6 W/m^2
  f.power_W_per_m2 = Eigen::ArrayXXd::Constant(1, 1, 3e6);
  f.tau_x_Pa.setZero();  // D is read, not the cell means
  EXPECT_NEAR(usfd_depth_per_passage(f, UsfdWearFunction{}, 7850)(0) / 2.025477707006369e-10, 1, 1e-13);
  // per duty cycle: V T / (2 pi R_w) passages
  WearLaw w;
  w.law = WearLawKind::Usfd;
  DutyCycle d;
  d.worn_radius_m = 0.5;
  d.stretches = {f};
  EXPECT_NEAR(depth_per_duty_cycle(w, d)(0) / (h(0) / (2 * kPi * 0.5)), 1, 1e-14);
  // the same cell rolling at V = 0: T gamma/A has no rolled distance to refer to
  d.stretches = {one_cell(1e9, 180e6, 240e6, -0.006, -0.008, 1e-4, 0.0, 1.0)};
  const std::string m = message_of([&] { depth_per_duty_cycle(w, d); });
  EXPECT_NE(m.find("rolling speed > 0"), std::string::npos) << m;
}

// ---- every law ----

TEST(WearLaw, ZeroCreepageProducesNoWearForEveryLaw) {
  const ContactPatch p = paper_patch(40);
  const TangentialSolution s = paper_steady(p, {0, 0, 0});
  const DutyCycle d = steady_duty(p, s, 100.0, 0.02);
  WearLaw kth, usfd;
  kth.law = WearLawKind::Kth;
  kth.hardness_Pa = 6e9;
  usfd.law = WearLawKind::Usfd;
  for (const WearLaw& law : {energy_law(1e-13), archard_law(1e-4, 6e9), kth, usfd}) {
    const Eigen::ArrayXd h = depth_per_duty_cycle(law, d);
    ASSERT_EQ(h.size(), 40) << to_string(law.law);
    EXPECT_TRUE((h == 0).all()) << to_string(law.law) << ": max " << h.abs().maxCoeff();
  }
}

TEST(WearLaw, LocalLawsGrowWithCreepage) {
  // sanity of the local laws on the paper's case: more creepage, more wear, strip by strip in total
  const ContactPatch p = paper_patch(40);
  WearLaw kth, usfd;
  kth.law = WearLawKind::Kth;
  kth.hardness_Pa = 6e9;
  usfd.law = WearLawKind::Usfd;
  double prev_kth = 0, prev_usfd = 0;
  for (double xi : {5e-4, 1e-3, 3e-3}) {
    const DutyCycle d = steady_duty(p, paper_steady(p, {xi, 0, 0}), 1.0, 0.02);
    const double h_kth = depth_per_duty_cycle(kth, d).sum(), h_usfd = depth_per_duty_cycle(usfd, d).sum();
    EXPECT_GT(h_kth, prev_kth) << "xi " << xi;
    EXPECT_GT(h_usfd, prev_usfd) << "xi " << xi;
    prev_kth = h_kth;
    prev_usfd = h_usfd;
  }
}

// ---- configuration ----

TEST(WearLaw, UnknownLawListsTheValidOnes) {
  const std::string m = message_of([] { parse_wear_law("archad"); });
  EXPECT_NE(m.find("wear.law"), std::string::npos) << m;
  EXPECT_NE(m.find("'archad'"), std::string::npos) << m;
  EXPECT_NE(m.find("energy, archard, kth or usfd"), std::string::npos) << m;
  EXPECT_EQ(parse_wear_law("kth"), WearLawKind::Kth);
  EXPECT_EQ(to_string(WearLawKind::Usfd), "usfd");
}

TEST(WearLaw, ValidateNamesTheParameterAndItsRange) {
  EXPECT_EQ(message_of([] { validate(archard_law(0, 6e9)); }), "wear.archard_k: must be in (0, 1], got 0");
  EXPECT_EQ(message_of([] { validate(archard_law(1e-4, 6.0)); }),  // GPa typed as Pa
            "wear.hardness_Pa: must be in [1e8, 1e11] Pa, got 6");
  EXPECT_EQ(message_of([] { validate(energy_law(1e-4)); }),  // mm^3/(N m) typed as m^3/J
            "wear.k_E_m3_per_J: must be in (0, 1e-6] m^3/J, got 0.0001");
  EXPECT_EQ(message_of([] { validate(energy_law(-1e-13)); }), "wear.k_E_m3_per_J: must be in (0, 1e-6] m^3/J, got -1e-13");
  WearLaw u;
  u.law = WearLawKind::Usfd;
  u.density_kg_per_m3 = 7.85;  // g/cm^3
  EXPECT_EQ(message_of([&] { validate(u); }), "wear.density_kg_per_m3: must be in [100, 3e4] kg/m^3, got 7.85");
  WearLaw k;
  k.law = WearLawKind::Kth;
  k.hardness_Pa = 3e9;
  k.kth.slip_speed_high_m_per_s = 0.1;
  const std::string m = message_of([&] { validate(k); });
  EXPECT_NE(m.find("wear.kth.slip_speed_high_m_per_s: must be in (kth.slip_speed_low_m_per_s = 0.2"), std::string::npos)
      << m;
  // the parameters of other laws are not read: an energy law with archard_k = 0 is fine
  EXPECT_EQ(message_of([] { validate(energy_law(1e-13)); }), "no exception");
}

TEST(WearLaw, MissingInputsAndBadRadiusAreReported) {
  DutyCycle d;
  d.worn_radius_m = 0.02;
  WearLaw kth;
  kth.law = WearLawKind::Kth;
  kth.hardness_Pa = 6e9;
  EXPECT_NE(message_of([&] { depth_per_duty_cycle(energy_law(1e-13), d); }).find("no strip_energy_J_per_m"),
            std::string::npos);
  EXPECT_NE(message_of([&] { depth_per_duty_cycle(kth, d); }).find("no per-cell fields"), std::string::npos);
  d.worn_radius_m = 0;
  d.strip_energy_J_per_m = Eigen::ArrayXd::Ones(2);
  EXPECT_EQ(message_of([&] { depth_per_duty_cycle(energy_law(1e-13), d); }),
            "duty cycle: worn_radius_m must be > 0, got 0");
  // a steady solution without fields cannot feed the local laws
  const ContactPatch p = paper_patch(10);
  const TangentialSolution s = contact::solve_steady(
      p, contact::make_tangential_problem(p, kSteel, {1e-3, 0, 0}, 0.3, 1.0), TangentialScheme::Consistent, {false});
  EXPECT_NE(message_of([&] { cell_fields(p, s, 0.3, 1.0, 1.0); }).find("SteadyOptions::fields = true"),
            std::string::npos);
}

}  // namespace
}  // namespace wear
