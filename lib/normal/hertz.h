// Hertz's solution of the normal problem for two bodies with principal curvatures aligned with the
// rolling (x) and lateral (y) directions (docs/physics.md §2):
//   A = (1/Rx1 + 1/Rx2)/2,  B = (1/Ry1 + 1/Ry2)/2  (concave radius negative, infinite radius 0).
// With k = minor/major semi-axis and e^2 = 1 - k^2, e is the root of
//   (larger curvature)/(smaller curvature) = ((1/k^2) E(e) - K(e)) / (K(e) - E(e)),
//   major^3 = 3 F (K - E) / (2 pi (smaller curvature) E* e^2),
//   delta   = 3 F K / (2 pi E* major),   p0 = 3 F / (2 pi a b).
// The circular limit A = B: a^3 = 3 F R / (4 E*), delta = a^2 / R, R = 1/(2A).
#pragma once

#include <limits>

#include "lib/elastic.h"
#include "lib/patch.h"

namespace contact {

constexpr double kFlat = std::numeric_limits<double>::infinity();

struct BodyRadii {
  double Rx_m = kFlat;  // radius of curvature in the rolling plane (xz); concave negative; inf = flat
  double Ry_m = kFlat;  // radius of curvature in the lateral plane (yz)
};

struct Bodies {
  BodyRadii body1;  // upper body (the roller)
  BodyRadii body2;  // lower body (the path)
};

struct HertzContact {
  double A_per_m = 0, B_per_m = 0;  // relative curvatures along x and y
  double Estar_Pa = 0;
  double normal_load_N = 0;
  double a_m = 0, b_m = 0;  // semi-axes along x and y (either may be the larger)
  double p0_Pa = 0;
  double approach_m = 0;    // delta
  double eccentricity = 0;  // e of the ellipse (0 = circle)
};

// throws std::invalid_argument for conforming or impossible geometry (A <= 0 or B <= 0, a zero
// radius), a non-positive or non-finite load, or bad materials
HertzContact solve_hertz(const Bodies& bodies, const ElasticPair& pair, double normal_load_N);

// the Hertz ellipse sampled as strips on a given grid (which may be larger than the ellipse)
ContactPatch hertz_patch(const HertzContact& h, const Grid& grid);

// the normal problem on a grid over the ellipse's bounding box
ContactPatch solve_normal_hertz(const Bodies& bodies, const ElasticPair& pair, double normal_load_N,
                                const GridSpec& spec);

}  // namespace contact
