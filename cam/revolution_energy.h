// Energy over the periodic revolution (docs/cam-follower.md §10), every term in J per revolution, summed
// over the angle steps (each row's power times the step's duration dt):
//   shaft work      sum T omega dt, T the shaft torque with the roller's creep force F_t and its F_n
//   train           sum (F_0 + k s + m omega^2 s'') s' omega dt: the spring's and the mass's energy, periodic (0
//                   to the rectangle rule's error on a periodic integrand)
//   guide           sum mu_g |Q| |s'| omega dt
//   bearing         sum T_b(omega_r) omega_r dt
//   creep (rigid)   sum -F_t w dt: the creep force's work against the roller's rigid slip w at the reference line
//   Heathcote (roller)  sum M_z omega_r dt: the crowned roller's strips act below its rolling radius
//                   (cam/roller_dynamics.h), so their slip over the track works too
//   Heathcote (track)   sum -(n x t)_z M2 omega dt: a crowned track's strips act below the cam's surface, their
//                   moment in the shaft's torque (shaft_torque_N_m of cam/roller_motion.h)
//   roller          sum (R_r F_t - M_z - T_b) omega_r dt: the roller's spin energy over the revolution, 0 for the
//                   exact periodic motion; what the steps sum it to is the integrator's error (BDF2, second
//                   order in the angle step), the rectangle rule on the kinematic spin's energy
//                   sum J alpha_kin omega_r,kin dt (kinematic_J) among it
// Per step T omega = (F_n cos phi + F_t sin phi) s' omega + R_r F_t omega_r,kin (no loss at a rolling contact,
// docs/cam-follower.md §3) and omega_r,kin = omega_r - w/R_r, so, to rounding,
//   shaft = train + guide + bearing + creep (rigid) + Heathcote (roller) + Heathcote (track) + roller + residual;
// the balance's content is that train and roller are 0 to the integrator's tolerance.
// The contact's own work: the steady law's creep work (the one the spin used) sum -V sum_j (xi + offset_j) F_j dy dt,
// Heathcote's offsets (docs/physics.md §2.4) with the roller's spin relative to the contact, V/R_r; the roller's
// term above has its spin in the fixed frame, |omega_r| = V/R_r + (omega |P'| kappa_p - omega): the two agree on the
// dwells, and differ by the contact frame's rotation elsewhere (frame_J = steady creep - rigid - Heathcote terms).
// The tangential solve's balance (cam/revolution_transient.h): dissipated (the integral of P dt) = creep work -
// elastic terms (Satran's springs: elastic change, trailing edge, transport; the relaxed model: the relaxation,
// the creep force's work against the creepage's lag), its creep work the steady law's plus the transient's
// departure from it (transient_J).
#pragma once

#include "cam/revolution.h"
#include "cam/revolution_transient.h"
#include "cam/roller_dynamics.h"

namespace cam {

struct RevolutionEnergy {
  double shaft_J = 0, train_J = 0, guide_J = 0, bearing_J = 0, creep_rigid_J = 0;
  double heathcote_roller_J = 0;  // sum M_z omega_r dt
  double heathcote_track_J = 0;   // sum -(n x t)_z M2 omega dt: a crowned track's strips below the cam's surface
  double roller_J = 0;      // sum (R_r F_t - M_z - T_b) omega_r dt: the roller's spin energy over the revolution
  double kinematic_J = 0;   // sum J alpha_kin omega_r,kin dt: 0 but for the rectangle rule on the kinematic spin
  double residual_J = 0;    // shaft - (train + guide + bearing + creep_rigid + heathcote_roller + roller)
  double creep_steady_J = 0;  // the steady law's creep work, Heathcote's offsets included
  double frame_J = 0;  // creep_steady - (creep_rigid + heathcote_roller + heathcote_track): the frame's rotation
  // the tangential solve's (transient revolution), when given
  double dissipated_J = 0;      // the integral of P dt
  double creep_work_J = 0;      // the rigid slip's work in the tangential solve, Heathcote's included
  double transient_J = 0;       // creep_work - creep_steady: the transient's departure from the steady law
  double elastic_J = 0;         // elastic change + trailing + transport (Satran's springs) + relaxation (relaxed model)
  double tangential_residual_J = 0;  // dissipated - (creep_work - elastic)
};

// throws std::invalid_argument when the motion does not match the revolution
RevolutionEnergy revolution_energy(const CamModel& m, const Revolution& r, const PeriodicMotion& p,
                                   const TransientRevolution* transient = nullptr);

}  // namespace cam
