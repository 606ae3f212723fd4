// The roller's spin over the periodic revolution (cam/roller_dynamics.h, docs/cam-follower.md §7): while
// |J alpha + T_b| < mu F_n R_r it rolls with the creepage the steady law gives for F_t = (J alpha + T_b)/R_r
// (in the linear range xi = F_t/(G a b C11), tests/cam_dissipation_test.cpp); beyond it slides, the creep
// force saturated; the revolution repeats until omega_r(2 pi) = omega_r(0).
#include <gtest/gtest.h>

#include "tests/cam_shipped_law.h"

#include <cmath>
#include <limits>

#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/roller_dynamics.h"
#include "lib/numeric.h"

namespace {

using namespace cam;
using contact::kPi;

constexpr double kDeg = kPi / 180;
constexpr double kInf = std::numeric_limits<double>::infinity();

CamModel model(double inertia_kg_m2, double omega_rad_per_s, int steps) {
  CamModel m;
  m.geometry = {0.04, 0.013, 0};
  m.law = shipped_lift_law();
  m.train = {2e4, 150, 0.4, 0.05, inertia_kg_m2, 0.004, 1e-5};
  m.bodies = {0.011, 0.5, 0.014, kInf, {{2.1e11, 0.3}, {2.1e11, 0.3}}};
  m.omega_rad_per_s = omega_rad_per_s;
  m.mu = 0.1;
  m.min_radius_m = 0.003;
  m.max_pressure_angle_rad = 30 * kDeg;
  m.angle_steps = steps;
  return m;
}

RollerDynamicsSettings coarse() {
  RollerDynamicsSettings s;
  s.law.grid = {20, 20};
  return s;
}

// The shipped roller at 600 rpm rolls all round. Where it rolls the creep force is the one rolling needs,
// F_req = (J alpha_kin + T_b + M_z)/R_r (M_z the strips' depth moment, cam/roller_dynamics.h), plus the lag's own inertia J d delta/dt / R_r (delta = omega_r - omega_r,kin,
// the slip's spin, which changes as the force does), plus the bearing's drag on that spin, c_b delta/R_r. Both
// are estimated from the quasi-static motion (cam/roller_motion.h, the law inverted for F_req at each angle,
// no dynamics): the periodic revolution's force stays within 1.5 times the estimate of F_req (the estimate's
// difference quotient against the integrator's) plus BDF2's excursion where delta' has a kink, its creepage
// within 0.1 % of the largest of the quasi-static's.
TEST(CamRollerDynamics, RollingRollerHasTheSteadyLawsCreepageForTheForceRollingNeeds) {
  const CamModel m = model(3.8e-6, 62.83, 180);
  const Revolution r = run_revolution(m);
  ASSERT_EQ(r.sliding_steps, 0);
  const RollerDynamicsSettings s = coarse();
  const PeriodicMotion p = periodic_motion(m, r, s);
  ASSERT_TRUE(p.converged);
  EXPECT_LE(p.periodicity_residual_rad_per_s, p.tolerance_rad_per_s);
  EXPECT_EQ(p.sliding_steps, 0);
  const RollerMotion q = quasi_static_motion(m, r, s.law);
  const std::size_t n = r.rows.size();
  const double dt = 2 * kPi / n / m.omega_rad_per_s;
  double worst = 0, worst_xi = 0, xi_max = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto delta = [&](std::size_t k) {
      return q.angles[k % n].omega_r_rad_per_s - r.rows[k % n].kin.roller_omega_rad_per_s;
    };
    // the larger of the backward and forward differences (the lift's segments join with kinks in delta')
    const double rate = std::max(std::abs(delta(i) - delta(i + n - 1)), std::abs(delta(i + 1) - delta(i))) / dt;
    const double lag_N = m.train.roller_inertia_kg_m2 * rate / m.geometry.roller_radius_m;
    // BDF2's rate departs from the backward difference by half the second difference, which its history carries
    // over the next steps where delta' has a kink (the lift's segments join with a jump in the jerk)
    double second = 0;
    for (std::size_t k = i + n - 3; k <= i + n; ++k)
      second = std::max(second, std::abs(delta(k) - 2 * delta(k - 1) + delta(k - 2)) / dt);
    const double kink_N = m.train.roller_inertia_kg_m2 * second / m.geometry.roller_radius_m;
    // and the bearing's drag on the slip's own spin, c_b delta/R_r (the need is taken at omega_r,kin)
    const double drag_N = m.train.bearing_drag_N_m_s * std::abs(delta(i)) / m.geometry.roller_radius_m;
    const RollerAngle& a = p.motion.angles[i];
    // the crowned roller's strips act below its rolling radius: the creep torque is R_r F_t - M_z
    const double F_req = r.rows[i].loads.required_tangential_N + a.depth_moment_N_m / m.geometry.roller_radius_m;
    EXPECT_NEAR(a.tangential_N, F_req, 1.5 * lag_N + kink_N + 1.1 * drag_N + 1e-9 * m.mu * a.normal_N) << i;
    EXPECT_EQ(a.regime, RollerRegime::Rolling);
    worst = std::max(worst, std::abs(a.tangential_N - F_req) / (m.mu * a.normal_N));
    worst_xi = std::max(worst_xi, std::abs(a.xi - q.angles[i].xi));
    xi_max = std::max(xi_max, std::abs(q.angles[i].xi));
  }
  std::printf("max |F_t - F_req|/(mu F_n) = %.3e, max |xi - xi_qs| = %.3e of max |xi| %.3e; revolutions %d, residual "
              "%.3e rad/s\n", worst, worst_xi, xi_max, p.revolutions, p.periodicity_residual_rad_per_s);
  EXPECT_LT(worst_xi, 1e-3 * xi_max);
}

// A heavier roller (J = 1e-4 kg m^2) at 60 rad/s: where the cam's acceleration asks more than friction gives
// (|J alpha + T_b| >= mu F_n R_r) the creep force is saturated (within 5 % of mu F_n: the law approaches it
// smoothly, and the row where the criterion first holds is still gripping) and the roller slides, its spin
// leaving the kinematic one; where the criterion holds with a margin (|need| >= 1.05 mu F_n R_r) the dynamics
// reports sliding; it grips again after the criterion clears, and rolls elsewhere
TEST(CamRollerDynamics, HeavyRollerSlidesWhereTheFrictionCannotAccelerateIt) {
  const CamModel m = model(1e-4, 60, 180);
  const Revolution r = run_revolution(m);
  ASSERT_GT(r.sliding_steps, 0);
  const PeriodicMotion p = periodic_motion(m, r, coarse());
  ASSERT_TRUE(p.converged);
  EXPECT_LE(p.periodicity_residual_rad_per_s, p.tolerance_rad_per_s);
  constexpr double kSaturated = 0.95;
  int rolling = 0;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const RollerAngle& a = p.motion.angles[i];
    const double need = std::abs(r.rows[i].loads.required_tangential_N) / (m.mu * r.rows[i].loads.normal_N);
    if (r.rows[i].loads.regime == RollerRegime::Sliding) {
      EXPECT_GE(std::abs(a.tangential_N), kSaturated * m.mu * a.normal_N) << i;
      if (need >= 1.05) {
        EXPECT_EQ(a.regime, RollerRegime::Sliding) << i;
      }
    }
    if (a.regime == RollerRegime::Sliding) {
      EXPECT_GE(std::abs(a.tangential_N), kSaturated * m.mu * a.normal_N) << i;
    }
    rolling += a.regime == RollerRegime::Rolling;
  }
  EXPECT_GT(rolling, static_cast<int>(r.rows.size()) / 2);
  EXPECT_GE(p.sliding_steps, r.sliding_steps);
}

}  // namespace
