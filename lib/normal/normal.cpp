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

// ---- the half-space on profiles (normal.h, HalfspaceOnProfiles) ----

constexpr double kLoadedRel = 1e-6;        // a cell carrying less than this of the peak counts as unloaded
constexpr double kCoarseStartLineWidths = 3;  // the coarse box's first half-length, in line-contact half-widths
constexpr int kMaxCoarseDoublings = 30;
constexpr int kMaxEnlargements = 20;

// the gap of the profiles and A x^2, measured from its minimum over the overlap, on a grid centred on y0
struct ProfileGap {
  const Profiles& profiles;
  double lo, hi, A, minimum;

  ProfileGap(const Profiles& p, double Rx1, double Rx2)
      : profiles(p), lo(std::max(p.body1.y_m(0), p.body2.y_m(0))),
        hi(std::min(p.body1.y_m(p.body1.y_m.size() - 1), p.body2.y_m(p.body2.y_m.size() - 1))),
        A((1 / Rx1 + 1 / Rx2) / 2) {
    // piecewise linear between either profile's nodes: its minimum is at one of them or an end
    minimum = std::min(across(lo), across(hi));
    for (const Profile* q : {&p.body1, &p.body2})
      for (Eigen::Index i = 0; i < q->y_m.size(); ++i)
        if (q->y_m(i) > lo && q->y_m(i) < hi) minimum = std::min(minimum, across(q->y_m(i)));
  }
  double across(double y) const { return profile_z(profiles.body1, y) + profile_z(profiles.body2, y); }
  Eigen::ArrayXXd on(const Grid& g, double y0) const {
    Eigen::ArrayXXd gap(g.nx, g.ny);
    for (int j = 0; j < g.ny; ++j) {
      const double h = across(y0 + g.y_m(j)) - minimum;
      for (int i = 0; i < g.nx; ++i) gap(i, j) = h + A * g.x_m(i) * g.x_m(i);
    }
    return gap;
  }
};

bool same_grid(const Grid& a, double a_y0, const Grid& b, double b_y0) {
  return a.nx == b.nx && a.ny == b.ny && a.half_x_m == b.half_x_m && a.half_y_m == b.half_y_m && a_y0 == b_y0;
}

// the start on (grid, y0) from a previous solve's pressure on (from, from_y0): as it is on the same grid,
// else interpolated; none without one
const Eigen::ArrayXXd* start_on(const Grid& grid, double y0, const Grid& from, double from_y0,
                                const Eigen::ArrayXXd& p, Eigen::ArrayXXd& buffer) {
  if (p.size() == 0 || from.nx < 1) return nullptr;
  if (same_grid(grid, y0, from, from_y0)) return &p;
  buffer = interpolate_pressure(p, from, from_y0, grid, y0);
  return &buffer;
}

// one solve, counted; false when it did not converge (the status says why)
bool solve_counted(const Grid& grid, const Eigen::ArrayXXd& gap, double Estar, double F,
                   const Eigen::ArrayXXd* start, HalfspaceOnProfiles& h, HalfspaceSolution& s) {
  HalfspaceOptions opt;
  opt.initial_pressure_Pa = start;
  opt.warn_at_border = false;
  s = solve_halfspace(grid, gap, Estar, F, opt);
  h.solves += 1;
  h.iterations += s.status.iterations;
  return s.status.converged();
}

void fail_unconverged(NormalSolution& n, SolveStatus status, const std::string& which) {
  n.status = std::move(status);
  n.status.message = "half-space (" + which + "): " + n.status.message;
  if (n.status.kind == SolveStatus::Kind::Failed) n.status.kind = SolveStatus::Kind::MaxIterations;
  n.solve_converged = false;
}

}  // namespace

NormalSolution solve_halfspace_on_profiles(const NormalProblem& p) {
  if (!p.profiles) throw std::invalid_argument("solve_halfspace_on_profiles: the half-space on profiles needs profiles");
  NormalSolution n;
  n.solver = NormalSolverKind::Halfspace;
  HalfspaceOnProfiles& h = n.halfspace;
  const Profiles& profiles = *p.profiles;
  const double Rx1 = p.bodies.body1.Rx_m, Rx2 = p.bodies.body2.Rx_m;
  const ProfileGap gap(profiles, Rx1, Rx2);
  const double Estar = effective_modulus_Pa(p.pair);
  const double F = p.normal_load_N;
  if (!(gap.hi > gap.lo)) throw std::invalid_argument("solve_halfspace_on_profiles: the profiles do not overlap");
  if (!(gap.A > 0) || !std::isfinite(gap.A))
    throw std::invalid_argument("solve_halfspace_on_profiles: the rolling curvature (1/Rx1 + 1/Rx2)/2 must be positive");
  const HalfspaceOnProfiles* warm = p.halfspace_start;
  Eigen::ArrayXXd buffer;

  // 1. coarse, over the whole overlap across; along x from a line contact as long as the overlap
  const double width = gap.hi - gap.lo;
  const double a_line = std::sqrt(4 * F / (2 * gap.A) / (kPi * Estar * width));
  h.coarse_y0_m = (gap.lo + gap.hi) / 2;
  HalfspaceSolution s;
  LoadedCells cells;
  double X = kCoarseStartLineWidths * a_line;
  for (int doubling = 0;; ++doubling, X *= 2) {
    h.coarse_grid = make_grid(X, width / 2, p.halfspace_coarse_grid);
    const Eigen::ArrayXXd* start =
        warm ? start_on(h.coarse_grid, h.coarse_y0_m, warm->coarse_grid, warm->coarse_y0_m, warm->coarse_pressure_Pa, buffer)
             : nullptr;
    if (!solve_counted(h.coarse_grid, gap.on(h.coarse_grid, h.coarse_y0_m), Estar, F, start, h, s)) {
      fail_unconverged(n, s.status, "coarse");
      return n;
    }
    cells = loaded_cells(s.pressure_Pa, kLoadedRel);
    if (cells.i0 > 0 && cells.i1 < h.coarse_grid.nx - 1) break;
    if (doubling == kMaxCoarseDoublings) {
      n.status = s.status;
      n.status.kind = SolveStatus::Kind::MaxIterations;
      n.status.message = fmt::format("half-space (coarse): the contact still reaches the box's ends along x at +-{:.3e} m",
                                     X);
      return n;
    }
  }
  h.coarse_pressure_Pa = std::move(s.pressure_Pa);

  // 2. fine: the coarse contact's refined extent (cells below kLoadedRel of the peak taken as unloaded),
  // one coarse cell more on every side, within the overlap: continuous in the gap
  const Grid& cg = h.coarse_grid;
  const double margin = std::max(p.halfspace_margin_cells, 0);
  double half_x = 0, w_lo = 0, w_hi = 0;
  {
    HalfspaceSolution sc;
    sc.pressure_Pa = (h.coarse_pressure_Pa > kLoadedRel * h.coarse_pressure_Pa.maxCoeff()).select(h.coarse_pressure_Pa, 0.0);
    const double carried = sc.pressure_Pa.sum() * cg.dx_m * cg.dy_m;
    half_x = halfspace_patch(sc, cg, carried).a_m + margin * cg.dx_m;
    double e_lo = 0, e_hi = 0;
    loaded_lateral_extent(sc, cg, e_lo, e_hi);
    w_lo = std::max(gap.lo, h.coarse_y0_m + e_lo - margin * cg.dy_m);
    w_hi = std::min(gap.hi, h.coarse_y0_m + e_hi + margin * cg.dy_m);
  }
  const Grid* previous = warm && warm->pressure_Pa.size() > 0 ? &warm->grid : nullptr;
  double previous_y0 = warm ? warm->grid_y0_m : 0;
  Eigen::ArrayXXd previous_p = warm ? warm->pressure_Pa : Eigen::ArrayXXd();
  Grid grid;
  double y0 = 0;
  for (int enlargement = 0;; ++enlargement) {
    grid = make_grid(half_x, (w_hi - w_lo) / 2, p.grid);
    y0 = (w_lo + w_hi) / 2;
    const Eigen::ArrayXXd* start =
        previous ? start_on(grid, y0, *previous, previous_y0, previous_p, buffer) : nullptr;
    if (!solve_counted(grid, gap.on(grid, y0), Estar, F, start, h, s)) {
      fail_unconverged(n, s.status, "fine");
      return n;
    }
    const LoadedCells c = loaded_cells(s.pressure_Pa, kLoadedRel);
    const bool x_cut = c.i0 == 0 || c.i1 == grid.nx - 1;
    const bool lo_cut = c.j0 == 0 && w_lo > gap.lo, hi_cut = c.j1 == grid.ny - 1 && w_hi < gap.hi;
    if (!x_cut && !lo_cut && !hi_cut) break;
    if (enlargement == kMaxEnlargements) {
      h.reaches_border = true;
      break;
    }
    const double grow_y = std::max(cg.dy_m, (w_hi - w_lo) / 4);
    if (x_cut) half_x += std::max(cg.dx_m, half_x / 4);
    if (lo_cut) w_lo = std::max(gap.lo, w_lo - grow_y);
    if (hi_cut) w_hi = std::min(gap.hi, w_hi + grow_y);
    previous = &h.grid;  // the next attempt starts from this one's pressures
    h.grid = grid;
    previous_y0 = y0;
    previous_p = s.pressure_Pa;
  }
  h.grid = grid;
  h.grid_y0_m = y0;

  // the patch and what the wear loop reads
  n.patch = halfspace_patch(s, grid, F);
  n.grid_y0_m = y0;
  const Eigen::ArrayXd q = s.pressure_Pa.colwise().sum().transpose() * grid.dx_m;  // strip loads (N/m)
  h.reference_y_m = y0 + (q * grid.y_m).sum() / q.sum();
  double e_lo = 0, e_hi = 0;
  loaded_lateral_extent(s, grid, e_lo, e_hi);
  h.contact_y_min_m = y0 + e_lo;
  h.contact_y_max_m = y0 + e_hi;
  if (p.semi_hertz.heathcote_slip)
    n.patch.strip_xi_offset = heathcote_xi_offset(profiles, Rx1, Rx2, y0 + grid.y_m, h.reference_y_m);
  n.patches = 0;
  for (int j = 0; j < grid.ny; ++j)
    if (n.patch.half_length_m(j) > 0 && (j == 0 || !(n.patch.half_length_m(j - 1) > 0))) ++n.patches;
  const LoadedCells c = loaded_cells(s.pressure_Pa, kLoadedRel);
  const bool at_lo = w_lo == gap.lo && c.j0 == 0, at_hi = w_hi == gap.hi && c.j1 == grid.ny - 1;
  n.reaches_edge = at_lo || at_hi;

  // the edge value (HalfspaceOnProfiles::edge_value_m): where the contact's lateral edge lies past the
  // overlap's end, extrapolated from the strip loads (linear at a contact's edge), in units of the approach
  // per half-width of the contact
  const double delta = s.approach_m;
  const double half_extent = (e_hi - e_lo) / 2;
  const auto edge_value = [&](double y_end, bool grid_reaches_it, int j_out, int j_in, double extent_m, double sign) {
    double past_m = sign * (extent_m - y_end);  // the refined extent: within the unloaded neighbour's centre
    if (grid_reaches_it && q(j_out) > 0) {      // the strip at the end is loaded: the extrapolation continued
      const double t = q(j_in) > 0 ? q(j_out) / q(j_in) : 1.0;
      const double r = t <= 0.5 ? t / (1 - t) : 1 + 4 * (t - 0.5);  // C1 in t: t/(1 - t) and its slope at 1/2
      past_m = (r - 0.5) * grid.dy_m;
    }
    return delta * past_m / half_extent;
  };
  h.edge_value_m = std::max(edge_value(gap.lo, w_lo == gap.lo, 0, 1, h.contact_y_min_m, -1.0),
                            edge_value(gap.hi, w_hi == gap.hi, grid.ny - 1, grid.ny - 2, h.contact_y_max_m, 1.0));
  h.pressure_Pa = std::move(s.pressure_Pa);

  n.status = s.status;
  n.status.iterations = h.iterations;
  n.status.message = fmt::format("{} ({} half-space solves, {} iterations in all)", s.status.message, h.solves,
                                 h.iterations);
  n.solve_converged = s.status.converged() && !h.reaches_border;
  if (h.reaches_border) {
    n.status.kind = SolveStatus::Kind::MaxIterations;
    n.status.message = fmt::format("the contact still reaches the grid's border after {} enlargements; ",
                                   kMaxEnlargements) + n.status.message;
  } else if (n.reaches_edge) {
    n.status.kind = SolveStatus::Kind::Failed;
    n.status.message = "the contact reaches a body's edge; " + n.status.message;
  }
  return n;
}


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

  if (p.choice == NormalChoice::Halfspace) {
    n = solve_halfspace_on_profiles(p);
    n.reason = "solver.normal halfspace, on a grid sized from the geometry";
    return n;
  }
  const SemiHertzResult sh = solve_semi_hertz(profiles, Rx1, Rx2, p.pair, p.normal_load_N, p.grid, p.semi_hertz);
  take_profile_result(sh, n);
  n.solve_converged = profile_solve_converged(sh, p.semi_hertz);
  n.solver = NormalSolverKind::SemiHertz;
  n.reason = p.choice == NormalChoice::Auto ? "solver.normal auto: the geometry is worn" : "solver.normal semi-hertz";
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
