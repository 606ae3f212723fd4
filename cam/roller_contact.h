// The contact between the roller and the cam at one cam angle (docs/cam-follower.md §4): the normal
// problem between the roller (R_r along the rolling direction, its crown across) and the cam (its local
// radius of curvature rho_cam along, its track flat or crowned across), solved by lib/normal/normal.h on
// the lateral profiles (solver.normal auto: Hertz's closed form on these profiles of constant curvature);
// then the roller's creepage from the tangential load the loads ask for: while it rolls, Kalker's linear
// law xi = -F_t/(G a b C11) (F_t along the pitch tangent t; the sign makes xi > 0 a roller lagging the
// cam, driven forward by the creep force, docs/physics.md §1), valid while |F_t| is small against mu F_n
// (the linear range, flagged by linear_range); when it slides xi is not defined by a steady law (the
// roller's own dynamics decides its slip) and is NaN.
#pragma once

#include "cam/kinematics.h"
#include "cam/loads.h"
#include "lib/elastic.h"
#include "lib/normal/normal.h"
#include "lib/normal/profile.h"

namespace cam {

struct RollerAndTrack {
  double roller_width_m = 0;
  double roller_crown_radius_m = 0;  // > 0; inf for a cylindrical roller (then the track must be crowned)
  double track_width_m = 0;
  double track_crown_radius_m = 0;   // > 0 crowned, inf flat
  contact::ElasticPair pair;         // body1 the roller, body2 the cam
};

// the lateral profiles the normal problem works on (roller: body1, track: body2); throws
// std::invalid_argument for a flat roller on a flat track (a line contact: not a Hertz point contact)
contact::Profiles roller_and_track_profiles(const RollerAndTrack& r);

// the linear range: |F_t| <= this fraction of mu F_n, a chosen bound. (By the Johnson-Vermeulen cubic,
// F = F_lin (1 - F_lin/(3 mu F_n)) to first order, the linear creepage would be some 10 % low at 0.3;
// the steady creep law beyond it comes with the roller's dynamics.)
constexpr double kLinearRangeFraction = 0.3;

struct RollerContact {
  contact::NormalSolverKind solver = contact::NormalSolverKind::Hertz;
  double a_m = 0, b_m = 0;  // along the rolling direction, across
  double p0_Pa = 0;
  double approach_m = 0;
  double C11 = 0;
  double xi = 0;              // NaN while sliding
  bool linear_range = true;   // |F_t| <= kLinearRangeFraction mu F_n
  bool reaches_edge = false;  // the contact reaches a body's edge (the roller's or the track's width)
};

// Throws std::runtime_error when the normal solve does not converge,
// std::invalid_argument for a load <= 0 or geometry the solvers refuse.
RollerContact roller_contact(const RollerAndTrack& r, const contact::Profiles& profiles, double roller_radius_m,
                             const CamKinematics& k, const CamLoads& loads, double mu);

}  // namespace cam
