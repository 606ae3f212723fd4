#include "lib/io/case_run.h"

#include <limits>
#include <stdexcept>
#include <string>

#include <spdlog/spdlog.h>

#include "lib/io/errors.h"
#include "lib/tangential/exact.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/steady.h"

namespace contact {

ContactRun solve_contact_case(const ContactCase& c, bool fields) {
  validate_steady(c);  // constants only, no inertia
  ContactRun r;
  r.scheme = parse_tangential_scheme(c.solver.tangential);

  // normal problem, then the steady tangential problem on its patch
  r.normal = solve_normal_of(c);
  const ContactPatch& patch = r.normal.patch;
  r.problem = make_tangential_problem(patch, materials_of(c), creepages_of(c), c.friction.mu, speed_of(c));
  SteadyOptions steady_options;
  steady_options.fields = fields;  // not asked for: not computed either
  if (r.scheme == TangentialScheme::Exact) {  // Kalker's exact theory on the half-space (lib/tangential/exact.h)
    const ElasticPair pair = materials_of(c);
    const ExactSolution e = solve_exact_steady(patch, combined_shear_modulus_Pa(pair), combined_poisson(pair),
                                               creepages_of(c), c.friction.mu, speed_of(c));
    if (!e.status.converged()) throw SolverError("exact steady solve: " + e.status.message);
    spdlog::info("exact steady solve: {}", e.status.message);
    r.solution = e.fields;
    r.exact_solve = e.status.message;
    // the simplified theory's coefficients play no part in this solve: not reported (nan in summary.csv)
    r.problem.C.C11 = r.problem.C.C22 = r.problem.C.C23 = r.problem.C.C33 = std::numeric_limits<double>::quiet_NaN();
    r.problem.L_m_per_Pa = std::numeric_limits<double>::quiet_NaN();
  } else if (r.scheme == TangentialScheme::Relaxed) {  // matched to the exact theory (lib/tangential/relaxed.h)
    r.solution = solve_relaxed_steady(patch, materials_of(c), creepages_of(c), c.friction.mu, speed_of(c), fields);
  } else {
    r.solution = solve_steady(patch, r.problem, r.scheme, steady_options);
  }
  return r;
}

ContactPatch in_profile_coordinates(const NormalSolution& normal) {
  ContactPatch p = normal.patch;
  p.grid.y_m += normal.grid_y0_m;
  return p;
}

TransientResult run_transient_case(const ContactCase& c, const TransientCase& t, const StepObserver& observe) {
  try {
    const TangentialScheme scheme = parse_tangential_scheme(c.solver.tangential);
    return scheme == TangentialScheme::Exact     ? run_exact_transient(t, observe)
           : scheme == TangentialScheme::Relaxed ? run_relaxed_transient(t, observe)
                                                 : run_transient(t, observe);
  } catch (const SettingError& e) {  // the settings refused: the key (data) and its line
    throw transient_error(c, e);
  } catch (const std::invalid_argument& e) {  // inside the solver, on settings that passed: its failure
    throw SolverError(std::string("transient: ") + e.what());
  }
}

}  // namespace contact
