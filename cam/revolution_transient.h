// The tangential problem along the revolution (docs/cam-follower.md §9), with the relaxed model (the default,
// lib/tangential/relaxed.h: its effective creepage relaxing over the rolled distance, each step the steady model
// at it; below) or with Satran (lib/tangential/satran.h, shift scheme; TransientRevolutionSettings::scheme
// Consistent): the contact of each angle step (Hertz on the roller's and the track's profiles,
// the normal load and creepage of the roller's motion, cam/roller_motion.h) on one grid over the
// revolution's largest contact, the traction state carried from step to step while the geometry, the load,
// the flexibility and the creepage change from one angle step to the next. Each angle step rolls V dt; the
// shift scheme steps one cell dx at a time (its steps exact, docs/physics.md §4.1), the remainder carried to
// the next angle step, and the step's strip energies divided by the time they span give its power per unit
// width. The state's memory is one transit of the contact: from any state, after rolling 2 half_x + 2 dx it is
// the same, so the revolution starts from rest that far before theta = 0 (a warm-up on the revolution's
// last steps, its energy not counted), and so does every resumption after a skip.
//
// The quasi-steady skip: the transient differs from the steady solution by the change of its inputs over
// one transit of the contact. A step's unsteadiness is
//   epsilon_i = (2 a_i / V_i) / dt * max over (a, b, F_n, V, xi) of |change to the neighbouring steps| / value
// (for xi the value is max(|xi_i|, |xi_neighbour|): a sign change counts as unsteady). A step whose own and
// preceding steps within one transit (2 half_x + 2 dx rolled) all have epsilon <= the tolerance takes the
// steady solution (cam/revolution_dissipation.h) on the same grid instead of the transient's steps.
//
// The relaxed model along the revolution: its state is the effective creepage xi_eff alone, relaxing towards the
// row's xi over the rolled distance q, d xi_eff/dq = (xi - xi_eff)/sigma (sigma = sigma0(a/b) a (1 - e_eff)^p,
// relaxed.h), each step the relaxed steady model at xi_eff on the row's contact. A change of the contact, the load
// or the speed at a constant xi leaves xi_eff = xi: only xi's history makes the transient depart from the steady
// solution, by about sigma dxi/dq. So here
//   epsilon_i = (sigma_i / V_i) / dt * |change of xi to the neighbouring steps| / max(|xi_i|, |xi_neighbour|),
// sigma_i the row's unsaturated (longest) relaxation length, and the memory is sigma ln(1/tolerance): a step is
// quasi-steady when it and the steps within that distance before it have epsilon <= the tolerance, and a
// transient stretch after a quasi-steady one starts from its steady state (xi_eff = xi). The full transient
// starts kWarmupSigmas relaxation lengths before theta = 0 from the steady state there (a warm-up, not counted).
// An angle step of V dt is rolled in equal steps of at most one cell dx of the row's grid (as the model's own
// runs step, lib/tangential/relaxed.h), its power their mean. Each row on its own contact: the common grid's
// Hertz (transient_revolution) or the worn semi-Hertzian patches the life solves (worn_transient_revolution).
#pragma once

#include <vector>

#include "cam/angle_dissipation.h"
#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/roller_motion.h"
#include "lib/grid.h"
#include "lib/normal/solver_kind.h"
#include "lib/patch.h"
#include "lib/tangential/tangential.h"

namespace cam {

struct CamWearGrid;   // cam/cam_wear.h
struct CamWearState;

struct TransientRevolutionSettings {
  contact::GridSpec grid{40, 40};  // over the revolution's largest contact
  bool heathcote_slip = true;
  bool skip = true;                      // the quasi-steady skip
  double quasi_steady_tolerance = 1e-3;  // epsilon at or below which a settled step is quasi-steady
  // Relaxed (the default) or Consistent (Satran's shift scheme on the common grid)
  contact::TangentialScheme scheme = contact::kDefaultTangentialScheme;
  // the relaxed model's step, in cells dx of the row's grid (an angle step in equal steps of at most this)
  double relaxed_step_cells = 1;
};

// the relaxed full transient's warm-up before theta = 0, in relaxation lengths: what is left of its start is
// exp(-30) = 1e-13 of it
constexpr double kWarmupSigmas = 30;

// Energy over the revolution's counted steps (J), from Satran's step balance (docs/physics.md §4.1):
//   dissipated = creep work - elastic change - trailing - released - flexibility - transport (+ residual)
// skipped steps add their steady power and creep power times the step's duration to dissipated and creep work
// The relaxed model (no springs): dissipated = creep work - relaxation, relaxation_J the work of the creep force
// against the creepage's lag, sum -V (xi - xi_eff) Fx dt (its steady power is -V xi_eff Fx, Heathcote's offsets
// aside, relaxed.h), summed step by step on its own; Satran's terms 0
struct TransientEnergy {
  double dissipated_J = 0, creep_work_J = 0, elastic_change_J = 0, trailing_J = 0, released_J = 0,
         flexibility_J = 0, transport_J = 0, balance_residual_J = 0;
  double relaxation_J = 0;
};

struct TransientRevolution {
  RevolutionDissipation dissipation;  // one per row, strips on the common grid
  contact::Grid grid;                 // the common grid (Satran's, and the relaxed model's on unworn profiles)
  contact::TangentialScheme scheme = contact::kDefaultTangentialScheme;
  std::vector<double> a_m, b_m, p0_Pa;  // each row's contact (Hertz under the motion's F_n; worn: the patch's)
  std::vector<double> xi;             // each row's creepage (the motion's; worn: the one for its F_t there)
  std::vector<double> unsteadiness;   // epsilon_i
  std::vector<char> skipped;          // 1: the row took the steady solution
  int skipped_rows = 0;
  long transient_steps = 0;           // Satran's (relaxed model's) steps counted in the revolution
  long warmup_steps = 0;              // Satran steps run from rest before a transient stretch (not counted)
  long steady_solves = 0;
  TransientEnergy energy;
  // every row quasi-steady on its own contact (quasi_steady_revolution): no transient was run
  bool quasi_steady_only = false;
  long creep_evaluations = 0;        // ... the steady solves of its creepages' inversions
  contact::NormalSolverKind normal_solver = contact::NormalSolverKind::Hertz;  // ... its rows' normal solver
};

// The contact of angle k under normal_load_N on `grid` (Hertz on the profiles' fitted radii, centred on the
// gap's vertex, as lib/normal/normal.h's constant-curvature branch, with its Heathcote offsets). Throws
// std::invalid_argument when a profile is not of constant curvature (a worn one: not built here) or the
// ellipse does not fit inside the grid.
AngleContact angle_contact_on_grid(const RollerAndTrack& bodies, const contact::Profiles& profiles,
                                   double roller_radius_m, const CamKinematics& k, double normal_load_N, double mu,
                                   bool heathcote_slip, const contact::Grid& grid,
                                   contact::TangentialScheme scheme = contact::kDefaultTangentialScheme);

// throws std::invalid_argument when the motion does not match the revolution or (Satran) an angle step rolls less
// than one cell (angle_steps too many for the grid: the shift scheme needs V dt >= dx), and as angle_contact_on_grid
TransientRevolution transient_revolution(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                         const TransientRevolutionSettings& s = {});

// The relaxed model along the revolution on the worn state `worn`, each angle's contact and creepage as the life's
// quasi-steady worn revolution has them (worn_revolution_dissipation, cam/cam_life.h: the semi-Hertzian contact on
// the worn profiles at the row's arc, the strips over the profiles' fixed lateral extent, the creepage whose steady
// force is the motion's F_t). Relaxed only (std::invalid_argument for another scheme); s.grid is not used (the
// law's). Throws what the solvers throw.
TransientRevolution worn_transient_revolution(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                              const contact::Profiles& unworn, const CamWearGrid& g,
                                              const CamWearState& worn, const CreepLawSettings& law,
                                              const TransientRevolutionSettings& s = {});

// The revolution's rows quasi-steady, each the steady solution of the law (angle_contact: its normal solver and
// model, e.g. the half-space and the exact theory) on its own contact, at the creepage whose steady force is the
// motion's F_t there where the law is not the motion's own (is_motion_law), else at the motion's creepage. What
// `rollwear cam` runs where the transient along the revolution is not built: Satran and the relaxed model's steps
// run on the common grid's Hertz contacts, and the exact theory's rolling steps along the revolution are not
// built. Throws what the solvers throw.
TransientRevolution quasi_steady_revolution(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                            const CreepLawSettings& law);

// the skip's error against the full transient: the largest difference in a step's total power over the largest
// power, the revolution's dissipated energy's relative difference, and the steps saved
struct SkipComparison {
  double max_power_error = 0;  // max_i |P_skip - P_full| / max_i P_full
  double energy_error = 0;     // (E_skip - E_full) / E_full
  double step_saving = 0;      // 1 - (steps + warm-ups with skip) / (steps + warm-ups without)
};
SkipComparison compare_skip(const TransientRevolution& with_skip, const TransientRevolution& full);
// the same errors of any dissipation against the full transient's (step_saving 0), e.g. the life's quasi-steady one
SkipComparison compare_dissipation(const RevolutionDissipation& d, const RevolutionDissipation& full);

}  // namespace cam
