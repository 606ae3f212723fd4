// The cam's contact at one angle on the elastic half-space (cam/halfspace_contact.h).
#include "cam/halfspace_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "lib/normal/halfspace.h"
#include "lib/normal/hertz.h"
#include "lib/normal/semi_hertz.h"
#include "lib/numeric.h"

namespace cam {

contact::NormalSolution halfspace_angle_normal(const RollerAndTrack& bodies, const contact::Profiles& profiles,
                                               double roller_radius_m, double cam_radius_m, double normal_load_N,
                                               const HalfspaceAngleSettings& s, HalfspaceAngleStats* stats) {
  if (!(normal_load_N > 0) || !std::isfinite(normal_load_N))
    throw std::invalid_argument("halfspace_angle_normal: the normal load must be > 0");
  if (s.grid.nx < 2 || s.grid.ny < 2) throw std::invalid_argument("halfspace_angle_normal: nx, ny must be >= 2");
  const double A = (1 / roller_radius_m + 1 / cam_radius_m) / 2;
  if (!(A > 0)) throw std::invalid_argument("halfspace_angle_normal: the bodies conform along the rolling direction");
  // the unworn bodies' Hertz contact at this angle and load: the lattice's cell length, the first bound
  const contact::Bodies radii{{roller_radius_m, bodies.roller_crown_radius_m},
                              {cam_radius_m, bodies.track_crown_radius_m}};
  const contact::HertzContact hz = contact::solve_hertz(radii, bodies.pair, normal_load_N);

  // the lateral lattice: the fixed window, else the profiles' overlap in strips of 2 b_H / ny
  const double overlap_lo = std::max(profiles.body1.y_m(0), profiles.body2.y_m(0));
  const double overlap_hi = std::min(profiles.body1.y_m(profiles.body1.y_m.size() - 1),
                                     profiles.body2.y_m(profiles.body2.y_m.size() - 1));
  const bool fixed = s.fixed_y_hi_m > s.fixed_y_lo_m;
  const double lo = fixed ? s.fixed_y_lo_m : overlap_lo;
  const double hi = fixed ? s.fixed_y_hi_m : overlap_hi;
  int strips = 0;
  double dy = 0;
  if (fixed) {
    if (s.fixed_strips < 2) throw std::invalid_argument("halfspace_angle_normal: a fixed window needs >= 2 strips");
    strips = s.fixed_strips;
    dy = (hi - lo) / strips;
  } else {
    dy = 2 * hz.b_m / s.grid.ny;
    strips = static_cast<int>(std::floor((hi - lo) / dy));
    if (strips < 2) throw std::invalid_argument("halfspace_angle_normal: the profiles' overlap is narrower than 2 strips");
  }
  if (lo < overlap_lo - 1e-12 || hi > overlap_hi + 1e-12)
    throw std::invalid_argument("halfspace_angle_normal: the fixed window lies outside the profiles' overlap");
  // the lateral gap at the strips' centres, zero at its minimum over the lattice
  Eigen::ArrayXd h(strips);
  for (int j = 0; j < strips; ++j) {
    const double y = lo + (j + 0.5) * dy;
    h(j) = contact::profile_z(profiles.body1, y) + contact::profile_z(profiles.body2, y);
  }
  h -= h.minCoeff();
  const double dx = 2 * hz.a_m / s.grid.nx;
  const double Estar = contact::effective_modulus_Pa(bodies.pair);

  double bound = (s.initial_approach_m > 0 ? s.initial_approach_m : hz.approach_m) * 1.1;
  contact::HalfspaceOptions opt;
  opt.tol = s.tol;
  for (int attempt = 1; attempt <= kHalfspaceWindowTries; ++attempt) {
    // the window: every strip with h < bound (and the strips between), every cell with A x^2 < bound, one more each way
    int jmin = strips, jmax = -1;
    for (int j = 0; j < strips; ++j)
      if (h(j) < bound) {
        jmin = std::min(jmin, j);
        jmax = j;
      }
    const int j0 = std::max(0, jmin - 1), j1 = std::min(strips - 1, jmax + 1);
    const int ny = j1 - j0 + 1;
    const int half_nx = static_cast<int>(std::ceil(std::sqrt(kHalfspaceWindowX * bound / A) / dx)) + 1;
    const contact::Grid g = contact::make_grid(half_nx * dx, ny * dy / 2, {2 * half_nx, ny});
    Eigen::ArrayXXd gap(g.nx, g.ny);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < g.nx; ++i) gap(i, j) = h(j0 + j) + A * g.x_m(i) * g.x_m(i);
    const contact::HalfspaceSolution hs = contact::solve_halfspace(g, gap, Estar, normal_load_N, opt);
    if (stats) {
      ++stats->solves;
      stats->window_nx = g.nx;
      stats->window_ny = g.ny;
      stats->iterations += hs.status.iterations;
    }
    if (!hs.status.converged())
      throw contact::NormalSolveError(fmt::format("the cam's half-space contact did not converge ({} x {} cells): {}",
                                                  g.nx, g.ny, hs.status.message));
    // the contact lies where h + A x^2 < delta: inside the window when delta <= bound; else (or cut by the
    // window's border) the window grows
    const bool cut_by_lattice_end = (j0 == 0 && hs.pressure_Pa.col(0).maxCoeff() > 0) ||
                                    (j1 == strips - 1 && hs.pressure_Pa.col(ny - 1).maxCoeff() > 0);
    const bool x_border = hs.pressure_Pa.row(0).maxCoeff() > 0 || hs.pressure_Pa.row(g.nx - 1).maxCoeff() > 0;
    const bool y_border = (j0 > 0 && hs.pressure_Pa.col(0).maxCoeff() > 0) ||
                          (j1 < strips - 1 && hs.pressure_Pa.col(ny - 1).maxCoeff() > 0);
    if (hs.approach_m > bound || x_border || y_border) {
      bound = std::max(bound, hs.approach_m) * kHalfspaceWindowGrowth;
      continue;
    }
    // the patch on the loaded cells' box and one cell more each way (symmetric in x, on the same lattice): the
    // tangential solvers' grid, no larger than the contact needs
    int i_lo = g.nx, i_hi = -1, c_lo = ny, c_hi = -1;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < g.nx; ++i)
        if (hs.pressure_Pa(i, j) > 0) {
          i_lo = std::min(i_lo, i);
          i_hi = std::max(i_hi, i);
          c_lo = std::min(c_lo, j);
          c_hi = std::max(c_hi, j);
        }
    if (i_hi < 0) throw contact::NormalSolveError("the cam's half-space contact: no cell carries the load");
    const int keep_half = std::min(half_nx, std::max(half_nx - i_lo, i_hi + 1 - half_nx) + 1);
    c_lo = std::max(0, c_lo - 1);
    c_hi = std::min(ny - 1, c_hi + 1);
    const int cny = c_hi - c_lo + 1;
    const contact::Grid cg = contact::make_grid(keep_half * dx, cny * dy / 2, {2 * keep_half, cny});
    contact::HalfspaceSolution crop = hs;
    crop.pressure_Pa = hs.pressure_Pa.block(half_nx - keep_half, c_lo, 2 * keep_half, cny);
    spdlog::debug("cam half-space: window {} x {} cells (attempt {}), patch {} x {}, {} iterations, approach {:.4e} m",
                  g.nx, g.ny, attempt, cg.nx, cg.ny, hs.status.iterations, hs.approach_m);
    contact::NormalSolution n;
    n.solver = contact::NormalSolverKind::Halfspace;
    n.reason = "cam: the half-space on the angle's fixed lattice";
    n.patch = contact::halfspace_patch(crop, cg, normal_load_N);
    n.grid_y0_m = lo + (j0 + c_lo + 0.5 * cny) * dy;
    // the strips' loads: their centroid is the Heathcote offsets' reference, their extent the contact's
    double load = 0, moment = 0, y_min = 0, y_max = 0;
    bool any = false;
    n.patches = 0;
    for (int j = 0; j < cny; ++j) {
      const bool loaded = n.patch.half_length_m(j) > 0;
      if (loaded && (j == 0 || !(n.patch.half_length_m(j - 1) > 0))) ++n.patches;
      if (!loaded) continue;
      const double y = n.grid_y0_m + cg.y_m(j);
      const double Lj = crop.pressure_Pa.col(j).sum();
      load += Lj;
      moment += Lj * y;
      if (!any) y_min = y - dy / 2;
      y_max = y + dy / 2;
      any = true;
    }
    const double reference = load > 0 ? moment / load : n.grid_y0_m;
    if (s.heathcote_slip)
      n.patch.strip_xi_offset =
          contact::heathcote_xi_offset(profiles, roller_radius_m, cam_radius_m, n.grid_y0_m + cg.y_m, reference);
    n.on_profiles.approach_m = hs.approach_m;
    n.on_profiles.reference_y_m = reference;
    n.on_profiles.contact_y_min_m = y_min;
    n.on_profiles.contact_y_max_m = y_max;
    n.on_profiles.grid_y0_m = n.grid_y0_m;
    n.on_profiles.patches = n.patches;
    n.on_profiles.solver = contact::NormalSolverKind::Halfspace;
    n.status = hs.status;
    n.solve_converged = true;
    n.reaches_edge = cut_by_lattice_end;  // the window is the profiles' overlap: a body's edge
    if (n.reaches_edge) {
      n.status.kind = contact::SolveStatus::Kind::Failed;
      n.status.message = "the contact reaches the end of the lateral window; " + n.status.message;
    }
    return n;
  }
  throw contact::NormalSolveError(fmt::format("the cam's half-space contact: the window did not hold the contact after "
                                              "{} enlargements (approach bound {:.4g} m)",
                                              kHalfspaceWindowTries, bound));
}

}  // namespace cam
