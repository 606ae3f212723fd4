// Fatigue indicators (lib/subsurface/shakedown.h, docs/subsurface.md §4): Johnson's shakedown map and the
// surface fatigue index of Ekberg, Kabo and Andersson.
#include "lib/subsurface/shakedown.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

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

}  // namespace
}  // namespace contact
