// Rolling-contact fatigue indicators of one steady contact (docs/subsurface.md §4): where the load stands on
// Johnson's shakedown map, and the surface fatigue index of Ekberg, Kabo and Andersson, whole and per cell.
// They need the shear yield stress k of the body (bodies.bodyN.shear_yield_Pa); without it there are none.
//
// Shakedown map (elastic-perfectly plastic, repeated rolling; Johnson, Contact Mechanics, ch. 9): the load
// factor p0/k stays inside shakedown below
//   p0/k = min(S, 1/f),  S = 4.0 for a line contact, 4.7 for a circular one (the subsurface limit),
// 1/f the surface limit, f = |(Fx, Fy)|/Fz the traction coefficient. The surface fatigue index is the
// distance beyond the surface limit, FI_surf = f - 2 pi a b k/(3 Fz) (= f - k/p0 on Hertz's ellipse), and per
// cell (|tau| - k)/p: positive where a cell's traction exceeds k.
#pragma once

#include <Eigen/Core>

#include "lib/patch.h"
#include "lib/tangential/tangential.h"

namespace contact {

enum class ShakedownContact { Line, Point };
const char* to_string(ShakedownContact c);

constexpr double kLineShakedownP0OverK = 4.0;   // Johnson: line contact, subsurface limit
constexpr double kPointShakedownP0OverK = 4.7;  // Ponter, Hearle and Johnson (1985): circular contact
// a contact whose semi-axes' ratio min/max is at least this takes the circular contact's limit, any longer
// one the line contact's (the lower, so the map errs on the safe side between them)
constexpr double kPointContactAspect = 0.5;
// the range of bodies.bodyN.shear_yield_Pa (k): soft steels' 100 MPa to hardened bearing steels' ~1.2 GPa,
// with room on both sides
constexpr double kShearYieldMin_Pa = 1e6, kShearYieldMax_Pa = 5e9;

ShakedownContact shakedown_contact_of(double a_m, double b_m);
// the shakedown limit of p0/k at traction coefficient f >= 0
double shakedown_limit_p0_over_k(ShakedownContact c, double traction_coefficient);

struct FatigueIndicators {
  double shear_yield_Pa = 0;        // k
  ShakedownContact contact = ShakedownContact::Point;
  double traction_coefficient = 0;  // f = |(Fx, Fy)| / Fz
  double p0_over_k = 0;             // the load factor
  double limit_p0_over_k = 0;       // the shakedown limit at f
  bool surface_limit = false;       // the limit is the surface's (1/f below the subsurface's)
  double margin = 0;                // limit / (p0/k) - 1: > 0 inside shakedown, < 0 beyond it
  double FI_surf = 0;               // f - 2 pi a b k / (3 Fz): > 0 beyond the surface limit
  Eigen::ArrayXXd cell_index;       // (nx x ny) (|tau| - k)/p in loaded cells, NaN outside the contact
  double cell_index_max = 0;        // its largest value over the loaded cells, and where
  double cell_x_m = 0, cell_y_m = 0;
};

// throws std::invalid_argument for k outside [kShearYieldMin_Pa, kShearYieldMax_Pa] or a patch without load
FatigueIndicators fatigue_indicators(const ContactPatch& patch, const TangentialSolution& solution,
                                     double shear_yield_Pa);

}  // namespace contact
