// The wear loop (wear_loop.h, docs/wear-loop.md).
#include "wear/wear_loop.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "lib/io/case.h"
#include "lib/numeric.h"
#include "lib/tangential/steady.h"
#include "wear/profile_update.h"

namespace wear {

using contact::kPi;

namespace {

constexpr double kNominalEnergyCoefficient_m3_per_J = 1e-13;  // scales e for the per-cell laws
constexpr std::size_t kCachedRates = 4;  // an RK step's stages, the step end, a root's probes

// k_E of an energy-type law (energy, archard), 0 for the per-cell laws
double energy_coefficient(const WearLaw& law, double mu) {
  const WearLawKind kind = parse_wear_law(law.law);
  if (kind == WearLawKind::Energy) return law.k_E_m3_per_J;
  if (kind == WearLawKind::Archard) return archard_energy_coefficient_m3_per_J(law.archard_k, law.hardness_Pa, mu);
  return 0;
}

const contact::Profile& profile_of(const WearModel& m, int body) {
  return body == 1 ? m.profiles.body1 : m.profiles.body2;
}

// the dissipated energy per unit width over one duty cycle, with what the per-cell laws read
struct DutyCycleEnergy {
  Eigen::ArrayXd strip_energy_J_per_m;
  std::vector<CellFields> stretches;  // steady running only
  double rolled_m = 0;                // distance rolled in the cycle
  double duration_s = 0;
  double Fx_N = 0;
  double dissipated_J = 0;
};

DutyCycleEnergy duty_cycle_energy(const WearModel& m, const contact::ContactPatch& patch, bool need_fields) {
  DutyCycleEnergy d;
  if (!m.transient) {
    // steady running: one cycle is one revolution of the reference body
    const contact::TangentialProblem problem =
        contact::make_tangential_problem(patch, m.materials, m.creepages, m.mu, m.speed_m_per_s);
    contact::SteadyOptions options;
    options.fields = need_fields;
    const contact::TangentialSolution s = contact::solve_steady(patch, problem, m.scheme, options);
    d.rolled_m = 2 * kPi * m.reference_radius_m;
    d.duration_s = d.rolled_m / m.speed_m_per_s;
    d.strip_energy_J_per_m = s.strip_power_W_per_m * d.duration_s;
    d.Fx_N = s.Fx_N;
    d.dissipated_J = s.power_W * d.duration_s;
    if (need_fields) d.stretches.push_back(cell_fields(patch, s, m.mu, m.speed_m_per_s, d.duration_s));
    return d;
  }
  // the transient history, on the worn contact, with its steady stretches skipped
  contact::TransientCase t = *m.transient;
  t.patch = patch;
  double last_Fx = 0;
  const contact::TransientResult r =
      contact::run_transient(t, [&](const contact::TransientRecord& rec, const Eigen::ArrayXd&) { last_Fx = rec.Fx_N; });
  d.strip_energy_J_per_m = r.strip_energy_J_per_m;
  d.rolled_m = r.q_end_m;
  d.duration_s = r.t_end_s;
  d.Fx_N = last_Fx;
  d.dissipated_J = r.dissipated_J;
  if (!(d.rolled_m > 0))
    throw std::invalid_argument("the duty cycle rolls no distance: its wear cannot be spread over revolutions");
  return d;
}

// a body's depth per duty cycle at its profile's nodes: the law per strip, mapped and smoothed
Eigen::ArrayXd node_depth_per_cycle(const WearModel& m, int body, const WearLaw& law, const DutyCycleEnergy& d,
                                    double strip_y0_m, double dy_m) {
  DutyCycle duty;
  duty.worn_radius_m = body == 1 ? m.Rx1_m : m.Rx2_m;
  duty.mu = m.mu;
  duty.strip_energy_J_per_m = d.strip_energy_J_per_m;
  duty.stretches = d.stretches;
  const Eigen::ArrayXd strips = depth_per_duty_cycle(law, duty);
  const contact::Profile& p = profile_of(m, body);
  return smooth_conserving(strips_to_nodes(strips, strip_y0_m, dy_m, p.y_m), p.y_m, m.smoothing_wavelength_m);
}

bool needs_fields(const std::optional<WearLaw>& law) {
  if (!law) return false;
  const WearLawKind k = parse_wear_law(law->law);
  return k == WearLawKind::Kth || k == WearLawKind::Usfd;
}

}  // namespace

WearModel make_wear_model(const WearCase& c) {
  validate(c);
  const contact::ContactCase& k = c.contact;
  WearModel m;
  m.name = k.name;
  m.profiles = k.profiles->profiles;
  m.Rx1_m = k.bodies.body1.Rx_m;
  m.Rx2_m = k.bodies.body2.Rx_m;
  m.materials = contact::materials_of(k);
  m.grid = contact::grid_of(k);
  m.normal_options.heathcote_slip = k.profiles->heathcote_slip;
  m.semi_hertz_always = k.solver.normal == "semi-hertz";
  m.normal_load_N = k.load.normal_load_N.value.front();
  m.mu = k.friction.mu;
  m.scheme = contact::parse_tangential_scheme(k.solver.tangential);
  if (k.transient) {
    m.transient = contact::transient_case_of(k);
    m.transient->settings.skip_steady = true;
    m.transient->settings.snapshot_times_s.clear();
  } else {
    m.speed_m_per_s = contact::speed_of(k);
    m.creepages = contact::creepages_of(k);
  }
  m.law1 = c.wear.body1;
  m.law2 = c.wear.body2;
  m.n1 = m.law1 ? static_cast<int>(m.profiles.body1.y_m.size()) : 0;
  m.n2 = m.law2 ? static_cast<int>(m.profiles.body2.y_m.size()) : 0;
  m.reference_radius_m = m.law1 ? m.Rx1_m : m.Rx2_m;
  const WearLaw& reference = m.law1 ? *m.law1 : *m.law2;
  const double k_E = energy_coefficient(reference, m.mu);
  const contact::Profile& p = m.law1 ? m.profiles.body1 : m.profiles.body2;
  const double width = p.y_m(p.y_m.size() - 1) - p.y_m(0);
  // e = the depth the energy would wear spread evenly over the reference body's width
  m.energy_scale = (k_E > 0 ? k_E : kNominalEnergyCoefficient_m3_per_J) / (2 * kPi * m.reference_radius_m * width);
  m.smoothing_wavelength_m = c.wear.smoothing_wavelength_m;
  m.limits = c.wear.limits;
  return m;
}

Eigen::VectorXd initial_state(const WearModel& m) { return Eigen::VectorXd::Zero(m.state_size()); }

contact::Profiles worn_profiles(const WearModel& m, const Eigen::VectorXd& state) {
  if (state.size() != m.state_size())
    throw std::invalid_argument(fmt::format("wear state has {} values, the model {}", state.size(), m.state_size()));
  contact::Profiles p = m.profiles;
  // wear removes material: the surface recedes into the body, z grows by the depth
  if (m.n1 > 0) p.body1.z_m += state.segment(0, m.n1).array();
  if (m.n2 > 0) p.body2.z_m += state.segment(m.n1, m.n2).array();
  return p;
}

NormalState normal_state(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  const contact::Profiles profiles = worn_profiles(m, state);
  const std::uint64_t key = contact::profile_hash(profiles);
  if (cache.reuse && cache.normal_valid && cache.normal_key == key) return cache.normal;
  // a body worn deeper than it is wide (a cached profile passed): no profile can be (contact::check_profile),
  // the life ends
  for (const auto& [body, p] : {std::pair{1, &profiles.body1}, std::pair{2, &profiles.body2}}) {
    const double width_m = p->y_m(p->y_m.size() - 1) - p->y_m(0);
    Eigen::Index deepest = 0;
    const double depth_m = p->z_m.abs().maxCoeff(&deepest);
    if (depth_m > width_m)
      throw WornThrough(fmt::format("body {} is worn through: its worn profile is {:.6g} m deep at y = {:.6g} m, "
                                    "more than its width {:.6g} m (wear.limits.max_depth_m ends a life before that)",
                                    body, depth_m, p->y_m(deepest), width_m));
  }

  // normal problem on the current worn geometry: Hertz while unworn profiles have constant curvature,
  // semi-Hertz once anything is worn (never back: the switch is a jump in f of up to 6.4e-4,
  // docs/semi-hertz.md, which the step control would meet at every crossing)
  const bool unworn = m.n1 + m.n2 == 0 || state.head(m.n1 + m.n2).isZero(0);
  NormalState n;
  contact::GridSpec grid = m.grid;
  for (int refinement = 0;; ++refinement) {
    try {
      n.normal = m.semi_hertz_always || !unworn
                     ? contact::solve_semi_hertz(profiles, m.Rx1_m, m.Rx2_m, m.materials, m.normal_load_N, grid,
                                                 m.normal_options)
                     : contact::solve_normal_on_profiles(profiles, m.Rx1_m, m.Rx2_m, m.materials, m.normal_load_N,
                                                         grid, m.normal_options, contact::kCaseCurvatureRtol);
      break;
    } catch (const std::invalid_argument& e) {
      // a worn profile can split the contact into narrow patches that no strip centre of the case's grid
      // hits: twice the strips, up to 8 times (the wear maps from any strips onto the nodes)
      if (std::string(e.what()).find("no strip centre lies in the contact") == std::string::npos) throw;
      if (refinement == 3)
        throw UnresolvedContact(fmt::format(
            "the worn contact splits into patches that no strip centre hits, even with {} strips ({}): the strips "
            "cannot carry its load (docs/stress-suite.md, finding 7); wear.smoothing_wavelength_m of about a strip's "
            "width spreads the sharp steps of the worn profile where such patches form",
            grid.ny, e.what()));
      grid.ny *= 2;
      spdlog::debug("wear: {}; solving again with ny = {}", e.what(), grid.ny);
    }
  }
  // the lifetime's edge limit: how far the contact is from the end of the profiles' overlap
  const double lo = std::max(profiles.body1.y_m(0), profiles.body2.y_m(0));
  const double hi = std::min(profiles.body1.y_m(profiles.body1.y_m.size() - 1),
                             profiles.body2.y_m(profiles.body2.y_m.size() - 1));
  n.edge_margin_m = n.normal.reaches_edge
                        ? 0.0
                        : std::min(n.normal.contact_y_min_m - lo, hi - n.normal.contact_y_max_m);
  ++cache.counters.normal_solves;
  cache.normal_key = key;
  cache.normal = n;
  cache.normal_valid = true;
  return n;
}

WearRate wear_rate(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  ++cache.counters.rate_evaluations;
  const std::uint64_t key = contact::profile_hash(worn_profiles(m, state));
  if (cache.reuse)
    for (const auto& [k, rate] : cache.rates)
      if (k == key) return rate;

  // normal problem on the current worn geometry
  const NormalState n = normal_state(m, state, cache);
  const contact::ContactPatch& patch = n.normal.patch;

  // tangential problem over the duty cycle: dissipated energy per unit width
  const DutyCycleEnergy duty = duty_cycle_energy(m, patch, needs_fields(m.law1) || needs_fields(m.law2));
  ++cache.counters.tangential_solves;

  // wear law per strip, onto each worn body's nodes (volume-conserving smoothing), per revolution
  WearRate r;
  r.strip_energy_J_per_m = duty.strip_energy_J_per_m;
  r.strip_y0_m = n.normal.grid_y0_m + patch.grid.y_edge(0);
  r.strip_dy_m = patch.grid.dy_m;
  r.cycles_per_revolution = 2 * kPi * m.reference_radius_m / duty.rolled_m;
  r.energy_per_revolution_J = duty.strip_energy_J_per_m.sum() * r.strip_dy_m * r.cycles_per_revolution;
  r.dstate_dN = Eigen::VectorXd::Zero(m.state_size());
  if (m.law1)
    r.dstate_dN.segment(0, m.n1) =
        r.cycles_per_revolution * node_depth_per_cycle(m, 1, *m.law1, duty, r.strip_y0_m, r.strip_dy_m).matrix();
  if (m.law2)
    r.dstate_dN.segment(m.n1, m.n2) =
        r.cycles_per_revolution * node_depth_per_cycle(m, 2, *m.law2, duty, r.strip_y0_m, r.strip_dy_m).matrix();
  r.dstate_dN(m.energy_index()) = m.energy_scale * r.energy_per_revolution_J;

  r.contact.a_m = patch.a_m;
  r.contact.b_m = patch.b_m;
  r.contact.p0_Pa = patch.p0_Pa;
  r.contact.Fx_N = duty.Fx_N;
  r.contact.power_W = duty.duration_s > 0 ? duty.dissipated_J / duty.duration_s : 0;
  r.contact.edge_margin_m = n.edge_margin_m;
  r.contact.normal_solver = n.normal.status.message.rfind("constant curvature", 0) == 0 ? "hertz" : "semi-hertz";

  if (cache.rates.size() >= kCachedRates) cache.rates.erase(cache.rates.begin());
  cache.rates.emplace_back(key, r);
  return r;
}

double max_depth_m(const WearModel& m, const Eigen::VectorXd& state) {
  const int n = m.n1 + m.n2;
  return n > 0 ? state.head(n).maxCoeff() : 0.0;
}

double worn_volume_m3(const WearModel& m, const Eigen::VectorXd& state, int body) {
  if (body == 1 && m.n1 > 0)
    return 2 * kPi * m.Rx1_m * profile_area_m2(state.segment(0, m.n1).array(), m.profiles.body1.y_m);
  if (body == 2 && m.n2 > 0)
    return 2 * kPi * m.Rx2_m * profile_area_m2(state.segment(m.n1, m.n2).array(), m.profiles.body2.y_m);
  return 0;
}

double dissipated_energy_J(const WearModel& m, const Eigen::VectorXd& state) {
  return state(m.energy_index()) / m.energy_scale;
}

// ---- the life ----

namespace {

enum Limit { kDepth, kPressure, kEdge, kLimits };

// The wear is carried by the worn bodies' profile nodes: a contact narrower than a few node spacings
// would put a strip's wear on one node and the next solve could not see the worn shape. Throws
// contact::CaseError at the profile's key, naming what the user can set (wear_case.h).
constexpr int kMinNodesAcrossContact = 4;
void check_profile_resolves_contact(const WearCase& c, const WearModel& m, const NormalState& n) {
  const double width = n.normal.contact_y_max_m - n.normal.contact_y_min_m;
  for (int body : {1, 2}) {
    if ((body == 1 ? m.n1 : m.n2) == 0) continue;
    const Eigen::ArrayXd& y = body == 1 ? m.profiles.body1.y_m : m.profiles.body2.y_m;
    const double spacing = (y.tail(y.size() - 1) - y.head(y.size() - 1)).maxCoeff();
    wear::check_profile_resolves_contact(c, body, spacing, width, kMinNodesAcrossContact);
  }
}
const char* const kLimitNames[kLimits] = {"max_depth", "max_pressure", "edge"};

// whether e, or an exception nested in it (wear::integrate nests what f threw), is a LifeEndingGeometry
bool ends_life(const std::exception& e) {
  if (dynamic_cast<const LifeEndingGeometry*>(&e)) return true;
  try {
    std::rethrow_if_nested(e);
  } catch (const std::exception& inner) {
    return ends_life(inner);
  } catch (...) {
  }
  return false;
}

}  // namespace

LifeResult run_life(const WearModel& m, const WearCase& c, const LifeStart& start, const LifeHooks& hooks,
                    WearCache& cache) {
  LifeResult life;
  life.N = start.N;
  life.state = start.state.size() ? start.state : initial_state(m);
  life.next_step = start.next_step;
  life.steps = start.steps;
  life.rhs_evals = start.rhs_evals;
  life.rejected = start.rejected;

  // the lifetime limits as event functions g_k(N, h): a sign change ends the life
  const auto limit_values = [&](const Eigen::VectorXd& h, Eigen::VectorXd& g) {
    g.resize(kLimits);
    g(kDepth) = m.limits.max_depth_m > 0 ? max_depth_m(m, h) - m.limits.max_depth_m : -1;
    const bool need_normal = m.limits.max_pressure_Pa > 0 || m.limits.edge;
    const NormalState n = need_normal ? normal_state(m, h, cache) : NormalState{};
    g(kPressure) = m.limits.max_pressure_Pa > 0 ? n.normal.patch.p0_Pa - m.limits.max_pressure_Pa : -1;
    g(kEdge) = m.limits.edge ? -n.edge_margin_m : -1;
  };
  const auto end_with = [&](const char* why, const std::string& message) {
    life.ended_by = why;
    life.message = message;
    life.contact = wear_rate(m, life.state, cache).contact;
    return life;
  };

  // the worn body's profile must resolve the contact: its nodes carry the wear
  check_profile_resolves_contact(c, m, normal_state(m, life.state, cache));

  // a limit already reached (a resumed run, or an unworn contact at the edge)
  Eigen::VectorXd g0;
  limit_values(life.state, g0);
  for (int k = 0; k < kLimits; ++k)
    if (g0(k) >= 0)
      return end_with(kLimitNames[k], fmt::format("{} reached at the start, N {:.10g}", kLimitNames[k], life.N));

  const Rhs f = [&](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) {
    dhdN = wear_rate(m, h, cache).dstate_dN;
  };
  const Roots roots = [&](double, const Eigen::VectorXd& h, Eigen::VectorXd& g) { limit_values(h, g); };

  // the segments: up to each snapshot revolution, then to the budget
  std::vector<double> ends;
  for (double N : c.wear.snapshots_revolutions)
    if (N > life.N) ends.push_back(N);
  if (ends.empty() || ends.back() < c.wear.revolutions) ends.push_back(c.wear.revolutions);

  IntegratorOptions options = integrator_options(c.wear.stepping);
  for (double N_end : ends) {
    options.initial_step = life.next_step;
    options.max_steps = c.wear.stepping.max_steps - life.steps;
    if (options.max_steps <= 0) return end_with("max_steps", fmt::format("max_steps {} reached", c.wear.stepping.max_steps));
    const long steps0 = life.steps, rhs0 = life.rhs_evals, rejected0 = life.rejected;
    LifeStart last{life.N, life.state, 0, life.steps, life.rhs_evals, life.rejected};  // the last accepted step
    const OnStep on_step = [&](const StepInfo& info, const Eigen::VectorXd& h) {
      LifeStep s;
      s.step = steps0 + info.steps;
      s.N = info.N;
      s.state = &h;
      s.info = info;
      s.info.steps = s.step;
      s.info.rhs_evals = rhs0 + info.rhs_evals;
      s.info.rejected = rejected0 + info.rejected;
      s.contact = wear_rate(m, h, cache).contact;
      last = {s.N, h, s.info.next_step, s.step, s.info.rhs_evals, s.info.rejected};
      return hooks.on_step ? hooks.on_step(s) : true;
    };
    IntegratorResult r;
    try {
      r = integrate(f, roots, kLimits, life.N, life.state, N_end, options, on_step);
    } catch (const std::exception& e) {
      // a contact the strips cannot resolve, or a body worn through, ends the life at its last accepted
      // step, status failed
      if (!ends_life(e)) throw;
      life.N = last.N;
      life.state = last.state;
      life.steps = last.steps;
      life.rhs_evals = last.rhs_evals;
      life.rejected = last.rejected;
      spdlog::warn("wear: {}; the life ends at N {:.10g}, its last accepted step", e.what(), life.N);
      return end_with("failed", fmt::format("ended at N {:.10g}, the last accepted step: {}", life.N, e.what()));
    }
    life.N = r.N;
    life.state = r.h_m;
    life.steps = steps0 + r.steps;
    life.rhs_evals = rhs0 + r.rhs_evals;
    life.rejected = rejected0 + r.rejected;
    if (r.next_step > 0) life.next_step = r.next_step;
    switch (r.status.kind) {
      case IntegratorStatus::Kind::ReachedEnd: {
        const auto& snaps = c.wear.snapshots_revolutions;
        if (hooks.on_snapshot && std::find(snaps.begin(), snaps.end(), N_end) != snaps.end())
          hooks.on_snapshot(life.N, life.state);
        break;
      }
      case IntegratorStatus::Kind::RootFound:
        return end_with(kLimitNames[r.status.roots.front()],
                        fmt::format("{} reached at N {:.10g} ({})", kLimitNames[r.status.roots.front()], r.N,
                                    r.status.message));
      case IntegratorStatus::Kind::Stopped: return end_with("stopped", r.status.message);
      case IntegratorStatus::Kind::MaxSteps: return end_with("max_steps", r.status.message);
      case IntegratorStatus::Kind::Failed: return end_with("failed", r.status.message);
    }
  }
  return end_with("revolutions", fmt::format("the life budget wear.revolutions = {:.10g} reached with no limit",
                                             c.wear.revolutions));
}

}  // namespace wear
