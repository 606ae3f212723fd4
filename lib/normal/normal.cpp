// The one choice of the normal solver (normal.h).
#include "lib/normal/normal.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "lib/errors.h"
#include "lib/normal/halfspace.h"
#include "lib/numeric.h"

namespace contact {

namespace {

constexpr double kBoxMargin = 1.25;  // the half-space grid: the semi-Hertzian contact's box enlarged by 25 %

void take_profile_result(const SemiHertzResult& r, NormalSolution& n) {
  n.patch = r.patch;
  n.patches = r.patches;
  n.reaches_edge = r.reaches_edge;
  n.grid_y0_m = r.grid_y0_m;
  n.status = r.status;
  n.on_profiles = r;
}

// the semi-Hertzian (or Hertzian) solve converged: its load residual within load_rtol, at an edge too
// (status Failed there says only that the contact is cut)
bool profile_solve_converged(const SemiHertzResult& r, const SemiHertzOptions& options) {
  if (r.solver == NormalSolverKind::Hertz) return r.status.converged();
  return r.status.kind != SolveStatus::Kind::MaxIterations && r.status.residual <= options.load_rtol;
}

// the half-space solver on the semi-Hertzian contact's box enlarged by 25 %, within the profiles' overlap
void solve_on_halfspace(const NormalProblem& p, const SemiHertzResult& sh, NormalSolution& n) {
  const Profiles& profiles = *p.profiles;
  const double Rx1 = p.bodies.body1.Rx_m, Rx2 = p.bodies.body2.Rx_m;
  const double lo = std::max(profiles.body1.y_m(0), profiles.body2.y_m(0));
  const double hi = std::min(profiles.body1.y_m(profiles.body1.y_m.size() - 1),
                             profiles.body2.y_m(profiles.body2.y_m.size() - 1));
  const double centre = (sh.contact_y_min_m + sh.contact_y_max_m) / 2;
  const double half_y = std::min({kBoxMargin * (sh.contact_y_max_m - sh.contact_y_min_m) / 2, centre - lo, hi - centre});
  const Grid grid = make_grid(kBoxMargin * sh.patch.grid.half_x_m, half_y, p.grid);

  // gap: the profiles across, A x^2 along, zero at its minimum
  const double A = (1 / Rx1 + 1 / Rx2) / 2;
  Eigen::ArrayXXd gap(grid.nx, grid.ny);
  for (int j = 0; j < grid.ny; ++j) {
    const double y = centre + grid.y_m(j);
    const double h = profile_z(profiles.body1, y) + profile_z(profiles.body2, y);
    for (int i = 0; i < grid.nx; ++i) gap(i, j) = h + A * grid.x_m(i) * grid.x_m(i);
  }
  gap -= gap.minCoeff();

  const HalfspaceSolution s = solve_halfspace(grid, gap, effective_modulus_Pa(p.pair), p.normal_load_N);
  n.patch = halfspace_patch(s, grid, p.normal_load_N);
  n.grid_y0_m = centre;
  n.on_profiles = sh;
  if (p.semi_hertz.heathcote_slip)
    n.patch.strip_xi_offset = heathcote_xi_offset(profiles, Rx1, Rx2, centre + grid.y_m, sh.reference_y_m);
  // patches: runs of strips in contact; the edge: the semi-Hertzian contact's, or a loaded end strip of a cut box
  n.patches = 0;
  for (int j = 0; j < grid.ny; ++j)
    if (n.patch.half_length_m(j) > 0 && (j == 0 || !(n.patch.half_length_m(j - 1) > 0))) ++n.patches;
  const bool cut = half_y < kBoxMargin * (sh.contact_y_max_m - sh.contact_y_min_m) / 2;
  n.reaches_edge = sh.reaches_edge || (cut && (n.patch.half_length_m(0) > 0 || n.patch.half_length_m(grid.ny - 1) > 0));
  // Failed is for geometry that cannot carry the load (a body narrower than the contact); the
  // half-space's own Failed (a search direction lost, a non-finite residual) is a solve that did not
  // converge
  n.status = s.status;
  n.solve_converged = s.status.converged();
  if (n.status.kind == SolveStatus::Kind::Failed) n.status.kind = SolveStatus::Kind::MaxIterations;
  if (n.reaches_edge) {
    n.status.kind = SolveStatus::Kind::Failed;
    n.status.message = "the contact reaches a body's edge; " + n.status.message;
  }
}

}  // namespace

NormalChoice parse_normal_choice(const std::string& name) {
  if (const std::optional<NormalChoice> c = enum_from_name(kNormalChoiceNames, name)) return *c;
  throw std::invalid_argument("unknown normal solver '" + clipped(name) + "' (valid: " +
                              enum_names_list(kNormalChoiceNames) + ")");
}

const char* to_string(NormalChoice c) { return enum_name(kNormalChoiceNames, c); }

NormalSolution solve_normal(const NormalProblem& p) {
  NormalSolution n;
  const std::string choice = to_string(p.choice);

  // no profiles: Hertz from the four radii
  if (!p.profiles) {
    if (p.choice == NormalChoice::SemiHertz || p.choice == NormalChoice::Halfspace)
      throw NormalChoiceError("the " + choice + " solver works on lateral profiles; give profiles (or normal: auto)");
    n.patch = solve_normal_hertz(p.bodies, p.pair, p.normal_load_N, p.grid);
    n.solver = NormalSolverKind::Hertz;
    n.reason = "solver.normal " + choice + ", no profiles: Hertz from the radii";
    n.status.kind = SolveStatus::Kind::Converged;
    n.status.message = "Hertz's closed form";
    n.solve_converged = true;
    return n;
  }

  const Profiles& profiles = *p.profiles;
  const double Rx1 = p.bodies.body1.Rx_m, Rx2 = p.bodies.body2.Rx_m;
  if (p.choice == NormalChoice::Hertz || (p.choice == NormalChoice::Auto && !p.worn)) {
    // Hertz's closed form on constant curvature, else the semi-Hertzian solver
    const SemiHertzResult r =
        solve_normal_on_profiles(profiles, Rx1, Rx2, p.pair, p.normal_load_N, p.grid, p.semi_hertz, p.curvature_rtol);
    if (p.choice == NormalChoice::Hertz && r.solver != NormalSolverKind::Hertz)
      throw NormalChoiceError("Hertz needs profiles of constant curvature whose ellipse fits inside their overlap; "
                              "use normal: auto, semi-hertz or halfspace");
    take_profile_result(r, n);
    n.solve_converged = profile_solve_converged(r, p.semi_hertz);
    n.solver = r.solver;
    n.reason = p.choice == NormalChoice::Hertz     ? "solver.normal hertz, profiles of constant curvature"
               : r.solver == NormalSolverKind::Hertz ? "solver.normal auto: both profiles have constant curvature"
                                                     : "solver.normal auto: the profiles are not of constant curvature";
    return n;
  }

  const SemiHertzResult sh = solve_semi_hertz(profiles, Rx1, Rx2, p.pair, p.normal_load_N, p.grid, p.semi_hertz);
  if (p.choice != NormalChoice::Halfspace) {
    take_profile_result(sh, n);
    n.solve_converged = profile_solve_converged(sh, p.semi_hertz);
    n.solver = NormalSolverKind::SemiHertz;
    n.reason = p.choice == NormalChoice::Auto ? "solver.normal auto: the geometry is worn" : "solver.normal semi-hertz";
    return n;
  }
  if (sh.status.kind == SolveStatus::Kind::MaxIterations) {  // no box to put the half-space on
    n.on_profiles = sh;
    n.status = sh.status;
    n.solver = NormalSolverKind::Halfspace;
    return n;
  }
  solve_on_halfspace(p, sh, n);
  n.solver = NormalSolverKind::Halfspace;
  n.reason = "solver.normal halfspace, on the semi-Hertzian contact's box enlarged by 25 %";
  return n;
}

NormalSolution solve_normal_converged(const NormalProblem& problem) {
  NormalSolution n = solve_normal(problem);
  // an unconverged solve is no result, at a body's edge too; a converged contact cut at the edge is
  // reported with the patch (reaches_edge)
  if (!n.solve_converged)
    throw NormalSolveError(fmt::format("the normal problem ({}) did not converge: {}", to_string(n.solver),
                                       n.status.message));
  return n;
}

}  // namespace contact
