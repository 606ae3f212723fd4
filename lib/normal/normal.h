// The normal problem, chosen in one place (docs/physics.md §2, docs/semi-hertz.md, docs/halfspace.md):
//   Hertz       from the four radii (no profiles), or on profiles of constant curvature whose ellipse
//               fits inside their overlap (Hertz's closed form with the fitted radii);
//   semi-Hertz  on any lateral profiles (lib/normal/semi_hertz.h);
//   half-space  the exact solver on the semi-Hertzian contact's box enlarged by 25 %, the gap built
//               here from the profiles across and A x^2 along.
// NormalChoice::Auto: Hertz without profiles; with profiles Hertz's closed form while they have
// constant curvature and are unworn, else semi-Hertz. Once worn, never back to Hertz: the switch is a
// jump in the wear rate of up to 6.4e-4 (docs/semi-hertz.md), which the step control would meet at
// every crossing. Which solver ran is NormalSolution::solver.
#pragma once

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
};

struct NormalSolution {
  NormalSolverKind solver = NormalSolverKind::Hertz;  // the solver that ran
  std::string reason;         // why that one ("solver.normal auto, no profiles: Hertz from the radii")
  ContactPatch patch;
  int patches = 1;            // separate contact patches along y
  bool reaches_edge = false;  // the contact reaches a body's edge (the end of the profiles' overlap)
  double grid_y0_m = 0;       // profiles' y of the grid's y = 0 (strip j at grid_y0_m + grid.y_m(j))
  // with profiles: the profile solve's diagnostics (reference point, lateral extent, approach, rule);
  // its patch is this solution's patch except for the half-space, where it is the semi-Hertzian one
  SemiHertzResult on_profiles;
  // Converged, MaxIterations (no approach carries the load, or the half-space did not converge: never
  // to be used as a result), Failed (the contact reaches a body's edge: a body narrower than the contact
  // cannot carry the load)
  SolveStatus status;
  // the solver's own convergence, whether or not the contact reaches an edge (status.residual against
  // the solver's tolerance): Hertz's closed form; the semi-Hertzian load residual |F(delta)/F - 1| within
  // SemiHertzOptions::load_rtol; the half-space's complementarity residual within its tol (and its box's
  // semi-Hertzian solve converged). A solve that did not converge is never used as a result.
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

// solve_normal, and a NormalSolveError naming the solver and its status unless the solve converged; a
// converged contact cut at a body's edge comes back (reaches_edge, status Failed)
NormalSolution solve_normal_converged(const NormalProblem& problem);

}  // namespace contact
