// What the wear of the cam track and of the roller reads from one angle step of the periodic revolution
// (docs/cam-follower.md): the frictional power the contact dissipates per unit width, strip by strip
// across the track, while the contact sits at one place on the cam. The revolution's tangential solve
// (transient along the revolution, or quasi-steady where that is exact to the case's tolerance) fills
// it; the cam's wear map and the roller's wear turn it into depth with the wear laws.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace cam {

struct AngleDissipation {
  double theta_rad = 0;                   // the cam angle at the step's start
  double duration_s = 0;                  // the step's duration, (2 pi / angle_steps) / omega
  double cam_arc_m = 0;                   // the contact's position along the cam's circumference
  double rolling_speed_m_per_s = 0;       // the contact's speed along the cam's surface
  double roller_surface_speed_m_per_s = 0;  // the contact's speed along the roller's surface
  Eigen::ArrayXd y_m;                     // strip centres across the track, from its centre line
  Eigen::ArrayXd power_W_per_m;           // mean dissipated power per unit width over the step
  Eigen::ArrayXd mean_pressure_Pa;        // per strip, mean over the contact length (for local laws)
};

using RevolutionDissipation = std::vector<AngleDissipation>;

}  // namespace cam
