// The work of `rollwear contact` and `rollwear transient` on a case that is read, without the files and
// the printing: shared by the command line (app/), the sweeps (session/sweep.cpp) and the Python bindings
// (python/). The case's tangential model is solved by lib/model/contact_model.h.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "lib/io/case.h"
#include "lib/normal/normal.h"
#include "lib/subsurface/shakedown.h"
#include "lib/subsurface/subsurface.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace contact {

// one steady contact: the normal problem, then the tangential problem on its patch
struct ContactRun {
  NormalSolution normal;
  TangentialProblem problem;
  TangentialSolution solution;
  TangentialScheme scheme = kDefaultTangentialScheme;
  std::string exact_solve;  // scheme Exact: the exact solve's status message (problem.C and L are nan then)
};

// validate_steady, the normal solve (solve_normal_of), then the steady tangential solve of the case's model
// (solve_tangential_steady; SolverError when the exact theory's does not converge). `fields`: the per-cell
// fields computed (else left empty). Throws CaseError for bad input, SolverError or NormalSolveError for a
// solver's failure.
ContactRun solve_contact_case(const ContactCase& c, bool fields);

// The stresses below the surface of each body under the run's tractions (lib/subsurface/subsurface.h: body 1
// carries the solution's tractions, body 2 their reverse, each at its own Poisson's ratio; planes to
// options.depth_over_semi_axis times min(a, b)), and the fatigue indicators of each body with a shear yield
// stress (bodies.bodyN.shear_yield_Pa; lib/subsurface/shakedown.h). The run must have its fields (solved with
// fields true), else the tractions are taken as frictionless. [0] is body 1, [1] body 2. The maxima's and the
// cell index's y are in the profiles' lateral coordinate (strips.csv's y_m); the planes stay on the patch's grid.
struct BodySubsurface {
  Subsurface stresses;
  std::optional<FatigueIndicators> fatigue;
};
std::array<BodySubsurface, 2> subsurface_of_contact(const ContactCase& c, const ContactRun& run,
                                                    const SubsurfaceOptions& options = {});

// the patch with its strips at the profiles' lateral positions (strips.csv's y_m, as `rollwear contact` writes it)
ContactPatch in_profile_coordinates(const NormalSolution& normal);

// The transient run of t (transient_case_of(c)) with the case's model (run_tangential_transient). Settings the
// run refuses are a CaseError at the key's line (transient_error); any other std::invalid_argument from inside
// the solver, on settings that passed, is its failure (SolverError).
TransientResult run_transient_case(const ContactCase& c, const TransientCase& t, const StepObserver& observe);

}  // namespace contact
