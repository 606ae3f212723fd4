// Kinematics of a disc cam turning at constant omega > 0 (counter-clockwise) with a translating roller
// follower (docs/cam-follower.md §2). The follower's axis is the line x = e (offset e) of the fixed frame,
// the cam's centre the origin; the roller's centre is at (e, d), d = s0 + s(theta), s0 = sqrt(Rp^2 - e^2),
// Rp = r_b + R_r the prime circle. In the cam's frame the roller's centre traces the pitch curve
// P(theta) = Rot(-theta) (e, d), with, in the follower's axes,
//   P' = (d, d' - e),   P'' = (2 d' - e, d'' - d),   |P'| = sqrt(d^2 + (d' - e)^2),
//   pressure angle   tan phi = (d' - e)/d                (radial follower: s'/(r_b + R_r + s)),
//   pitch curvature  kappa_p = (d^2 + (d' - e)(2d' - e) - d d'') / |P'|^3   (> 0 convex;
//                    radial: ((Rp+s)^2 + 2 s'^2 - (Rp+s) s'') / ((Rp+s)^2 + s'^2)^(3/2)),
//   cam surface      rho_cam = 1/kappa_p - R_r  (the offset curve; < 0 concave; inf flat),
//   rolling speed    V = omega |P'| (1 - R_r kappa_p): the speed of the contact point along the cam's
//                    surface, and along the roller's when it rolls,
//   roller spin      omega_r = omega (1 - |P'|/R_r) in pure rolling (base circle: -omega r_b/R_r),
//                    d omega_r/dt = -omega^2 (d d' + (d' - e) d'')/(|P'| R_r).
// The contact point C = (e, d) - R_r n, n = (e - d', d)/|P'| the pitch curve's outward normal, t = (d,
// d' - e)/|P'| its tangent (both in the fixed frame at this instant); n makes the angle phi with the axis.
#pragma once

#include "cam/lift_law.h"

namespace cam {

struct CamGeometry {
  double base_radius_m = 0;    // r_b, of the cam surface
  double roller_radius_m = 0;  // R_r
  double offset_m = 0;         // e; |e| < r_b + R_r
};

struct CamKinematics {
  double theta_rad = 0;
  LiftSample lift;
  double d_m = 0;                      // s0 + s: the roller centre's height along the axis
  double pitch_speed_m_per_rad = 0;    // |P'|
  double pressure_angle_rad = 0;       // phi, signed as (d' - e)
  double pitch_curvature_per_m = 0;    // kappa_p, > 0 convex
  double cam_curvature_per_m = 0;      // kappa_p/(1 - R_r kappa_p): the cam surface's, > 0 convex, 0 flat
  double arc_rate_m_per_rad = 0;       // d(arc length of the contact along the cam)/d theta = |P'| (1 - R_r kappa_p)
  double rolling_speed_m_per_s = 0;    // V = omega arc_rate
  double roller_omega_rad_per_s = 0;   // omega_r in pure rolling (fixed frame, counter-clockwise > 0)
  double roller_alpha_rad_per_s2 = 0;  // its rate
  double normal_x = 0, normal_y = 0;   // n (fixed frame)
  double tangent_x = 0, tangent_y = 0; // t (fixed frame)
  double contact_x_m = 0, contact_y_m = 0;  // C (fixed frame, from the cam's centre)
  double contact_angle_rad = 0;             // the polar angle of C in the cam's frame, in [0, 2 pi)
};

// throws std::invalid_argument for r_b <= 0, R_r <= 0, |e| >= r_b + R_r or omega <= 0
void check_geometry(const CamGeometry& g, double omega_rad_per_s);

CamKinematics cam_kinematics(const CamGeometry& g, const LiftSample& lift, double theta_rad, double omega_rad_per_s);

// the cam surface's radius in the rolling direction, 1/cam_curvature (inf where flat, < 0 concave)
double cam_radius_m(const CamKinematics& k);

}  // namespace cam
