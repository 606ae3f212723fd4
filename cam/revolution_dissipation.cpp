// The quasi-steady dissipation over the revolution (docs/cam-follower.md §8).
#include "cam/revolution_dissipation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lib/numeric.h"

namespace cam {

AngleDissipation angle_step(const RevolutionRow& row, const RollerAngle& roller, double duration_s) {
  AngleDissipation d;
  d.theta_rad = row.kin.theta_rad;
  d.duration_s = duration_s;
  d.cam_arc_m = row.contact_arc_m;
  d.rolling_speed_m_per_s = row.kin.rolling_speed_m_per_s;
  d.roller_surface_speed_m_per_s = roller_surface_speed_m_per_s(row.kin.rolling_speed_m_per_s, roller.slip_speed_m_per_s);
  return d;
}

AngleDissipation angle_dissipation(const AngleContact& c, const RevolutionRow& row, const RollerAngle& roller,
                                   double duration_s) {
  return angle_dissipation(c, row, roller, duration_s, steady_creep(c, roller.xi, roller.speed_m_per_s));
}

AngleDissipation angle_dissipation(const AngleContact& c, const RevolutionRow& row, const RollerAngle& roller,
                                   double duration_s, const contact::TangentialSolution& steady) {
  const contact::ContactPatch& patch = c.normal.patch;
  AngleDissipation d = angle_step(row, roller, duration_s);
  d.y_m = c.normal.grid_y0_m + patch.grid.y_m;
  d.power_W_per_m = steady.strip_power_W_per_m;
  // an iterative solve's (the exact theory's) strips outside its slip carry rounding of either sign: below
  // kStripPowerRounding of the largest strip, or of the full slide's mean mu F_n V / (2 b) where the whole step
  // dissipates next to nothing, they are nothing (a real negative power is left for the wear to refuse)
  const double slide = c.problem.mu * patch.normal_load_N * std::abs(roller.speed_m_per_s) / (2 * patch.b_m);
  const double floor =
      -kStripPowerRounding * std::max(d.power_W_per_m.abs().maxCoeff(), std::isfinite(slide) ? slide : 0.0);
  d.power_W_per_m = (d.power_W_per_m < 0 && d.power_W_per_m >= floor).select(0.0, d.power_W_per_m);
  d.mean_pressure_Pa = (patch.half_length_m > 0).select(contact::kPi / 4 * patch.strip_peak_Pa, 0.0);
  return d;
}

RevolutionDissipation revolution_dissipation(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                             const CreepLawSettings& s) {
  if (motion.angles.size() != r.rows.size())
    throw std::invalid_argument("revolution_dissipation: the roller's motion has " +
                                std::to_string(motion.angles.size()) + " angles, the revolution " +
                                std::to_string(r.rows.size()) + " rows");
  if (s.grid.ny < 2) throw std::invalid_argument("revolution_dissipation: ny must be >= 2");
  const contact::Profiles profiles = roller_and_track_profiles(m.bodies);
  const double duration = 2 * contact::kPi / m.angle_steps / m.omega_rad_per_s;
  const bool own_creepage = is_motion_law(s);  // the motion's creepage is this law's
  RevolutionDissipation out;
  out.reserve(r.rows.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const AngleContact c = angle_contact(m.bodies, profiles, m.geometry.roller_radius_m, r.rows[i].kin,
                                         motion.angles[i].normal_N, mu_at(m, i), s);
    RollerAngle roller = motion.angles[i];
    if (!own_creepage) {  // the creepage that carries the motion's F_t with this law, on this contact
      const CreepageForForce xi = creepage_for_force(c, roller.tangential_N);
      if (xi.found) {
        roller.xi = xi.xi;
        roller.slip_speed_m_per_s = xi.xi * roller.speed_m_per_s;
      }
    }
    out.push_back(angle_dissipation(c, r.rows[i], roller, duration));
  }
  return out;
}

double total_power_W(const AngleDissipation& d) {
  if (d.y_m.size() < 2) return 0;
  return d.power_W_per_m.sum() * (d.y_m(1) - d.y_m(0));
}

DissipationTotals dissipation_totals(const RevolutionDissipation& d) {
  DissipationTotals t;
  for (const AngleDissipation& a : d) {
    const double P = total_power_W(a);
    t.energy_J += P * a.duration_s;
    if (P > t.max_power_W) {
      t.max_power_W = P;
      t.max_power_theta_rad = a.theta_rad;
    }
  }
  return t;
}

}  // namespace cam
