// Pressure fields of a strip patch. Along strip j, p = p_j sqrt(1 - u^2), u = x/a_j, so over a cell
// [xl, xr] cut to |x| < a_j:
//   integral of p dx   = p_j a_j   [S(ur) - S(ul)],  S(u) = (u sqrt(1-u^2) + asin u)/2 + pi/4,
//   integral of x p dx = p_j a_j^2 [M(ur) - M(ul)],  M(u) = -(1 - u^2)^(3/2) / 3.
#include "lib/patch.h"

#include <algorithm>
#include <cmath>

namespace contact {

namespace {
constexpr double kPi = 3.14159265358979323846;
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
  for (int j = 0; j < g.ny; ++j) {
    const double a = patch.half_length_m(j);
    const double p = patch.strip_peak_Pa(j);
    if (!(a > 0) || !(p > 0)) continue;
    // cells cut by the strip ends: only the part in contact counts
    for (int i = 0; i < g.nx; ++i) {
      const double xl = std::max(g.x_edge(i), -a);
      const double xr = std::min(g.x_edge(i + 1), a);
      if (xr <= xl) continue;
      const double ul = xl / a, ur = xr / a;
      patch.pressure_Pa(i, j) = p * a * (semi_ellipse_integral(ur) - semi_ellipse_integral(ul)) / g.dx_m;
      patch.pressure_moment_Pa_m(i, j) = p * a * a * (semi_ellipse_moment(ur) - semi_ellipse_moment(ul)) / g.dx_m;
    }
    for (int i = 0; i <= g.nx; ++i) {
      const double u = g.x_edge(i) / a;
      if (std::abs(u) < 1) patch.edge_pressure_Pa(i, j) = p * std::sqrt(1 - u * u);
    }
  }
}

}  // namespace contact
