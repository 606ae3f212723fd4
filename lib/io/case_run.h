// The work of `rollwear contact` and `rollwear transient` on a case that is read, without the files and
// the printing: shared by the command line (app/), the sweeps (session/sweep.cpp) and the Python bindings
// (python/). The case's tangential model is solved by lib/model/contact_model.h.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "lib/io/case.h"
#include "lib/lubrication/film.h"
#include "lib/lubrication/regime.h"
#include "lib/thermal/flash_temperature.h"
#include "lib/normal/normal.h"
#include "lib/subsurface/dang_van.h"
#include "lib/subsurface/shakedown.h"
#include "lib/subsurface/subsurface.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace contact {

// The film of a lubricated steady contact (docs/lubrication-and-temperature.md §1-2): Hamrock and Dowson's
// point formula on the reduced radius along rolling, 1/Rx = 1/Rx1 + 1/Rx2, the solved patch's ellipticity
// k = b/a (its equivalent ellipse), the normal load, E' = 2 E* and the entrainment speed V = (v1 + v2)/2.
struct ContactLubrication {
  double entrainment_m_per_s = 0;
  double Rx_m = 0;              // reduced radius along rolling
  FilmThickness film;
  bool within_fit_range = true;  // k in Hamrock and Dowson's [1, 8]
  double lambda = 0;             // h_min / sqrt(Rq1^2 + Rq2^2)
  LubricationRegime regime = LubricationRegime::Boundary;
  double mu = 0;                 // the case's friction coefficient of the regime (reported; the contact's solve uses
                                 // friction.mu, a life the regime law's, lib/lubrication/regime.h)
  double wear_factor = 0;        // the case's factor on the wear coefficient in the regime
};
ContactLubrication lubrication_of(const ContactCase& c, const ContactPatch& patch);

// The flash temperature of a steady contact: its dissipated power density (power_W_per_m2) shared by
// Blok's rule between the surfaces moving at v1 = V (1 - xi/2) and v2 = V (1 + xi/2)
struct ContactThermal {
  double v1_m_per_s = 0, v2_m_per_s = 0;
  FlashTemperature flash;
  std::optional<double> contact_temperature_C;  // bulk + flash maximum, with bulk_temperature_C
  std::optional<double> scuffing_margin_K;      // critical - (bulk + flash), with critical_temperature_C
};
ContactThermal thermal_of(const ContactCase& c, const ContactPatch& patch, const TangentialSolution& s);

// one steady contact: the normal problem, then the tangential problem on its patch
struct ContactRun {
  NormalSolution normal;
  TangentialProblem problem;
  TangentialSolution solution;
  TangentialScheme scheme = kDefaultTangentialScheme;
  std::string exact_solve;  // scheme Exact: the exact solve's status message (problem.C and L are nan then)
  std::optional<ContactLubrication> lubrication;  // with a lubricant: section
  std::optional<ContactThermal> thermal;          // with a thermal: section
};

// validate_steady, the normal solve (solve_normal_of), then the steady tangential solve of the case's model
// (solve_tangential_steady; SolverError when the exact theory's does not converge), then the film and the
// flash temperature when the case has their sections. `fields`: the per-cell fields computed (else left
// empty; computed anyway with thermal:, whose heat source is the power field). Throws CaseError for bad input, SolverError or NormalSolveError for a
// solver's failure.
ContactRun solve_contact_case(const ContactCase& c, bool fields);

// The stresses below the surface of each body under the run's tractions (lib/subsurface/subsurface.h: body 1
// carries the solution's tractions, body 2 their reverse, each at its own Poisson's ratio; planes to
// options.depth_over_semi_axis times min(a, b)), and the fatigue indicators of each body with a shear yield
// stress (bodies.bodyN.shear_yield_Pa; lib/subsurface/shakedown.h). The run must have its fields (solved with
// fields true), else the tractions are taken as frictionless. [0] is body 1, [1] body 2. The maxima's and the
// cell index's y are in the profiles' lateral coordinate (strips.csv's y_m); the planes stay on the patch's grid.
// With bodies.bodyN.dang_van, Dang Van's index of that body over one rolling pass (lib/subsurface/dang_van.h),
// its y in the profiles' coordinate too.
struct BodySubsurface {
  Subsurface stresses;
  std::optional<FatigueIndicators> fatigue;
  std::optional<DangVanField> dang_van;
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
