// The roller-cam contact (cam/roller_contact.h, docs/cam-follower.md §4): on the base-circle dwell it is
// Hertz's between the roller and the base circle (closed form, lib/normal/hertz.h); the roller's two
// regimes by |J alpha + T_b| < mu F_n R_r, on the dwell where alpha = 0 and F_n = F_0 by hand: rolling
// with Kalker's linear creepage xi = F_t/(G a b C11) (the roller lags: xi > 0), sliding with F_t = mu F_n.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cam/kinematics.h"
#include "cam/lift_law.h"
#include "cam/loads.h"
#include "cam/revolution.h"
#include "cam/roller_contact.h"
#include "lib/elastic.h"
#include "lib/normal/hertz.h"
#include "lib/normal/profile.h"
#include "lib/numeric.h"
#include "lib/tangential/kalker.h"

namespace {

using namespace cam;
using contact::kPi;

constexpr double kDeg = kPi / 180;
constexpr double kInf = std::numeric_limits<double>::infinity();

CamModel dwell_model(double bearing_torque_N_m) {
  CamModel m;
  m.geometry = {0.04, 0.013, 0};
  DwellRiseDwellReturn d;
  d.lift_m = 0.01;
  d.rise_rad = 100 * kDeg;
  d.dwell_high_rad = 40 * kDeg;
  d.return_rad = 100 * kDeg;
  m.law = make_dwell_rise_dwell_return(d);
  m.train = {2e4, 150, 0.4, 0, 3.8e-6, bearing_torque_N_m, 0};
  m.bodies = {0.011, 0.5, 0.014, kInf, {{2.1e11, 0.3}, {2.1e11, 0.3}}};
  m.omega_rad_per_s = 20;
  m.mu = 0.1;
  m.min_radius_m = 0.003;
  m.max_pressure_angle_rad = 30 * kDeg;
  m.angle_steps = 360;
  return m;
}

TEST(CamContact, OnTheBaseCircleDwellTheContactIsHertzBetweenRollerAndBaseCircle) {
  const Revolution r = run_revolution(dwell_model(0));
  ASSERT_EQ(r.status, RevolutionStatus::Complete);
  // lib/normal/normal.h puts Hertz on the profiles' fitted parabolas: the roller's crown arc over its
  // width has the fitted radius 1/curvature (within (w/2R)^2 ~ 1e-4 of R = 0.5 m)
  const cam::CamModel m = dwell_model(0);
  const contact::Profiles prof = roller_and_track_profiles(m.bodies);
  const double Ry = 1 / contact::fit_parabola(prof.body1).curvature_per_m;
  EXPECT_NEAR(Ry, 0.5, 1e-4 * 0.5);
  const contact::HertzContact h = contact::solve_hertz({{0.013, Ry}, {0.04, kInf}},
                                                       {{2.1e11, 0.3}, {2.1e11, 0.3}}, 150);
  const contact::HertzContact nominal = contact::solve_hertz({{0.013, 0.5}, {0.04, kInf}},
                                                             {{2.1e11, 0.3}, {2.1e11, 0.3}}, 150);
  constexpr double kHertzRtol = 1e-9;  // the same closed form reached through the profiles: rounding
  constexpr double kNominalRtol = 1e-4;  // against the nominal crown radius: the fit above
  int checked = 0;
  for (const RevolutionRow& w : r.rows) {
    if (w.kin.theta_rad < 245 * kDeg) continue;  // the low dwell: 240-360 deg
    ASSERT_EQ(w.contact.solver, contact::NormalSolverKind::Hertz);
    EXPECT_NEAR(w.loads.normal_N, 150, 1e-12 * 150);
    EXPECT_NEAR(w.contact.a_m, h.a_m, kHertzRtol * h.a_m);
    EXPECT_NEAR(w.contact.b_m, h.b_m, kHertzRtol * h.b_m);
    EXPECT_NEAR(w.contact.p0_Pa, h.p0_Pa, kHertzRtol * h.p0_Pa);
    EXPECT_NEAR(w.contact.b_m, nominal.b_m, kNominalRtol * nominal.b_m);
    EXPECT_NEAR(w.contact.p0_Pa, nominal.p0_Pa, kNominalRtol * nominal.p0_Pa);
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

// On the dwell alpha = 0 and omega_r = -omega r_b/R_r < 0, so T_b = -T_0 and F_t = -T_0/R_r; F_n = F_0.
// T_0 = 0.5 mu F_0 R_r rolls (xi = T_0/(R_r G a b C11) > 0: the bearing makes the roller lag);
// T_0 = 2 mu F_0 R_r slides (F_t = -mu F_n, xi undefined).
TEST(CamContact, TheRollerRollsBelowTheFrictionLimitAndSlidesAbove) {
  const double mu = 0.1, F0 = 150, Rr = 0.013;
  const contact::ElasticPair pair{{2.1e11, 0.3}, {2.1e11, 0.3}};
  const double Ry = 1 / contact::fit_parabola(roller_and_track_profiles(dwell_model(0).bodies).body1).curvature_per_m;
  const contact::HertzContact h = contact::solve_hertz({{Rr, Ry}, {0.04, kInf}}, pair, F0);
  const double G = contact::combined_shear_modulus_Pa(pair);
  const double C11 = contact::kalker_coefficients(h.a_m, h.b_m, contact::combined_poisson(pair)).C11;
  {
    const double T0 = 0.5 * mu * F0 * Rr;
    const Revolution r = run_revolution(dwell_model(T0));
    const RevolutionRow& w = r.rows[300];  // 300 deg, on the dwell
    EXPECT_EQ(w.loads.regime, RollerRegime::Rolling);
    EXPECT_NEAR(w.loads.tangential_N, -T0 / Rr, 1e-12);
    const double xi = T0 / Rr / (G * h.a_m * h.b_m * C11);
    EXPECT_NEAR(w.contact.xi, xi, 1e-9 * xi);
    EXPECT_GT(w.contact.xi, 0);
    EXPECT_FALSE(w.contact.linear_range);  // 0.5 mu F_n: beyond kLinearRangeFraction, flagged
  }
  {
    const double T0 = 2 * mu * F0 * Rr;
    const Revolution r = run_revolution(dwell_model(T0));
    const RevolutionRow& w = r.rows[300];
    EXPECT_EQ(w.loads.regime, RollerRegime::Sliding);
    EXPECT_NEAR(w.loads.tangential_N, -mu * F0, 1e-12 * F0);
    EXPECT_TRUE(std::isnan(w.contact.xi));
    for (const RevolutionRow& v : r.rows) {  // the whole low dwell slides (F_n = F_0 there)
      if (v.kin.theta_rad >= 240 * kDeg) {
        EXPECT_EQ(v.loads.regime, RollerRegime::Sliding) << v.kin.theta_rad / kDeg;
      }
    }
  }
  {  // small drag: the linear range
    const double T0 = 0.1 * mu * F0 * Rr;
    const RevolutionRow w = run_revolution(dwell_model(T0)).rows[300];
    EXPECT_EQ(w.loads.regime, RollerRegime::Rolling);
    EXPECT_TRUE(w.contact.linear_range);
  }
}

// the regime follows |J alpha + T_b| < mu F_n R_r at every angle of a revolution where the roller's
// inertia makes it slide where the cam accelerates it hard
TEST(CamContact, RegimeFollowsTheCriterionOverTheRevolution) {
  CamModel m = dwell_model(0.002);
  m.train.roller_inertia_kg_m2 = 4e-4;  // a heavy roller
  m.omega_rad_per_s = 60;
  const Revolution r = run_revolution(m);
  ASSERT_EQ(r.status, RevolutionStatus::Complete);
  int sliding = 0;
  for (const RevolutionRow& w : r.rows) {
    const double wr = w.kin.roller_omega_rad_per_s;
    const double need = m.train.roller_inertia_kg_m2 * w.kin.roller_alpha_rad_per_s2 +
                        m.train.bearing_torque_N_m * (wr > 0 ? 1 : -1);
    const bool rolls = std::abs(need) < m.mu * w.loads.normal_N * m.geometry.roller_radius_m;
    EXPECT_EQ(w.loads.regime == RollerRegime::Rolling, rolls) << w.kin.theta_rad / kDeg;
    sliding += !rolls;
  }
  EXPECT_GT(sliding, 0);
  EXPECT_LT(sliding, static_cast<int>(r.rows.size()));
  EXPECT_EQ(sliding, r.sliding_steps);
}

// a steep lift on a small base circle has concave flanks (rho_p < 0): the cam's radius there is
// rho_p - R_r < 0 and the contact is Hertz's with that concave radius along the rolling direction
TEST(CamContact, ConcaveFlankGivesHertzWithTheConcaveRadius) {
  CamModel m = dwell_model(0);
  m.geometry = {0.010, 0.005, 0};
  DwellRiseDwellReturn d;
  d.lift_m = 0.02;
  d.rise_rad = 60 * kDeg;
  d.dwell_high_rad = 30 * kDeg;
  d.return_rad = 60 * kDeg;
  m.law = make_dwell_rise_dwell_return(d);
  m.min_radius_m = 0;
  m.max_pressure_angle_rad = 80 * kDeg;
  m.bodies.roller_width_m = 0.006;
  const Revolution r = run_revolution(m);
  ASSERT_EQ(r.status, RevolutionStatus::Complete);
  int concave = 0;
  for (const RevolutionRow& w : r.rows) {
    if (!(w.kin.pitch_curvature_per_m < 0)) continue;
    ++concave;
    const double rho_cam = cam_radius_m(w.kin);
    EXPECT_NEAR(rho_cam, 1 / w.kin.pitch_curvature_per_m - m.geometry.roller_radius_m, 1e-12);
    EXPECT_LT(rho_cam, -m.geometry.roller_radius_m);  // the roller fits the hollow
    const double Ry = 1 / contact::fit_parabola(roller_and_track_profiles(m.bodies).body1).curvature_per_m;
    const contact::HertzContact h = contact::solve_hertz({{m.geometry.roller_radius_m, Ry}, {rho_cam, kInf}},
                                                         m.bodies.pair, w.loads.normal_N);
    EXPECT_NEAR(w.contact.a_m, h.a_m, 1e-9 * h.a_m);
    EXPECT_NEAR(w.contact.p0_Pa, h.p0_Pa, 1e-9 * h.p0_Pa);
  }
  EXPECT_GT(concave, 0);
  EXPECT_NE(revolution_csv(r).find(",concave,"), std::string::npos);
}

}  // namespace
