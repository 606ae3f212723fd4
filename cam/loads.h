// The loads of the follower train over the revolution (docs/cam-follower.md §3). The cam pushes the roller
// with F_n along the pitch curve's normal n and F_t along its tangent t (kinematics.h). Along the axis:
//   F_n cos phi + F_t sin phi = F_0 + k s + m omega^2 s''(theta) + guide friction,
// the guide friction mu_g |Q| sign(s') with Q = F_n sin phi - F_t cos phi the guide's lateral reaction
// (one guide, no bending moment of the stem). F_t spins the roller against its inertia and bearing:
//   R_r F_t = J domega_r/dt + T_b(omega_r),   T_b = T_0 sign(omega_r) + c_b omega_r,
// with omega_r the pure-rolling spin. It rolls while |F_t| < mu F_n; else it slides and F_t = mu F_n with
// the required one's sign (the roller's speed then leaves the kinematic one: that dynamics is not modelled
// here). The cam shaft's torque is T = (C x (F_n n + F_t t))_z; while the roller rolls it satisfies
// T omega = (F_n cos phi + F_t sin phi) omega s' + F_t R_r omega_r (no loss at the contact).
// Jump speed (contact lost, F_t and phi ignored): omega_jump = min over s'' < 0 of sqrt((F_0 + k s)/(m |s''|)).
#pragma once

#include "cam/kinematics.h"
#include "cam/lift_law.h"

namespace cam {

struct FollowerTrain {
  double spring_rate_N_per_m = 0;   // k >= 0
  double preload_N = 0;             // F_0 at s = 0 (the base circle) > 0
  double moving_mass_kg = 0;        // m: follower, roller and a third of the spring
  double guide_mu = 0;              // mu_g >= 0 (0: no guide friction)
  double roller_inertia_kg_m2 = 0;  // J >= 0, about the roller's axle
  double bearing_torque_N_m = 0;    // T_0 >= 0
  double bearing_drag_N_m_s = 0;    // c_b >= 0 (N m per rad/s)
};

enum class RollerRegime { Rolling, Sliding };
const char* to_string(RollerRegime r);

struct CamLoads {
  double axial_N = 0;                // F_0 + k s + m omega^2 s'' (without guide friction)
  double normal_N = 0;               // F_n
  double tangential_N = 0;           // F_t on the roller along t
  double required_tangential_N = 0;  // (J alpha + T_b)/R_r: what rolling needs
  double guide_reaction_N = 0;       // Q
  double shaft_torque_N_m = 0;       // the torque driving the cam
  RollerRegime regime = RollerRegime::Rolling;
  bool contact_lost = false;         // the axial balance needs F_n <= 0: the follower jumps
};

// throws std::invalid_argument for negative or non-finite values, preload <= 0, mass <= 0
void check_train(const FollowerTrain& t);

CamLoads cam_loads(const FollowerTrain& t, const CamGeometry& g, const CamKinematics& k, double omega_rad_per_s,
                   double mu);

// the same balance with a given F_t on the roller (its own dynamics, cam/roller_motion.h): F_n, Q and the
// torque; required_tangential_N as cam_loads; regime Rolling (the caller sets it)
CamLoads cam_loads_with_tangential(const FollowerTrain& t, const CamGeometry& g, const CamKinematics& k,
                                   double omega_rad_per_s, double tangential_N);

// the bearing's resisting torque T_b = T_0 sign(omega_r) + c_b omega_r
double bearing_torque_N_m(const FollowerTrain& t, double omega_r_rad_per_s);

// sampled on n_samples equal steps of the revolution; +inf when s'' never goes negative
struct JumpSpeed {
  double omega_rad_per_s = 0;
  double at_theta_rad = 0;
};
JumpSpeed jump_speed(const FollowerTrain& t, const LiftLaw& law, int n_samples);

// angle steps of the jump speed's sampling: 0.01 deg
constexpr int kJumpSamples = 36000;

}  // namespace cam
