// One cam revolution at constant speed, angle by angle (docs/cam-follower.md §5): lift, kinematics,
// loads, the contact and the roller's regime on angle_steps equal steps of [0, 2 pi), with the design's
// checks (CamError naming the angle) and the jump check (status Jump, no table).
#pragma once

#include <string>
#include <vector>

#include "cam/kinematics.h"
#include "cam/lift_law.h"
#include "cam/loads.h"
#include "cam/roller_contact.h"

namespace cam {

struct CamModel {
  CamGeometry geometry;
  LiftLaw law;
  FollowerTrain train;
  RollerAndTrack bodies;
  double omega_rad_per_s = 0;
  double mu = 0;                     // roller-cam friction
  // the friction per angle step (cam.lubricant.friction_by_regime: the regime law's mu at each angle's film,
  // cam/cam_lubrication.h); empty: mu at every angle
  std::vector<double> mu_by_step;
  double min_radius_m = 0;           // convex pitch curve: rho_pitch - R_r must be >= this
  double max_pressure_angle_rad = 0; // |phi| must be <= this
  int angle_steps = 720;
};

// the friction at angle step i: mu_by_step[i], or mu when it is empty. Throws std::invalid_argument when
// mu_by_step is neither empty nor one per angle step.
double mu_at(const CamModel& m, std::size_t i);

struct RevolutionRow {
  CamKinematics kin;
  CamLoads loads;
  RollerContact contact;
  double contact_arc_m = 0;  // the contact's position along the cam's circumference from theta = 0
};

enum class RevolutionStatus { Complete, Jump };
const char* to_string(RevolutionStatus s);

struct Revolution {
  RevolutionStatus status = RevolutionStatus::Complete;
  JumpSpeed jump;                    // omega_jump and where
  double jump_at_theta_rad = 0;      // status Jump: where the contact is lost first
  std::vector<RevolutionRow> rows;   // angle_steps rows when Complete, empty on Jump
  double cam_circumference_m = 0;    // the cam's surface length (trapezoid rule on the angle steps)
  int sliding_steps = 0;             // rows where the roller slides
  int outside_linear_steps = 0;      // rolling rows outside the linear range
  int edge_steps = 0;                // rows whose contact reaches a body's edge
};

// throws CamError (Undercut, PressureAngle) naming the first angle that fails, std::invalid_argument for
// bad values, std::runtime_error for a normal solve that did not converge
Revolution run_revolution(const CamModel& m);

// revolution.csv: one row per angle step, units in the column names:
//   cam_angle_deg,lift_m,lift_rate_m_per_rad,lift_accel_m_per_rad2,pressure_angle_deg,pitch_radius_m,
//   cam_radius_m,surface,contact_arc_m,contact_angle_deg,rolling_speed_m_per_s,axial_load_N,normal_load_N,
//   tangential_load_N,guide_reaction_N,shaft_torque_N_m,a_m,b_m,p0_Pa,regime,xi,linear_range,
//   roller_omega_rad_per_s
// surface: convex | flat | concave; radii inf where flat; regime rolling | sliding; xi nan while sliding
std::string revolution_csv(const Revolution& r);

}  // namespace cam
