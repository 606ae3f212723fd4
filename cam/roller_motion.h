// The roller's motion over one cam revolution (docs/cam-follower.md §7): at every angle step its spin
// omega_r, its creepage xi over the cam, the creep force F_t and the normal load F_n that goes with it.
//   quasi_static_motion: the roller follows its required force at every angle (F_t = (J alpha_kin +
//     T_b)/R_r of cam/loads.h), xi from the steady creep law (cam/creep_law.h) inverted for that force;
//     a row whose force the law cannot give (the roller slides) is refused. It leaves out the strips' depth
//     moment M_z of cam/roller_dynamics.h (some 1e-4 of the torque): a reference, not the motion.
//   periodic_motion (cam/roller_dynamics.h): the spin integrated through the revolution.
// F_n comes from the follower's axial balance with the motion's F_t (cam_loads_with_tangential), and the
// contact of each angle from that F_n.
#pragma once

#include <vector>

#include "cam/creep_law.h"
#include "cam/revolution.h"

namespace cam {

struct RollerAngle {
  double omega_r_rad_per_s = 0;       // the roller's spin (fixed frame, counter-clockwise > 0)
  double xi = 0;                      // w_x/V: the roller's slip over the cam, w_x = R_r (omega_r - omega_r,kin)
  double slip_speed_m_per_s = 0;      // w_x
  double speed_m_per_s = 0;           // V = V_cam - w_x/2, the mean of the two surfaces' speeds (docs/physics.md §1)
  double tangential_N = 0;            // F_t on the roller along t, from the steady law at xi
  double depth_moment_N_m = 0;        // the strips' radii: the creep torque on the roller is R_r F_t - this
  double track_depth_moment_N_m = 0;  // the same on the cam's side (a crowned track): see shaft_torque_N_m
  double creep_power_W = 0;           // the steady solution's creep work rate -V sum_j (xi + offset_j) F_j dy
  double normal_N = 0;                // F_n with that F_t
  double stick_fraction = 0;          // of the steady solution at xi
  RollerRegime regime = RollerRegime::Rolling;
};

struct RollerMotion {
  std::vector<RollerAngle> angles;  // one per revolution row
  long creep_law_evaluations = 0;   // steady solves
};

// throws std::invalid_argument naming the first sliding row's angle (the roller's dynamics decides there),
// contact::NormalSolveError from a normal solve
RollerMotion quasi_static_motion(const CamModel& m, const Revolution& r, const CreepLawSettings& s = {});

// the shaft's torque with the strips of a crowned track acting below the cam's surface: the loads' torque
// (C x F) plus, for strip forces F_j along t at C - dz2_j n, sum_j (-dz2_j n x F_j t)_z = -(n x t)_z M2
double shaft_torque_N_m(const CamLoads& loads, const CamKinematics& k, double track_depth_moment_N_m);

// the cam's surface speed and the roller's through the contact for slip w_x: V_cam and V_cam - w_x
inline double roller_surface_speed_m_per_s(double cam_speed_m_per_s, double slip_speed_m_per_s) {
  return cam_speed_m_per_s - slip_speed_m_per_s;
}

}  // namespace cam
