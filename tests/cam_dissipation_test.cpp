// The roller's steady creep law and the quasi-steady dissipation over the revolution (cam/creep_law.h,
// cam/roller_motion.h, cam/revolution_dissipation.h; docs/cam-follower.md §7-8), against closed forms:
// the linear law xi = -F_t/(G a b C11) for a small force, full slip mu p |w| per strip at a gross slip
// (docs/physics.md §4.2: the stick zone shrinks as m^2), and P = V xi |F_t| for pure xi (docs/physics.md §4.1).
#include <gtest/gtest.h>

#include "tests/cam_shipped_law.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/revolution_dissipation.h"
#include "cam/roller_dynamics.h"
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
  m.law = shipped_lift_law();
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

// A small force (1e-4 of mu F_n) without Heathcote slip, the simplified theory (consistent): xi from the inverted
// steady law is the linear law's, with the strip sum's quadrature across y: in the linear range each strip's force
// is 2 (xi/L1) a_j^2, a parabola in y, which ny strips over [-b, b] sum by the midpoint rule 1/(2 ny^2) too high
// (h^2/(8 b^2), h = 2b/ny), so xi is that much lower; the saturation's correction is of the order of F/(mu F_n) = 1e-4.
TEST(CamCreepLaw, SmallForceGivesKalkersLinearCreepage) {
  const CamModel m = shipped_like(0);
  CreepLawSettings s;
  s.heathcote_slip = false;
  s.scheme = contact::TangentialScheme::Consistent;
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

// The same with the relaxed model (the default): its law is the simplified theory's at the creepage g_x xi, g_x
// the factor fitted to the exact solver (80^2 cells) at its lowest level e = 0.05 and held below it: 0.970-0.982
// over the table's a/b (lib/tangential/relaxed_table.h). So the linear creepage is Kalker's, xi = F/(G a b C11), to
// that fit: within kRelaxedLinearRtol (the exact theory's linear limit is C11 itself; the factor's departure from
// 1 is the fit's and the exact solver's grid error at e = 0.05), and the law is linear there: the ratio to the
// simplified theory's creepage is the same at 1e-4 and 1e-5 of mu F_n, to the inversion's tolerance.
TEST(CamCreepLaw, RelaxedSmallForceGivesKalkersLinearCreepageToItsFit) {
  const CamModel m = shipped_like(0);
  CreepLawSettings s;
  s.heathcote_slip = false;
  ASSERT_EQ(s.scheme, contact::TangentialScheme::Relaxed);  // the default
  const AngleContact c = dwell_contact(m, s);
  s.scheme = contact::TangentialScheme::Consistent;
  const AngleContact simplified = dwell_contact(m, s);
  constexpr double kRelaxedLinearRtol = 0.035;  // 1/0.970 - 1 = 0.031, the table's largest departure
  const double xi_lin_per_N = 1 / (c.G_Pa * c.normal.patch.a_m * c.normal.patch.b_m * c.problem.C.C11);
  double ratio[2];
  for (int k = 0; k < 2; ++k) {
    const double F = -(k == 0 ? 1e-4 : 1e-5) * m.mu * m.train.preload_N;
    const CreepageForForce inv = creepage_for_force(c, F), ref = creepage_for_force(simplified, F);
    ASSERT_TRUE(inv.found && ref.found);
    EXPECT_NEAR(inv.xi / (-F * xi_lin_per_N), 1, kRelaxedLinearRtol);
    EXPECT_NEAR(steady_creep_force_N(c, inv.xi), F, 2 * kCreepForceRtol * m.mu * m.train.preload_N);
    ratio[k] = inv.xi / ref.xi;
  }
  std::printf("relaxed linear creepage / simplified theory's: %.9f (1e-4 mu F_n), %.9f (1e-5)\n", ratio[0], ratio[1]);
  EXPECT_GT(ratio[0], 1);  // g_x < 1 at the lowest level: a larger creepage for the same force
  EXPECT_NEAR(ratio[0], ratio[1], 1e-5);  // the law's own nonlinearity at 1e-4 of saturation, and the inversion's
}

// A gross slip (xi = 0.5): the steady strip tends to full slip, tau = mu p against the slip, so each strip
// dissipates mu (pi/2 p_j a_j) |V xi_j|, xi_j = xi + its Heathcote offset. The stick zone left at the leading
// edge has the length 2 a_j m^2/(1 + m^2), m = mu p_j L1/(xi a_j) (docs/physics.md §4.2): about 1e-3 here, so
// the strips are within 1e-5 of full slip (the simplified theory; the relaxed model solves it at g_x xi, further
// into full slip).
// The relaxed model's total is the creep forces' work, V sum_j |xi_j| mu (pi/2 p_j a_j) dy at full slip: within
// 1e-5 too. Its strips are the simplified theory's at g_x xi + offset_j scaled to that total (g_x = 2.87 held
// beyond its last level), whose shares differ from those of xi + offset_j by up to (1 - 1/g_x) |offset_j - mean| /
// |xi| (relative): some 1e-4 with the crowned roller's offsets, none without them (checked: strips within 1e-5).
TEST(CamCreepLaw, GrossSlipDissipatesMuTimesLineLoadTimesSlipSpeedStripByStrip) {
  const CamModel m = shipped_like(0);
  constexpr double kFullSlipRtol = 1e-5;
  for (const contact::TangentialScheme scheme : {contact::TangentialScheme::Consistent, contact::TangentialScheme::Relaxed})
    for (const bool heathcote : {true, false}) {
      CreepLawSettings s;
      s.scheme = scheme;
      s.heathcote_slip = heathcote;
      const AngleContact c = dwell_contact(m, s);
      const double xi = 0.5, V = 2.5;
      const contact::TangentialSolution sol = steady_creep(c, xi, V);
      const contact::ContactPatch& p = c.normal.patch;
      const bool relaxed = scheme == contact::TangentialScheme::Relaxed;
      double offset_spread = 0;  // max |offset_j| over |xi|: the relaxed strips' share error's bound (above)
      for (int j = 0; heathcote && j < p.grid.ny; ++j)
        if (p.half_length_m(j) > 0) offset_spread = std::max(offset_spread, 2 * std::abs(p.strip_xi_offset(j)) / xi);
      const double strip_rtol = relaxed && heathcote ? std::max(kFullSlipRtol, offset_spread) : kFullSlipRtol;
      int strips = 0;
      double total = 0;
      for (int j = 0; j < p.grid.ny; ++j) {
        if (!(p.half_length_m(j) > 0)) continue;
        const double xi_j = xi + (heathcote ? p.strip_xi_offset(j) : 0.0);
        const double full = m.mu * kPi / 2 * p.strip_peak_Pa(j) * p.half_length_m(j) * V * std::abs(xi_j);
        EXPECT_NEAR(sol.strip_power_W_per_m(j), full, strip_rtol * full) << to_string(scheme) << " " << j;
        total += full * p.grid.dy_m;
        ++strips;
      }
      EXPECT_GT(strips, s.grid.ny / 2);
      EXPECT_NEAR(sol.power_W, total, kFullSlipRtol * total) << to_string(scheme);
      EXPECT_NEAR(sol.Fx_N, -m.mu * m.train.preload_N, kFullSlipRtol * m.mu * m.train.preload_N) << to_string(scheme);
      if (relaxed && heathcote) {
        EXPECT_LT(offset_spread, 1e-3);  // the bound is small: the offsets are some 1e-4 of xi
      }
    }
}

// The relaxed law saturates where the simplified theory it solves, at xi g_x(a/b, e), does: at the saturation
// creepage of cam/roller_dynamics.h (Johnson and Vermeulen's times relaxed_xi_saturation_level, about 0.6 here) its
// force is the simplified theory's at Johnson and Vermeulen's creepage (without Heathcote's offsets, to rounding:
// 0.97 mu F_n, the semi-elliptic strips keeping a leading stick zone, docs/physics.md §4.2), beyond it it tends to
// mu F_n, and it rises monotonically up to it (the factor's e g_x(e) increasing on the table).
TEST(CamCreepLaw, RelaxedLawSaturatesAtItsSaturationCreepage) {
  const CamModel m = shipped_like(0);
  CreepLawSettings s;
  s.heathcote_slip = false;
  const AngleContact c = dwell_contact(m, s);
  const double muN = m.mu * m.train.preload_N;
  const double xs = saturation_creepage(c);
  const double jv = 3 * muN / (c.G_Pa * c.normal.patch.a_m * c.normal.patch.b_m * c.problem.C.C11);
  std::printf("relaxed saturation creepage %.6e = %.4f of Johnson and Vermeulen's\n", xs, xs / jv);
  EXPECT_GT(xs / jv, 0.5);
  EXPECT_LT(xs / jv, 0.75);
  s.scheme = contact::TangentialScheme::Consistent;
  const double F_jv = steady_creep_force_N(dwell_contact(m, s), jv);
  EXPECT_LT(F_jv, -0.95 * muN);
  EXPECT_NEAR(steady_creep_force_N(c, xs), F_jv, 1e-9 * muN);
  EXPECT_LT(steady_creep_force_N(c, 2 * xs), F_jv);
  EXPECT_GT(steady_creep_force_N(c, 2 * xs), -muN);
  double previous = 0;
  for (int k = 1; k <= 200; ++k) {
    const double F = steady_creep_force_N(c, xs * k / 200.0);
    EXPECT_LT(F, previous) << k;  // -F rises
    previous = F;
  }
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
