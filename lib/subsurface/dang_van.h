// Dang Van's multiaxial fatigue criterion over one rolling pass (docs/subsurface.md §5). In steady rolling the
// field below the contact travels with it, so the stress history of a material point at lateral position y and
// depth z over one pass is the field along x at (y, z), preceded and followed by the unloaded state (the point
// far ahead of and far behind the contact). Per point:
//   s(t)   the deviator of sigma(t),
//   s*     the shakedown shift of the deviatoric path: the centre of the smallest hypersphere enclosing it in
//          the norm sqrt(s:s) (smallest_enclosing_centre below),
//   tau(t) the mesoscopic shear stress, Tresca's (s1 - s3)/2 of s(t) - s*,
//   p_h(t) the hydrostatic stress tr(sigma(t))/3, tension positive,
//   index  max over t of (tau(t) + a p_h(t)) / b:  >= 1 predicts fatigue crack initiation at that point.
// The constants a (dimensionless) and b (Pa) are the material's: from its fully reversed torsion and bending
// fatigue limits tau_w and sigma_w, b = tau_w and a = 3 tau_w / sigma_w - 3/2 (the criterion met exactly in
// both tests).
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

#include "lib/grid.h"
#include "lib/subsurface/rectangle_stress.h"
#include "lib/subsurface/subsurface.h"

namespace contact {

struct DangVanConstants {
  double a = 0;     // sensitivity to the hydrostatic stress, [kDangVanAMin, kDangVanAMax]
  double b_Pa = 0;  // the fatigue limit in fully reversed torsion, [kDangVanBMin_Pa, kDangVanBMax_Pa]
};
// the ranges the case file and the library accept: a from 0 (no hydrostatic sensitivity) to 2 (beyond any
// steel's ~0.2-0.6), b from 1 MPa to 5 GPa (torsion fatigue limits of steels lie at 0.1-0.8 GPa)
constexpr double kDangVanAMin = 0, kDangVanAMax = 2;
constexpr double kDangVanBMin_Pa = 1e6, kDangVanBMax_Pa = 5e9;

// The centre of the smallest ball enclosing the points (Euclidean), by Frank and Wolfe's method with away steps
// on the dual (E. A. Yildirim, "Two algorithms for the minimum enclosing ball problem", SIAM J. Optim. 19 (2008)
// 1368-1391): stops when the farthest point's squared distance is within (1 + tolerance) of the dual bound,
// so the radius is within tolerance/2 of the smallest and the centre within sqrt(tolerance) radii of its.
// A smooth path touches its ball tangentially, its neighbouring samples nearly on the sphere, which slows the
// method: kSmallestBallTolerance = 1e-4 (centre within 1e-2 radii at worst) takes at most 12 062 iterations on
// the rolling line contact's 41 x 41 x 31 histories, 1e-5 up to 29 383. Throws std::invalid_argument for no
// points, std::runtime_error when kSmallestBallIterations do not reach the tolerance. iterations (optional):
// the iterations taken.
constexpr double kSmallestBallTolerance = 1e-4;
constexpr int kSmallestBallIterations = 100000;
std::array<double, 6> smallest_enclosing_centre(const std::vector<std::array<double, 6>>& points, double tolerance,
                                                int* iterations = nullptr);

// one material point's history (any order; the unloaded state is not added here)
struct DangVanPoint {
  double index = 0;           // max over t of (tau + a p_h) / b
  int step = -1;              // the history's entry where it is reached
  double tau_Pa = 0;          // tau and p_h there
  double hydrostatic_Pa = 0;
  StressTensor shift;         // s*, the deviatoric centre of the path (traceless)
};
// throws std::invalid_argument for constants out of range or an empty history
DangVanPoint dang_van_of_history(const std::vector<StressTensor>& history, const DangVanConstants& k);

// Over a contact's planes (lib/subsurface/subsurface.h): every strip j and plane depth z_k is a material point
// whose history is the unloaded state followed by the field at (x_i, y_j, z_k), i = 0 ... nx - 1.
struct DangVanField {
  DangVanConstants constants;
  Eigen::ArrayXXd index;      // (ny x planes): the index of the material point at (y_j, z_k)
  double index_max = 0;       // the largest, and where: the point's y and depth, and the x at which its
  double x_m = 0, y_m = 0, z_m = 0;  // history reaches the maximum (the grid's coordinates)
  double tau_Pa = 0, hydrostatic_Pa = 0;  // tau and p_h there
};
// throws std::invalid_argument for constants out of range, no planes or planes not on the grid
DangVanField dang_van_field(const Subsurface& s, const Grid& grid, const DangVanConstants& k);

}  // namespace contact
