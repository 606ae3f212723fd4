// The contact model: the case's choice of tangential model (solver.tangential, cam.tangential.scheme) turned
// into its solves, in one place. The normal problem is chosen in lib/normal/normal.h (solve_normal); this stage
// takes its patch and solves the tangential problem on it with the model asked for:
//   Classic, Consistent  Kalker's simplified theory, the strip march (lib/tangential/steady.h) and Satran in time
//                        (lib/tangential/satran.h)
//   Relaxed              the consistent march matched to the exact theory (lib/tangential/relaxed.h)
//   Exact                Kalker's exact theory on the half-space (lib/tangential/exact.h)
// The wear loop, the cam, the commands and the Python module call these functions; what differs between the
// models besides their solves (which of them a cam or a wear life takes, how a report names them) is the
// TangentialModelTraits below. A new model is one TangentialScheme value, its row in contact_model.cpp, its
// implementation and its tests.
#pragma once

#include <string>

#include "lib/elastic.h"
#include "lib/patch.h"
#include "lib/solve_status.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace contact {

// What a tangential model takes and how the reports name it: data, one row per scheme (contact_model.cpp).
struct TangentialModelTraits {
  // Kalker's simplified coefficients C and mean flexibility L are the model's (reported); the exact theory
  // solves without them (nan in summary.csv, its solve's status printed in their place)
  bool simplified_coefficients = true;
  // solves with friction only (mu > 0): the exact theory; validate names friction.mu
  bool needs_friction = false;
  // the steady pure-xi strip has a closed form (solve_steady's skip): a wear life need not compute the
  // pressure fields for it (lib/tangential/steady.h)
  bool pure_xi_closed_form = false;
  // the cam's creep law and revolution take it (cam/creep_law.h): relaxed, consistent and exact
  bool cam = false;
  // its transient relaxes the steady law over the rolled distance (the relaxed model: the cam's revolution
  // steps its rows with the steady solves), else it is Satran's strip march in time
  bool relaxes_steady_law = false;
  const char* theory = "";            // "simplified theory", "exact theory", "relaxed model"
  const char* run_note = "";          // after the scheme in the transient command's first line: ", exact theory"
  const char* steps_name = "";        // the cam's transient steps: "Satran", "relaxed"
  const char* stored_energy = "";     // the cam's stored energy in the balance: "elastic", "relaxation"
  const char* needs_friction_as = ""; // the model in the friction message: "exact solver"
  // the transient run's name in summary.csv's scheme column: its own ("exact"), or "" for the transient
  // scheme's (shift, upwind, lax-friedrichs)
  const char* transient_name = "";
};

const TangentialModelTraits& tangential_traits(TangentialScheme scheme);

// the scheme column of a transient run's summary.csv: the model's own name, else the transient scheme's
std::string transient_run_name(TangentialScheme scheme, TransientScheme transient);

// A steady solve of the tangential problem with a model.
struct SteadyModelSolution {
  TangentialProblem problem;  // the problem as the model solved it: the exact theory's C and L nan (unused)
  TangentialSolution solution;
  // an iterative model's solve (the exact theory's): the caller ends the run unless it converged; the
  // direct marches are Converged with no message
  SolveStatus status;
};

// How a steady solve is done beyond the model's choice (solver section of a case)
struct SteadyModelOptions {
  // the exact theory: its solve on the patch's grid and on half the cells each way, extrapolated in the grid
  // (lib/tangential/grid_extrapolation.h, solver.grid_extrapolation; nx and ny even and at least 4); the other
  // models refuse it (std::invalid_argument: the case reader refuses the key with them)
  bool grid_extrapolation = false;
};

// The steady tangential problem on `patch` with the model `scheme`: problem holds the creepages, mu and the
// rolling speed (and the simplified theory's coefficients, make_tangential_problem), pair the materials.
// fields: the per-cell fields computed (else left empty).
SteadyModelSolution solve_tangential_steady(TangentialScheme scheme, const ContactPatch& patch,
                                            const ElasticPair& pair, const TangentialProblem& problem, bool fields,
                                            const SteadyModelOptions& options = {});

// The transient run of t with the model `scheme`: Satran (classic and consistent), the relaxed model's run,
// or the exact theory's. Throws what the run throws (SettingError for settings it refuses).
TransientResult run_tangential_transient(TangentialScheme scheme, const TransientCase& t,
                                         const StepObserver& observe);

// The model's pure-xi creep law against the simplified theory's on a patch: the factor on the linear slope
// G a b C11 (the relaxed model's creepage factor over its shape factor) and on the creepage where the force
// saturates, 3 mu F / (G a b C11) (the relaxed model's level); 1 for the others
double xi_slope_factor(TangentialScheme scheme, const ContactPatch& patch);
double xi_saturation_factor(TangentialScheme scheme, const ContactPatch& patch);

}  // namespace contact
