// Cam kinematics (docs/cam-follower.md §2).
#include "cam/kinematics.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lib/numeric.h"

namespace cam {

void check_geometry(const CamGeometry& g, double omega) {
  if (!(g.base_radius_m > 0) || !std::isfinite(g.base_radius_m)) throw std::invalid_argument("base radius must be > 0");
  if (!(g.roller_radius_m > 0) || !std::isfinite(g.roller_radius_m))
    throw std::invalid_argument("roller radius must be > 0");
  if (!(std::abs(g.offset_m) < g.base_radius_m + g.roller_radius_m))
    throw std::invalid_argument("|offset| must be < base radius + roller radius");
  if (!(omega > 0) || !std::isfinite(omega)) throw std::invalid_argument("cam speed must be > 0");
}

CamKinematics cam_kinematics(const CamGeometry& g, const LiftSample& lift, double theta, double omega) {
  CamKinematics k;
  k.theta_rad = theta;
  k.lift = lift;
  const double Rp = g.base_radius_m + g.roller_radius_m, e = g.offset_m, Rr = g.roller_radius_m;
  const double s0 = std::sqrt(Rp * Rp - e * e);
  const double d = s0 + lift.s_m, d1 = lift.ds_m_per_rad, d2 = lift.d2s_m_per_rad2;
  k.d_m = d;
  // pitch curve P' = (d, d' - e), P'' = (2d' - e, d'' - d) in the follower's axes
  const double px = d, py = d1 - e, qx = 2 * d1 - e, qy = d2 - d;
  const double speed = std::hypot(px, py);
  k.pitch_speed_m_per_rad = speed;
  k.pressure_angle_rad = std::atan2(py, px);
  // traversed clockwise as theta grows: convex has px qy - py qx < 0
  k.pitch_curvature_per_m = -(px * qy - py * qx) / (speed * speed * speed);
  const double shrink = 1 - Rr * k.pitch_curvature_per_m;  // |dC/dtheta| / |P'|
  k.cam_curvature_per_m = k.pitch_curvature_per_m / shrink;
  k.arc_rate_m_per_rad = speed * shrink;
  k.rolling_speed_m_per_s = omega * k.arc_rate_m_per_rad;
  k.roller_omega_rad_per_s = omega * (1 - speed / Rr);
  k.roller_alpha_rad_per_s2 = -omega * omega * (d * d1 + py * d2) / (speed * Rr);
  k.tangent_x = px / speed;
  k.tangent_y = py / speed;
  k.normal_x = -k.tangent_y;  // the tangent turned by +90 deg: outward
  k.normal_y = k.tangent_x;
  k.contact_x_m = e - Rr * k.normal_x;
  k.contact_y_m = d - Rr * k.normal_y;
  // in the cam's frame: the fixed frame turned by -theta
  const double cx = std::cos(theta) * k.contact_x_m + std::sin(theta) * k.contact_y_m;
  const double cy = -std::sin(theta) * k.contact_x_m + std::cos(theta) * k.contact_y_m;
  double a = std::atan2(cy, cx);
  if (a < 0) a += 2 * contact::kPi;
  k.contact_angle_rad = a;
  return k;
}

double cam_radius_m(const CamKinematics& k) {
  return k.cam_curvature_per_m == 0 ? std::numeric_limits<double>::infinity() : 1 / k.cam_curvature_per_m;
}

}  // namespace cam
