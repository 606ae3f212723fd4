// The relaxed model (lib/tangential/relaxed.h) on contacts that are not elliptic: its shape factor
// (lib/tangential/relaxed_shape.h) against its closed forms, and the model on the crown of cases/paper-wear.yaml
// worn for 1e7 revolutions against Kalker's exact theory in-house (tests/data/fast_model/exact_worn_crown.csv,
// with the command and grids that made it; Richardson-extrapolated from 80 and 160 cells).
#include "lib/tangential/relaxed_shape.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <string>

#include "lib/io/case_run.h"
#include "lib/grid.h"
#include "lib/io/case.h"
#include "lib/csv_reader.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "lib/tangential/tangential.h"

namespace contact {
namespace {

const std::string kData = std::string(ROLLWEAR_SOURCE_DIR) + "/tests/data/fast_model/";

// the steady targets (not loosened): Fx within 2 % of the exact theory, the power within 3 % of the
// exact creep forces' work
constexpr double kForceTarget = 0.02, kPowerTarget = 0.03;

// A Hertz patch is its own equivalent ellipse: S = 1 to rounding (the model is unchanged on Hertz contacts).
TEST(RelaxedShape, HertzPatchIsOne) {
  for (const double ab : {0.05, 0.3, 1.0, 3.0}) {
    HertzContact h;
    h.b_m = 1e-3;
    h.a_m = ab * h.b_m;
    h.p0_Pa = 1e9;
    h.normal_load_N = 2 * kPi * h.a_m * h.b_m * h.p0_Pa / 3;
    EXPECT_NEAR(relaxed_shape_factor(hertz_patch(h, make_grid(h.a_m, h.b_m, {40, 80}))), 1.0, 1e-12) << ab;
  }
}

// A band of uniform half-length A over |y| < b (the flattest contact), its equivalent ellipse of the same area
// (a = 4A/pi): S = A / (a (4/3)/(pi/2)) = 3 pi^2 / 32 in the limit of many strips (closed form, relaxed_shape.h);
// 2000 strips: the strips' sums within 1e-3 of the integrals.
TEST(RelaxedShape, UniformBandTendsToTheClosedForm) {
  ContactPatch p;
  const double b = 1e-3, A = 1e-4;
  p.b_m = b;
  p.a_m = 4 * A / kPi;
  p.grid = make_grid(A, b, {10, 2000});
  p.half_length_m = Eigen::ArrayXd::Constant(2000, A);
  EXPECT_NEAR(relaxed_shape_factor(p), 3 * kPi * kPi / 32, 1e-3);
  // a band off the grid's centre: the same (the equivalent ellipse is centred on the strips' centroid)
  p.grid = make_grid(A, 2 * b, {10, 4000});
  p.half_length_m = (p.grid.y_m > 0).select(Eigen::ArrayXd::Constant(4000, A), 0.0);
  EXPECT_NEAR(relaxed_shape_factor(p), 3 * kPi * kPi / 32, 1e-3);
}

// The factor is memoised per thread on the patch's values: a patch changed in place (the same object) is seen.
TEST(RelaxedShape, PatchChangedInPlaceIsSeen) {
  ContactPatch p;
  const double b = 1e-3, A = 1e-4;
  p.b_m = b;
  p.a_m = 4 * A / kPi;
  p.grid = make_grid(A, b, {10, 400});
  p.half_length_m = Eigen::ArrayXd::Constant(400, A);
  const double band = relaxed_shape_factor(p);
  p.half_length_m = A * (1 - (p.grid.y_m / b).square()).max(0.0).sqrt();  // an ellipse of semi-axes A, b
  p.a_m = A;
  EXPECT_NEAR(relaxed_shape_factor(p), 1.0, 1e-12);
  EXPECT_NEAR(band, 3 * kPi * kPi / 32, 2e-3);
}

// The strips' weights move the power among the strips and keep its total; on a thin Hertz contact (p = 1 - (a/b)/2)
// the strip of half-length a_j gets (a / a_j)^p of the springs' share.
TEST(RelaxedShape, StripWeightsKeepTheTotal) {
  HertzContact h;
  h.b_m = 1e-3;
  h.a_m = 0.1 * h.b_m;
  h.p0_Pa = 1e9;
  h.normal_load_N = 2 * kPi * h.a_m * h.b_m * h.p0_Pa / 3;
  const ContactPatch patch = hertz_patch(h, make_grid(h.a_m, h.b_m, {20, 40}));
  TangentialSolution s;
  s.strip_power_W_per_m = patch.half_length_m.square();  // the springs' linear strip power ~ a_j^2
  const double total = s.strip_power_W_per_m.sum();
  redistribute_strip_power(s, patch);
  EXPECT_NEAR(s.strip_power_W_per_m.sum(), total, 1e-12 * total);
  const double p = relaxed_strip_power_exponent(0.1);
  EXPECT_DOUBLE_EQ(p, 0.95);
  const int mid = 20, off = 35;  // a_j^(2 - p) after the weights
  EXPECT_NEAR(s.strip_power_W_per_m(off) / s.strip_power_W_per_m(mid),
              std::pow(patch.half_length_m(off) / patch.half_length_m(mid), 2 - p), 1e-12);
}

// The exponent fades to none at full slip (e = 1: the exact and the springs' strip powers both tend to
// mu integral of p |s| dx) and under pure spin, continuously (relaxed_shape.h: p0 (1 - e^3) (1 - s)).
TEST(RelaxedShape, StripExponentFadesWithLevelAndSpin) {
  const double p0 = relaxed_strip_power_exponent(0.1);
  EXPECT_DOUBLE_EQ(relaxed_strip_power_exponent(0.1, 0, 0), p0);
  EXPECT_DOUBLE_EQ(relaxed_strip_power_exponent(0.1, 1, 0), 0.0);
  EXPECT_DOUBLE_EQ(relaxed_strip_power_exponent(0.1, 0, 1), 0.0);
  EXPECT_DOUBLE_EQ(relaxed_strip_power_exponent(0.1, 0.5, 0.5), p0 * (1 - 0.125) * 0.5);
  EXPECT_DOUBLE_EQ(relaxed_strip_power_exponent(0.1, 1.5, -0.5), 0.0);  // clamped to [0, 1]
  constexpr double kStep = 1e-6;  // continuity: a small change of e or s moves p by at most about 3 p0 times it
  for (double e = 0; e < 1; e += 0.05) {
    EXPECT_LE(std::abs(relaxed_strip_power_exponent(0.1, e + kStep, 0.2) - relaxed_strip_power_exponent(0.1, e, 0.2)),
              3 * p0 * kStep * 1.0001);
    EXPECT_LE(std::abs(relaxed_strip_power_exponent(0.1, 0.3, e + kStep) - relaxed_strip_power_exponent(0.1, 0.3, e)),
              p0 * kStep * 1.0001);
  }
  // on a thin Hertz patch at full slip the springs' distribution is left as it is
  HertzContact h;
  h.b_m = 1e-3;
  h.a_m = 0.1 * h.b_m;
  h.p0_Pa = 1e9;
  h.normal_load_N = 2 * kPi * h.a_m * h.b_m * h.p0_Pa / 3;
  const ContactPatch patch = hertz_patch(h, make_grid(h.a_m, h.b_m, {20, 40}));
  TangentialSolution s;
  s.strip_power_W_per_m = patch.half_length_m.square();
  const Eigen::ArrayXd before = s.strip_power_W_per_m;
  redistribute_strip_power(s, patch, 1.0, 0.0);
  EXPECT_TRUE((s.strip_power_W_per_m == before).all());
}

// the exact reference: (heathcote_slip, n) -> Fx, power, creep work; n = 0 the extrapolation
std::map<std::string, std::array<double, 3>> exact_worn_crown() {
  std::map<std::string, std::array<double, 3>> m;
  for (const auto& r : read_csv_table(kData + "exact_worn_crown.csv").rows)
    m[r.at(0) + "," + r.at(1)] = {std::stod(r.at(2)), std::stod(r.at(3)), std::stod(r.at(4))};
  return m;
}

ContactRun worn_crown(const std::string& scheme, bool heathcote) {
  ContactCase c = read_contact_case(kData + "worn-crown-1e7.yaml");
  c.solver.tangential = parse_tangential_scheme(scheme);
  c.profiles->heathcote_slip = heathcote;
  return solve_contact_case(c, false);
}

// The crown of paper-wear worn for 1e7 revolutions (a/b = 0.037, semi-Hertz, its band flattened: S = 0.947):
// the relaxed model's Fx within 2 % of the exact theory's and its power within 3 % of the exact creep work, with
// the Heathcote offsets and without them (before the shape factor: -3.9 % both ways, the power -4.2 %).
TEST(RelaxedWorn, WornCrownForceAndPowerWithinTheTargetsOfTheExactTheory) {
  const auto exact = exact_worn_crown();
  for (const bool heathcote : {true, false}) {
    const std::array<double, 3>& ref = exact.at(std::string(heathcote ? "true" : "false") + ",0");
    const ContactRun relaxed = worn_crown("relaxed", heathcote), consistent = worn_crown("consistent", heathcote);
    const double fx = relaxed.solution.Fx_N / ref[0] - 1, p = relaxed.solution.power_W / -ref[2] - 1;
    std::cout << "worn crown, heathcote " << heathcote << ": S = " << relaxed_shape_factor(relaxed.normal.patch)
              << ", relaxed Fx " << relaxed.solution.Fx_N << " N (" << 100 * fx << " %), P " << relaxed.solution.power_W
              << " W (" << 100 * p << " %); consistent Fx " << consistent.solution.Fx_N << " N ("
              << 100 * (consistent.solution.Fx_N / ref[0] - 1) << " %); exact (extrapolated) " << ref[0] << " N, "
              << -ref[2] << " W\n";
    EXPECT_NEAR(fx, 0, kForceTarget) << heathcote;
    EXPECT_NEAR(p, 0, kPowerTarget) << heathcote;
  }
}

}  // namespace
}  // namespace contact
