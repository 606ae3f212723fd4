#include "lib/grid.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace contact {

Grid make_grid(double half_x_m, double half_y_m, const GridSpec& spec) {
  if (spec.nx < 1 || spec.ny < 1)
    throw std::invalid_argument("grid: nx and ny must be at least 1, got " + std::to_string(spec.nx) +
                                " x " + std::to_string(spec.ny));
  if (!(half_x_m > 0) || !(half_y_m > 0) || !std::isfinite(half_x_m) || !std::isfinite(half_y_m))
    throw std::invalid_argument("grid: the bounding box must have positive finite size");
  Grid g;
  g.nx = spec.nx;
  g.ny = spec.ny;
  g.half_x_m = half_x_m;
  g.half_y_m = half_y_m;
  g.dx_m = 2 * half_x_m / spec.nx;
  g.dy_m = 2 * half_y_m / spec.ny;
  g.x_m = Eigen::ArrayXd::LinSpaced(spec.nx, -half_x_m + g.dx_m / 2, half_x_m - g.dx_m / 2);
  g.y_m = Eigen::ArrayXd::LinSpaced(spec.ny, -half_y_m + g.dy_m / 2, half_y_m - g.dy_m / 2);
  return g;
}

}  // namespace contact
