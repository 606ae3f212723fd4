// The exact normal problem on the elastic half-space (docs/physics.md §1-2): piecewise-constant pressure on
// the grid's cells, Boussinesq influence coefficients (Love's closed form for a uniformly loaded
// rectangle), solved by the bound-constrained conjugate gradient method of Polonsky & Keer (1999)
// with the total load prescribed, preconditioned by the inverse of the half-space's symbol. It is the
// reference the Hertz and semi-Hertzian solutions are checked against, and a user option for any gap
// (worn profiles).
//
// The discrete problem: find p_i >= 0 and the approach delta such that the separation
//   s_i = h_i + u_i - delta,   u_i = sum_j K_ij p_j,
// is zero at the centre of every loaded cell (p_i > 0) and non-negative elsewhere, with
// sum_i p_i dx dy = F. h is the undeformed gap at the cell centres, u the combined elastic
// displacement of both surfaces, K_ij the displacement at cell centre i from unit pressure on cell j.
//
// Convergence: the complementarity residual
//   residual = max_i |v_i| / (delta - min_i h_i),  v_i = s_i where p_i > 0,  v_i = min(s_i, 0) where p_i = 0,
// the largest gap error (open gap under load, or overlap outside the loaded cells) as a fraction of
// the rigid interference delta - min h (= delta when the gap touches zero, the scale of h and u over
// the contact). Converged when residual <= tol. The pressure returned is the one the residual was
// measured on; it is non-negative and carries F to rounding at every iteration.
#pragma once

#include <Eigen/Core>

#include "lib/grid.h"
#include "lib/patch.h"
#include "lib/solve_status.h"

namespace contact {

struct HalfspaceOptions {
  double tol = 1e-9;         // on the complementarity residual above
  int max_iterations = 2000;  // conjugate-gradient iterations (one FFT convolution each, two when many cells change)
  // warm start: the pressure to start from on this grid (nx x ny, e.g. the last solve's, or it
  // interpolated onto this grid: interpolate_pressure), its negative values taken as 0 and the rest
  // scaled to the load; null, or one that carries nothing, starts from the load spread evenly. The
  // solve converges to the same tol either way: the start changes the result only within tol.
  const Eigen::ArrayXXd* initial_pressure_Pa = nullptr;
  bool warn_at_border = true;  // false: a contact that reaches the border is data only (a caller that enlarges)
  // true: the spectral preconditioner (halfspace.cpp, docs/halfspace.md): 5 times fewer iterations on a
  // worn 80 x 80 contact, same convergence criterion; false: Polonsky & Keer's plain iteration
  bool precondition = true;
};

struct HalfspaceSolution {
  Eigen::ArrayXXd pressure_Pa;  // (nx x ny) piecewise-constant cell pressures, column j = strip j
  double approach_m = 0;        // rigid approach (penetration) delta, measured from the gap's zero
  double contact_area_m2 = 0;   // loaded cells times dx dy
  SolveStatus status;           // iterations, complementarity residual, message with the numbers
  bool reaches_border = false;  // a cell on the grid's border is loaded: the contact is cut by the grid
  int products = 0;             // FFT convolutions u = K p the solve took (the start's and the final check's included)
};

// Displacement of the surface at (x, y) relative to the centre of a dx x dy rectangle carrying unit
// uniform pressure (Love 1929), both bodies together (1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2):
//   u = (1/(pi E*)) integral over the rectangle of dA / r.
// Far from the rectangle it tends to the point load's Boussinesq displacement dx dy / (pi E* r).
double rectangle_influence_m_per_Pa(double x_m, double y_m, double dx_m, double dy_m, double Estar_Pa);

// gap_m: undeformed separation at the cell centres (nx x ny), min over the grid = 0 at first touch.
// The grid must hold the whole contact: a contact that reaches the grid's border is reported with a
// spdlog::warn (the half-space outside the grid carries no pressure).
// throws std::invalid_argument for a gap of the wrong size or with a non-finite value, E* <= 0, a
// non-positive or non-finite load, an empty grid, tol <= 0 or max_iterations < 1
HalfspaceSolution solve_halfspace(const Grid& grid, const Eigen::ArrayXXd& gap_m, double Estar_Pa,
                                  double normal_load_N, const HalfspaceOptions& opt = {});

// The pressure p on `from` (nx x ny of that grid, centred on the profiles' y from_y0_m) as a start on
// `to` (centred on to_y0_m): bilinear between cell centres, 0 beyond the outer centres of `from`.
// throws std::invalid_argument for a pressure of the wrong size
Eigen::ArrayXXd interpolate_pressure(const Eigen::ArrayXXd& p, const Grid& from, double from_y0_m, const Grid& to,
                                     double to_y0_m);

// The extent of the loaded cells (p > threshold_rel x the largest cell pressure), as cell indices:
// i0..i1 along x over all strips, j0..j1 along y. A cell that carries less than threshold_rel of the
// peak counts as unloaded: cells loaded only to the solver's tolerance do not move the extent.
// throws std::invalid_argument when no cell is loaded
struct LoadedCells {
  int i0 = 0, i1 = 0, j0 = 0, j1 = 0;
};
LoadedCells loaded_cells(const Eigen::ArrayXXd& pressure_Pa, double threshold_rel = 1e-6);

// The lateral extent of the loaded strips in the grid's y, each end refined like halfspace_patch's
// (the strip load linear in the distance to the edge): [y_lo, y_hi]. throws std::invalid_argument as
// loaded_cells
void loaded_lateral_extent(const HalfspaceSolution& s, const Grid& grid, double& y_lo_m, double& y_hi_m);

// The combined displacement of both surfaces at (x, y) (the grid's coordinates, anywhere) under the
// solution's cell pressures, by direct summation of rectangle_influence_m_per_Pa (O(nx ny); beyond 4 cell
// sizes its expansion to second order in the cell's size, within 1e-4 of each cell's share).
// throws std::invalid_argument for a pressure of the wrong size
double displacement_at_m(const HalfspaceSolution& s, const Grid& grid, double x_m, double y_m, double Estar_Pa);

// The half-space solution as strips for the tangential solvers (patch.h), each strip recentred on x = 0:
// - a_j: half of strip j's contact extent along x. The extent runs over its loaded cells (p > 0); each
//   end is refined with the semi-ellipse's square-root edge, p^2 linear in the distance to the edge,
//   through the two outermost loaded cells (clamped between the outermost loaded cell's centre and
//   the first unloaded one's), and a_j <= the grid's half-length.
// - p_j: (pi/2) p_j a_j dy equals strip j's load, sum_i p_ij dx dy, scaled by normal_load_N / (the
//   solution's load), so the strips carry exactly normal_load_N.
// - the equivalent ellipse: a = max_j a_j; b = half the lateral extent of the loaded strips, each end
//   refined like the strip ends with the strip load (linear in the distance to the edge, as for a
//   semi-ellipsoid). p0 = max_j p_j (the peak of the patch's own pressure field); approach from s.
// The pressure fields are the strips' semi-ellipses (fill_strip_pressures), not s.pressure_Pa.
// throws std::invalid_argument for a solution of the wrong size, no loaded cell, or a normal load that
// differs from the solution's load by more than 1e-6 of it
ContactPatch halfspace_patch(const HalfspaceSolution& s, const Grid& grid, double normal_load_N);

}  // namespace contact
