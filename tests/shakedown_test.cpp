// Fatigue indicators (lib/subsurface/shakedown.h, docs/subsurface.md §4-5): Johnson's shakedown map and the
// surface fatigue index of Ekberg, Kabo and Andersson; Dang Van's criterion over a rolling pass
// (lib/subsurface/dang_van.h, §5) by hand and against McEwen's line contact.
#include "lib/subsurface/dang_van.h"
#include "lib/subsurface/shakedown.h"
#include "lib/subsurface/stress_measures.h"
#include "lib/subsurface/subsurface.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "tests/closed_forms.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace contact {
namespace {

constexpr double kRounding = 1e-12;

// Johnson's map: the line contact's limit is p0/k = 4.0 at low traction and falls as 1/f beyond f = 0.25;
// the circular contact's subsurface limit is 4.7, meeting 1/f at f = 1/4.7
TEST(Shakedown, LimitsFollowJohnsonsMap) {
  EXPECT_NEAR(shakedown_limit_p0_over_k(ShakedownContact::Line, 0), 4.0, kRounding);
  EXPECT_NEAR(shakedown_limit_p0_over_k(ShakedownContact::Line, 0.2), 4.0, kRounding);
  EXPECT_NEAR(shakedown_limit_p0_over_k(ShakedownContact::Line, 0.25), 4.0, kRounding);
  EXPECT_NEAR(shakedown_limit_p0_over_k(ShakedownContact::Line, 0.4), 2.5, kRounding);
  EXPECT_NEAR(shakedown_limit_p0_over_k(ShakedownContact::Point, 0.1), 4.7, kRounding);
  EXPECT_NEAR(shakedown_limit_p0_over_k(ShakedownContact::Point, 0.5), 2.0, kRounding);
  EXPECT_THROW(shakedown_limit_p0_over_k(ShakedownContact::Point, -0.1), std::invalid_argument);
  EXPECT_EQ(shakedown_contact_of(1e-3, 1.1e-3), ShakedownContact::Point);
  EXPECT_EQ(shakedown_contact_of(0.23e-3, 2.61e-3), ShakedownContact::Line);  // the paper's roller, a/b = 0.088
}

// On Hertz's ellipse 2 pi a b / (3 Fz) = 1/p0, so FI_surf = f - k/p0; full sliding at mu puts every cell's
// traction at mu p, so the cell index (mu p - k)/p is largest where p is (mu - k/p0 there)
TEST(Shakedown, SurfaceIndexOnHertzIsTractionLessKOverP0) {
  constexpr double kCellMean = 2e-3;  // the centre cell's mean pressure is below p0 by O(cell^2)
  const ElasticPair steel{{210e9, 0.3}, {210e9, 0.3}};
  const ContactPatch patch = solve_normal_hertz({{0.010, 0.010}, {0.010, 0.010}}, steel, 100, {21, 21});
  const double mu = 0.4, k = 300e6;
  TangentialSolution s;
  s.tau_x_Pa = mu * patch.pressure_Pa;
  s.tau_y_Pa = Eigen::ArrayXXd::Zero(21, 21);
  s.Fx_N = mu * patch.normal_load_N;
  const FatigueIndicators fi = fatigue_indicators(patch, s, k);
  EXPECT_EQ(fi.contact, ShakedownContact::Point);
  EXPECT_NEAR(fi.traction_coefficient, mu, kRounding);
  EXPECT_NEAR(fi.FI_surf, mu - k / patch.p0_Pa, 1e-9);
  EXPECT_NEAR(fi.p0_over_k, patch.p0_Pa / k, kRounding);
  EXPECT_NEAR(fi.limit_p0_over_k, 1 / mu, kRounding);
  EXPECT_TRUE(fi.surface_limit);
  EXPECT_NEAR(fi.margin, (1 / mu) / (patch.p0_Pa / k) - 1, kRounding);
  // the margin and the index agree on which side of the surface limit the load lies
  EXPECT_EQ(fi.margin < 0, fi.FI_surf > 0);
  EXPECT_NEAR(fi.cell_index_max, mu - k / patch.p0_Pa, kCellMean);
  EXPECT_NEAR(fi.cell_x_m, 0, 1e-12);
  EXPECT_TRUE(std::isnan(fi.cell_index(0, 0)));  // the box's corner lies outside the contact
  EXPECT_THROW(fatigue_indicators(patch, s, 0), std::invalid_argument);
}


// ---- Dang Van ----

// a history of n + 1 states t = 0 ... n of the stress f(t) (radians 2 pi t / n)
template <class F>
std::vector<StressTensor> history_of(int n, F f) {
  std::vector<StressTensor> h;
  for (int t = 0; t <= n; ++t) h.push_back(f(2 * kPi * t / n));
  return h;
}

// Pure shear reversing (sigma_xz = tau_a sin): the shift is 0, tau(t) = |sigma_xz|, p_h = 0, so the index is
// tau_a / b; a mean shear (tau_m + tau_a sin) is taken up by the shift and leaves the same index.
TEST(DangVan, ShearAmplitudeByHand) {
  const DangVanConstants k{0.3, 400e6};
  const DangVanPoint reversed =
      dang_van_of_history(history_of(64, [](double w) { return StressTensor{0, 0, 0, 0, 200e6 * std::sin(w), 0}; }), k);
  EXPECT_NEAR(reversed.index, 0.5, kRounding);
  EXPECT_NEAR(reversed.tau_Pa, 200e6, 1e-6);
  EXPECT_NEAR(reversed.hydrostatic_Pa, 0, 1e-6);
  EXPECT_NEAR(reversed.shift.xz, 0, 1e-6);
  const DangVanPoint mean = dang_van_of_history(
      history_of(64, [](double w) { return StressTensor{0, 0, 0, 0, 150e6 + 200e6 * std::sin(w), 0}; }), k);
  EXPECT_NEAR(mean.index, 0.5, kRounding);
  EXPECT_NEAR(mean.shift.xz, 150e6, 1e-6);
}

// Stresses are positive in tension, and tension raises the index: uniaxial sigma_xx from 0 to +S (pulsating
// tension) has the shift at S/2's deviator, tau(t) = |sigma - S/2|/2 <= S/4 and p_h = sigma/3, so the index is
// (S/4 + a S/3)/b, reached at sigma = S; from 0 to -S (pulsating compression) it is (S/4)/b, reached at the
// unloaded state. Fully reversed (+-S): (S/2 + a S/3)/b at the tension peak. With a = 3 tau_w/sigma_w - 3/2 and
// b = tau_w, fully reversed bending at sigma_w and torsion at tau_w both sit on the limit (index 1).
TEST(DangVan, SignConventionTensionPositiveByHand) {
  const double S = 600e6, a = 0.35, b = 350e6;
  const DangVanConstants k{a, b};
  const auto uniaxial = [](double lo, double hi) {
    return history_of(64, [=](double w) { return StressTensor{lo + (hi - lo) * (1 - std::cos(w)) / 2, 0, 0, 0, 0, 0}; });
  };
  const DangVanPoint tension = dang_van_of_history(uniaxial(0, S), k);
  EXPECT_NEAR(tension.index, (S / 4 + a * S / 3) / b, kRounding);
  EXPECT_NEAR(tension.hydrostatic_Pa, S / 3, 1e-6);
  const DangVanPoint compression = dang_van_of_history(uniaxial(0, -S), k);
  EXPECT_NEAR(compression.index, (S / 4) / b, kRounding);
  EXPECT_NEAR(compression.hydrostatic_Pa, 0, 1e-6);
  EXPECT_GT(tension.index, compression.index);
  const DangVanPoint reversed = dang_van_of_history(uniaxial(-S, S), k);
  EXPECT_NEAR(reversed.index, (S / 2 + a * S / 3) / b, kRounding);
  // the constants from two fatigue limits
  const double tau_w = 420e6, sigma_w = 700e6;
  const DangVanConstants fitted{3 * tau_w / sigma_w - 1.5, tau_w};
  EXPECT_NEAR(dang_van_of_history(uniaxial(-sigma_w, sigma_w), fitted).index, 1, kRounding);
  EXPECT_NEAR(dang_van_of_history(history_of(64, [=](double w) { return StressTensor{0, 0, 0, tau_w * std::sin(w), 0, 0}; }),
                                  fitted).index,
              1, kRounding);
  EXPECT_THROW(dang_van_of_history({}, k), std::invalid_argument);
  EXPECT_THROW(dang_van_of_history(uniaxial(0, S), {-0.1, b}), std::invalid_argument);
  EXPECT_THROW(dang_van_of_history(uniaxial(0, S), {a, 0}), std::invalid_argument);
}

// McEwen's stresses in the line contact (Johnson, Contact Mechanics, §4.2 eq. 4.49), plane strain, over p0 with
// lengths over the half-width: m and n take the signs of z and x
StressTensor mcewen(double x, double z, double nu) {
  const double c = 1 - x * x + z * z, root = std::sqrt(c * c + 4 * x * x * z * z);
  const double m = std::sqrt((root + c) / 2), n = std::copysign(std::sqrt(std::max(0.0, (root - c) / 2)), x);
  const double mn = m * m + n * n;
  StressTensor s;
  s.xx = -(m * (1 + (z * z + n * n) / mn) - 2 * z);
  s.zz = -m * (1 - (z * z + n * n) / mn);
  s.xz = n * (m * m - z * z) / mn;
  s.yy = nu * (s.xx + s.zz);
  return s;
}

// The exact shakedown shift, for comparison with the product's mid-range: the centre of the smallest ball
// enclosing the deviatoric path in the tensor norm sqrt(s:s), by Yildirim's Frank-Wolfe algorithm on the dual
// (E. A. Yildirim, "Two algorithms for the minimum enclosing ball problem", SIAM J. Optim. 19 (2008) 1368-1391),
// (plain, without the product's away steps), to a squared radius within 1e-6 relative: the centre within
// 1e-3 radii
std::array<double, 6> smallest_ball_centre(const std::vector<StressTensor>& history) {
  const double w = std::sqrt(2.0);  // shear components count twice in s:s
  std::vector<std::array<double, 6>> p;
  for (const StressTensor& s : history) {
    const double h = (s.xx + s.yy + s.zz) / 3;
    p.push_back({s.xx - h, s.yy - h, s.zz - h, w * s.xy, w * s.xz, w * s.yz});
  }
  const auto dist2 = [](const std::array<double, 6>& a, const std::array<double, 6>& b) {
    double d = 0;
    for (int c = 0; c < 6; ++c) d += (a[c] - b[c]) * (a[c] - b[c]);
    return d;
  };
  std::vector<double> u(p.size(), 1.0 / p.size());
  std::array<double, 6> centre{};
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int c = 0; c < 6; ++c) centre[c] += u[i] * p[i][c];
  for (int iteration = 0; iteration < 1000000; ++iteration) {
    double gamma = 0;  // the dual objective: sum u |p - c|^2
    std::size_t far = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      gamma += u[i] * dist2(p[i], centre);
      if (dist2(p[i], centre) > dist2(p[far], centre)) far = i;
    }
    const double delta = dist2(p[far], centre) / gamma - 1;
    if (delta <= 1e-6) break;
    const double lambda = delta / (2 * (1 + delta));
    for (double& v : u) v *= 1 - lambda;
    u[far] += lambda;
    for (int c = 0; c < 6; ++c) centre[c] = (1 - lambda) * centre[c] + lambda * p[far][c];
  }
  return {centre[0], centre[1], centre[2], centre[3] / w, centre[4] / w, centre[5] / w};
}

// the index with a given shift (tests' own: Tresca's shear of s - shift, p_h = tr/3)
double index_with_shift(const std::vector<StressTensor>& history, const std::array<double, 6>& c,
                        const DangVanConstants& k) {
  double best = -1e300;
  for (const StressTensor& s : history) {
    const double h = (s.xx + s.yy + s.zz) / 3;
    const StressTensor m{s.xx - h - c[0], s.yy - h - c[1], s.zz - h - c[2], s.xy - c[3], s.xz - c[4], s.yz - c[5]};
    best = std::max(best, (tresca_Pa(m) + k.a * h) / k.b_Pa);
  }
  return best;
}

// A rolling line contact (frictionless Hertz, a long ellipse a/b = 0.05 as in tests/subsurface_test.cpp's line
// test): the product's index per depth in the middle strip against the index of McEwen's plane-strain history at
// the same x (the cell centres, with the unloaded state), a = 0.3, b = 0.3 p0. The ellipse is O(a/b) from
// plane strain (sigma_x 1.7-1.9 % of p0 less compressive on the axis): within 0.01 from 0.1 a to 1.35 a
// (measured 9e-3 at 0.1 a, below 1.6e-3 from 0.2 a), the largest 0.5527 against 0.5523, both at 0.55 a. At the
// surface and 0.05 a the cells' tractions (0.317 and 0.260 against 0.333 and 0.307), and from 1.4 a the
// history's end at the box's edge x = +-a, where the two fields differ most, part them (docs/subsurface.md §7).
TEST(DangVan, RollingLineContactMatchesMcEwensHistory) {
  constexpr double kLine = 0.01;  // of the index (of order 1): the ellipse's O(a/b) gap
  constexpr double kShift = 5e-3;  // of the index: the product's centre within 1e-2 radii, the test's 1e-3
  constexpr double kNu = 0.3;
  const HertzContact h = solve_hertz({{0.010, 1.17}, {kFlat, kFlat}}, {{210e9, kNu}, {210e9, kNu}}, 2000);
  ASSERT_NEAR(h.a_m / h.b_m, 0.05, 0.005);
  const Grid grid = make_grid(h.a_m, h.b_m, {41, 41});
  const ContactPatch patch = hertz_patch(h, grid);
  const Subsurface sub = solve_subsurface(surface_tractions(patch, nullptr, 1), kNu, h.a_m);
  // McEwen's field itself: Johnson's axis stresses (tests/closed_forms.h) and tau_zx 0.25 p0 at (0.87 a, 0.5 a)
  for (const double z : {0.25, 0.5, 1.0}) {
    EXPECT_NEAR(mcewen(0, z, kNu).xx, rollwear_test::hertz_line_axis_stress(z).radial, kRounding);
    EXPECT_NEAR(mcewen(0, z, kNu).zz, rollwear_test::hertz_line_axis_stress(z).normal, kRounding);
  }
  EXPECT_NEAR(std::abs(mcewen(0.866, 0.5, kNu).xz), 0.25, 1e-3);
  EXPECT_NEAR(mcewen(-0.866, 0.5, kNu).xz, -mcewen(0.866, 0.5, kNu).xz, kRounding);
  const DangVanConstants k{0.3, 0.3 * h.p0_Pa};
  const DangVanField field = dang_van_field(sub, grid, k);
  // McEwen's history along x at each plane's depth (his stresses times p0)
  double best_closed = 0, best_depth = 0, worst_shift = 0;
  for (std::size_t z = 0; z < sub.planes.size(); ++z) {
    std::vector<StressTensor> history = {StressTensor{}};
    for (int i = 0; i < grid.nx; ++i) {
      const StressTensor s = mcewen(grid.x_m(i) / h.a_m, sub.planes[z].z_m / h.a_m, kNu);
      history.push_back({s.xx * h.p0_Pa, s.yy * h.p0_Pa, s.zz * h.p0_Pa, 0, s.xz * h.p0_Pa, 0});
    }
    const double closed = dang_van_of_history(history, k).index;
    // the product's shift against the test's own smallest ball (at 0.25 a, 0.55 a and 1 a: the plain method
    // is slow)
    if (z == 5 || z == 11 || z == 20) {
      const double exact = index_with_shift(history, smallest_ball_centre(history), k);
      worst_shift = std::max(worst_shift, std::abs(closed - exact));
    }
    const double depth = sub.planes[z].z_m / h.a_m;
    if (depth > 0.09 && depth < 1.36) {  // the cells' surface layer and the box's edge at depth: see above
      EXPECT_NEAR(field.index(20, static_cast<Eigen::Index>(z)), closed, kLine) << "z/a " << depth;
    }
    if (closed > best_closed) best_closed = closed, best_depth = sub.planes[z].z_m;
  }
  EXPECT_NEAR(field.index_max, best_closed, 2e-3);  // measured 4e-4: 0.5527 against 0.5523, both at 0.55 a
  EXPECT_NEAR(field.z_m, best_depth, 1e-3 * h.a_m);
  EXPECT_NEAR(field.y_m, 0, 0.1 * h.b_m);
  // the product's smallest ball against the test's, by the index at every depth
  EXPECT_LT(worst_shift, kShift);
  RecordProperty("index_gap_to_test_ball", std::to_string(worst_shift));
  RecordProperty("index_max", std::to_string(field.index_max));
  RecordProperty("depth_over_a", std::to_string(field.z_m / h.a_m));
}

}  // namespace
}  // namespace contact
