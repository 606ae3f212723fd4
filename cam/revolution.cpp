// One cam revolution (docs/cam-follower.md §5).
#include "cam/revolution.h"

#include <cmath>
#include <limits>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_error.h"
#include "lib/number.h"
#include "lib/numeric.h"

namespace cam {

const char* to_string(RevolutionStatus s) { return s == RevolutionStatus::Complete ? "complete" : "jump"; }

double mu_at(const CamModel& m, std::size_t i) {
  if (m.mu_by_step.empty()) return m.mu;
  if (m.mu_by_step.size() != static_cast<std::size_t>(m.angle_steps) || i >= m.mu_by_step.size())
    throw std::invalid_argument(fmt::format("the friction per angle step: {} values for {} angle steps (step {})",
                                            m.mu_by_step.size(), m.angle_steps, i));
  return m.mu_by_step[i];
}

Revolution run_revolution(const CamModel& m) {
  check_geometry(m.geometry, m.omega_rad_per_s);
  if (!m.mu_by_step.empty()) {
    if (m.mu_by_step.size() != static_cast<std::size_t>(m.angle_steps))
      throw std::invalid_argument(fmt::format("the friction per angle step: {} values for {} angle steps",
                                              m.mu_by_step.size(), m.angle_steps));
    for (const double mu : m.mu_by_step)
      if (!(mu >= 0 && mu <= 2)) throw std::invalid_argument("the friction per angle step must be in [0, 2]");
  }
  check_train(m.train);
  if (m.angle_steps < 8) throw std::invalid_argument("angle_steps must be >= 8");
  Revolution r;
  // the jump speed first: above it there is no revolution to tabulate
  r.jump = jump_speed(m.train, m.law, kJumpSamples);
  if (m.omega_rad_per_s >= r.jump.omega_rad_per_s) {
    r.status = RevolutionStatus::Jump;
    r.jump_at_theta_rad = r.jump.at_theta_rad;
    return r;
  }
  const contact::Profiles profiles = roller_and_track_profiles(m.bodies);
  const double Rr = m.geometry.roller_radius_m;
  r.rows.reserve(static_cast<std::size_t>(m.angle_steps));
  for (int i = 0; i < m.angle_steps; ++i) {
    const double theta = 2 * contact::kPi * i / m.angle_steps;
    RevolutionRow row;
    row.kin = cam_kinematics(m.geometry, lift_at(m.law, theta), theta, m.omega_rad_per_s);
    const CamKinematics& k = row.kin;
    // the design's checks
    if (k.pitch_curvature_per_m > 0 && 1 / k.pitch_curvature_per_m - Rr < m.min_radius_m)
      throw CamError(CamErrorKind::Undercut, theta, "min_radius_m",
                     fmt::format("at cam angle {:.6g} deg the convex pitch curve's radius {:.6g} m less the "
                                 "roller's {:.6g} m is {:.6g} m < min_radius_m {:.6g} m (undercut or too sharp): "
                                 "a larger base circle, a smaller roller or a gentler lift",
                                 theta * kDegPerRad, 1 / k.pitch_curvature_per_m, Rr,
                                 1 / k.pitch_curvature_per_m - Rr, m.min_radius_m));
    if (std::abs(k.pressure_angle_rad) > m.max_pressure_angle_rad)
      throw CamError(CamErrorKind::PressureAngle, theta, "max_pressure_angle_rad",
                     fmt::format("at cam angle {:.6g} deg the pressure angle {:.4g} deg exceeds "
                                 "max_pressure_angle_rad {:.6g} ({:.4g} deg): a larger base circle, an offset or a "
                                 "longer rise",
                                 theta * kDegPerRad, k.pressure_angle_rad * kDegPerRad, m.max_pressure_angle_rad,
                                 m.max_pressure_angle_rad * kDegPerRad));
    row.loads = cam_loads(m.train, m.geometry, k, m.omega_rad_per_s, mu_at(m, i));
    if (row.loads.contact_lost) {  // the guide or the roller's friction can lose contact below omega_jump
      r.status = RevolutionStatus::Jump;
      r.jump_at_theta_rad = theta;
      r.rows.clear();
      return r;
    }
    row.contact = roller_contact(m.bodies, profiles, Rr, k, row.loads, mu_at(m, i));
    if (row.loads.regime == RollerRegime::Sliding) ++r.sliding_steps;
    else if (!row.contact.linear_range) ++r.outside_linear_steps;
    if (row.contact.reaches_edge) ++r.edge_steps;
    r.rows.push_back(row);
  }
  // the contact's position along the cam: the arc rate integrated by the trapezoid rule
  const double h = 2 * contact::kPi / m.angle_steps;
  double arc = 0;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    r.rows[i].contact_arc_m = arc;
    const double next = r.rows[(i + 1) % r.rows.size()].kin.arc_rate_m_per_rad;
    arc += 0.5 * h * (r.rows[i].kin.arc_rate_m_per_rad + next);
  }
  r.cam_circumference_m = arc;
  return r;
}

std::string revolution_csv(const Revolution& r) {
  std::string out =
      "cam_angle_deg,lift_m,lift_rate_m_per_rad,lift_accel_m_per_rad2,pressure_angle_deg,pitch_radius_m,"
      "cam_radius_m,surface,contact_arc_m,contact_angle_deg,rolling_speed_m_per_s,axial_load_N,normal_load_N,"
      "tangential_load_N,guide_reaction_N,shaft_torque_N_m,a_m,b_m,p0_Pa,regime,xi,linear_range,"
      "roller_omega_rad_per_s\n";
  const auto num = [&out](double v) {
    contact::append_round_trip(out, v);
    out += ',';
  };
  const double inf = std::numeric_limits<double>::infinity();
  for (const RevolutionRow& w : r.rows) {
    const CamKinematics& k = w.kin;
    num(k.theta_rad * kDegPerRad);
    num(k.lift.s_m);
    num(k.lift.ds_m_per_rad);
    num(k.lift.d2s_m_per_rad2);
    num(k.pressure_angle_rad * kDegPerRad);
    num(k.pitch_curvature_per_m == 0 ? inf : 1 / k.pitch_curvature_per_m);
    num(cam_radius_m(k));
    out += k.cam_curvature_per_m > 0 ? "convex," : k.cam_curvature_per_m < 0 ? "concave," : "flat,";
    num(w.contact_arc_m);
    num(k.contact_angle_rad * kDegPerRad);
    num(k.rolling_speed_m_per_s);
    num(w.loads.axial_N);
    num(w.loads.normal_N);
    num(w.loads.tangential_N);
    num(w.loads.guide_reaction_N);
    num(w.loads.shaft_torque_N_m);
    num(w.contact.a_m);
    num(w.contact.b_m);
    num(w.contact.p0_Pa);
    out += to_string(w.loads.regime);
    out += ',';
    num(w.contact.xi);
    out += w.contact.linear_range ? "1," : "0,";
    contact::append_round_trip(out, k.roller_omega_rad_per_s);
    out += '\n';
  }
  return out;
}

}  // namespace cam
