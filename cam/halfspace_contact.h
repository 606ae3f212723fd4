// The cam's contact at one angle on the elastic half-space (docs/cam-follower.md §16): the exact normal problem
// (lib/normal/halfspace.h, Boussinesq's influence coefficients, Polonsky and Keer) on the roller's and the
// track's lateral profiles, on a lattice of cells that does not move with the contact, so that the cam's wear
// map and the strips line up and the answer is a continuous function of the worn profiles:
//   - across (y): strips of width dy over the lateral window [y_lo, y_hi] (the life's fixed window, the
//     profiles' overlap, CreepLawSettings::fixed_grid_y_lo/hi_m; without one, the profiles' overlap with
//     dy = 2 b_H / ny), strip j centred at y_lo + (j + 1/2) dy;
//   - along (x): cells of length dx = 2 a_H / nx centred at x = +-(k + 1/2) dx, a_H Hertz's semi-axis of the
//     unworn bodies (the nominal roller and track crowns, the angle's cam radius) under the angle's load: the
//     same lattice at that angle over the whole life.
// The problem is solved on the part of that lattice where the contact can be: every loaded cell has
// h(y) + A x^2 < delta (the separation h + u - delta vanishes there and u > 0), so the window holds the strips
// with h(y_j) < bound, one more each way, bound >= the approach. Along x, where the gap is convex on every strip,
// it holds the cells with A x^2 < kHalfspaceWindowX bound and one more (Hertz's ellipse has A a^2 < delta; a cut
// shows as a loaded cell on the window's first or last row, and the window grows). It starts
// from the caller's approach (the angle's last one in a life, else Hertz's) and, where the solution's approach
// exceeds the bound or a loaded cell touches the window's border, is enlarged (bound = 1.3 x the approach) and
// solved again. Cells added outside the contact carry nothing, so the solution does not depend on the window:
// it is the lattice's (to the solver's tolerance), whatever the history of the life. Separate lobes across the
// width are one problem (the window spans every strip below the bound). The patch handed to the tangential
// solvers (halfspace_patch) lies on the loaded cells' box and one cell more each way, on the same lattice
// (symmetric in x): the exact theory's cost is its grid's.
#pragma once

#include "cam/roller_contact.h"
#include "lib/grid.h"
#include "lib/normal/normal.h"
#include "lib/normal/profile.h"

namespace cam {

struct HalfspaceAngleSettings {
  contact::GridSpec grid{40, 40};  // nx cells over the unworn contact's length 2 a_H; ny strips over 2 b_H
                                   // (without a fixed window)
  double fixed_y_lo_m = 0, fixed_y_hi_m = 0;  // the lattice's window across; both 0: the profiles' overlap
  int fixed_strips = 0;            // strips over the fixed window (> 0 with one)
  double initial_approach_m = 0;   // the first bound's approach: 0 = Hertz's
  bool heathcote_slip = true;      // the strips' Heathcote offsets (reference: the strips' load centroid)
  double tol = 1e-9;               // the half-space solver's complementarity residual
};

struct HalfspaceAngleStats {
  int solves = 0;            // half-space solves (the first and the enlargements)
  int window_nx = 0, window_ny = 0;  // the last window's cells
  int iterations = 0;        // conjugate-gradient iterations over the solves
};

// The normal solution at cam angle k under normal_load_N on `profiles` (solver Halfspace; patch on the window's
// grid, grid_y0_m its centre in the profiles' y; on_profiles.approach_m = the approach). Throws
// contact::NormalSolveError when the solve does not converge or the window cannot be made to hold the contact,
// std::invalid_argument for bad values.
contact::NormalSolution halfspace_angle_normal(const RollerAndTrack& bodies, const contact::Profiles& profiles,
                                               double roller_radius_m, double cam_radius_m, double normal_load_N,
                                               const HalfspaceAngleSettings& s, HalfspaceAngleStats* stats = nullptr);

// the window along x: A x^2 < this times the bound (a tighter box than the sure one, grown where it cuts)
constexpr double kHalfspaceWindowX = 0.6;
// the window's enlargement factor on the approach, and the most enlargements tried
constexpr double kHalfspaceWindowGrowth = 1.3;
constexpr int kHalfspaceWindowTries = 8;

}  // namespace cam
