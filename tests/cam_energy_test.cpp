// Energy over the periodic revolution (cam/revolution_energy.h, docs/cam-follower.md §10): the shaft's work
// equals the guide's friction, the bearing's loss and the creep force's work against the roller's rigid slip,
// the spring-and-mass term and the roller's spin energy being 0 to the integrator's tolerance; the tangential
// solve's dissipation equals its creep work less its elastic terms (the relaxed model's relaxation, the default;
// Satran's springs with consistent), to rounding. A roller that rolls and one that slides.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "cam/revolution.h"
#include "cam/revolution_energy.h"
#include "cam/revolution_transient.h"
#include "cam/roller_dynamics.h"
#include "lib/numeric.h"

namespace {

using namespace cam;
using contact::kPi;

constexpr double kDeg = kPi / 180;
constexpr double kInf = std::numeric_limits<double>::infinity();

CamModel model(double inertia_kg_m2, double omega_rad_per_s, double lift_m = 0.01) {
  CamModel m;
  m.geometry = {0.04, 0.013, 0};
  DwellRiseDwellReturn d;
  d.lift_m = lift_m;
  d.rise_rad = 100 * kDeg;
  d.dwell_high_rad = 40 * kDeg;
  d.return_law = SegmentLaw::Polynomial345;
  d.return_rad = 100 * kDeg;
  m.law = make_dwell_rise_dwell_return(d);
  m.train = {2e4, 150, 0.4, 0.05, inertia_kg_m2, 0.004, 1e-5};
  m.bodies = {0.011, 0.5, 0.014, kInf, {{2.1e11, 0.3}, {2.1e11, 0.3}}};
  m.omega_rad_per_s = omega_rad_per_s;
  m.mu = 0.1;
  m.min_radius_m = 0.003;
  m.max_pressure_angle_rad = 30 * kDeg;
  m.angle_steps = 180;
  return m;
}

// the integrator's tolerance on the revolution's energy: BDF2's error on the roller's spin energy and the
// rectangle rule on the periodic spring, mass and kinematic spin terms. Measured at 180 steps: 5e-8 of the
// shaft's work rolling, 8e-5 sliding (the slide's onset and end are kinks in the spin; second order: 2.0e-5,
// 4.6e-6, 1.1e-6 at 360, 720, 1440 steps, docs/cam-follower.md §10)
constexpr double kIntegratorRtol = 1e-4;

void check(const CamModel& m, bool sliding) {
  const Revolution r = run_revolution(m);
  RollerDynamicsSettings ds;
  ds.law.grid = {20, 20};
  const PeriodicMotion p = periodic_motion(m, r, ds);
  ASSERT_TRUE(p.converged);
  EXPECT_EQ(p.sliding_steps > 0, sliding);
  TransientRevolutionSettings ts;
  ts.grid = {20, 20};
  const TransientRevolution t = transient_revolution(m, r, p.motion, ts);
  const RevolutionEnergy e = revolution_energy(m, r, p, &t);
  std::printf("shaft %.6e J = guide %.6e + bearing %.6e + creep (rigid) %.6e + Heathcote (roller) %.6e + train %.3e + "
              "roller %.3e (kinematic %.3e) + residual %.3e; tangential: dissipated %.6e = creep %.6e - elastic %.3e + "
              "%.3e; creep = steady %.6e (frame %.3e) + transient %.3e\n",
              e.shaft_J, e.guide_J, e.bearing_J, e.creep_rigid_J, e.heathcote_roller_J, e.train_J, e.roller_J,
              e.kinematic_J, e.residual_J, e.dissipated_J, e.creep_work_J, e.elastic_J, e.tangential_residual_J,
              e.creep_steady_J, e.frame_J, e.transient_J);
  EXPECT_NEAR(e.residual_J, 0, 1e-12 * e.shaft_J);  // the per-step identity: rounding
  EXPECT_NEAR(e.train_J, 0, kIntegratorRtol * e.shaft_J);
  EXPECT_NEAR(e.roller_J, 0, kIntegratorRtol * e.shaft_J);
  EXPECT_NEAR(e.shaft_J, e.guide_J + e.bearing_J + e.creep_rigid_J + e.heathcote_roller_J,
              2 * kIntegratorRtol * e.shaft_J);
  EXPECT_GT(e.guide_J, 0);
  EXPECT_GT(e.bearing_J, 0);
  EXPECT_GT(e.dissipated_J, 0);
  EXPECT_NEAR(e.tangential_residual_J, 0, 1e-10 * e.creep_work_J);
  if (sliding) {
    EXPECT_GT(e.creep_rigid_J, 0.01 * e.shaft_J);  // the slide's loss is a visible share of the shaft's work
  }
}

TEST(CamEnergy, RollingRollerShaftWorkIsGuideBearingAndCreepLosses) { check(model(3.8e-6, 62.83), false); }

TEST(CamEnergy, SlidingRollerShaftWorkIsGuideBearingAndCreepLosses) { check(model(1e-4, 60), true); }

// A cam that is nearly its base circle (a lift of 1 um): the contact frame hardly turns (alpha_dot = omega (1 -
// |P'| kappa_p) ~ 0), so the roller's Heathcote term is the contact's: the shaft's work is the guide's, the
// bearing's and the steady law's whole creep work, Heathcote's slip included (docs/physics.md §2.4), to the
// integrator's tolerance; the contact frame's term is 0 to 1e-4 of the creep work
// (a flat track, then one crowned with 0.3 m: its strips act below the cam's surface, in the shaft's torque)
TEST(CamEnergy, OnANearlyCircularCamShaftWorkIncludesHeathcotesSlipWork) {
  for (const double track_crown_m : {kInf, 0.3}) {
    CamModel m = model(3.8e-6, 62.83, 1e-6);
    m.bodies.track_crown_radius_m = track_crown_m;
    const Revolution r = run_revolution(m);
    RollerDynamicsSettings ds;
    ds.law.grid = {20, 20};
    const PeriodicMotion p = periodic_motion(m, r, ds);
    ASSERT_TRUE(p.converged);
    const RevolutionEnergy e = revolution_energy(m, r, p);
    std::printf("shaft %.9e = guide %.9e + bearing %.9e + steady creep %.6e (rigid %.6e, Heathcote roller %.6e, track "
                "%.6e); frame %.3e, roller %.3e, train %.3e\n", e.shaft_J, e.guide_J, e.bearing_J, e.creep_steady_J,
                e.creep_rigid_J, e.heathcote_roller_J, e.heathcote_track_J, e.frame_J, e.roller_J, e.train_J);
    EXPECT_GT(e.heathcote_roller_J, 0.5 * e.creep_steady_J);  // the roller's drag is small: Heathcote's slip dominates
    if (std::isinf(track_crown_m)) {
      EXPECT_EQ(e.heathcote_track_J, 0);
    } else {
      EXPECT_GT(std::abs(e.heathcote_track_J), 0.1 * e.creep_steady_J);
    }
    EXPECT_NEAR(e.frame_J, 0, 1e-4 * e.creep_steady_J);  // the frame turns at ~ s''/R_p: some 1e-5 here
    EXPECT_NEAR(e.shaft_J, e.guide_J + e.bearing_J + e.creep_steady_J, 1e-3 * e.creep_steady_J);
  }
}

}  // namespace
