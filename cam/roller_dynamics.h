// The roller's spin over the revolution (docs/cam-follower.md §7): driven only by the creep force against
// its inertia and its bearing,
//   J d omega_r/dt = R_r F_t(xi) - M_z(xi) - T_b(omega_r),   T_b = T_0 sign(omega_r) + c_b omega_r,
// F_t(xi) the steady creep law of each angle's contact (cam/creep_law.h: nonlinear, saturating towards
// mu F_n), xi = w/V its creepage, w = R_r (omega_r - omega_r,kin) the slip over the cam and V = V_cam - w/2;
// M_z = sum_j F_j (z1(y_j) - z1(y0)) dy the crowned roller's strips acting below its rolling radius
// (cam/creep_law.h CreepForce; with Heathcote slip, else 0).
// Written for delta = omega_r - omega_r,kin (omega_r,kin, alpha_kin of cam/kinematics.h exact at every row),
//   J d delta/dt = R_r F_t(xi(delta)) - M_z - T_b(omega_r,kin + delta) - J alpha_kin,
// and integrated from row to row by the second-order backward differentiation formula (BDF2, stable on stiff
// problems: the law's rate R_r^2 G a b C11/(J V) is some 1e6 1/s against steps of 1e-4 s; backward Euler for
// the very first step, and as an option), each step's end solved for delta by find_root_bracketed on the
// contact of that row. While the friction can give what rolling needs the roller follows the kinematic spin with
// F_t = (J alpha_kin + T_b + M_z)/R_r + J d delta/dt, the last term the lag's own inertia; beyond, F_t saturates and
// the roller slides until it grips again. The revolution is repeated, each from the previous one's end,
// until omega_r(2 pi) = omega_r(0) within the tolerance: the periodic revolution. Each revolution's contacts
// carry the normal load of the previous one's F_t (the axial balance, cam_loads_with_tangential).
#pragma once

#include <vector>

#include "cam/roller_motion.h"

namespace cam {

struct RollerDynamicsSettings {
  CreepLawSettings law;
  // periodic when |omega_r(2 pi) - omega_r(0)| <= this times max |omega_r,kin| over the revolution
  double periodicity_rtol = 1e-9;
  int max_revolutions = 30;
  // the step's root: delta to this times max |omega_r,kin| (a slip speed some 1e-12 of the surface speed)
  double delta_rtol = 1e-13;
  bool bdf2 = true;  // the second-order backward differentiation formula (false: backward Euler, first order)
};

struct PeriodicMotion {
  RollerMotion motion;                     // the last revolution, one RollerAngle per row
  int revolutions = 0;                     // integrated, the last one included
  std::vector<double> residuals_rad_per_s;  // |omega_r(2 pi) - omega_r(0)| of each revolution
  double periodicity_residual_rad_per_s = 0;  // the last one's
  double tolerance_rad_per_s = 0;
  bool converged = false;
  int sliding_steps = 0;                   // rows with |xi| >= the law's saturation creepage (saturation_creepage)
  double start_omega_r_rad_per_s = 0;      // the last revolution's start (the one before's end), at theta = 0
};

// the creepage at which the contact's law saturates: the simplified theory's (consistent) that of Johnson and
// Vermeulen, 3 mu F_n/(G a b C11); the relaxed model's that times relaxed_xi_saturation_level (about 0.6 on Hertz
// patches, lib/tangential/relaxed.h: where it gives the force the simplified theory gives at 3 mu F_n/(G a b C11)).
// A row whose |xi| reaches it is reported as sliding (a report only: the law itself decides the force; Heathcote's
// offsets are not in it)
double saturation_creepage(const AngleContact& c);

// Throws std::invalid_argument for bad settings, std::runtime_error when a step finds no root (the roller
// stalls: |xi| beyond kMaxCreepage), contact::NormalSolveError from a normal solve. A revolution that is not
// periodic after max_revolutions comes back with converged false (the caller decides: exit 1).
PeriodicMotion periodic_motion(const CamModel& m, const Revolution& r, const RollerDynamicsSettings& s = {});

}  // namespace cam
