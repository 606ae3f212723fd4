// The tangential problem along the revolution (cam/revolution_transient.h, docs/cam-follower.md §9), with Satran
// (consistent) and with the relaxed model (the default): on the common grid the contact is the normal solver's
// Hertz; on the base-circle dwell, a constant stretch, the transient's power is the steady solution's on the same
// contact (Satran's steady state, docs/physics.md §4.1; the relaxed model's effective creepage settled); the
// energy balance holds over the revolution to rounding; the quasi-steady skip stays within its tolerance of the
// full transient while saving steps, on the unworn revolution and on a worn one.
#include <gtest/gtest.h>

#include "tests/cam_shipped_law.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/revolution_dissipation.h"
#include "cam/revolution_transient.h"
#include "cam/roller_dynamics.h"
#include "lib/numeric.h"

namespace {

using namespace cam;
using contact::kPi;

constexpr double kDeg = kPi / 180;
constexpr double kInf = std::numeric_limits<double>::infinity();

CamModel shipped_like() {
  CamModel m;
  m.geometry = {0.04, 0.013, 0};
  m.law = shipped_lift_law();
  m.train = {2e4, 150, 0.4, 0.05, 3.8e-6, 0.004, 1e-5};
  m.bodies = {0.011, 0.5, 0.014, kInf, {{2.1e11, 0.3}, {2.1e11, 0.3}}};
  m.omega_rad_per_s = 62.83;
  m.mu = 0.1;
  m.min_radius_m = 0.003;
  m.max_pressure_angle_rad = 30 * kDeg;
  m.angle_steps = 180;
  return m;
}

struct CamRun {
  CamModel m = shipped_like();
  Revolution r;
  PeriodicMotion p;
  TransientRevolutionSettings s;
  CamRun() {
    r = run_revolution(m);
    RollerDynamicsSettings ds;
    ds.law.grid = {20, 20};
    p = periodic_motion(m, r, ds);
    s.grid = {20, 20};
  }
};

const CamRun& cam_run() {
  static const CamRun r;
  return r;
}

TEST(CamTransient, ContactOnTheCommonGridIsTheNormalSolversHertz) {
  const CamRun& x = cam_run();
  const contact::Profiles prof = roller_and_track_profiles(x.m.bodies);
  const contact::Grid g = contact::make_grid(1e-3, 3e-3, {20, 20});
  for (const std::size_t i : {0, 30, 60, 150}) {
    const RevolutionRow& row = x.r.rows[i];
    const AngleContact a = angle_contact(x.m.bodies, prof, 0.013, row.kin, row.loads.normal_N, x.m.mu, {});
    const AngleContact b = angle_contact_on_grid(x.m.bodies, prof, 0.013, row.kin, row.loads.normal_N, x.m.mu, true, g);
    EXPECT_NEAR(b.normal.patch.a_m, a.normal.patch.a_m, 1e-12 * a.normal.patch.a_m);
    EXPECT_NEAR(b.normal.patch.b_m, a.normal.patch.b_m, 1e-12 * a.normal.patch.b_m);
    EXPECT_NEAR(b.normal.patch.p0_Pa, a.normal.patch.p0_Pa, 1e-12 * a.normal.patch.p0_Pa);
    EXPECT_EQ(b.normal.grid_y0_m, a.normal.grid_y0_m);
  }
}

// On the low dwell (from 250 deg) every step's strip powers are the steady model's on the same contact and grid,
// to rounding (kRounding: the shift scheme's exact steps, or the relaxed creepage settled); more than 40 steps
void expect_dwell_steps_steady(const CamRun& x, const TransientRevolution& t, contact::TangentialScheme scheme) {
  const contact::Profiles prof = roller_and_track_profiles(x.m.bodies);
  int checked = 0;
  for (std::size_t i = 0; i < x.r.rows.size(); ++i) {
    if (x.r.rows[i].kin.theta_rad < 250 * kDeg) continue;
    const RollerAngle& a = x.p.motion.angles[i];
    const AngleContact c = angle_contact_on_grid(x.m.bodies, prof, 0.013, x.r.rows[i].kin, a.normal_N, x.m.mu, true,
                                                 t.grid, scheme);
    const contact::TangentialSolution sol = steady_creep(c, a.xi, a.speed_m_per_s);
    constexpr double kRounding = 1e-9;
    for (int j = 0; j < t.grid.ny; ++j)
      EXPECT_NEAR(t.dissipation[i].power_W_per_m(j), sol.strip_power_W_per_m(j),
                  kRounding * sol.strip_power_W_per_m.maxCoeff()) << i << " " << j;
    ++checked;
  }
  EXPECT_GT(checked, 40);
}

// On the low dwell (240-360 deg) nothing changes: after one transit the shift scheme's power at every step
// is the steady solver's on the same contact and grid, to rounding; over the revolution the step balance
// dissipated = creep work - elastic change - trailing - transport holds to rounding
TEST(CamTransient, OnTheDwellTheTransientIsTheSteadySolutionAndTheBalanceHolds) {
  const CamRun& x = cam_run();
  TransientRevolutionSettings s = x.s;
  s.skip = false;
  s.scheme = contact::TangentialScheme::Consistent;
  const TransientRevolution t = transient_revolution(x.m, x.r, x.p.motion, s);
  EXPECT_EQ(t.skipped_rows, 0);
  expect_dwell_steps_steady(x, t, s.scheme);
  const TransientEnergy& e = t.energy;
  EXPECT_GT(e.dissipated_J, 0);
  EXPECT_NEAR(e.dissipated_J, e.creep_work_J - e.elastic_change_J - e.trailing_J - e.transport_J,
              1e-10 * e.creep_work_J);
  EXPECT_EQ(e.transport_J, 0);  // shift steps only
}

// The relaxed model along the revolution: on the low dwell its effective creepage has settled on the row's xi
// (exp(-q/sigma) of any start, q many sigma), so every step is the relaxed steady model on the same contact, to
// rounding; over the revolution dissipated = creep work - relaxation (the creep force's work against the lag
// xi - xi_eff) step by step, to rounding; the springs' terms are Satran's only
TEST(CamTransient, RelaxedOnTheDwellIsTheSteadyModelAndItsBalanceHolds) {
  const CamRun& x = cam_run();
  TransientRevolutionSettings s = x.s;
  s.skip = false;
  ASSERT_EQ(s.scheme, contact::TangentialScheme::Relaxed);  // the default
  const TransientRevolution t = transient_revolution(x.m, x.r, x.p.motion, s);
  EXPECT_EQ(t.skipped_rows, 0);
  EXPECT_GT(t.warmup_steps, 0);
  expect_dwell_steps_steady(x, t, s.scheme);
  const TransientEnergy& e = t.energy;
  std::printf("relaxed: dissipated %.9e J = creep work %.9e - relaxation %.3e (+ %.2e)\n", e.dissipated_J,
              e.creep_work_J, e.relaxation_J, e.dissipated_J - (e.creep_work_J - e.relaxation_J));
  EXPECT_GT(e.dissipated_J, 0);
  EXPECT_NE(e.relaxation_J, 0);  // the rise and return: xi changes, xi_eff lags
  EXPECT_NEAR(e.dissipated_J, e.creep_work_J - e.relaxation_J, 1e-10 * e.creep_work_J);
  EXPECT_EQ(e.elastic_change_J + e.trailing_J + e.transport_J + e.flexibility_J, 0);
}

// The skip: the dwells are quasi-steady, the rise and return are not; against the full transient its error is
// within the tolerance, and it saves steps (Satran and the relaxed model)
TEST(CamTransient, QuasiSteadySkipStaysWithinItsToleranceOfTheFullTransient) {
  const CamRun& x = cam_run();
  for (const contact::TangentialScheme scheme : {contact::TangentialScheme::Consistent, contact::TangentialScheme::Relaxed}) {
    TransientRevolutionSettings s = x.s;
    s.scheme = scheme;
    s.quasi_steady_tolerance = 1e-3;
    const TransientRevolution with = transient_revolution(x.m, x.r, x.p.motion, s);
    s.skip = false;
    const TransientRevolution full = transient_revolution(x.m, x.r, x.p.motion, s);
    EXPECT_GT(with.skipped_rows, 0);
    for (std::size_t i = 0; i < x.r.rows.size(); ++i) {
      const double th = x.r.rows[i].kin.theta_rad;
      if (th > 10 * kDeg && th < 95 * kDeg) {
        EXPECT_FALSE(with.skipped[i]) << th / kDeg;  // the rise: the creepage changes within the memory
      }
      if (th > 260 * kDeg) {
        EXPECT_TRUE(with.skipped[i]) << th / kDeg;  // the low dwell, settled
      }
    }
    const SkipComparison c = compare_skip(with, full);
    std::printf("%s skip: %d of %zu rows, saving %.3f of the steps, max power error %.3e, energy error %.3e\n",
                to_string(scheme).c_str(), with.skipped_rows, x.r.rows.size(), c.step_saving, c.max_power_error,
                c.energy_error);
    EXPECT_LE(c.max_power_error, s.quasi_steady_tolerance);
    EXPECT_LE(std::abs(c.energy_error), s.quasi_steady_tolerance);
    EXPECT_GT(c.step_saving, 0.2);
  }
}

// The skip on a worn revolution (the relaxed model on the semi-Hertzian patches the life solves,
// worn_transient_revolution): the shipped case at 72 angle steps on a 72 x 28 map, worn by its unworn rate to
// 3 um at the deepest cell. Against the full transient the skip stays within its tolerance (the largest error in
// a step's power of the peak power, and the revolution's energy); skipping every step (the quasi-steady solution
// everywhere, what the life takes) is beyond it on the rise, which the check must see.
TEST(CamTransient, QuasiSteadySkipOnAWornRevolutionStaysWithinItsTolerance) {
  const cam::CamCase file = cam::read_cam_case(
      (std::filesystem::path(ROLLWEAR_SOURCE_DIR) / "cases" / "cam-follower.yaml").string());
  cam::CamModel model = file.model;
  model.angle_steps = 72;
  cam::CamWearSpec spec = *file.wear;
  spec.arc_cells = 72;
  spec.lateral_cells = 28;
  const std::unique_ptr<cam::CamLifeSetup> u = cam::set_up_cam_life(file.name, model, spec);
  const cam::CamWearRate rate = cam::wear_per_revolution(u->unworn, u->life.grid, u->life.laws);
  const double N = 3e-6 / std::max(rate.depth_per_revolution.cam_depth_m.maxCoeff(),
                                   rate.depth_per_revolution.roller_depth_m.maxCoeff());
  cam::CamWearState worn = rate.depth_per_revolution;
  worn.cam_depth_m *= N;
  worn.roller_depth_m *= N;
  TransientRevolutionSettings s;
  s.quasi_steady_tolerance = 1e-3;
  const auto run = [&](bool skip, double tolerance) {
    TransientRevolutionSettings k = s;
    k.skip = skip;
    k.quasi_steady_tolerance = tolerance;
    return worn_transient_revolution(u->model, u->revolution, u->motion.motion, u->unworn_profiles, u->life.grid,
                                     worn, u->dynamics.law, k);
  };
  {  // Satran needs the common grid's Hertz contacts: refused
    TransientRevolutionSettings k = s;
    k.scheme = contact::TangentialScheme::Consistent;
    EXPECT_THROW(worn_transient_revolution(u->model, u->revolution, u->motion.motion, u->unworn_profiles, u->life.grid,
                                           worn, u->dynamics.law, k),
                 std::invalid_argument);
  }
  const TransientRevolution full = run(false, s.quasi_steady_tolerance);
  const TransientRevolution with = run(true, s.quasi_steady_tolerance);
  const TransientRevolution everywhere = run(true, std::numeric_limits<double>::infinity());
  EXPECT_GT(with.skipped_rows, 0);
  EXPECT_LT(with.skipped_rows, static_cast<int>(u->revolution.rows.size()));
  EXPECT_EQ(everywhere.skipped_rows, static_cast<int>(u->revolution.rows.size()));
  const SkipComparison c = compare_skip(with, full), all = compare_skip(everywhere, full);
  // the life's own quasi-steady worn revolution is the skip everywhere: the same contacts and creepages
  const SkipComparison life = compare_dissipation(
      cam::worn_revolution_dissipation(u->model, u->revolution, u->motion.motion, u->unworn_profiles, u->life.grid,
                                       worn, u->dynamics.law),
      full.dissipation);
  std::printf("worn (3 um): skip %d of %zu rows, saving %.3f, max power error %.3e, energy error %.3e; everywhere: "
              "%.3e, %.3e; the life's quasi-steady revolution: %.3e, %.3e\n",
              with.skipped_rows, u->revolution.rows.size(), c.step_saving, c.max_power_error, c.energy_error,
              all.max_power_error, all.energy_error, life.max_power_error, life.energy_error);
  EXPECT_LE(c.max_power_error, s.quasi_steady_tolerance);
  EXPECT_LE(std::abs(c.energy_error), s.quasi_steady_tolerance);
  EXPECT_GT(c.step_saving, 0.1);
  EXPECT_GT(all.max_power_error, s.quasi_steady_tolerance);  // the check can fail: a skip where it should not be
  EXPECT_NEAR(life.max_power_error, all.max_power_error, 1e-9);
}

}  // namespace
