// Cam kinematics (cam/kinematics.h, docs/cam-follower.md §2) against closed forms: the base circle's
// radius and speeds on a dwell, the radial follower's pressure angle tan phi = s'/(r_b + R_r + s), the
// radial pitch curve's textbook curvature, and, with an offset, the curvature and the contact's arc rate
// against the pitch and cam curves traced point by point (finite differences of the curve itself).
#include <gtest/gtest.h>

#include <cmath>

#include "cam/cam_error.h"
#include "cam/kinematics.h"
#include "cam/lift_law.h"
#include "cam/revolution.h"
#include "lib/numeric.h"

namespace {

using namespace cam;
using contact::kPi;

constexpr double kDeg = kPi / 180;
constexpr double kRounding = 1e-12;  // relative: closed forms in double

LiftLaw test_law() {
  DwellRiseDwellReturn d;
  d.rise_law = SegmentLaw::Cycloidal;
  d.return_law = SegmentLaw::Polynomial345;
  d.lift_m = 0.012;
  d.rise_rad = 90 * kDeg;
  d.dwell_high_rad = 30 * kDeg;
  d.return_rad = 110 * kDeg;
  return make_dwell_rise_dwell_return(d);
}

constexpr double kOmega = 40;  // rad/s

TEST(CamKinematics, OnTheBaseCircleDwellTheCamRadiusIsTheBaseCircles) {
  const LiftLaw law = test_law();
  for (double e : {0.0, 0.012, -0.02}) {
    const CamGeometry g{0.035, 0.011, e};
    for (double deg : {240.0, 300.0, 355.0}) {  // the low dwell: 230-360 deg
      const CamKinematics k = cam_kinematics(g, lift_at(law, deg * kDeg), deg * kDeg, kOmega);
      EXPECT_NEAR(cam_radius_m(k), g.base_radius_m, kRounding * g.base_radius_m) << e << " " << deg;
      EXPECT_NEAR(1 / k.pitch_curvature_per_m, g.base_radius_m + g.roller_radius_m, kRounding);
      // the surface moves through the contact at omega r_b; the roller turns backwards at omega r_b/R_r
      EXPECT_NEAR(k.rolling_speed_m_per_s, kOmega * g.base_radius_m, kRounding * kOmega);
      EXPECT_NEAR(k.roller_omega_rad_per_s, -kOmega * g.base_radius_m / g.roller_radius_m, kRounding * kOmega);
      EXPECT_NEAR(k.roller_alpha_rad_per_s2, 0, kRounding * kOmega * kOmega);
      // offset: tan phi = -e/s0; the contact on the base circle
      const double Rp = g.base_radius_m + g.roller_radius_m, s0 = std::sqrt(Rp * Rp - e * e);
      EXPECT_NEAR(std::tan(k.pressure_angle_rad), -e / s0, kRounding);
      EXPECT_NEAR(std::hypot(k.contact_x_m, k.contact_y_m), g.base_radius_m, kRounding);
    }
  }
}

TEST(CamKinematics, RadialFollowerPressureAngleAndPitchCurvatureMatchTextbookForms) {
  const LiftLaw law = test_law();
  const CamGeometry g{0.035, 0.011, 0};
  const double Rp = g.base_radius_m + g.roller_radius_m;
  for (double deg = 1; deg < 230; deg += 6.5) {
    const LiftSample s = lift_at(law, deg * kDeg);
    const CamKinematics k = cam_kinematics(g, s, deg * kDeg, kOmega);
    const double d = Rp + s.s_m, v = s.ds_m_per_rad, a = s.d2s_m_per_rad2;
    EXPECT_NEAR(std::tan(k.pressure_angle_rad), v / d, kRounding) << deg;
    // rho = ((Rp + s)^2 + s'^2)^(3/2) / ((Rp + s)^2 + 2 s'^2 - (Rp + s) s'')
    const double rho = std::pow(d * d + v * v, 1.5) / (d * d + 2 * v * v - d * a);
    EXPECT_NEAR(1 / k.pitch_curvature_per_m, rho, kRounding * std::abs(rho)) << deg;
    EXPECT_NEAR(cam_radius_m(k), rho - g.roller_radius_m, kRounding * std::abs(rho)) << deg;
  }
}

// the pitch curve P(theta) = Rot(-theta) (e, s0 + s) and the cam curve traced point by point: their
// curvature from the circle through three neighbouring points, and the contact's arc rate from chords
TEST(CamKinematics, OffsetFollowerCurvatureAndArcRateMatchTheTracedCurves) {
  const LiftLaw law = test_law();
  const CamGeometry g{0.030, 0.012, 0.008};
  const double Rp = g.base_radius_m + g.roller_radius_m, s0 = std::sqrt(Rp * Rp - g.offset_m * g.offset_m);
  const auto pitch = [&](double t, double& x, double& y) {
    const double d = s0 + lift_at(law, t).s_m;
    x = std::cos(t) * g.offset_m + std::sin(t) * d;
    y = -std::sin(t) * g.offset_m + std::cos(t) * d;
  };
  const auto contact_point = [&](double t, double& x, double& y) {
    const CamKinematics k = cam_kinematics(g, lift_at(law, t), t, kOmega);
    x = std::cos(t) * k.contact_x_m + std::sin(t) * k.contact_y_m;
    y = -std::sin(t) * k.contact_x_m + std::cos(t) * k.contact_y_m;
  };
  const double h = 1e-4;  // rad: three-point curvature's error ~ h^2, rounding ~ 1e-16/h^2
  constexpr double kTraceTol = 1e-5;  // relative
  // the points avoid the segment ends (90, 120, 230 deg), where s''' jumps and a stencil across it loses order
  for (double deg = 2.9; deg < 360; deg += 11.7) {
    const double t = deg * kDeg;
    double x0, y0, x1, y1, x2, y2;
    pitch(t - h, x0, y0);
    pitch(t, x1, y1);
    pitch(t + h, x2, y2);
    // the circle through three points: kappa = 2 cross / (|a| |b| |c|), negative for clockwise
    const double cross = (x1 - x0) * (y2 - y1) - (y1 - y0) * (x2 - x1);
    const double kappa = -2 * cross / (std::hypot(x1 - x0, y1 - y0) * std::hypot(x2 - x1, y2 - y1) * std::hypot(x2 - x0, y2 - y0));
    const CamKinematics k = cam_kinematics(g, lift_at(law, t), t, kOmega);
    EXPECT_NEAR(k.pitch_curvature_per_m, kappa, kTraceTol * (1 / Rp)) << deg;
    // the contact's arc rate: |dC/dtheta| by a central chord
    contact_point(t - h, x0, y0);
    contact_point(t + h, x2, y2);
    EXPECT_NEAR(k.arc_rate_m_per_rad, std::hypot(x2 - x0, y2 - y0) / (2 * h), kTraceTol * Rp) << deg;
    // the contact lies on the roller: |C - P| = R_r, and tan phi against the offset form
    EXPECT_NEAR(std::hypot(k.contact_x_m - g.offset_m, k.contact_y_m - k.d_m), g.roller_radius_m, kRounding);
    const LiftSample s = lift_at(law, t);
    EXPECT_NEAR(std::tan(k.pressure_angle_rad), (s.ds_m_per_rad - g.offset_m) / (s0 + s.s_m), kRounding) << deg;
  }
}

CamModel model_of(const CamGeometry& g, double min_radius_m, double max_phi_deg) {
  CamModel m;
  m.geometry = g;
  m.law = test_law();
  m.train = {1e4, 100, 0.3, 0, 0, 0, 0};
  m.bodies = {0.008, 0.3, 0.012, std::numeric_limits<double>::infinity(), {{2.1e11, 0.3}, {2.1e11, 0.3}}};
  m.omega_rad_per_s = 10;
  m.mu = 0.1;
  m.min_radius_m = min_radius_m;
  m.max_pressure_angle_rad = max_phi_deg * kDeg;
  m.angle_steps = 360;
  return m;
}

TEST(CamKinematics, SharpOrSteepDesignsAreRefusedNamingTheAngle) {
  // a small base circle under a fast return: the convex pitch curve's radius at the top falls below
  // R_r + min_radius_m; the error names where
  CamModel m = model_of({0.012, 0.011, 0}, 0.010, 89);
  try {
    run_revolution(m);
    FAIL() << "accepted an undercut cam";
  } catch (const CamError& e) {
    EXPECT_EQ(e.kind, CamErrorKind::Undercut);
    EXPECT_EQ(e.key, "min_radius_m");
    // the check at that angle, recomputed
    const CamKinematics k = cam_kinematics(m.geometry, lift_at(m.law, e.angle_rad), e.angle_rad, m.omega_rad_per_s);
    EXPECT_GT(k.pitch_curvature_per_m, 0);
    EXPECT_LT(1 / k.pitch_curvature_per_m - m.geometry.roller_radius_m, m.min_radius_m);
  }
  // the same lift on that base circle, tolerated radius, but a 20 deg pressure-angle limit
  m = model_of({0.012, 0.011, 0}, 0, 20);
  try {
    run_revolution(m);
    FAIL() << "accepted a pressure angle above the limit";
  } catch (const CamError& e) {
    EXPECT_EQ(e.kind, CamErrorKind::PressureAngle);
    const CamKinematics k = cam_kinematics(m.geometry, lift_at(m.law, e.angle_rad), e.angle_rad, m.omega_rad_per_s);
    EXPECT_GT(std::abs(k.pressure_angle_rad), 20 * kDeg);
    // the first such angle on the steps: the step before is within the limit
    const double before = e.angle_rad - 2 * kPi / m.angle_steps;
    EXPECT_LE(std::abs(cam_kinematics(m.geometry, lift_at(m.law, before), before, 10).pressure_angle_rad), 20 * kDeg);
  }
  // a large base circle passes both
  EXPECT_NO_THROW(run_revolution(model_of({0.040, 0.011, 0}, 0.003, 30)));
}

}  // namespace
