// The solution of a normal problem as the tangential solvers consume it: strips with a
// semi-elliptic pressure along x (Hertz and the semi-Hertzian methods alike, docs/physics.md §2),
//   p(x, y_j) = p_j sqrt(1 - (x/a_j)^2)   for |x| < a_j,
// sampled on one Cartesian grid. The strip ends +-a_j are exact and cut the end cells; the
// tangential solvers use them. Each strip carries the load of its whole cell row exactly, so the
// pressure field integrates to the normal load (up to rounding).
#pragma once

#include <Eigen/Core>

#include "lib/grid.h"

namespace contact {

struct ContactPatch {
  double a_m = 0, b_m = 0;     // semi-axes of the (equivalent) ellipse: a along rolling x, b lateral y;
                               // Kalker's coefficients and flexibilities are taken from them
  double p0_Pa = 0;            // peak pressure
  double normal_load_N = 0;
  double approach_m = 0;       // approach of distant points (penetration)
  Grid grid;                   // Cartesian cell centres x_m (nx), y_m (ny)
  Eigen::ArrayXd half_length_m;  // (ny) a_j: strip j covers |x| < a_j; 0 = strip out of contact
  Eigen::ArrayXd strip_peak_Pa;  // (ny) p_j, the peak of strip j's semi-ellipse
  Eigen::ArrayXXd pressure_Pa;   // (nx x ny) mean over each full cell, 0 outside; column j = strip j
  Eigen::ArrayXXd pressure_moment_Pa_m;  // (nx x ny) mean over each full cell of x p (first moment)
  Eigen::ArrayXXd edge_pressure_Pa;  // (nx+1 x ny) p at the cell edges x_edge(i), 0 outside
  Eigen::ArrayXd strip_xi_offset;  // (ny) Heathcote slip: xi(y_j) = xi + offset_j from the rolling
                                   // radii varying across profiled bodies (docs/physics.md §2); empty = none
};

// Fills the pressure fields of a patch from its strips (grid, half_length_m, strip_peak_Pa set).
void fill_strip_pressures(ContactPatch& patch);

// Integral of sqrt(1 - u^2) from -1 to u, for u in [-1, 1] (clamped outside).
double semi_ellipse_integral(double u);
// Integral of u sqrt(1 - u^2) from -1 to u, for u in [-1, 1] (clamped outside).
double semi_ellipse_moment(double u);

}  // namespace contact
