// The one Cartesian grid of a contact (docs/physics.md §1): nx x ny uniform cells over a bounding box
// centred on the contact. Cell i (along x) spans [x_edge(i), x_edge(i+1)]; strip j is the grid row
// at fixed y_j. Rolling runs from the leading edge x = +half_x to the trailing edge x = -half_x.
#pragma once

#include <Eigen/Core>

namespace contact {

struct GridSpec {
  int nx = 80;  // cells along x (rolling)
  int ny = 80;  // cells along y (lateral) = number of strips
};

struct Grid {
  int nx = 0, ny = 0;
  double half_x_m = 0, half_y_m = 0;  // bounding box [-half_x, half_x] x [-half_y, half_y]
  double dx_m = 0, dy_m = 0;
  Eigen::ArrayXd x_m;  // (nx) cell centres, increasing
  Eigen::ArrayXd y_m;  // (ny) cell centres = strip positions, increasing

  double x_edge(int i) const { return -half_x_m + i * dx_m; }  // i in [0, nx]
  double y_edge(int j) const { return -half_y_m + j * dy_m; }  // j in [0, ny]
};

// throws std::invalid_argument for non-positive sizes or counts
Grid make_grid(double half_x_m, double half_y_m, const GridSpec& spec);

}  // namespace contact
