// Loads of the follower train (cam/loads.h, docs/cam-follower.md §3) against hand-computed values, the
// shaft torque against the power balance of a rolling roller, the guide friction's balance, and the
// jump speed against its closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cam/kinematics.h"
#include "cam/lift_law.h"
#include "cam/loads.h"
#include "cam/revolution.h"
#include "lib/numeric.h"

namespace {

using namespace cam;
using contact::kPi;

constexpr double kDeg = kPi / 180;

// cycloidal rise h = 10 mm over 90 deg from 0, return the same, no dwells high
LiftLaw quarter_law() {
  DwellRiseDwellReturn d;
  d.lift_m = 0.01;
  d.rise_rad = kPi / 2;
  d.return_rad = kPi / 2;
  return make_dwell_rise_dwell_return(d);
}

// By hand (a calculator, 16 digits) at theta = 22.5 deg (u = 1/4 of the rise): s = h(1/4 - 1/(2 pi)) =
// 9.084505690810466e-4 m, s' = h/beta = 6.366197723675813e-3 m/rad, s'' = 2 pi h/beta^2 =
// 2.5464790894703257e-2 m/rad^2; r_b = 30 mm, R_r = 10 mm: tan phi = s'/(0.04 + s) = 0.1556206024700295;
// F_0 = 100 N, k = 1e4 N/m, m = 0.5 kg, omega = 20 rad/s: W = 100 + 9.0845 + 5.0930 = 114.17746386975111 N,
// F_n = W/cos phi = 115.55175496695266 N (no roller inertia, bearing or guide: F_t = 0).
TEST(CamLoads, RadialFollowerNormalLoadMatchesTheHandComputedValue) {
  const CamGeometry g{0.03, 0.01, 0};
  const FollowerTrain t{1e4, 100, 0.5, 0, 0, 0, 0};
  const CamKinematics k = cam_kinematics(g, lift_at(quarter_law(), 22.5 * kDeg), 22.5 * kDeg, 20);
  const CamLoads L = cam_loads(t, g, k, 20, 0.1);
  constexpr double kHandDigits = 1e-12;  // relative: the hand values carry 16 digits
  EXPECT_NEAR(std::tan(k.pressure_angle_rad), 0.1556206024700295, kHandDigits);
  EXPECT_NEAR(L.axial_N, 114.17746386975111, kHandDigits * 114);
  EXPECT_NEAR(L.normal_N, 115.55175496695266, kHandDigits * 115);
  EXPECT_EQ(L.tangential_N, 0);
  EXPECT_EQ(L.regime, RollerRegime::Rolling);
  // the shaft torque without friction is W s' (virtual work): 114.17746386975111 * 6.366197723675813e-3
  EXPECT_NEAR(L.shaft_torque_N_m, 0.726876310582687, kHandDigits);
}

// the torque against the power balance of a rolling roller, with offset, roller inertia and bearing
// drag: T omega = (F_n cos phi + F_t sin phi) omega s' + F_t R_r omega_r
TEST(CamLoads, ShaftTorqueBalancesThePowerOfARollingRoller) {
  const CamGeometry g{0.032, 0.012, 0.006};
  const FollowerTrain t{2e4, 150, 0.4, 0, 2e-5, 0.01, 2e-5};
  const LiftLaw law = quarter_law();
  const double w = 30;
  for (double deg = 1; deg < 360; deg += 13.1) {
    const CamKinematics k = cam_kinematics(g, lift_at(law, deg * kDeg), deg * kDeg, w);
    const CamLoads L = cam_loads(t, g, k, w, 0.3);
    ASSERT_EQ(L.regime, RollerRegime::Rolling) << deg;
    const double axial = L.normal_N * std::cos(k.pressure_angle_rad) + L.tangential_N * std::sin(k.pressure_angle_rad);
    const double power = axial * w * k.lift.ds_m_per_rad + L.tangential_N * g.roller_radius_m * k.roller_omega_rad_per_s;
    EXPECT_NEAR(L.shaft_torque_N_m * w, power, 1e-12 * std::abs(L.normal_N) * w * 0.05) << deg;
    // the axial balance without guide friction
    EXPECT_NEAR(axial, L.axial_N, 1e-12 * L.axial_N) << deg;
  }
}

// the guide friction mu_g |Q| opposes the follower's motion: the balance's residual vanishes and
// the normal load grows on the rise, shrinks on the return
TEST(CamLoads, GuideFrictionEntersTheAxialBalance) {
  const CamGeometry g{0.03, 0.01, 0.005};
  const FollowerTrain dry{1e4, 100, 0.5, 0.2, 1e-5, 0.005, 0};
  FollowerTrain none = dry;
  none.guide_mu = 0;
  const LiftLaw law = quarter_law();
  for (double deg : {20.0, 45.0, 70.0, 110.0, 135.0, 160.0}) {
    const CamKinematics k = cam_kinematics(g, lift_at(law, deg * kDeg), deg * kDeg, 20);
    const CamLoads L = cam_loads(dry, g, k, 20, 0.3), L0 = cam_loads(none, g, k, 20, 0.3);
    const double phi = k.pressure_angle_rad;
    const double Q = L.normal_N * std::sin(phi) - L.tangential_N * std::cos(phi);
    const double residual = L.normal_N * std::cos(phi) + L.tangential_N * std::sin(phi) -
                            dry.guide_mu * std::abs(Q) * (k.lift.ds_m_per_rad > 0 ? 1 : -1) - L.axial_N;
    EXPECT_NEAR(residual, 0, 1e-12 * L.axial_N) << deg;
    EXPECT_NEAR(Q, L.guide_reaction_N, 1e-12 * L.normal_N);
    if (deg < 90) EXPECT_GT(L.normal_N, L0.normal_N) << deg;
    else EXPECT_LT(L.normal_N, L0.normal_N) << deg;
  }
}

// k = 0: omega_jump = sqrt(F_0/(m max|s''|)), max |s''| = 2 pi h/beta^2 = 0.025464790894703257 m/rad^2:
// sqrt(100/(0.5 * 0.025464790894703257)) = 88.6226925452758 rad/s (by hand)
TEST(CamLoads, JumpSpeedMatchesItsClosedFormAndStopsTheRun) {
  const FollowerTrain t{0, 100, 0.5, 0, 0, 0, 0};
  const JumpSpeed j = jump_speed(t, quarter_law(), kJumpSamples);
  // the sampling at 0.01 deg meets the peak (67.5 deg, 112.5 deg) exactly
  EXPECT_NEAR(j.omega_rad_per_s, 88.6226925452758, 1e-9);
  // with a spring the minimum moves towards the top of the lift but stays above the k = 0 value
  FollowerTrain sprung = t;
  sprung.spring_rate_N_per_m = 1e4;
  EXPECT_GT(jump_speed(sprung, quarter_law(), kJumpSamples).omega_rad_per_s, j.omega_rad_per_s);

  CamModel m;
  m.geometry = {0.04, 0.01, 0};
  m.law = quarter_law();
  m.train = t;
  m.bodies = {0.008, 0.3, 0.012, std::numeric_limits<double>::infinity(), {{2.1e11, 0.3}, {2.1e11, 0.3}}};
  m.mu = 0.1;
  m.min_radius_m = 0;
  m.max_pressure_angle_rad = 45 * kDeg;
  m.angle_steps = 360;
  m.omega_rad_per_s = 0.99 * j.omega_rad_per_s;
  const Revolution below = run_revolution(m);
  EXPECT_EQ(below.status, RevolutionStatus::Complete);
  EXPECT_EQ(below.rows.size(), 360u);
  m.omega_rad_per_s = 1.01 * j.omega_rad_per_s;
  const Revolution above = run_revolution(m);
  EXPECT_EQ(above.status, RevolutionStatus::Jump);
  EXPECT_TRUE(above.rows.empty());
  EXPECT_NEAR(above.jump_at_theta_rad, 67.5 * kDeg, 1e-9);
}

}  // namespace
