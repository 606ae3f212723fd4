// The tangential problem along the revolution with Satran (docs/cam-follower.md §9).
#include "cam/revolution_transient.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_error.h"
#include "cam/cam_life.h"
#include "cam/cam_wear.h"
#include "cam/revolution_dissipation.h"
#include "lib/normal/hertz.h"
#include "lib/normal/semi_hertz.h"
#include "lib/model/contact_model.h"
#include "lib/numeric.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/steady.h"

namespace cam {

namespace {

struct Fits {
  contact::ParabolaFit f1, f2;
  double y0 = 0;
};

Fits profile_fits(const contact::Profiles& profiles) {
  Fits f{contact::fit_parabola(profiles.body1), contact::fit_parabola(profiles.body2), 0};
  if (!contact::has_constant_curvature(f.f1, contact::kConstantCurvatureRtol) ||
      !contact::has_constant_curvature(f.f2, contact::kConstantCurvatureRtol))
    throw std::invalid_argument("the revolution's transient needs profiles of constant curvature (Hertz)");
  const double c = f.f1.curvature_per_m + f.f2.curvature_per_m;
  if (!(c > 0)) throw std::invalid_argument("the revolution's transient: the profiles' gap has no curvature");
  f.y0 = (f.f1.curvature_per_m * f.f1.vertex_y_m + f.f2.curvature_per_m * f.f2.vertex_y_m) / c;
  return f;
}

contact::HertzContact hertz_at(const RollerAndTrack& bodies, const Fits& f, double Rr, const CamKinematics& k,
                               double normal_load_N) {
  const auto radius = [](double curvature) { return curvature == 0 ? contact::kFlat : 1 / curvature; };
  const contact::Bodies b{{Rr, radius(f.f1.curvature_per_m)}, {cam_radius_m(k), radius(f.f2.curvature_per_m)}};
  return contact::solve_hertz(b, bodies.pair, normal_load_N);
}

AngleContact contact_from_hertz(const RollerAndTrack& bodies, const contact::Profiles& profiles, const Fits& f,
                                double Rr, const CamKinematics& k, const contact::HertzContact& h, double mu,
                                bool heathcote_slip, const contact::Grid& grid, contact::TangentialScheme scheme) {
  if (h.a_m > grid.half_x_m * (1 + 1e-12) || h.b_m > grid.half_y_m * (1 + 1e-12))
    throw std::invalid_argument("the contact does not fit inside the revolution's grid");
  AngleContact c;
  c.normal.solver = contact::NormalSolverKind::Hertz;
  c.normal.patch = contact::hertz_patch(h, grid);
  c.normal.grid_y0_m = f.y0;
  c.normal.status.kind = contact::SolveStatus::Kind::Converged;
  c.normal.solve_converged = true;
  if (heathcote_slip)
    c.normal.patch.strip_xi_offset =
        contact::heathcote_xi_offset(profiles, Rr, cam_radius_m(k), f.y0 + grid.y_m, f.y0);
  c.problem = contact::make_tangential_problem(c.normal.patch, bodies.pair, {}, mu, 0);
  c.G_Pa = contact::combined_shear_modulus_Pa(bodies.pair);
  c.scheme = scheme;
  c.pair = bodies.pair;
  if (heathcote_slip) {
    c.roller_depth_m = roller_depth_m(profiles, f.y0, grid);
    c.track_depth_m = track_depth_m(profiles, f.y0, grid);
  }
  return c;
}


// a skipped row i: the steady solution on its contact, its strips and its energies (the steps' sign: the creep
// work is the energy the rigid slip puts in)
void add_quasi_steady_row(const AngleContact& c, const RevolutionRow& row, const RollerAngle& a, double dt_row,
                          std::size_t i, TransientRevolution& out) {
  const contact::TangentialSolution sol = steady_creep(c, a.xi, a.speed_m_per_s);
  out.dissipation[i] = angle_dissipation(c, row, a, dt_row, sol);
  ++out.steady_solves;
  out.energy.dissipated_J += sol.power_W * dt_row;
  out.energy.creep_work_J += -sol.creep_work_W * dt_row;
}

double relative_change(double x, double y, double ref) { return ref > 0 ? std::abs(x - y) / ref : 0.0; }

// the relaxed model along the revolution on the rows' contacts (revolution_transient.h): fills out's dissipation,
// unsteadiness, skipped rows, step counts and energies
void relaxed_rows(const std::vector<AngleContact>& contacts, const Revolution& r, const std::vector<RollerAngle>& rollers,
                  double dt_row, const TransientRevolutionSettings& s, TransientRevolution& out) {
  const std::size_t n = r.rows.size();
  if (!(s.relaxed_step_cells > 0 && std::isfinite(s.relaxed_step_cells)))
    throw std::invalid_argument("relaxed_step_cells must be > 0 and finite");
  std::vector<double> sigma(n, 0.0);
  double sigma_max = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const contact::ContactPatch& p = contacts[i].normal.patch;
    if (!(rollers[i].speed_m_per_s > 0))
      throw std::invalid_argument(fmt::format("the revolution's transient: at cam angle {:.6g} deg the rolling speed is "
                                              "not positive", r.rows[i].kin.theta_rad * kDegPerRad));
    if (p.a_m > 0 && p.b_m > 0) sigma[i] = contact::relaxation_lengths_m(p.a_m, p.b_m).xi;
    sigma_max = std::max(sigma_max, sigma[i]);
  }
  out.xi.resize(n);
  for (std::size_t i = 0; i < n; ++i) out.xi[i] = rollers[i].xi;
  out.unsteadiness.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = rollers[i].xi;
    double change = 0;
    for (const std::size_t k : {(i + 1) % n, (i + n - 1) % n})
      change = std::max(change, relative_change(xi, rollers[k].xi, std::max(std::abs(xi), std::abs(rollers[k].xi))));
    out.unsteadiness[i] = sigma[i] / rollers[i].speed_m_per_s / dt_row * change;
  }
  // how many rows before i (i excluded) roll `length`
  const auto rows_back = [&](std::size_t i, double length) {
    std::size_t k = 0;
    double rolled = 0;
    while (rolled < length && k < n) {
      ++k;
      rolled += rollers[(i + n - k) % n].speed_m_per_s * dt_row;
    }
    return k;
  };
  out.skipped.assign(n, 0);
  const double tol = s.quasi_steady_tolerance;
  if (s.skip && tol > 0) {
    const double memory = sigma_max * std::log(1 / std::min(tol, 0.5));  // the lag left: tol of a change
    for (std::size_t i = 0; i < n; ++i) {
      bool qs = out.unsteadiness[i] <= tol;
      const std::size_t back = rows_back(i, memory);
      for (std::size_t k = 1; qs && k <= back; ++k) qs = out.unsteadiness[(i + n - k) % n] <= tol;
      out.skipped[i] = qs;
      out.skipped_rows += qs;
    }
  }

  contact::RelaxedState state = contact::relaxed_rest();
  // row i's steps, each at most one cell of its grid; its strip energies into e and the energies into energy
  const auto run_row = [&](std::size_t i, Eigen::ArrayXd* e, TransientEnergy* energy, long& steps) {
    const AngleContact& c = contacts[i];
    const contact::ContactPatch& p = c.normal.patch;
    const double V = rollers[i].speed_m_per_s, xi = rollers[i].xi;
    const double rolled = V * dt_row;
    const long k = std::max(1L, static_cast<long>(std::ceil(rolled / (s.relaxed_step_cells * p.grid.dx_m) - 1e-9)));
    const double dq = rolled / static_cast<double>(k), dts = dt_row / static_cast<double>(k);
    for (long q = 0; q < k; ++q) {
      const contact::TangentialSolution sol =
          contact::relaxed_step(p, c.pair, {xi, 0, 0}, c.problem.mu, V, dq, state, false);
      ++steps;
      if (e) *e += sol.strip_power_W_per_m * dts;
      if (energy) {
        energy->dissipated_J += sol.power_W * dts;
        energy->creep_work_J += -sol.creep_work_W * dts;  // the steps' sign: energy the rigid slip puts in
        energy->relaxation_J += -V * (xi - state.effective.xi) * sol.Fx_N * dts;
      }
    }
  };

  out.dissipation.resize(n);
  bool warm = false;
  for (std::size_t i = 0; i < n; ++i) {
    const RevolutionRow& row = r.rows[i];
    const RollerAngle& a = rollers[i];
    if (out.skipped[i]) {
      add_quasi_steady_row(contacts[i], row, a, dt_row, i, out);
      warm = false;
      continue;
    }
    if (!warm) {
      const std::size_t before = (i + n - 1) % n;
      if (out.skipped[before]) {
        state = contact::relaxed_steady_state({rollers[before].xi, 0, 0});  // quasi-steady there
      } else {  // from the steady state kWarmupSigmas relaxation lengths back
        const std::size_t back = rows_back(i, kWarmupSigmas * sigma_max);
        state = contact::relaxed_steady_state({rollers[(i + n - back) % n].xi, 0, 0});
        for (std::size_t k = back; k >= 1; --k) run_row((i + n - k) % n, nullptr, nullptr, out.warmup_steps);
      }
    }
    warm = true;
    const contact::ContactPatch& patch = contacts[i].normal.patch;
    Eigen::ArrayXd e = Eigen::ArrayXd::Zero(patch.grid.ny);
    run_row(i, &e, &out.energy, out.transient_steps);
    AngleDissipation& d = out.dissipation[i];
    d = angle_step(row, a, dt_row);
    d.y_m = contacts[i].normal.grid_y0_m + patch.grid.y_m;
    d.power_W_per_m = e / dt_row;
    d.mean_pressure_Pa = (patch.half_length_m > 0).select(contact::kPi / 4 * patch.strip_peak_Pa, 0.0);
  }
}

}  // namespace

AngleContact angle_contact_on_grid(const RollerAndTrack& bodies, const contact::Profiles& profiles,
                                   double roller_radius_m, const CamKinematics& k, double normal_load_N, double mu,
                                   bool heathcote_slip, const contact::Grid& grid, contact::TangentialScheme scheme) {
  check_cam_scheme(scheme);
  const Fits f = profile_fits(profiles);
  return contact_from_hertz(bodies, profiles, f, roller_radius_m, k,
                            hertz_at(bodies, f, roller_radius_m, k, normal_load_N), mu, heathcote_slip, grid, scheme);
}

TransientRevolution transient_revolution(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                         const TransientRevolutionSettings& s) {
  const std::size_t n = r.rows.size();
  if (motion.angles.size() != n || n < 2)
    throw std::invalid_argument("transient_revolution: the roller's motion does not match the revolution");
  if (!(s.quasi_steady_tolerance >= 0)) throw std::invalid_argument("quasi_steady_tolerance must be >= 0");
  check_cam_scheme(s.scheme);
  const double Rr = m.geometry.roller_radius_m;
  const double dt_row = 2 * contact::kPi / static_cast<double>(n) / m.omega_rad_per_s;
  const contact::Profiles profiles = roller_and_track_profiles(m.bodies);
  const Fits f = profile_fits(profiles);

  // the contacts first: the grid covers the largest
  std::vector<contact::HertzContact> hertz(n);
  double a_max = 0, b_max = 0;
  for (std::size_t i = 0; i < n; ++i) {
    hertz[i] = hertz_at(m.bodies, f, Rr, r.rows[i].kin, motion.angles[i].normal_N);
    a_max = std::max(a_max, hertz[i].a_m);
    b_max = std::max(b_max, hertz[i].b_m);
  }
  TransientRevolution out;
  for (const contact::HertzContact& h : hertz) {
    out.a_m.push_back(h.a_m);
    out.b_m.push_back(h.b_m);
    out.p0_Pa.push_back(h.p0_Pa);
  }
  out.grid = contact::make_grid(a_max, b_max, s.grid);
  out.scheme = s.scheme;
  const contact::Grid& g = out.grid;
  std::vector<AngleContact> contacts(n);
  for (std::size_t i = 0; i < n; ++i)
    contacts[i] =
        contact_from_hertz(m.bodies, profiles, f, Rr, r.rows[i].kin, hertz[i], mu_at(m, i), s.heathcote_slip, g, s.scheme);
  if (contact::tangential_traits(s.scheme).relaxes_steady_law) {  // the relaxed model: its rows' steady solves
    relaxed_rows(contacts, r, motion.angles, dt_row, s, out);
    return out;
  }

  // unsteadiness per row
  out.unsteadiness.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const RollerAngle& ai = motion.angles[i];
    const double V = ai.speed_m_per_s;
    if (!(V * dt_row >= g.dx_m))
      throw std::invalid_argument(fmt::format("transient_revolution: at cam angle {:.6g} deg an angle step rolls {:.3g} m, "
                                              "less than a cell ({:.3g} m): fewer angle steps or a finer grid",
                                              r.rows[i].kin.theta_rad * kDegPerRad, V * dt_row, g.dx_m));
    double change = 0;
    for (const std::size_t k : {(i + 1) % n, (i + n - 1) % n}) {
      const RollerAngle& ak = motion.angles[k];
      const auto rel = [](double x, double y, double ref) { return ref > 0 ? std::abs(x - y) / ref : 0.0; };
      change = std::max({change, rel(hertz[i].a_m, hertz[k].a_m, hertz[i].a_m), rel(hertz[i].b_m, hertz[k].b_m, hertz[i].b_m),
                         rel(ai.normal_N, ak.normal_N, ai.normal_N), rel(V, ak.speed_m_per_s, V),
                         rel(ai.xi, ak.xi, std::max(std::abs(ai.xi), std::abs(ak.xi)))});
    }
    out.unsteadiness[i] = 2 * hertz[i].a_m / V / dt_row * change;
  }
  // the transit: rows back from i within 2 half_x + 2 dx rolled
  const double transit = 2 * g.half_x_m + 2 * g.dx_m;
  const auto rows_back = [&](std::size_t i) {  // how many rows before i (i itself excluded) cover the transit
    std::size_t k = 0;
    double rolled = 0;
    while (rolled < transit && k < n) {
      ++k;
      rolled += motion.angles[(i + n - k) % n].speed_m_per_s * dt_row;
    }
    return k;
  };
  out.skipped.assign(n, 0);
  if (s.skip) {
    for (std::size_t i = 0; i < n; ++i) {
      bool qs = out.unsteadiness[i] <= s.quasi_steady_tolerance;
      const std::size_t back = rows_back(i);
      for (std::size_t k = 1; qs && k <= back; ++k) qs = out.unsteadiness[(i + n - k) % n] <= s.quasi_steady_tolerance;
      out.skipped[i] = qs;
      out.skipped_rows += qs;
    }
  }

  contact::TransientState state = contact::rest_state(g);
  double carry = 0;  // rolled distance not yet stepped
  const auto problem_at = [&](std::size_t i) {
    contact::TangentialProblem p = contacts[i].problem;
    p.creepages = {motion.angles[i].xi, 0, 0};
    p.L_m_per_Pa = contact::mean_flexibility_m_per_Pa(p.flex, p.creepages, hertz[i].a_m, hertz[i].b_m);
    p.speed_m_per_s = motion.angles[i].speed_m_per_s;
    return p;
  };
  // the shift steps of row i; energies into e (per strip, J/m) and the balance terms into energy when counted
  const auto run_row = [&](std::size_t i, Eigen::ArrayXd* e, TransientEnergy* energy, long& steps) {
    const contact::TangentialProblem p = problem_at(i);
    const double V = p.speed_m_per_s;
    const double rolled = V * dt_row + carry;
    const long k = static_cast<long>(std::floor(rolled / g.dx_m));
    carry = rolled - static_cast<double>(k) * g.dx_m;
    contact::StepKinematics kin;
    kin.dt_s = g.dx_m / V;
    kin.dq_m = g.dx_m;
    kin.slip_x_m = motion.angles[i].xi * g.dx_m;  // w dt = xi V dt
    for (long q = 0; q < k; ++q) {
      const contact::StepResult st = contact::satran_step(contacts[i].normal.patch, p, kin, contact::TransientScheme::Shift, state);
      ++steps;
      if (e) *e += st.strip_energy_J_per_m;
      if (energy) {
        energy->dissipated_J += st.dissipated_J;
        energy->creep_work_J += st.creep_work_J;
        energy->elastic_change_J += st.elastic_change_J;
        energy->trailing_J += st.trailing_J;
        energy->released_J += st.released_J;
        energy->flexibility_J += st.flexibility_J;
        energy->transport_J += st.transport_J;
        energy->balance_residual_J += st.balance_residual_J;
      }
    }
    return k;
  };
  // from rest over the rows before `i` covering the transit
  const auto warm_up = [&](std::size_t i) {
    state = contact::rest_state(g);
    carry = 0;
    const std::size_t back = rows_back(i);
    for (std::size_t k = back; k >= 1; --k) run_row((i + n - k) % n, nullptr, nullptr, out.warmup_steps);
  };

  out.dissipation.resize(n);
  bool warm = false;
  for (std::size_t i = 0; i < n; ++i) {
    const RevolutionRow& row = r.rows[i];
    const RollerAngle& a = motion.angles[i];
    if (out.skipped[i]) {
      add_quasi_steady_row(contacts[i], row, a, dt_row, i, out);
      warm = false;
      continue;
    }
    if (!warm) warm_up(i);
    warm = true;
    Eigen::ArrayXd e = Eigen::ArrayXd::Zero(g.ny);
    const long k = run_row(i, &e, &out.energy, out.transient_steps);
    AngleDissipation& d = out.dissipation[i];
    d = angle_step(row, a, dt_row);
    d.y_m = f.y0 + g.y_m;
    // the mean power over the steps' time; k >= 1 since V dt >= dx (checked)
    d.power_W_per_m = e / (static_cast<double>(k) * g.dx_m / a.speed_m_per_s);
    const contact::ContactPatch& patch = contacts[i].normal.patch;
    d.mean_pressure_Pa = (patch.half_length_m > 0).select(contact::kPi / 4 * patch.strip_peak_Pa, 0.0);
  }
  return out;
}

TransientRevolution worn_transient_revolution(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                              const contact::Profiles& unworn, const CamWearGrid& g,
                                              const CamWearState& worn, const CreepLawSettings& law,
                                              const TransientRevolutionSettings& s) {
  const std::size_t n = r.rows.size();
  if (motion.angles.size() != n || n < 2)
    throw std::invalid_argument("worn_transient_revolution: the roller's motion does not match the revolution");
  if (!contact::tangential_traits(s.scheme).relaxes_steady_law)
    throw std::invalid_argument("worn_transient_revolution: the relaxed model only (Satran needs the common grid's "
                                "Hertz contacts)");
  if (!(s.quasi_steady_tolerance >= 0)) throw std::invalid_argument("quasi_steady_tolerance must be >= 0");
  const double dt_row = 2 * contact::kPi / static_cast<double>(n) / m.omega_rad_per_s;
  // the contacts and creepages of worn_revolution_dissipation (cam/cam_life.h)
  double b_min = std::numeric_limits<double>::infinity();
  for (const RevolutionRow& row : r.rows) b_min = std::min(b_min, row.contact.b_m);
  CreepLawSettings fixed = worn_contact_settings(unworn, g, law, 2 * b_min / law.grid.ny);
  fixed.scheme = s.scheme;
  std::vector<AngleContact> contacts(n);
  std::vector<RollerAngle> rollers = motion.angles;
  TransientRevolution out;
  out.scheme = s.scheme;
  for (std::size_t i = 0; i < n; ++i) {
    const RevolutionRow& row = r.rows[i];
    const contact::Profiles profiles = worn_profiles_at(unworn, g, worn, row.contact_arc_m);
    contacts[i] = angle_contact(m.bodies, profiles, m.geometry.roller_radius_m, row.kin, rollers[i].normal_N, mu_at(m, i),
                                fixed);
    const CreepageForForce xi = creepage_for_force(contacts[i], rollers[i].tangential_N);
    if (xi.found) {
      rollers[i].xi = xi.xi;
      rollers[i].slip_speed_m_per_s = xi.xi * rollers[i].speed_m_per_s;
    }
    const contact::ContactPatch& p = contacts[i].normal.patch;
    out.a_m.push_back(p.a_m);
    out.b_m.push_back(p.b_m);
    out.p0_Pa.push_back(p.p0_Pa);
  }
  relaxed_rows(contacts, r, rollers, dt_row, s, out);
  return out;
}

TransientRevolution quasi_steady_revolution(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                            const CreepLawSettings& law) {
  const std::size_t n = r.rows.size();
  if (motion.angles.size() != n || n < 2)
    throw std::invalid_argument("quasi_steady_revolution: the roller's motion does not match the revolution");
  const double dt_row = 2 * contact::kPi / static_cast<double>(n) / m.omega_rad_per_s;
  const contact::Profiles profiles = roller_and_track_profiles(m.bodies);
  const bool own_creepage = is_motion_law(law);
  TransientRevolution out;
  out.scheme = law.scheme;
  out.quasi_steady_only = true;
  out.dissipation.resize(n);
  out.unsteadiness.assign(n, 0);
  out.skipped.assign(n, 1);
  out.skipped_rows = static_cast<int>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const RevolutionRow& row = r.rows[i];
    RollerAngle a = motion.angles[i];
    const AngleContact c = angle_contact(m.bodies, profiles, m.geometry.roller_radius_m, row.kin, a.normal_N, mu_at(m, i), law);
    if (!own_creepage) {
      const CreepageForForce xi = creepage_for_force(c, a.tangential_N);
      out.creep_evaluations += xi.evaluations;
      if (xi.found) {
        a.xi = xi.xi;
        a.slip_speed_m_per_s = xi.xi * a.speed_m_per_s;
      }
    }
    add_quasi_steady_row(c, row, a, dt_row, i, out);
    const contact::ContactPatch& p = c.normal.patch;
    out.a_m.push_back(p.a_m);
    out.b_m.push_back(p.b_m);
    out.p0_Pa.push_back(p.p0_Pa);
    out.xi.push_back(a.xi);
    out.normal_solver = c.normal.solver;
    if (i == 0) out.grid = p.grid;
  }
  return out;
}

SkipComparison compare_dissipation(const RevolutionDissipation& d, const RevolutionDissipation& full) {
  SkipComparison c;
  if (d.size() != full.size()) throw std::invalid_argument("compare_dissipation: the revolutions differ in steps");
  double p_max = 0, diff = 0, e_skip = 0, e_full = 0;
  for (std::size_t i = 0; i < full.size(); ++i) {
    const double pf = total_power_W(full[i]), ps = total_power_W(d[i]);
    p_max = std::max(p_max, pf);
    diff = std::max(diff, std::abs(ps - pf));
    e_full += pf * full[i].duration_s;
    e_skip += ps * d[i].duration_s;
  }
  c.max_power_error = p_max > 0 ? diff / p_max : 0;
  c.energy_error = e_full > 0 ? (e_skip - e_full) / e_full : 0;
  return c;
}

SkipComparison compare_skip(const TransientRevolution& with_skip, const TransientRevolution& full) {
  if (with_skip.dissipation.size() != full.dissipation.size())
    throw std::invalid_argument("compare_skip: the revolutions differ in steps");
  SkipComparison c = compare_dissipation(with_skip.dissipation, full.dissipation);
  const double steps_full = static_cast<double>(full.transient_steps + full.warmup_steps);
  c.step_saving = steps_full > 0 ? 1 - static_cast<double>(with_skip.transient_steps + with_skip.warmup_steps) / steps_full : 0;
  return c;
}

}  // namespace cam
