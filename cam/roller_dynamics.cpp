// The roller's spin over the revolution (docs/cam-follower.md §7).
#include "cam/roller_dynamics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "cam/cam_error.h"
#include "lib/numeric.h"
#include "lib/model/contact_model.h"
#include "lib/tangential/tangential.h"

namespace cam {

double saturation_creepage(const AngleContact& c) {
  const contact::ContactPatch& p = c.normal.patch;
  const double jv = 3 * c.problem.mu * p.normal_load_N / (c.G_Pa * p.a_m * p.b_m * c.problem.C.C11);
  return jv * contact::xi_saturation_factor(c.scheme, p);
}

namespace {

// the creepage of slip w at cam surface speed Vc: xi = w/V, V = Vc - w/2
double creepage_of(double w, double Vc) { return w / (Vc - w / 2); }

struct StepEnd {
  double delta = 0;
  double xi = 0, w = 0, V = 0, F = 0;
  int evaluations = 0;
};

}  // namespace

PeriodicMotion periodic_motion(const CamModel& m, const Revolution& r, const RollerDynamicsSettings& s) {
  if (!(s.periodicity_rtol > 0) || s.max_revolutions < 1 || !(s.delta_rtol > 0))
    throw std::invalid_argument("periodic_motion: periodicity_rtol, delta_rtol > 0 and max_revolutions >= 1");
  const std::size_t n = r.rows.size();
  if (n < 2) throw std::invalid_argument("periodic_motion: the revolution has no rows");
  const FollowerTrain& t = m.train;
  const double Rr = m.geometry.roller_radius_m, J = t.roller_inertia_kg_m2;
  const double dt = 2 * contact::kPi / static_cast<double>(n) / m.omega_rad_per_s;
  const contact::Profiles profiles = roller_and_track_profiles(m.bodies);
  const CreepLawSettings law = motion_law(s.law);  // the unworn contacts; the exact theory's place the relaxed model's
  double omega_scale = 0;
  for (const RevolutionRow& row : r.rows) omega_scale = std::max(omega_scale, std::abs(row.kin.roller_omega_rad_per_s));

  PeriodicMotion out;
  out.tolerance_rad_per_s = s.periodicity_rtol * omega_scale;
  const double delta_tol = s.delta_rtol * omega_scale;
  std::vector<double> normal(n);
  for (std::size_t i = 0; i < n; ++i) normal[i] = r.rows[i].loads.normal_N;
  std::vector<AngleContact> contacts(n);
  long evaluations = 0;

  // the step to row i's end from delta0 (and delta1 the step before, when bdf2):
  //   J (delta - delta0)/dt = R F(xi(delta)) - T_b - J alpha_kin                       (backward Euler)
  //   J (3 delta - 4 delta0 + delta1)/(2 dt) = R F(xi(delta)) - T_b - J alpha_kin     (BDF2)
  const auto step_to = [&](std::size_t i, double delta0, double delta1, bool bdf2) {
    const RevolutionRow& row = r.rows[i];
    const AngleContact& c = contacts[i];
    const double Vc = row.kin.rolling_speed_m_per_s, wk = row.kin.roller_omega_rad_per_s;
    const double alpha = row.kin.roller_alpha_rad_per_s2;
    StepEnd e;
    const auto g = [&](double delta) {
      ++e.evaluations;
      const double xi = creepage_of(Rr * delta, Vc);
      const double rate = bdf2 ? (1.5 * delta - 2 * delta0 + 0.5 * delta1) / dt : (delta - delta0) / dt;
      const CreepForce cf = creep_force(c, xi);
      return J * rate - (Rr * cf.force_N - cf.depth_moment_N_m) + bearing_torque_N_m(t, wk + delta) + J * alpha;
    };
    // delta's domain: |xi| <= kMaxCreepage, i.e. w in [-2 Vc/3 ... ] scaled: xi = w/(Vc - w/2)
    const double w_hi = kMaxCreepage * Vc / (1 + kMaxCreepage / 2), w_lo = -kMaxCreepage * Vc / (1 - kMaxCreepage / 2);
    const double d_hi = w_hi / Rr, d_lo = w_lo / Rr;
    // a first width: the quasi-static slip of the linear law for the force rolling needs
    const double K = c.G_Pa * c.normal.patch.a_m * c.normal.patch.b_m * c.problem.C.C11;
    const double need = (J * alpha + bearing_torque_N_m(t, wk)) / Rr;
    double width = std::max({std::abs(need) / K * Vc / Rr, std::abs(delta0) * 1e-3, delta_tol * 16});
    double lo = std::max(d_lo, delta0 - width), hi = std::min(d_hi, delta0 + width);
    double g_lo = g(lo), g_hi = g(hi);
    for (double w = width; g_lo > 0 && lo > d_lo;) g_lo = g(lo = std::max(d_lo, delta0 - (w *= 2)));
    for (double w = width; g_hi < 0 && hi < d_hi;) g_hi = g(hi = std::min(d_hi, delta0 + (w *= 2)));
    if (g_lo > 0 || g_hi < 0)
      throw std::runtime_error(fmt::format("the roller's spin at cam angle {:.6g} deg: no slip within |xi| <= {:g} "
                                           "balances its inertia and bearing (the roller stalls)",
                                           row.kin.theta_rad * kDegPerRad, kMaxCreepage));
    const contact::RootResult root = contact::find_root_bracketed(g, lo, hi, g_lo, g_hi, delta_tol);
    if (!root.converged)
      throw std::runtime_error(fmt::format("the roller's spin at cam angle {:.6g} deg: the step's root did not converge "
                                           "(residual {:.3g} N m)", row.kin.theta_rad * kDegPerRad, root.f));
    e.delta = root.x;
    e.w = Rr * e.delta;
    e.xi = creepage_of(e.w, Vc);
    e.V = Vc - e.w / 2;
    return e;
  };

  // the start: the quasi-static slip at row 0 where the law can give the force rolling needs, else none
  double delta0 = 0;
  {
    const AngleContact c0 = angle_contact(m.bodies, profiles, Rr, r.rows[0].kin, normal[0], mu_at(m, 0), law);
    const CreepageForForce q = creepage_for_force(c0, r.rows[0].loads.required_tangential_N);
    evaluations += q.evaluations;
    if (q.found) {
      const double Vc = r.rows[0].kin.rolling_speed_m_per_s;
      delta0 = q.xi * Vc / (1 + q.xi / 2) / Rr;
    }
  }
  std::vector<StepEnd> ends(n);
  double previous_last = 0;  // delta at row n-1 of the previous revolution
  for (int rev = 1; rev <= s.max_revolutions; ++rev) {
    for (std::size_t i = 0; i < n; ++i)
      contacts[i] = angle_contact(m.bodies, profiles, Rr, r.rows[i].kin, normal[i], mu_at(m, i), law);
    // row 0 holds the start; rows 1..n-1 and row 0 again (2 pi) are step ends
    // BDF2 but for the very first step (no history yet); later revolutions take the step before 0 from the
    // previous one's last row
    double delta = delta0;
    for (std::size_t k = 1; k <= n; ++k) {
      const std::size_t i = k % n;
      const bool history = rev > 1 || k > 1;
      const double before = k == 1 ? previous_last : ends[(k + n - 2) % n].delta;
      ends[i] = step_to(i, delta, before, s.bdf2 && history);
      evaluations += ends[i].evaluations;
      delta = ends[i].delta;
    }
    previous_last = ends[n - 1].delta;
    const double residual = std::abs(delta - delta0);
    out.residuals_rad_per_s.push_back(residual);
    out.revolutions = rev;
    spdlog::debug("roller dynamics: revolution {}: |omega_r(2 pi) - omega_r(0)| = {:.3e} rad/s", rev, residual);
    // the state at 0 of this revolution is row 0's start; its record is the step end that reaches 2 pi
    // (the same state once periodic)
    out.start_omega_r_rad_per_s = r.rows[0].kin.roller_omega_rad_per_s + delta0;
    delta0 = delta;
    // the next revolution's normal loads from this one's creep forces
    for (std::size_t i = 0; i < n; ++i)
      normal[i] = cam_loads_with_tangential(t, m.geometry, r.rows[i].kin, m.omega_rad_per_s,
                                            steady_creep_force_N(contacts[i], ends[i].xi))
                      .normal_N;
    // BDF2 takes its history from the revolution before: the first one starts with a backward Euler step, so a
    // periodic revolution is one of two or more
    if (residual <= out.tolerance_rad_per_s && (rev > 1 || !s.bdf2)) {
      out.converged = true;
      break;
    }
  }
  out.periodicity_residual_rad_per_s = out.residuals_rad_per_s.back();
  // the last revolution's states, on its contacts
  out.motion.angles.resize(n);
  out.sliding_steps = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const StepEnd& e = ends[i];
    const contact::TangentialSolution sol = steady_creep(contacts[i], e.xi, e.V);
    evaluations += 1;
    RollerAngle& a = out.motion.angles[i];
    a.omega_r_rad_per_s = r.rows[i].kin.roller_omega_rad_per_s + e.delta;
    a.xi = e.xi;
    a.slip_speed_m_per_s = e.w;
    a.speed_m_per_s = e.V;
    a.tangential_N = sol.Fx_N;
    const CreepForce cf = creep_force(contacts[i], e.xi);
    a.depth_moment_N_m = cf.depth_moment_N_m;
    a.track_depth_moment_N_m = cf.track_depth_moment_N_m;
    a.creep_power_W = -sol.creep_work_W;
    a.normal_N = contacts[i].normal.patch.normal_load_N;
    a.stick_fraction = sol.stick_fraction;
    a.regime = std::abs(e.xi) >= saturation_creepage(contacts[i]) ? RollerRegime::Sliding : RollerRegime::Rolling;
    out.sliding_steps += a.regime == RollerRegime::Sliding;
  }
  out.motion.creep_law_evaluations = evaluations;
  return out;
}

}  // namespace cam
