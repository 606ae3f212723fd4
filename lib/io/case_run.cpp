#include "lib/io/case_run.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <spdlog/spdlog.h>

#include "lib/errors.h"
#include "lib/model/contact_model.h"

namespace contact {

ContactRun solve_contact_case(const ContactCase& c, bool fields) {
  validate_steady(c);  // constants only, no inertia
  ContactRun r;
  r.scheme = c.solver.tangential;

  // normal problem, then the steady tangential problem on its patch with the case's model (lib/model/)
  r.normal = solve_normal_of(c);
  const ContactPatch& patch = r.normal.patch;
  const TangentialProblem problem =
      make_tangential_problem(patch, materials_of(c), creepages_of(c), c.friction.mu, speed_of(c));
  SteadyModelSolution s = solve_tangential_steady(r.scheme, patch, materials_of(c), problem, fields);
  if (!s.status.converged()) throw SolverError("exact steady solve: " + s.status.message);
  if (!s.status.message.empty()) {  // an iterative model's solve (the exact theory's)
    spdlog::info("exact steady solve: {}", s.status.message);
    r.exact_solve = s.status.message;
  }
  r.problem = s.problem;
  r.solution = std::move(s.solution);
  return r;
}

std::array<BodySubsurface, 2> subsurface_of_contact(const ContactCase& c, const ContactRun& run,
                                                    const SubsurfaceOptions& options) {
  const ContactPatch& patch = run.normal.patch;
  const double semi_axis = std::min(patch.a_m, patch.b_m);
  std::array<BodySubsurface, 2> out;
  const std::array<const BodySection*, 2> bodies = {&c.bodies.body1, &c.bodies.body2};
  for (int k = 0; k < 2; ++k) {
    const SurfaceTractions t = surface_tractions(patch, &run.solution, k + 1);
    // body 2 under the same tractions and Poisson's ratio as body 1 without friction is body 1's twin
    const bool frictionless = t.shear_x_Pa.size() == 0 ||
                              (t.shear_x_Pa.abs().maxCoeff() == 0 && t.shear_y_Pa.abs().maxCoeff() == 0);
    const bool twin = k == 1 && bodies[1]->nu == bodies[0]->nu && frictionless;
    out[k].stresses = twin ? out[0].stresses : solve_subsurface(t, bodies[k]->nu, semi_axis, options);
    if (bodies[k]->shear_yield_Pa > 0)
      out[k].fatigue = fatigue_indicators(patch, run.solution, bodies[k]->shear_yield_Pa);
    // where: in the profiles' lateral coordinate, as strips.csv's y_m
    SubsurfaceMaxima& m = out[k].stresses.maxima;
    for (StressPeak* p : {&m.von_mises, &m.tresca, &m.orthogonal_shear, &m.tension, &m.compression})
      p->y_m += run.normal.grid_y0_m;
    if (out[k].fatigue) out[k].fatigue->cell_y_m += run.normal.grid_y0_m;
  }
  return out;
}

ContactPatch in_profile_coordinates(const NormalSolution& normal) {
  ContactPatch p = normal.patch;
  p.grid.y_m += normal.grid_y0_m;
  return p;
}

TransientResult run_transient_case(const ContactCase& c, const TransientCase& t, const StepObserver& observe) {
  try {
    return run_tangential_transient(c.solver.tangential, t, observe);
  } catch (const SettingError& e) {  // the settings refused: the key (data) and its line
    throw transient_error(c, e);
  } catch (const std::invalid_argument& e) {  // inside the solver, on settings that passed: its failure
    throw SolverError(std::string("transient: ") + e.what());
  }
}

}  // namespace contact
