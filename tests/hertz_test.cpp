// Hertz's normal problem against closed forms (docs/physics.md §2).
#include "lib/normal/hertz.h"
#include "lib/numeric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace contact {
namespace {

Bodies paper_bodies() { return {{0.020, 0.500}, {0.025, kFlat}}; }
ElasticPair steel() { return {{210e9, 0.28}, {210e9, 0.28}}; }

// docs/physics.md §2 quotes the paper's case to six digits; the paper itself prints a = 0.229 mm,
// b = 2.627 mm, p0 = 1190 MPa from approximate formulas (about 0.7 % off).
TEST(HertzNormal, PaperCaseMatchesReferenceValues) {
  constexpr double kSixDigits = 5e-6;  // the reference values are given to 6-7 significant digits
  const HertzContact h = solve_hertz(paper_bodies(), steel(), 1500);
  EXPECT_NEAR(h.a_m / 0.230290e-3, 1, kSixDigits);
  EXPECT_NEAR(h.b_m / 2.610098e-3, 1, kSixDigits);
  EXPECT_NEAR(h.p0_Pa / 1191.517e6, 1, kSixDigits);
  EXPECT_NEAR(h.approach_m / 9.1991e-6, 1, 2e-5);  // given to 5 digits
}

TEST(HertzNormal, CircularContactRadiusMatchesClosedForm) {
  // two equal spheres R = 10 mm: R_eff = 5 mm, a^3 = 3 F R / (4 E*), delta = a^2 / R, p0 = 3F/(2 pi a^2)
  const Bodies balls{{0.010, 0.010}, {0.010, 0.010}};
  const HertzContact h = solve_hertz(balls, steel(), 100);
  const double Estar = 210e9 / (2 * (1 - 0.28 * 0.28));
  const double R = 0.005;
  const double a = std::cbrt(3 * 100 * R / (4 * Estar));
  EXPECT_NEAR(h.a_m / a, 1, 1e-14);
  EXPECT_NEAR(h.b_m / a, 1, 1e-14);
  EXPECT_NEAR(h.approach_m / (a * a / R), 1, 1e-14);
  EXPECT_NEAR(h.p0_Pa / (3 * 100 / (2 * kPi * a * a)), 1, 1e-14);
}

// Just off the circle the elliptic formulas must join the circular closed form continuously.
TEST(HertzNormal, NearlyCircularJoinsCircularLimit) {
  const Bodies near{{0.010, 0.010 * (1 + 1e-6)}, {0.010, 0.010}};
  const Bodies circle{{0.010, 0.010}, {0.010, 0.010}};
  const HertzContact e = solve_hertz(near, steel(), 100), c = solve_hertz(circle, steel(), 100);
  EXPECT_NEAR(std::sqrt(e.a_m * e.b_m) / c.a_m, 1, 1e-6);
  EXPECT_NEAR(e.approach_m / c.approach_m, 1, 1e-6);
}

// The ellipse equations (hertz.h) hold at the solution, for either orientation.
class HertzEllipse : public testing::TestWithParam<double> {};
TEST_P(HertzEllipse, SatisfiesCurvatureRatioEquationEitherOrientation) {
  const double ratio = GetParam();  // Ry1/Rx1 for body 1 on a flat
  for (bool swap : {false, true}) {
    const double Rx = swap ? 0.01 * ratio : 0.01, Ry = swap ? 0.01 : 0.01 * ratio;
    const HertzContact h = solve_hertz({{Rx, Ry}, {kFlat, kFlat}}, steel(), 1000);
    const double major = std::max(h.a_m, h.b_m), minor = std::min(h.a_m, h.b_m);
    const double k = minor / major, e = std::sqrt(1 - k * k);
    const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    EXPECT_NEAR(((E / (k * k)) - K) / (K - E) / ratio, 1, 1e-10);
    // the semi-axis along the larger curvature is the smaller one
    EXPECT_EQ(h.a_m < h.b_m, !swap);
    EXPECT_NEAR(h.p0_Pa * 2 * kPi * h.a_m * h.b_m / 3, 1000, 1e-9);
  }
}
INSTANTIATE_TEST_SUITE_P(Ratios, HertzEllipse, testing::Values(1.5, 10.0, 45.0, 1e3, 1e5));

// Two materials: 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2 enters the normal problem.
TEST(HertzNormal, DifferentMaterialsUseCombinedModulus) {
  const ElasticPair pair{{210e9, 0.3}, {70e9, 0.33}};
  const HertzContact h = solve_hertz({{0.01, 0.01}, {0.01, 0.01}}, pair, 50);
  const double Estar = 1 / ((1 - 0.09) / 210e9 + (1 - 0.33 * 0.33) / 70e9);
  EXPECT_NEAR(h.a_m / std::cbrt(3 * 50 * 0.005 / (4 * Estar)), 1, 1e-14);
}

class HertzPatchGrid : public testing::TestWithParam<int> {};
TEST_P(HertzPatchGrid, PressureIntegratesToNormalLoad) {
  const int n = GetParam();
  const ContactPatch p = solve_normal_hertz(paper_bodies(), steel(), 1500, {n, n});
  const double load = p.pressure_Pa.sum() * p.grid.dx_m * p.grid.dy_m;
  EXPECT_NEAR(load / 1500, 1, 1e-12);  // strips carry their rows' loads exactly
  // and each strip's semi-ellipse integrates to its row load: (pi/2) p_j a_j
  for (int j = 0; j < n; ++j)
    EXPECT_NEAR(p.pressure_Pa.col(j).sum() * p.grid.dx_m, kPi / 2 * p.strip_peak_Pa(j) * p.half_length_m(j),
                1e-9 * p.p0_Pa * p.a_m);
}
INSTANTIATE_TEST_SUITE_P(Grids, HertzPatchGrid, testing::Values(1, 5, 20, 80, 317));

TEST(HertzNormal, StripsFollowTheEllipse) {
  const ContactPatch p = solve_normal_hertz(paper_bodies(), steel(), 1500, {40, 40});
  for (int j = 0; j < 40; ++j) {
    const double s = p.grid.y_m(j) / p.b_m;
    EXPECT_NEAR(p.half_length_m(j), p.a_m * std::sqrt(1 - s * s), 1e-15);
    // the row-averaged peak differs from the point value p0 sqrt(1 - s^2) by O(dy^2)
    EXPECT_NEAR(p.strip_peak_Pa(j) / (p.p0_Pa * std::sqrt(1 - s * s)), 1, 0.05);
  }
}

TEST(HertzNormal, GridLargerThanEllipseKeepsLoad) {
  const HertzContact h = solve_hertz(paper_bodies(), steel(), 1500);
  const ContactPatch p = hertz_patch(h, make_grid(1.7 * h.a_m, 1.3 * h.b_m, {50, 50}));
  EXPECT_NEAR(p.pressure_Pa.sum() * p.grid.dx_m * p.grid.dy_m / 1500, 1, 1e-12);
  EXPECT_TRUE((p.pressure_Pa >= 0).all());
}

TEST(HertzNormal, RejectsImpossibleInput) {
  const ElasticPair m = steel();
  EXPECT_THROW(solve_hertz({{0.02, 0.5}, {-0.02, kFlat}}, m, 1500), std::invalid_argument);  // A = 0
  EXPECT_THROW(solve_hertz({{0.02, 0.5}, {0.025, -0.4}}, m, 1500), std::invalid_argument);   // B < 0
  EXPECT_THROW(solve_hertz({{kFlat, kFlat}, {kFlat, kFlat}}, m, 1500), std::invalid_argument);
  EXPECT_THROW(solve_hertz({{0.0, 0.5}, {0.025, kFlat}}, m, 1500), std::invalid_argument);
  EXPECT_THROW(solve_hertz(paper_bodies(), m, 0), std::invalid_argument);
  EXPECT_THROW(solve_hertz(paper_bodies(), m, -1), std::invalid_argument);
  EXPECT_THROW(solve_hertz(paper_bodies(), {{0, 0.28}, {210e9, 0.28}}, 1500), std::invalid_argument);
  EXPECT_THROW(solve_hertz(paper_bodies(), {{210e9, 0.5}, {210e9, 0.28}}, 1500), std::invalid_argument);
  EXPECT_THROW(solve_hertz(paper_bodies(), {{210e9, -0.1}, {210e9, 0.28}}, 1500), std::invalid_argument);
}

}  // namespace
}  // namespace contact
