// The roller's motion over one cam revolution (docs/cam-follower.md §7).
#include "cam/roller_motion.h"

#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_error.h"

namespace cam {

double shaft_torque_N_m(const CamLoads& loads, const CamKinematics& k, double track_depth_moment_N_m) {
  const double n_cross_t = k.normal_x * k.tangent_y - k.normal_y * k.tangent_x;
  return loads.shaft_torque_N_m - n_cross_t * track_depth_moment_N_m;
}

RollerMotion quasi_static_motion(const CamModel& m, const Revolution& r, const CreepLawSettings& s) {
  const contact::Profiles profiles = roller_and_track_profiles(m.bodies);
  const double Rr = m.geometry.roller_radius_m;
  RollerMotion motion;
  motion.angles.reserve(r.rows.size());
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const RevolutionRow& row = r.rows[i];
    if (row.loads.regime == RollerRegime::Sliding)
      throw std::invalid_argument(fmt::format("the roller slides at cam angle {:.6g} deg: its slip comes from its "
                                              "dynamics, not from the quasi-static law",
                                              row.kin.theta_rad * kDegPerRad));
    const AngleContact c = angle_contact(m.bodies, profiles, Rr, row.kin, row.loads.normal_N, mu_at(m, i), s);
    const CreepageForForce inv = creepage_for_force(c, row.loads.tangential_N);
    motion.creep_law_evaluations += inv.evaluations + 1;
    if (!inv.found)
      throw std::invalid_argument(fmt::format("at cam angle {:.6g} deg the steady creep law cannot give F_t = {:.6g} N "
                                              "(mu F_n = {:.6g} N): the roller slides",
                                              row.kin.theta_rad * kDegPerRad, row.loads.tangential_N,
                                              mu_at(m, i) * row.loads.normal_N));
    RollerAngle a;
    a.xi = inv.xi;
    // w = xi V with V = V_cam - w/2
    a.slip_speed_m_per_s = inv.xi * row.kin.rolling_speed_m_per_s / (1 + inv.xi / 2);
    a.speed_m_per_s = row.kin.rolling_speed_m_per_s - a.slip_speed_m_per_s / 2;
    a.omega_r_rad_per_s = row.kin.roller_omega_rad_per_s + a.slip_speed_m_per_s / Rr;
    const contact::TangentialSolution sol = steady_creep(c, a.xi, a.speed_m_per_s);
    a.tangential_N = sol.Fx_N;
    const CreepForce cf = creep_force(c, a.xi);
    a.depth_moment_N_m = cf.depth_moment_N_m;
    a.track_depth_moment_N_m = cf.track_depth_moment_N_m;
    a.creep_power_W = -sol.creep_work_W;
    a.normal_N = row.loads.normal_N;
    a.stick_fraction = sol.stick_fraction;
    a.regime = RollerRegime::Rolling;
    motion.angles.push_back(a);
  }
  return motion;
}

}  // namespace cam
