// The roller's steady creep law and the quasi-steady dissipation over the revolution (cam/creep_law.h,
// cam/roller_motion.h, cam/revolution_dissipation.h; docs/cam-follower.md §7-8), against closed forms:
// the linear law xi = -F_t/(G a b C11) for a small force, full slip mu p |w| per strip at a gross slip
// (docs/physics.md §4.2: the stick zone shrinks as m^2), and P = V xi |F_t| for pure xi (docs/physics.md §4.1).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/revolution_dissipation.h"
#include "cam/roller_motion.h"
#include "lib/numeric.h"

namespace {

using namespace cam;
using contact::kPi;

constexpr double kDeg = kPi / 180;
constexpr double kInf = std::numeric_limits<double>::infinity();

CamModel shipped_like(double bearing_torque_N_m) {
  CamModel m;
  m.geometry = {0.04, 0.013, 0};
  DwellRiseDwellReturn d;
  d.lift_m = 0.01;
  d.rise_rad = 100 * kDeg;
  d.dwell_high_rad = 40 * kDeg;
  d.return_law = SegmentLaw::Polynomial345;
  d.return_rad = 100 * kDeg;
  m.law = make_dwell_rise_dwell_return(d);
  m.train = {2e4, 150, 0.4, 0.05, 3.8e-6, bearing_torque_N_m, 1e-5};
  m.bodies = {0.011, 0.5, 0.014, kInf, {{2.1e11, 0.3}, {2.1e11, 0.3}}};
  m.omega_rad_per_s = 62.8;
  m.mu = 0.1;
  m.min_radius_m = 0.003;
  m.max_pressure_angle_rad = 30 * kDeg;
  m.angle_steps = 180;
  return m;
}

// the contact on the low dwell (300 deg) under F_0
AngleContact dwell_contact(const CamModel& m, const CreepLawSettings& s) {
  const CamKinematics k = cam_kinematics(m.geometry, lift_at(m.law, 300 * kDeg), 300 * kDeg, m.omega_rad_per_s);
  return angle_contact(m.bodies, roller_and_track_profiles(m.bodies), m.geometry.roller_radius_m, k,
                       m.train.preload_N, m.mu, s);
}

// A small force (1e-4 of mu F_n) without Heathcote slip: xi from the inverted steady law is the linear law's,
// with the strip sum's quadrature across y: in the linear range each strip's force is 2 (xi/L1) a_j^2, a
// parabola in y, which ny strips over [-b, b] sum by the midpoint rule 1/(2 ny^2) too high (h^2/(8 b^2),
// h = 2b/ny), so xi is that much lower; the saturation's correction is of the order of F/(mu F_n) = 1e-4.
TEST(CamCreepLaw, SmallForceGivesKalkersLinearCreepage) {
  const CamModel m = shipped_like(0);
  CreepLawSettings s;
  s.heathcote_slip = false;
  const AngleContact c = dwell_contact(m, s);
  const double F = -1e-4 * m.mu * m.train.preload_N;
  const CreepageForForce inv = creepage_for_force(c, F);
  ASSERT_TRUE(inv.found);
  const double xi_lin = -F / (c.G_Pa * c.normal.patch.a_m * c.normal.patch.b_m * c.problem.C.C11);
  const double quadrature = 1.0 / (2.0 * s.grid.ny * s.grid.ny);
  EXPECT_NEAR(inv.xi / xi_lin, 1 / (1 + quadrature), 1e-4);
  EXPECT_GT(std::abs(inv.xi / xi_lin - 1), 0.5 * quadrature);  // the quadrature's term is there
  EXPECT_GT(inv.xi, 0);  // the force against the rolling direction: the roller lags
  EXPECT_NEAR(steady_creep_force_N(c, inv.xi), F, 2 * kCreepForceRtol * m.mu * m.train.preload_N);
}

// A gross slip (xi = 0.5): the steady strip tends to full slip, tau = mu p against the slip, so each strip
// dissipates mu (pi/2 p_j a_j) |V xi_j|, xi_j = xi + its Heathcote offset. The stick zone left at the leading
// edge has the length 2 a_j m^2/(1 + m^2), m = mu p_j L1/(xi a_j) (docs/physics.md §4.2): about 1e-3 here, so
// the strips are within 1e-5 of full slip.
TEST(CamCreepLaw, GrossSlipDissipatesMuTimesLineLoadTimesSlipSpeedStripByStrip) {
  const CamModel m = shipped_like(0);
  const CreepLawSettings s;
  const AngleContact c = dwell_contact(m, s);
  const double xi = 0.5, V = 2.5;
  const contact::TangentialSolution sol = steady_creep(c, xi, V);
  const contact::ContactPatch& p = c.normal.patch;
  constexpr double kFullSlipRtol = 1e-5;
  int strips = 0;
  for (int j = 0; j < p.grid.ny; ++j) {
    if (!(p.half_length_m(j) > 0)) continue;
    const double xi_j = xi + p.strip_xi_offset(j);
    const double full = m.mu * kPi / 2 * p.strip_peak_Pa(j) * p.half_length_m(j) * V * std::abs(xi_j);
    EXPECT_NEAR(sol.strip_power_W_per_m(j), full, kFullSlipRtol * full) << j;
    ++strips;
  }
  EXPECT_GT(strips, s.grid.ny / 2);
  EXPECT_NEAR(sol.Fx_N, -m.mu * m.train.preload_N, kFullSlipRtol * m.mu * m.train.preload_N);
}

// Over a revolution in which the roller rolls everywhere, without Heathcote slip, every angle's dissipated
// power is V xi |F_t| (pure xi, docs/physics.md §4.1) with F_t the force the roller needs there, to rounding;
// the strips' y lie across the track's centre line, symmetric
TEST(CamDissipation, QuasiSteadyPowerIsSpeedTimesCreepageTimesForceAtEveryAngle) {
  const CamModel m = shipped_like(0.004);
  CreepLawSettings s;
  s.heathcote_slip = false;
  const Revolution r = run_revolution(m);
  ASSERT_EQ(r.status, RevolutionStatus::Complete);
  ASSERT_EQ(r.sliding_steps, 0);
  const RollerMotion motion = quasi_static_motion(m, r, s);
  const RevolutionDissipation d = revolution_dissipation(m, r, motion, s);
  ASSERT_EQ(d.size(), r.rows.size());
  constexpr double kRounding = 1e-9;  // sums over 40 strips of the same closed-form strips
  const double duration = 2 * kPi / m.angle_steps / m.omega_rad_per_s;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const RollerAngle& a = motion.angles[i];
    EXPECT_NEAR(a.tangential_N, r.rows[i].loads.tangential_N, 2 * kCreepForceRtol * m.mu * a.normal_N);
    const double P = a.speed_m_per_s * std::abs(a.xi * a.tangential_N);
    EXPECT_NEAR(total_power_W(d[i]), P, kRounding * P) << i;
    EXPECT_NEAR(d[i].duration_s, duration, 1e-15);
    EXPECT_EQ(d[i].theta_rad, r.rows[i].kin.theta_rad);
    EXPECT_NEAR(d[i].y_m(0), -d[i].y_m(d[i].y_m.size() - 1), 1e-12);
    // the strips' mean pressures over their lengths 2 a_j carry the normal load (each strip carries its cell
    // row's load exactly, lib/patch.h)
    const AngleContact c = angle_contact(m.bodies, roller_and_track_profiles(m.bodies), m.geometry.roller_radius_m,
                                         r.rows[i].kin, a.normal_N, m.mu, s);
    const double dy = d[i].y_m(1) - d[i].y_m(0);
    EXPECT_NEAR((d[i].mean_pressure_Pa * 2 * c.normal.patch.half_length_m).sum() * dy, a.normal_N, 1e-9 * a.normal_N);
  }
  EXPECT_GT(dissipation_totals(d).energy_J, 0);
}

// The quasi-static law refuses a sliding row: its slip is the roller's dynamics' to give
TEST(CamDissipation, QuasiStaticMotionRefusesASlidingRow) {
  CamModel m = shipped_like(2 * 0.1 * 150 * 0.013);  // the bearing alone needs 2 mu F_0
  const Revolution r = run_revolution(m);
  ASSERT_GT(r.sliding_steps, 0);
  EXPECT_THROW(quasi_static_motion(m, r), std::invalid_argument);
}

}  // namespace
