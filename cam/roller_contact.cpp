// The roller-cam contact at one angle (docs/cam-follower.md §4).
#include "cam/roller_contact.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lib/tangential/kalker.h"

namespace cam {

contact::Profiles roller_and_track_profiles(const RollerAndTrack& r) {
  const bool roller_flat = std::isinf(r.roller_crown_radius_m), track_flat = std::isinf(r.track_crown_radius_m);
  if (roller_flat && track_flat)
    throw std::invalid_argument("a cylindrical roller on a flat track is a line contact: crown one of them");
  contact::Profiles p;
  p.body1 = roller_flat ? contact::flat_profile(r.roller_width_m)
                        : contact::crowned_profile(r.roller_crown_radius_m, r.roller_width_m);
  p.body2 = track_flat ? contact::flat_profile(r.track_width_m)
                       : contact::crowned_profile(r.track_crown_radius_m, r.track_width_m);
  return p;
}

RollerContact roller_contact(const RollerAndTrack& r, const contact::Profiles& profiles, double roller_radius_m,
                             const CamKinematics& k, const CamLoads& loads, double mu) {
  contact::NormalProblem np;
  np.choice = contact::NormalChoice::Auto;
  np.bodies.body1.Rx_m = roller_radius_m;
  np.bodies.body2.Rx_m = cam_radius_m(k);
  np.profiles = &profiles;
  np.pair = r.pair;
  np.normal_load_N = loads.normal_N;
  const contact::NormalSolution n = contact::solve_normal(np);
  if (!n.status.converged())
    throw std::runtime_error("the normal problem did not converge: " + n.status.message);
  RollerContact c;
  c.solver = n.solver;
  c.a_m = n.patch.a_m;
  c.b_m = n.patch.b_m;
  c.p0_Pa = n.patch.p0_Pa;
  c.approach_m = n.patch.approach_m;
  c.reaches_edge = n.reaches_edge;
  c.C11 = contact::kalker_coefficients(c.a_m, c.b_m, contact::combined_poisson(r.pair)).C11;
  const double G = contact::combined_shear_modulus_Pa(r.pair);
  if (loads.regime == RollerRegime::Rolling) {
    c.xi = -loads.tangential_N / (G * c.a_m * c.b_m * c.C11);
    c.linear_range = std::abs(loads.tangential_N) <= kLinearRangeFraction * mu * loads.normal_N;
  } else {
    c.xi = std::numeric_limits<double>::quiet_NaN();
    c.linear_range = false;
  }
  return c;
}

}  // namespace cam
