// Energy over the periodic revolution (docs/cam-follower.md §10), every term in J per revolution, summed
// over the angle steps (each row's power times the step's duration dt):
//   shaft work      sum T omega dt, T the shaft torque with the roller's creep force F_t and its F_n
//   train           sum (F_0 + k s + m omega^2 s'') s' omega dt: the spring's and the mass's energy, periodic (0
//                   to the rectangle rule's error on a periodic integrand)
//   guide           sum mu_g |Q| |s'| omega dt
//   bearing         sum T_b(omega_r) omega_r dt
//   creep (rigid)   sum -F_t w dt: the creep force's work against the roller's rigid slip w at the reference line
//   roller          sum (R_r F_t - T_b) omega_r dt: the roller's spin energy over the revolution, 0 for the exact
//                   periodic motion; what the steps sum it to is the integrator's error (BDF2 on the slip's spin,
//                   cam/roller_dynamics.h: second order in the angle step), the rectangle rule on the kinematic
//                   spin's energy sum J alpha_kin omega_r,kin dt (kinematic_J) among it
// Per step T omega = (F_n cos phi + F_t sin phi) s' omega + R_r F_t omega_r,kin (no loss at a rolling contact,
// docs/cam-follower.md §3) and omega_r,kin = omega_r - w/R_r, so, to rounding,
//   shaft = train + guide + bearing + creep (rigid) + roller + residual.
// The balance's content is that train and roller are 0 to the integrator's tolerance. The tangential solve's own balance (Satran, cam/revolution_transient.h):
//   dissipated (the integral of P dt) = creep work - elastic terms,
// its creep work the rigid slip's plus Heathcote's (the crowned roller's rolling radius across the contact,
// docs/physics.md §2.4), which the spin's torque R_r F_t at the nominal radius does not carry (reported apart).
#pragma once

#include "cam/revolution.h"
#include "cam/revolution_transient.h"
#include "cam/roller_dynamics.h"

namespace cam {

struct RevolutionEnergy {
  double shaft_J = 0, train_J = 0, guide_J = 0, bearing_J = 0, creep_rigid_J = 0;
  double roller_J = 0;      // sum (R_r F_t - T_b) omega_r dt: the roller's spin energy over the revolution
  double kinematic_J = 0;   // sum J alpha_kin omega_r,kin dt: 0 but for the rectangle rule on the kinematic spin
  double residual_J = 0;    // shaft - (train + guide + bearing + creep_rigid + roller)
  // the tangential solve's (transient revolution), when given
  double dissipated_J = 0;      // the integral of P dt
  double creep_work_J = 0;      // the rigid slip's work in the tangential solve, Heathcote's included
  double heathcote_J = 0;       // creep_work - creep_rigid
  double elastic_J = 0;         // elastic change + trailing + transport (the springs' terms of the step balance)
  double tangential_residual_J = 0;  // dissipated - (creep_work - elastic)
};

// throws std::invalid_argument when the motion does not match the revolution
RevolutionEnergy revolution_energy(const CamModel& m, const Revolution& r, const PeriodicMotion& p,
                                   const TransientRevolution* transient = nullptr);

}  // namespace cam
