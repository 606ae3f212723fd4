// The contact model (contact_model.h): one row per tangential model, its traits and its solves.
#include "lib/model/contact_model.h"

#include <limits>
#include <stdexcept>
#include <utility>

#include "lib/solve_status.h"
#include "lib/tangential/exact.h"
#include "lib/tangential/grid_extrapolation.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/steady.h"

namespace contact {

namespace {

using SteadySolve = SteadyModelSolution (*)(const ContactPatch&, const ElasticPair&, const TangentialProblem&, bool);
using TransientRun = TransientResult (*)(const TransientCase&, const StepObserver&);
using PatchFactor = double (*)(const ContactPatch&);

struct TangentialModel {
  TangentialScheme scheme;
  TangentialModelTraits traits;
  SteadySolve steady;
  TransientRun transient;
  PatchFactor xi_slope_factor;       // the pure-xi law's slope over the simplified theory's
  PatchFactor xi_saturation_factor;  // its saturation creepage over the simplified theory's
};

SteadyModelSolution direct(const TangentialProblem& problem, TangentialSolution solution) {
  SteadyModelSolution s;
  s.problem = problem;
  s.solution = std::move(solution);
  s.status.kind = SolveStatus::Kind::Converged;
  s.status.message.clear();
  return s;
}

// Kalker's simplified theory: the strip march with the scheme's discretisation
template <TangentialScheme kScheme>
SteadyModelSolution simplified_steady(const ContactPatch& patch, const ElasticPair&, const TangentialProblem& problem,
                                      bool fields) {
  SteadyOptions options;
  options.fields = fields;  // not asked for: not computed either
  return direct(problem, solve_steady(patch, problem, kScheme, options));
}

// the consistent march matched to the exact theory (lib/tangential/relaxed.h)
SteadyModelSolution relaxed_steady(const ContactPatch& patch, const ElasticPair& pair, const TangentialProblem& problem,
                                   bool fields) {
  return direct(problem,
                solve_relaxed_steady(patch, pair, problem.creepages, problem.mu, problem.speed_m_per_s, fields));
}

// an exact-theory solve as the model's solution
SteadyModelSolution exact_model_solution(const TangentialProblem& problem, const TangentialSolution& fields,
                                         const SolveStatus& status) {
  SteadyModelSolution s;
  s.problem = problem;
  // the simplified theory's coefficients play no part in this solve: not reported (nan in summary.csv)
  s.problem.C.C11 = s.problem.C.C22 = s.problem.C.C23 = s.problem.C.C33 = std::numeric_limits<double>::quiet_NaN();
  s.problem.L_m_per_Pa = std::numeric_limits<double>::quiet_NaN();
  s.solution = fields;
  s.status = status;
  return s;
}

// Kalker's exact theory on the half-space (lib/tangential/exact.h); it computes its fields in any case
SteadyModelSolution exact_steady(const ContactPatch& patch, const ElasticPair& pair, const TangentialProblem& problem,
                                 bool) {
  const ExactSolution e = solve_exact_steady(patch, combined_shear_modulus_Pa(pair), combined_poisson(pair),
                                             problem.creepages, problem.mu, problem.speed_m_per_s);
  return exact_model_solution(problem, e.fields, e.status);
}

TransientResult satran_run(const TransientCase& t, const StepObserver& observe) { return run_transient(t, observe); }
TransientResult relaxed_run(const TransientCase& t, const StepObserver& observe) {
  return run_relaxed_transient(t, observe);
}
TransientResult exact_run(const TransientCase& t, const StepObserver& observe) {
  // a wear life's duty cycle (its steady stretches skipped) to the duty cycle's tolerances (exact.h)
  return run_exact_transient(t, observe, t.settings.skip_steady ? exact_duty_cycle_options() : exact_run_options());
}

double one(const ContactPatch&) { return 1.0; }

TangentialModelTraits simplified_traits(bool closed_form, bool cam) {
  TangentialModelTraits t;
  t.pure_xi_closed_form = closed_form;
  t.cam = cam;
  t.theory = "simplified theory";
  t.steps_name = "Satran";
  t.stored_energy = "elastic";
  return t;
}

TangentialModelTraits relaxed_traits() {
  TangentialModelTraits t;
  t.pure_xi_closed_form = true;  // its steady solve is the consistent march at scaled creepages
  t.cam = true;
  t.relaxes_steady_law = true;
  t.theory = "relaxed model";
  t.run_note = ", relaxed model";
  t.steps_name = "relaxed";
  t.stored_energy = "relaxation";
  return t;
}

TangentialModelTraits exact_traits() {
  TangentialModelTraits t;
  t.simplified_coefficients = false;
  t.needs_friction = true;
  t.cam = true;  // the cam's creep law per angle (its quasi-steady rows; the roller's motion on the relaxed model)
  t.theory = "exact theory";
  t.run_note = ", exact theory";
  t.needs_friction_as = "exact solver";
  t.transient_name = "exact";
  return t;
}

const TangentialModel& model_of(TangentialScheme scheme) {
  static const TangentialModel kModels[] = {
      {TangentialScheme::Classic, simplified_traits(false, false), simplified_steady<TangentialScheme::Classic>,
       satran_run, one, one},
      {TangentialScheme::Consistent, simplified_traits(true, true), simplified_steady<TangentialScheme::Consistent>,
       satran_run, one, one},
      {TangentialScheme::Exact, exact_traits(), exact_steady, exact_run, one, one},
      {TangentialScheme::Relaxed, relaxed_traits(), relaxed_steady, relaxed_run, relaxed_xi_slope_factor,
       relaxed_xi_saturation_level},
  };
  for (const TangentialModel& m : kModels)
    if (m.scheme == scheme) return m;
  throw std::invalid_argument("no tangential model for the scheme " + to_string(scheme));
}

}  // namespace

const TangentialModelTraits& tangential_traits(TangentialScheme scheme) { return model_of(scheme).traits; }

std::string transient_run_name(TangentialScheme scheme, TransientScheme transient) {
  const char* own = model_of(scheme).traits.transient_name;
  return *own ? std::string(own) : to_string(transient);
}

SteadyModelSolution solve_tangential_steady(TangentialScheme scheme, const ContactPatch& patch,
                                            const ElasticPair& pair, const TangentialProblem& problem, bool fields,
                                            const SteadyModelOptions& options) {
  if (!options.grid_extrapolation) return model_of(scheme).steady(patch, pair, problem, fields);
  if (scheme != TangentialScheme::Exact)
    throw std::invalid_argument("grid extrapolation is for the exact theory, not the tangential model " +
                                to_string(scheme));
  // Kalker's exact theory on grids h and 2h, extrapolated (lib/tangential/grid_extrapolation.h)
  const ExtrapolatedExactSolution e =
      solve_exact_steady_extrapolated(patch, combined_shear_modulus_Pa(pair), combined_poisson(pair),
                                      problem.creepages, problem.mu, problem.speed_m_per_s);
  return exact_model_solution(problem, e.fields, e.status);
}

TransientResult run_tangential_transient(TangentialScheme scheme, const TransientCase& t,
                                         const StepObserver& observe) {
  return model_of(scheme).transient(t, observe);
}

double xi_slope_factor(TangentialScheme scheme, const ContactPatch& patch) {
  return model_of(scheme).xi_slope_factor(patch);
}

double xi_saturation_factor(TangentialScheme scheme, const ContactPatch& patch) {
  return model_of(scheme).xi_saturation_factor(patch);
}

}  // namespace contact
