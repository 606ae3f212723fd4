// The normal problem, chosen in one place (docs/physics.md §2, docs/semi-hertz.md, docs/halfspace.md):
//   Hertz       from the four radii (no profiles), or on profiles of constant curvature whose ellipse
//               fits inside their overlap (Hertz's closed form with the fitted radii);
//   semi-Hertz  on any lateral profiles (lib/normal/semi_hertz.h);
//   half-space  the exact solver (halfspace.h) on a grid sized from the geometry alone, the gap built
//               here from the profiles across and A x^2 along (solve_halfspace_on_profiles below).
// NormalChoice::Auto: Hertz without profiles; with profiles Hertz's closed form while they have
// constant curvature and are unworn, else semi-Hertz. Once worn, never back to Hertz: the switch is a
// jump in the wear rate of up to 6.4e-4 (docs/semi-hertz.md), which the step control would meet at
// every crossing. Which solver ran is NormalSolution::solver.
#pragma once

#include <Eigen/Core>

#include <stdexcept>
#include <string>

#include "lib/elastic.h"
#include "lib/grid.h"
#include "lib/enum_names.h"
#include "lib/normal/hertz.h"
#include "lib/normal/profile.h"
#include "lib/normal/semi_hertz.h"
#include "lib/normal/solver_kind.h"
#include "lib/patch.h"
#include "lib/solve_status.h"

namespace contact {

// solver.normal of a case
enum class NormalChoice { Auto, Hertz, SemiHertz, Halfspace };

// its names, in the order messages list them
constexpr EnumTable<NormalChoice, 4> kNormalChoiceNames = {{{NormalChoice::Auto, "auto"},
                                                            {NormalChoice::Hertz, "hertz"},
                                                            {NormalChoice::SemiHertz, "semi-hertz"},
                                                            {NormalChoice::Halfspace, "halfspace"}}};

// "auto" | "hertz" | "semi-hertz" | "halfspace"; throws std::invalid_argument naming the valid ones for
// anything else
NormalChoice parse_normal_choice(const std::string& name);
const char* to_string(NormalChoice c);

// profiles of constant curvature within this (relative) tolerance are treated by Hertz
constexpr double kConstantCurvatureRtol = 1e-3;

// The half-space on profiles (NormalChoice::Halfspace), a deterministic function of the gap, the load and
// the materials (the problem is convex, so the answer does not depend on where a solve starts):
//  1. coarse: kHalfspaceCoarseGrid cells over the profiles' whole overlap across, and +-X along, X from
//     3 times the half-width of a line contact as long as the overlap (no contact is narrower along x),
//     doubled while loaded cells touch the x border; its loaded cells (more than 1e-6 of the peak) say
//     where the load is, every lobe of it;
//  2. fine: the case's nx x ny over the coarse contact's extent (its ends refined as halfspace_patch's,
//     cells below 1e-6 of the peak taken as unloaded) and one coarse cell more on every side, inside the
//     overlap: a box continuous in the gap, so the wear rate is too (up to cells entering the contact);
//     enlarged by a quarter (at least a coarse cell) on each side whose loaded cells touch the border
//     (along y towards the overlap's ends, never past them) and solved again.
// The gap is measured from its minimum over the overlap, so the approach is too. Each solve may start
// from the pressures of a previous one (halfspace_start): on the same grid as they are, else
// interpolated; converged to the same tol, so the start changes the result only within tol.
struct HalfspaceOnProfiles {
  Grid coarse_grid;                   // over the profiles' overlap across, centred on coarse_y0_m
  double coarse_y0_m = 0;
  Eigen::ArrayXXd coarse_pressure_Pa;
  Grid grid;                          // the final grid (the patch's), centred on grid_y0_m (profiles' y)
  double grid_y0_m = 0;
  Eigen::ArrayXXd pressure_Pa;        // its cell pressures
  double contact_y_min_m = 0, contact_y_max_m = 0;  // lateral extent (profiles' y), ends refined (halfspace.h)
  double reference_y_m = 0;           // the strip loads' centroid: where the Heathcote offset vanishes
  bool reaches_border = false;        // loaded cells still touch a border of the final grid that is not an
                                      // end of the overlap (the enlargements ran out): not converged
  // The edge limit as a continuous function of the gap (m): at each end y_e of the overlap, how far the
  // contact's lateral edge y_c lies past it, f_e = delta (y_c - y_e) / b_c (outwards positive; b_c half the
  // contact's lateral extent), the value max(f_lo, f_hi). y_c is extrapolated from the strip loads, linear in
  // the distance to a contact's edge: inside, the refined extent (contact_y_min_m, contact_y_max_m); once the
  // strip at the end is loaded, y_c = y_out + (r - 1/2) dy past the end, r = t/(1 - t) (t = q_out/q_in, the
  // end strip's load over its neighbour's) up to t = 1/2 and 1 + 4 (t - 1/2) beyond (the same slope: C1,
  // rising as the cut edge carries more). It passes 0 where the contact's edge reaches the end, at every grid
  // (tests HalfspaceOnProfiles.EdgeValueVanishesWhereTheContactIsAsWideAsTheRoller, ...CutAtTheBodysEdge...).
  double edge_value_m = 0;
  int solves = 0, iterations = 0;     // half-space solves (coarse, fine, enlargements) and their iterations
};

// coarse grid of the half-space on profiles (nx along x, ny across the overlap)
constexpr GridSpec kHalfspaceCoarseGrid = {24, 64};

struct NormalProblem {
  NormalChoice choice = NormalChoice::Auto;
  Bodies bodies;                       // Rx of both; Ry only without profiles
  const Profiles* profiles = nullptr;  // the lateral geometry, or none (Hertz from the radii)
  bool worn = false;                   // Auto: a worn geometry is never treated by Hertz's closed form
  ElasticPair pair;
  double normal_load_N = 0;
  GridSpec grid;
  SemiHertzOptions semi_hertz;         // also the half-space box's semi-Hertzian solve
  double curvature_rtol = kConstantCurvatureRtol;
  const HalfspaceOnProfiles* halfspace_start = nullptr;  // the half-space's warm start (a previous solve's)
  GridSpec halfspace_coarse_grid = kHalfspaceCoarseGrid;  // the half-space's coarse grid
  int halfspace_margin_cells = 1;  // coarse cells added around the coarse loaded ones (0: the fine box is
                                   // usually too small and enlarged, for the tests of the enlargement)
};

struct NormalSolution {
  NormalSolverKind solver = NormalSolverKind::Hertz;  // the solver that ran
  std::string reason;         // why that one ("solver.normal auto, no profiles: Hertz from the radii")
  ContactPatch patch;
  int patches = 1;            // separate contact patches along y
  bool reaches_edge = false;  // the contact reaches a body's edge (the end of the profiles' overlap)
  double grid_y0_m = 0;       // profiles' y of the grid's y = 0 (strip j at grid_y0_m + grid.y_m(j))
  // with profiles: the profile solve's diagnostics (reference point, lateral extent, approach, rule);
  // (not filled by the half-space, which solves no semi-Hertzian problem: see halfspace)
  SemiHertzResult on_profiles;
  HalfspaceOnProfiles halfspace;  // the half-space's on profiles (solver Halfspace)
  // Converged, MaxIterations (no approach carries the load, or the half-space did not converge: never
  // to be used as a result), Failed (the contact reaches a body's edge: a body narrower than the contact
  // cannot carry the load)
  SolveStatus status;
  // the solver's own convergence, whether or not the contact reaches an edge (status.residual against
  // the solver's tolerance): Hertz's closed form; the semi-Hertzian load residual |F(delta)/F - 1| within
  // SemiHertzOptions::load_rtol; the half-space's complementarity residual within its tol (and its box's
  // enlargements ended inside the grid). A solve that did not converge is never used as a result.
  bool solve_converged = false;
};

// Typed failures of the choice itself (not of the input's values): Hertz asked for on geometry it
// cannot treat.
struct NormalChoiceError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A normal solve that did not converge (NormalSolution::solve_converged false), a contact cut at a
// body's edge included: no result; the command line ends with exit 1 and this message.
struct NormalSolveError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Solves the normal problem as the choice asks. Throws std::invalid_argument for bad values (from the
// solvers), NormalChoiceError when Hertz is asked for on profiles not of constant curvature or whose
// ellipse does not fit, NoStripCentreError (semi_hertz.h) for a grid too coarse for the contact.
// The status is the caller's to check.
NormalSolution solve_normal(const NormalProblem& problem);

// The half-space on the problem's profiles (HalfspaceOnProfiles above): what solve_normal runs for
// NormalChoice::Halfspace. Throws std::invalid_argument without profiles.
NormalSolution solve_halfspace_on_profiles(const NormalProblem& problem);

// solve_normal, and a NormalSolveError naming the solver and its status unless the solve converged; a
// converged contact cut at a body's edge comes back (reaches_edge, status Failed)
NormalSolution solve_normal_converged(const NormalProblem& problem);

}  // namespace contact
