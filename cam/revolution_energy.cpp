// Energy over the periodic revolution (docs/cam-follower.md §10).
#include "cam/revolution_energy.h"

#include <cmath>
#include <stdexcept>

#include "lib/numeric.h"

namespace cam {

RevolutionEnergy revolution_energy(const CamModel& m, const Revolution& r, const PeriodicMotion& p,
                                   const TransientRevolution* transient) {
  const std::size_t n = r.rows.size();
  if (p.motion.angles.size() != n || n < 2)
    throw std::invalid_argument("revolution_energy: the roller's motion does not match the revolution");
  const double w = m.omega_rad_per_s, dt = 2 * contact::kPi / static_cast<double>(n) / w;
  const double J = m.train.roller_inertia_kg_m2;
  RevolutionEnergy e;
  for (std::size_t i = 0; i < n; ++i) {
    const RevolutionRow& row = r.rows[i];
    const RollerAngle& a = p.motion.angles[i];
    const CamLoads L = cam_loads_with_tangential(m.train, m.geometry, row.kin, w, a.tangential_N);
    const double s1 = row.kin.lift.ds_m_per_rad;
    const double T = shaft_torque_N_m(L, row.kin, a.track_depth_moment_N_m);
    e.shaft_J += T * w * dt;
    e.heathcote_track_J += (T - L.shaft_torque_N_m) * w * dt;
    e.train_J += L.axial_N * s1 * w * dt;
    e.guide_J += m.train.guide_mu * std::abs(L.guide_reaction_N) * std::abs(s1) * w * dt;
    e.bearing_J += bearing_torque_N_m(m.train, a.omega_r_rad_per_s) * a.omega_r_rad_per_s * dt;
    e.creep_rigid_J += -a.tangential_N * a.slip_speed_m_per_s * dt;
    e.heathcote_roller_J += a.depth_moment_N_m * a.omega_r_rad_per_s * dt;
    e.creep_steady_J += a.creep_power_W * dt;
    e.roller_J += (m.geometry.roller_radius_m * a.tangential_N - a.depth_moment_N_m -
                   bearing_torque_N_m(m.train, a.omega_r_rad_per_s)) *
                  a.omega_r_rad_per_s * dt;
    e.kinematic_J += J * row.kin.roller_alpha_rad_per_s2 * row.kin.roller_omega_rad_per_s * dt;
  }
  e.residual_J =
      e.shaft_J - (e.train_J + e.guide_J + e.bearing_J + e.creep_rigid_J + e.heathcote_roller_J +
                   e.heathcote_track_J + e.roller_J);
  e.frame_J = e.creep_steady_J - (e.creep_rigid_J + e.heathcote_roller_J + e.heathcote_track_J);
  if (transient) {
    const TransientEnergy& t = transient->energy;
    e.dissipated_J = t.dissipated_J;
    e.creep_work_J = t.creep_work_J;
    e.transient_J = t.creep_work_J - e.creep_steady_J;
    e.elastic_J = t.elastic_change_J + t.trailing_J + t.transport_J + t.relaxation_J;
    e.tangential_residual_J = t.dissipated_J - (t.creep_work_J - e.elastic_J);
  }
  return e;
}

}  // namespace cam
