#include "lib/io/case_run.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <spdlog/spdlog.h>

#include "lib/elastic.h"
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
  SteadyModelSolution s =
      solve_tangential_steady(r.scheme, patch, materials_of(c), problem, fields || c.thermal.has_value(),
                              SteadyModelOptions{c.solver.grid_extrapolation});
  if (!s.status.converged()) throw SolverError("exact steady solve: " + s.status.message);
  if (!s.status.message.empty()) {  // an iterative model's solve (the exact theory's)
    spdlog::info("exact steady solve: {}", s.status.message);
    r.exact_solve = s.status.message;
  }
  r.problem = s.problem;
  r.solution = std::move(s.solution);
  if (c.lubricant) r.lubrication = lubrication_of(c, patch);
  if (c.thermal) r.thermal = thermal_of(c, patch, r.solution);
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
    if (bodies[k]->dang_van) {
      out[k].dang_van = dang_van_field(out[k].stresses, patch.grid, *bodies[k]->dang_van);
      out[k].dang_van->y_m += run.normal.grid_y0_m;
    }
  }
  return out;
}

ContactLubrication lubrication_of(const ContactCase& c, const ContactPatch& patch) {
  const LubricantSection& lub = *c.lubricant;
  ContactLubrication l;
  l.entrainment_m_per_s = speed_of(c);  // the rolling speed is the mean surface speed (docs/physics.md §1)
  l.Rx_m = 1 / (1 / c.bodies.body1.Rx_m + 1 / c.bodies.body2.Rx_m);
  const double k = patch.b_m / patch.a_m;
  const double E_prime = ehl_reduced_modulus_Pa(effective_modulus_Pa(materials_of(c)));
  l.film = film_point_contact(lub.lubricant, l.Rx_m, k, E_prime, patch.normal_load_N, l.entrainment_m_per_s);
  l.within_fit_range = k >= kHamrockDowsonMinEllipticity && k <= kHamrockDowsonMaxEllipticity;
  l.lambda = film_parameter(l.film.h_min_m, lub.Rq1_m, lub.Rq2_m);
  l.regime = regime_of(l.lambda, lub.thresholds);
  l.mu = lub.by_regime.mu[static_cast<int>(l.regime)];
  l.wear_factor = lub.by_regime.wear_factor[static_cast<int>(l.regime)];
  return l;
}

ContactThermal thermal_of(const ContactCase& c, const ContactPatch& patch, const TangentialSolution& s) {
  const ThermalSection& th = *c.thermal;
  ContactThermal t;
  const double V = speed_of(c), xi = creepages_of(c).xi;
  t.v1_m_per_s = V * (1 - xi / 2);  // xi = (v2 - v1)/V, V = (v1 + v2)/2
  t.v2_m_per_s = V * (1 + xi / 2);
  t.flash = flash_temperature(patch.grid, s.power_W_per_m2, t.v1_m_per_s, t.v2_m_per_s, th.body1, th.body2,
                              patch.a_m);
  if (th.bulk_temperature_C) t.contact_temperature_C = *th.bulk_temperature_C + t.flash.max_rise_K;
  if (th.critical_temperature_C)
    t.scuffing_margin_K =
        blok_scuffing_margin_K(*th.bulk_temperature_C, t.flash.max_rise_K, *th.critical_temperature_C);
  return t;
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
