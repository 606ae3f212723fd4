// Pressure fields of a strip patch. Along strip j, p = p_j sqrt(1 - u^2), u = x/a_j, so over a cell
// [xl, xr] cut to |x| < a_j:
//   integral of p dx   = p_j a_j   [S(ur) - S(ul)],  S(u) = (u sqrt(1-u^2) + asin u)/2 + pi/4,
//   integral of x p dx = p_j a_j^2 [M(ur) - M(ul)],  M(u) = -(1 - u^2)^(3/2) / 3.
#include "lib/patch.h"
#include "lib/numeric.h"

#include <algorithm>
#include <cmath>

namespace contact {

namespace {
}

double semi_ellipse_integral(double u) {
  u = std::clamp(u, -1.0, 1.0);
  return (u * std::sqrt(1 - u * u) + std::asin(u)) / 2 + kPi / 4;
}

double semi_ellipse_moment(double u) {
  u = std::clamp(u, -1.0, 1.0);
  const double w = 1 - u * u;
  return -w * std::sqrt(w) / 3;
}

void fill_strip_pressures(ContactPatch& patch) {
  const Grid& g = patch.grid;
  patch.pressure_Pa = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  patch.pressure_moment_Pa_m = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  patch.edge_pressure_Pa = Eigen::ArrayXXd::Zero(g.nx + 1, g.ny);
  Eigen::ArrayXd S(g.nx + 1), M(g.nx + 1);  // S(u), M(u) at the cell edges, u clamped to the strip
  for (int j = 0; j < g.ny; ++j) {
    const double a = patch.half_length_m(j);
    const double p = patch.strip_peak_Pa(j);
    if (!(a > 0) || !(p > 0)) continue;
    // once per edge (a cell's integrals are differences of its edges' values; a cell cut by a strip
    // end counts only the part in contact, and a cell outside it gets S(u) - S(u) = 0)
    for (int i = 0; i <= g.nx; ++i) {
      const double u = g.x_edge(i) / a;
      S(i) = semi_ellipse_integral(u);
      M(i) = semi_ellipse_moment(u);
      if (std::abs(u) < 1) patch.edge_pressure_Pa(i, j) = p * std::sqrt(1 - u * u);
    }
    for (int i = 0; i < g.nx; ++i) {
      patch.pressure_Pa(i, j) = p * a * (S(i + 1) - S(i)) / g.dx_m;
      patch.pressure_moment_Pa_m(i, j) = p * a * a * (M(i + 1) - M(i)) / g.dx_m;
    }
  }
}

}  // namespace contact
