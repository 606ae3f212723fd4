// One periodic cam revolution, all of it (docs/cam-follower.md §5, §7-10): the kinematics, loads and contact
// per angle (cam/revolution.h), the roller's spin until periodic (cam/roller_dynamics.h), Satran along the
// revolution with the quasi-steady skip and the full transient it is measured against
// (cam/revolution_transient.h), and the energy terms (cam/revolution_energy.h). `rollwear cam` runs it, prints
// cam_summary and writes revolution_csv; the cam's wear reads run.transient.dissipation.
#pragma once

#include <string>

#include "cam/cam_lubrication.h"
#include "cam/revolution.h"
#include "cam/revolution_energy.h"
#include "cam/revolution_transient.h"
#include "cam/roller_dynamics.h"

namespace cam {

// the case's cam.tangential section (docs/cam-follower.md §6)
struct CamSolverSettings {
  int nx = 40, ny = 40;                  // the transient's grid over the revolution's largest contact; ny the law's strips
  double quasi_steady_tolerance = 1e-3;  // the skip's epsilon (0: no skip)
  double periodic_rtol = 1e-9;           // |omega_r(2 pi) - omega_r(0)| over max |omega_r,kin|
  int max_revolutions = 30;
  bool compare_full_transient = true;    // also run the revolution without the skip, to measure the skip's error
  // the tangential model (cam.tangential.scheme): relaxed (the default, kDefaultTangentialScheme) or consistent
  contact::TangentialScheme scheme = contact::kDefaultTangentialScheme;
  // the normal solver (cam.normal.solver): auto (the default), semi-hertz or halfspace
  contact::NormalChoice normal = contact::NormalChoice::Auto;
};

// The roller's spin did not become periodic within max_revolutions: a solver's failure (exit 1)
struct PeriodicityError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CamRun {
  Revolution revolution;
  PeriodicMotion motion;               // empty on Jump
  std::vector<CamLoads> loads;         // per row with the motion's creep force (cam_loads_with_tangential)
  double mu = 0;
  std::vector<double> mu_by_step;      // the friction per angle step (CamModel::mu_by_step), empty: mu
  TransientRevolution transient;       // with the skip (as the settings ask)
  TransientRevolution full;            // without it (compare_full_transient), else empty
  SkipComparison skip;                 // transient against full
  RevolutionEnergy energy;
  CamLubricationSpec lubrication_spec;  // cam.lubricant, cam.thermal (none: dry, nothing below is computed)
  RevolutionLubrication lubrication;    // per angle on the periodic motion (cam/cam_lubrication.h)
  double cpu_lubrication_s = 0;
  double cpu_dynamics_s = 0, cpu_transient_s = 0, cpu_full_s = 0;  // process CPU time of each part
};

// throws CamError (a refused design), PeriodicityError, std::runtime_error / std::invalid_argument from the
// solvers. Status Jump: only the revolution (no rows) comes back.
// the roller's spin and the creep law as the case's cam.tangential asks (grid, scheme, periodicity): what
// rollwear cam, rollwear run and the benchmarks hand to periodic_motion and set_up_cam_life
RollerDynamicsSettings roller_dynamics_of(const CamSolverSettings& s);

// lubrication: the case's cam.lubricant and cam.thermal, evaluated per angle on the periodic motion (none: dry)
CamRun run_cam(const CamModel& m, const CamSolverSettings& s, const CamLubricationSpec& lubrication = {});

// the printed summary (after the revolution's own lines): the roller, the transient and its skip, the energy, and
// with cam.lubricant or cam.thermal the film's and the flash temperature's lines (lubrication_summary)
std::string cam_summary(const CamRun& run);

// revolution.csv with the roller's dynamics and the dissipation (docs/cam-follower.md §5): revolution_csv's
// columns, its loads, creepage, regime and roller speed now the periodic motion's, then
//   required_tangential_load_N,roller_omega_kinematic_rad_per_s,slip_speed_m_per_s,stick_fraction,
//   dissipated_power_W,quasi_steady,unsteadiness
// and with cam.lubricant or cam.thermal the columns of lubrication_csv_header
std::string revolution_csv(const CamRun& run);

}  // namespace cam
