// The roller's steady creep law at one cam angle (docs/cam-follower.md §7).
#include "cam/creep_law.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "cam/halfspace_contact.h"
#include "lib/numeric.h"
#include "lib/model/contact_model.h"

namespace cam {

void check_cam_scheme(contact::TangentialScheme scheme) {
  if (!contact::tangential_traits(scheme).cam)
    throw std::invalid_argument("the cam's tangential model is relaxed, consistent or exact, not " +
                                contact::to_string(scheme));
}

CreepLawSettings motion_law(const CreepLawSettings& s) {
  CreepLawSettings m = s;
  m.normal = contact::NormalChoice::Auto;
  if (s.scheme == contact::TangentialScheme::Exact) m.scheme = contact::TangentialScheme::Relaxed;
  return m;
}

bool is_motion_law(const CreepLawSettings& s) {
  const CreepLawSettings m = motion_law(s);
  return m.scheme == s.scheme && m.normal == s.normal;
}

double creep_force_tolerance_N(const AngleContact& c) {
  const double rtol = c.scheme == contact::TangentialScheme::Exact ? kExactCreepForceRtol : kCreepForceRtol;
  return rtol * c.problem.mu * c.normal.patch.normal_load_N;
}

namespace {
contact::NormalSolution halfspace_normal(const RollerAndTrack& bodies, const contact::Profiles& profiles,
                                         double roller_radius_m, const CamKinematics& k, double normal_load_N,
                                         const CreepLawSettings& s) {
  HalfspaceAngleSettings h;
  h.grid = s.grid;
  h.fixed_y_lo_m = s.fixed_grid_y_lo_m;
  h.fixed_y_hi_m = s.fixed_grid_y_hi_m;
  h.fixed_strips = s.grid.ny;
  h.initial_approach_m = s.initial_approach_m;
  h.heathcote_slip = s.heathcote_slip;
  return halfspace_angle_normal(bodies, profiles, roller_radius_m, cam_radius_m(k), normal_load_N, h);
}
}  // namespace

AngleContact angle_contact(const RollerAndTrack& bodies, const contact::Profiles& profiles, double roller_radius_m,
                           const CamKinematics& k, double normal_load_N, double mu, const CreepLawSettings& s) {
  check_cam_scheme(s.scheme);
  if (s.normal == contact::NormalChoice::Hertz)
    throw std::invalid_argument("the cam's normal solver is auto, semi-hertz or halfspace (auto takes Hertz's closed "
                                "form where it holds)");
  contact::NormalProblem np;
  np.choice = s.normal;
  np.bodies.body1.Rx_m = roller_radius_m;
  np.bodies.body2.Rx_m = cam_radius_m(k);
  np.profiles = &profiles;
  np.pair = bodies.pair;
  np.normal_load_N = normal_load_N;
  np.grid = s.grid;
  np.semi_hertz.heathcote_slip = s.heathcote_slip;
  np.semi_hertz.pressure_fields = false;  // the steady strips read only the strips
  // worn profiles change a little from one evaluation of the life's rate to the next: the contact must
  // follow them continuously (semi_hertz.h; docs/cam-follower.md §14)
  np.semi_hertz.continuous_rule = true;
  np.semi_hertz.fixed_grid_y_lo_m = s.fixed_grid_y_lo_m;
  np.semi_hertz.fixed_grid_y_hi_m = s.fixed_grid_y_hi_m;
  np.semi_hertz.initial_approach_m = s.initial_approach_m;
  np.semi_hertz.initial_slope = s.initial_slope;
  np.semi_hertz.load_rtol = s.normal_load_rtol;
  np.worn = s.worn;
  AngleContact c;
  c.normal = s.normal == contact::NormalChoice::Halfspace
                 ? halfspace_normal(bodies, profiles, roller_radius_m, k, normal_load_N, s)
                 : contact::solve_normal_converged(np);
  c.problem = contact::make_tangential_problem(c.normal.patch, bodies.pair, {}, mu, 0);
  c.G_Pa = contact::combined_shear_modulus_Pa(bodies.pair);
  c.scheme = s.scheme;
  c.pair = bodies.pair;
  if (s.heathcote_slip) {
    c.roller_depth_m = roller_depth_m(profiles, c.normal.grid_y0_m, c.normal.patch.grid);
    c.track_depth_m = track_depth_m(profiles, c.normal.grid_y0_m, c.normal.patch.grid);
  }
  return c;
}

namespace {
Eigen::ArrayXd depth_m(const contact::Profile& profile, double y0_m, const contact::Grid& grid) {
  const double z0 = contact::profile_z(profile, y0_m);
  Eigen::ArrayXd d(grid.ny);
  for (int j = 0; j < grid.ny; ++j) d(j) = contact::profile_z(profile, y0_m + grid.y_m(j)) - z0;
  return d;
}
}  // namespace

Eigen::ArrayXd roller_depth_m(const contact::Profiles& profiles, double y0_m, const contact::Grid& grid) {
  return depth_m(profiles.body1, y0_m, grid);
}
Eigen::ArrayXd track_depth_m(const contact::Profiles& profiles, double y0_m, const contact::Grid& grid) {
  return depth_m(profiles.body2, y0_m, grid);
}

CreepForce creep_force(const AngleContact& c, double xi) {
  const contact::TangentialSolution sol = steady_creep(c, xi, 1.0);
  CreepForce f;
  f.force_N = sol.Fx_N;
  if (c.roller_depth_m.size() > 0) {
    const contact::ContactPatch& p = c.normal.patch;
    for (int j = 0; j < p.grid.ny; ++j) {
      if (!(p.half_length_m(j) > 0)) continue;
      f.depth_moment_N_m += sol.strip_force_x_N_per_m(j) * c.roller_depth_m(j);
      f.track_depth_moment_N_m += sol.strip_force_x_N_per_m(j) * c.track_depth_m(j);
    }
    f.depth_moment_N_m *= p.grid.dy_m;
    f.track_depth_moment_N_m *= p.grid.dy_m;
  }
  return f;
}

contact::TangentialSolution steady_creep(const AngleContact& c, double xi, double speed_m_per_s, bool fields) {
  check_cam_scheme(c.scheme);
  contact::TangentialProblem p = c.problem;
  p.creepages = {xi, 0, 0};
  p.L_m_per_Pa = contact::mean_flexibility_m_per_Pa(p.flex, p.creepages, c.normal.patch.a_m, c.normal.patch.b_m);
  p.speed_m_per_s = speed_m_per_s;
  // the contact's model (lib/model/contact_model.h): strips and totals, the fields when asked; an iterative model's
  // (the exact theory's) solve that did not converge is no result
  contact::SteadyModelSolution sol = contact::solve_tangential_steady(c.scheme, c.normal.patch, c.pair, p, fields);
  if (!sol.status.converged())
    throw std::runtime_error(fmt::format("the cam's steady {} solve at xi {:.6g} did not converge: {}",
                                         contact::to_string(c.scheme), xi, sol.status.message));
  return std::move(sol.solution);
}

double steady_creep_force_N(const AngleContact& c, double xi) { return steady_creep(c, xi, 1.0).Fx_N; }

namespace {
// the root of F(xi) = force_N in a bracket grown from [centre - width, centre + width]
CreepageForForce creepage_in_bracket(const AngleContact& c, double force_N, double centre, double width) {
  CreepageForForce r;
  const auto f = [&](double xi) {
    ++r.evaluations;
    return steady_creep_force_N(c, xi) - force_N;
  };
  // F(xi) decreases with xi: widened until the sign changes
  double lo = centre - width, hi = centre + width;
  double f_lo = f(lo), f_hi = f(hi);
  while (f_lo < 0 && lo > -kMaxCreepage) {
    lo = std::max(-kMaxCreepage, centre - (width *= 2));
    f_lo = f(lo);
  }
  while (f_hi > 0 && hi < kMaxCreepage) {
    hi = std::min(kMaxCreepage, centre + (width *= 2));
    f_hi = f(hi);
  }
  if (f_lo < 0 || f_hi > 0) return r;  // beyond the law's reach
  const contact::RootResult root = contact::find_root_bracketed(f, lo, hi, f_lo, f_hi, 0, creep_force_tolerance_N(c));
  r.xi = root.x;
  r.found = root.converged;
  return r;
}

// the law's slope -dF_t/dxi at xi -> 0: G a b C11, the relaxed model's times its factor (its creepage factor over
// the shape factor), so that the inversion's first step lands on a nearly linear law's root
double linear_stiffness_N(const AngleContact& c) {
  const double k = c.G_Pa * c.normal.patch.a_m * c.normal.patch.b_m * c.problem.C.C11;
  return k * contact::xi_slope_factor(c.scheme, c.normal.patch);
}
}  // namespace

CreepageForForce creepage_for_force(const AngleContact& c, double force_N) {
  // the exact theory's solves are dear: from the linear law's root by its slope (the guessed start's path, two
  // solves and the root between them where the law is nearly linear, as here)
  if (c.scheme == contact::TangentialScheme::Exact) return creepage_for_force(c, force_N, -force_N / linear_stiffness_N(c));
  // the linear law's xi is where to start
  const double stiffness = linear_stiffness_N(c);
  double width = std::abs(force_N) / stiffness;
  if (c.normal.patch.strip_xi_offset.size() > 0)
    width = std::max(width, c.normal.patch.strip_xi_offset.abs().maxCoeff());
  width = std::max(width, 1e-9);
  return creepage_in_bracket(c, force_N, -force_N / stiffness, width);
}

CreepageForForce creepage_for_force(const AngleContact& c, double force_N, double xi_guess) {
  if (!std::isfinite(xi_guess) || std::abs(xi_guess) >= kMaxCreepage) return creepage_for_force(c, force_N);
  // from the guess one step of the linear law's slope, then the root in the bracket they make (the law is
  // nearly linear over so small a change), else the bracket grown around the step's end
  CreepageForForce r;
  const double tol = creep_force_tolerance_N(c);
  const auto f = [&](double xi) {
    ++r.evaluations;
    return steady_creep_force_N(c, xi) - force_N;
  };
  const double x0 = xi_guess, f0 = f(x0);
  if (std::abs(f0) <= tol) {
    r.xi = x0;
    r.found = true;
    return r;
  }
  const double x1 = std::clamp(x0 + f0 / linear_stiffness_N(c), -kMaxCreepage, kMaxCreepage), f1 = f(x1);
  if (std::abs(f1) <= tol) {
    r.xi = x1;
    r.found = true;
    return r;
  }
  if ((f0 > 0) != (f1 > 0)) {
    const bool up = x0 < x1;
    const contact::RootResult root =
        contact::find_root_bracketed(f, up ? x0 : x1, up ? x1 : x0, up ? f0 : f1, up ? f1 : f0, 0, tol);
    r.xi = root.x;
    r.found = root.converged;
    return r;
  }
  const int before = r.evaluations;
  CreepageForForce grown = creepage_in_bracket(c, force_N, x1, std::max(2 * std::abs(x1 - x0), 1e-12));
  grown.evaluations += before;
  return grown;
}

}  // namespace cam
