// The wear loop (wear_loop.h, docs/wear-loop.md).
#include "wear/wear_loop.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <tuple>
#include <utility>
#include <stdexcept>
#include <string>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "lib/io/case.h"
#include "lib/numeric.h"
#include "lib/errors.h"
#include "lib/model/contact_model.h"
#include "lib/subsurface/shakedown.h"
#include "lib/thermal/flash_temperature.h"
#include "wear/collective.h"
#include "wear/profile_update.h"

namespace wear {

using contact::kPi;

namespace {

constexpr double kNominalEnergyCoefficient_m3_per_J = 1e-13;  // scales e for the per-cell laws
constexpr std::size_t kCachedRates = 4;  // an RK step's stages, the step end, a root's probes

// k_E of an energy-type law (energy, archard), 0 for the per-cell laws
double energy_coefficient(const WearLaw& law, double mu) {
  const WearLawKind kind = law.law;
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
  double flash_rise_K = std::numeric_limits<double>::quiet_NaN();  // with the model's thermal: section
  double scuffing_margin_K = std::numeric_limits<double>::quiet_NaN();
};

DutyCycleEnergy duty_cycle_energy(const WearModel& m, const contact::ContactPatch& patch, bool need_fields) {
  DutyCycleEnergy d;
  if (!m.transient) {
    // steady running: one cycle is one revolution of the reference body
    const contact::TangentialProblem problem =
        contact::make_tangential_problem(patch, m.materials, m.creepages, m.mu, m.speed_m_per_s);
    // the case's model (lib/model/contact_model.h); the exact theory's solve may not converge
    contact::SteadyModelSolution solved =
        contact::solve_tangential_steady(m.scheme, patch, m.materials, problem, need_fields || m.thermal.has_value(),
                                         m.steady_options);
    if (!solved.status.converged())
      throw contact::SolverError("wear rate: exact steady solve: " + solved.status.message);
    const contact::TangentialSolution& s = solved.solution;
    d.rolled_m = 2 * kPi * m.reference_radius_m;
    d.duration_s = d.rolled_m / m.speed_m_per_s;
    d.strip_energy_J_per_m = s.strip_power_W_per_m * d.duration_s;
    d.Fx_N = s.Fx_N;
    d.dissipated_J = s.power_W * d.duration_s;
    if (need_fields) d.stretches.push_back(cell_fields(patch, s, m.mu, m.speed_m_per_s, d.duration_s));
    // the flash temperature of the frictional power (lib/thermal: Jaeger's band per strip, Blok's partition)
    if (m.thermal) {
      const contact::FlashTemperature flash = contact::flash_temperature(
          patch.grid, s.power_W_per_m2, m.v1_m_per_s, m.v2_m_per_s, m.thermal->body1, m.thermal->body2, patch.a_m);
      d.flash_rise_K = flash.max_rise_K;
      if (m.thermal->bulk_temperature_C && m.thermal->critical_temperature_C)
        d.scuffing_margin_K = contact::blok_scuffing_margin_K(*m.thermal->bulk_temperature_C, flash.max_rise_K,
                                                              *m.thermal->critical_temperature_C);
    }
    return d;
  }
  // the transient history, on the worn contact, with its steady stretches skipped
  contact::TransientCase t = *m.transient;
  t.patch = patch;
  double last_Fx = 0;
  const auto observe = [&](const contact::TransientRecord& rec, const Eigen::ArrayXd&) { last_Fx = rec.Fx_N; };
  const contact::TransientResult r = contact::run_tangential_transient(m.scheme, t, observe);
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
  const Eigen::ArrayXd strips = m.wear_factor * depth_per_duty_cycle(law, duty);  // 1 without a lubricant
  const contact::Profile& p = profile_of(m, body);
  return smooth_conserving(strips_to_nodes(strips, strip_y0_m, dy_m, p.y_m), body == 1 ? m.smoothing1 : m.smoothing2);
}

bool needs_fields(const std::optional<WearLaw>& law) {
  if (!law) return false;
  const WearLawKind k = law->law;
  return k == WearLawKind::Kth || k == WearLawKind::Usfd;
}

}  // namespace

double estimate_memory_bytes(const WearCase& c) {
  const contact::ContactCase& k = c.contact;
  if (!k.profiles) return 0;
  double per_condition = 0;
  const double lc = c.wear.smoothing_wavelength_m;
  for (const auto& [law, profile] : {std::pair{&c.wear.body1, &k.profiles->profiles.body1},
                                     std::pair{&c.wear.body2, &k.profiles->profiles.body2}}) {
    if (!*law) continue;
    const double n = static_cast<double>(profile->y_m.size());
    // the kernel's values (8 bytes each) and its per-row indices (first, count: 4 bytes each; offset: 8)
    per_condition += 8 * smoothing_kernel_entries(profile->y_m, lc) + 16 * n + 8 * kStateCopiesPerNode * n;
  }
  const double conditions = c.wear.collective.empty() ? 1.0 : static_cast<double>(c.wear.collective.size());
  return per_condition * conditions;
}

void check_memory(const WearCase& c) {
  const contact::ContactCase& k = c.contact;
  const double bytes = estimate_memory_bytes(c);
  const double limit = k.solver.max_memory_bytes;
  if (!(bytes > limit)) return;
  // the wearing body of the larger kernel names the profile
  const double lc = c.wear.smoothing_wavelength_m;
  const double entries1 = c.wear.body1 ? smoothing_kernel_entries(k.profiles->profiles.body1.y_m, lc) : -1;
  const double entries2 = c.wear.body2 ? smoothing_kernel_entries(k.profiles->profiles.body2.y_m, lc) : -1;
  const int body = entries1 >= entries2 ? 1 : 2;
  const contact::Profile& p = body == 1 ? k.profiles->profiles.body1 : k.profiles->profiles.body2;
  const double entries = std::max(entries1, entries2);
  const std::string key = fmt::format("profiles.body{}", body);
  throw contact::key_error(
      k, key,
      fmt::format("{}, wear.smoothing_wavelength_m, solver.max_memory_bytes: the run would need about {:.3g} bytes "
                  "({:.3g} GB), more than solver.max_memory_bytes = {:.0f}: the smoothing filter of body {}'s {} nodes "
                  "pairs each with {:.0f} others within wear.smoothing_wavelength_m = {:.3g} m{}; give a profile of "
                  "fewer nodes, a shorter smoothing_wavelength_m, or raise solver.max_memory_bytes",
                  key, bytes, bytes / 1e9, limit, body, p.y_m.size(),
                  p.y_m.size() > 0 ? entries / static_cast<double>(p.y_m.size()) : 0.0, c.wear.smoothing_wavelength_m,
                  c.wear.collective.empty() ? std::string()
                                            : fmt::format(", for each of {} running conditions", c.wear.collective.size())));
}

namespace {

// the case's model with the case's own normal and tangential models, without the fidelity's other models
WearModel make_own_model(const WearCase& c) {
  const contact::ContactCase& k = c.contact;
  WearModel m;
  m.name = k.name;
  m.profiles = k.profiles->profiles;
  m.Rx1_m = k.bodies.body1.Rx_m;
  m.Rx2_m = k.bodies.body2.Rx_m;
  m.materials = contact::materials_of(k);
  m.grid = contact::grid_of(k);
  m.normal_options.heathcote_slip = k.profiles->heathcote_slip;
  m.normal_choice = k.solver.normal;  // auto, semi-hertz or halfspace (validate)
  m.normal_load_N = k.load.normal_load_N.value.front();
  m.mu = k.friction.mu;
  if (k.lubricant) {  // the regime law's mu and wear factor on the unworn contact's film (validate: steady running)
    contact::ContactCase unworn = k;
    unworn.solver.normal = contact::NormalChoice::Auto;  // the same film for the exact physics' models
    m.lubrication = contact::lubrication_of(k, contact::solve_normal_of(unworn).patch);
    m.regime = contact::regime_friction(m.lubrication->lambda, k.lubricant->by_regime, k.lubricant->thresholds);
    m.mu = m.regime.mu;
    m.wear_factor = m.regime.wear_factor;
  }
  m.scheme = k.solver.tangential;  // one the duty cycle can run (validate)
  m.steady_options.grid_extrapolation = k.solver.grid_extrapolation && m.scheme == contact::TangentialScheme::Exact;
  if (k.solver.grid_extrapolation && k.transient)
    throw contact::SettingError("solver", "grid_extrapolation",
                                "is of steady solves; a transient duty cycle steps its grid by one cell");
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
  if (m.law1) m.smoothing1 = smoothing_kernel(m.profiles.body1.y_m, m.smoothing_wavelength_m);
  if (m.law2) m.smoothing2 = smoothing_kernel(m.profiles.body2.y_m, m.smoothing_wavelength_m);
  m.limits = c.wear.limits;
  // fatigue damage at the reference body's nodes, and the shakedown limit's k (the reference body's)
  m.fatigue = c.wear.fatigue;
  m.nD = m.fatigue ? static_cast<int>(p.y_m.size()) : 0;
  m.damage_scale_m = m.limits.max_depth_m > 0 ? m.limits.max_depth_m : kDamageScale_m;
  m.shear_yield_Pa = m.law1 ? k.bodies.body1.shear_yield_Pa : k.bodies.body2.shear_yield_Pa;
  if (k.thermal && !k.transient) {  // xi = (v2 - v1)/V, V = (v1 + v2)/2 (docs/physics.md §1)
    m.thermal = k.thermal;
    m.v1_m_per_s = m.speed_m_per_s * (1 - m.creepages.xi / 2);
    m.v2_m_per_s = m.speed_m_per_s * (1 + m.creepages.xi / 2);
  }
  // the pressure fields on the grid: read by the transient duty cycle (Satran), the per-cell laws and the
  // consistent march; not by the steady pure-xi closed form (solve_steady's skip) with the strip laws
  // (the relaxed model's steady solve is that march at scaled creepages: the same closed form)
  const bool closed_form = !m.transient && contact::tangential_traits(m.scheme).pure_xi_closed_form &&
                           m.creepages.eta == 0 && m.creepages.phi_per_m == 0;
  m.normal_options.pressure_fields = !closed_form || needs_fields(m.law1) || needs_fields(m.law2) || m.thermal.has_value();
  m.fidelity = k.solver.fidelity;
  m.correction_tolerance = k.solver.correction_tolerance;
  m.error_estimate = k.solver.error_estimate;
  return m;
}

}  // namespace

WearModel make_wear_model(const WearCase& c) {
  check_memory(c);  // before any kernel is built
  if (!c.wear.collective.empty()) return make_collective_model(c);
  validate(c);
  const contact::ContactCase& k = c.contact;
  WearModel m = make_own_model(c);
  // the fidelity: the exact physics on the same case, for the corrections or the error estimate; a transient duty
  // cycle's is steady rolling at its steady part (docs/fidelity.md, "Transient duty cycles": the exact theory's
  // transient duty cycle costs a minute per solve), and the correction compares it with the fast models there
  const std::optional<SteadyPart> part =
      m.transient ? steady_part(m.transient->inputs, m.transient->settings.t_end_s) : std::nullopt;
  if (m.fidelity != contact::Fidelity::Exact && k.friction.mu > 0 && (!m.transient || part)) {
    // a model as another's, in steady rolling at the transient duty cycle's steady part
    const auto at_steady_part = [&part](WearModel model) {
      if (!part) return model;
      model.transient.reset();
      model.speed_m_per_s = part->speed_m_per_s;
      model.creepages = part->creepages;
      model.normal_options.pressure_fields = true;
      return model;
    };
    WearCase exact = c;
    exact.contact.solver.normal = contact::NormalChoice::Halfspace;
    exact.contact.solver.tangential = contact::TangentialScheme::Exact;
    exact.contact.solver.fidelity = contact::Fidelity::Exact;
    const int grid = k.solver.correction_grid;
    if (grid > 0) exact.contact.solver.nx = exact.contact.solver.ny = grid;
    m.exact_physics.push_back(at_steady_part(make_own_model(exact)));
    m.steady_part = part;
    // the fast models on the correction grid, when it is another, or at a transient cycle's steady part: the
    // correction's like with like
    const bool other_grid = grid > 0 && (grid != k.solver.nx || grid != k.solver.ny);
    if (other_grid || part) {
      WearCase fast = c;
      if (other_grid) fast.contact.solver.nx = fast.contact.solver.ny = grid;
      fast.contact.solver.correction_grid = 0;
      fast.contact.solver.fidelity = contact::Fidelity::Fast;
      m.correction_fast.push_back(at_steady_part(make_own_model(fast)));
    }
    if (other_grid) {
      exact.contact.solver.nx = k.solver.nx;
      exact.contact.solver.ny = k.solver.ny;
      m.limits_physics.push_back(at_steady_part(make_own_model(exact)));
    }
  }
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

namespace {

// normal_state on the state's worn profiles and their hash, when the caller has them already
NormalState normal_state_on(const WearModel& m, const contact::Profiles& profiles, std::uint64_t key,
                            const Eigen::VectorXd& state, WearCache& cache) {
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

  // normal problem on the current worn geometry (contact::solve_normal chooses: Hertz while the unworn
  // profiles have constant curvature, semi-Hertz once anything is worn; or the half-space throughout)
  contact::NormalProblem problem;
  problem.choice = m.normal_choice;
  problem.bodies = {{m.Rx1_m, contact::kFlat}, {m.Rx2_m, contact::kFlat}};
  problem.profiles = &profiles;
  problem.worn = !(m.n1 + m.n2 == 0 || state.head(m.n1 + m.n2).isZero(0));
  problem.pair = m.materials;
  problem.normal_load_N = m.normal_load_N;
  problem.grid = m.grid;
  problem.semi_hertz = m.normal_options;
  // the half-space starts from the last solve's pressures
  if (cache.halfspace_warm_start && cache.normal_valid && cache.normal.solver == contact::NormalSolverKind::Halfspace)
    problem.halfspace_start = &cache.normal.halfspace;
  NormalState n;
  bool converged = false;
  std::string status_message;
  for (int refinement = 0;; ++refinement) {
    try {
      contact::NormalSolution s = contact::solve_normal(problem);
      n.solver = s.solver;
      converged = s.solve_converged;
      status_message = s.status.message;
      n.patch = std::move(s.patch);
      n.grid_y0_m = s.grid_y0_m;
      n.reaches_edge = s.reaches_edge;
      if (s.solver == contact::NormalSolverKind::Halfspace) {
        n.contact_y_min_m = s.halfspace.contact_y_min_m;
        n.contact_y_max_m = s.halfspace.contact_y_max_m;
        n.approach_m = n.patch.approach_m;
        n.edge_limit_m = s.halfspace.edge_value_m;
        cache.halfspace_solves += s.halfspace.solves;
        cache.halfspace_iterations += s.halfspace.iterations;
        n.halfspace = std::move(s.halfspace);
      } else {
        n.contact_y_min_m = s.on_profiles.contact_y_min_m;
        n.contact_y_max_m = s.on_profiles.contact_y_max_m;
        n.approach_m = s.on_profiles.approach_m;
        if (converged) n.edge_limit_m = edge_limit_value_m(profiles, s.on_profiles);
        n.profile_solve = std::move(s.on_profiles);
      }
      break;
    } catch (const contact::NoStripCentreError& e) {
      // a worn profile can split the contact into narrow patches that no strip centre of the case's grid
      // hits: twice the strips, up to 8 times (the wear maps from any strips onto the nodes)
      if (refinement == 3)
        throw UnresolvedContact(fmt::format(
            "the worn contact splits into patches that no strip centre hits, even with {} strips ({}): the strips "
            "cannot carry its load (docs/stress-suite.md, finding 7); wear.smoothing_wavelength_m of about a strip's "
            "width spreads the sharp steps of the worn profile where such patches form",
            problem.grid.ny, e.what()));
      problem.grid.ny *= 2;
      spdlog::debug("wear: {}; solving again with ny = {}", e.what(), problem.grid.ny);
    }
  }
  // no approach carries the load (the semi-Hertzian root find, remedy included, did not converge): no
  // result to wear with; the life ends at its last accepted step (a contact cut at a body's edge is the
  // edge limit's, below, but only once its approach carries the load)
  if (!converged)
    throw NormalNotConverged(fmt::format("the normal problem did not converge: {}", status_message));
  // the lifetime's edge limit: how far the contact is from the end of the profiles' overlap
  const double lo = std::max(profiles.body1.y_m(0), profiles.body2.y_m(0));
  const double hi = std::min(profiles.body1.y_m(profiles.body1.y_m.size() - 1),
                             profiles.body2.y_m(profiles.body2.y_m.size() - 1));
  n.edge_margin_m = n.reaches_edge ? 0.0 : std::min(n.contact_y_min_m - lo, hi - n.contact_y_max_m);
  ++cache.counters.normal_solves;
  cache.normal_key = key;
  cache.normal = n;
  cache.normal_valid = true;
  return n;
}

}  // namespace

double edge_limit_value_m(const contact::Profiles& worn, const contact::SemiHertzResult& normal) {
  const contact::Profile &p1 = worn.body1, &p2 = worn.body2;
  const double lo = std::max(p1.y_m(0), p2.y_m(0));
  const double hi = std::min(p1.y_m(p1.y_m.size() - 1), p2.y_m(p2.y_m.size() - 1));
  const auto gap = [&](double y) { return contact::profile_z(p1, y) + contact::profile_z(p2, y); };
  // the gap is linear between the nodes of either profile: its minimum over the overlap is at one of them.
  // The nodes come in increasing y, so each profile is interpolated with a cursor instead of a search:
  // the same interval and arithmetic as contact::profile_z, so the same numbers
  struct Cursor {
    const contact::Profile& p;
    Eigen::Index hi = 1;
    double z(double y) {  // y increasing from call to call, within the profile's extent
      const Eigen::Index n = p.y_m.size();
      while (hi < n - 1 && p.y_m(hi) <= y) ++hi;
      const Eigen::Index lo = hi - 1;
      const double t = (y - p.y_m(lo)) / (p.y_m(hi) - p.y_m(lo));
      return (1 - t) * p.z_m(lo) + t * p.z_m(hi);
    }
  };
  double gap_min = std::min(gap(lo), gap(hi));
  for (const contact::Profile* p : {&p1, &p2}) {
    Cursor c1{p1}, c2{p2};
    for (Eigen::Index i = 0; i < p->y_m.size(); ++i) {
      const double y = p->y_m(i);
      if (y > lo && y < hi) gap_min = std::min(gap_min, c1.z(y) + c2.z(y));
    }
  }
  const double bound_m = normal.epsilon * normal.approach_m;  // contact where gap - gap_min < eps delta
  return bound_m - (std::min(gap(lo), gap(hi)) - gap_min);
}

namespace {

NormalState solved_normal_state_on(const WearModel& m, const contact::Profiles& worn, std::uint64_t key,
                                   const Eigen::VectorXd& state, WearCache& cache) {
  const long solves = cache.counters.normal_solves;
  const NormalState n = normal_state_on(m, worn, key, state, cache);
  if (cache.counters.normal_solves == solves) return n;  // from the cache: reported when it was solved
  if (n.reaches_edge && !m.limits.edge && !cache.edge_reported) {
    cache.edge_reported = true;
    spdlog::warn("wear: the contact reaches the end of the profiles' overlap (a body is narrower than the contact) "
                 "and wear.limits.edge is off: the contact is cut there from now on");
  }
  return n;
}

}  // namespace

NormalState normal_state(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  const contact::Profiles profiles = worn_profiles(m, state);
  return normal_state_on(m, profiles, contact::profile_hash(profiles), state, cache);
}

NormalState solved_normal_state(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  const contact::Profiles profiles = worn_profiles(m, state);
  return solved_normal_state_on(m, profiles, contact::profile_hash(profiles), state, cache);
}

namespace {

// the fast models' rate (the case's normal and tangential models), cached by the worn profiles' hash
WearRate fast_wear_rate(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  const contact::Profiles worn = worn_profiles(m, state);
  const std::uint64_t key = contact::profile_hash(worn);
  if (cache.reuse)
    for (const auto& [k, rate] : cache.rates)
      if (k == key) return rate;

  // normal problem on the current worn geometry (the profiles and their hash from above)
  const NormalState n = solved_normal_state_on(m, worn, key, state, cache);
  const contact::ContactPatch& patch = n.patch;

  // tangential problem over the duty cycle: dissipated energy per unit width
  const DutyCycleEnergy duty = duty_cycle_energy(m, patch, needs_fields(m.law1) || needs_fields(m.law2));
  ++cache.counters.tangential_solves;

  // wear law per strip, onto each worn body's nodes (volume-conserving smoothing), per revolution
  WearRate r;
  r.strip_energy_J_per_m = duty.strip_energy_J_per_m;
  r.strip_y0_m = n.grid_y0_m + patch.grid.y_edge(0);
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
  // fatigue: Burstow's damage per pass of each strip's T-gamma, on the reference body's nodes (the mean over each
  // node's cell, unsmoothed); each point of the reference body passes the contact once per revolution
  if (m.nD > 0) {
    const Eigen::ArrayXd Tg =
        strip_tgamma_N(duty.strip_energy_J_per_m, duty.rolled_m, n.contact_y_max_m - n.contact_y_min_m);
    const Eigen::ArrayXd d = Tg.unaryExpr([&](double t) { return burstow_damage_per_pass(m.fatigue->burstow, t); });
    const Eigen::ArrayXd& y = m.law1 ? m.profiles.body1.y_m : m.profiles.body2.y_m;
    r.dstate_dN.segment(m.damage_index(), m.nD) =
        m.damage_scale_m * strips_to_nodes(d, r.strip_y0_m, r.strip_dy_m, y).matrix();
    r.contact.max_tgamma_N = Tg.size() > 0 ? Tg.maxCoeff() : 0.0;
  }

  r.contact.a_m = patch.a_m;
  r.contact.b_m = patch.b_m;
  r.contact.p0_Pa = patch.p0_Pa;
  r.contact.Fx_N = duty.Fx_N;
  r.contact.power_W = duty.duration_s > 0 ? duty.dissipated_J / duty.duration_s : 0;
  r.contact.edge_margin_m = n.edge_margin_m;
  r.contact.edge_limit_m = n.edge_limit_m;
  r.contact.normal_solver = n.solver;
  r.contact.flash_rise_K = duty.flash_rise_K;
  r.contact.scuffing_margin_K = duty.scuffing_margin_K;
  if (m.shear_yield_Pa > 0 && patch.p0_Pa > 0) {
    const double f = std::abs(duty.Fx_N) / m.normal_load_N;
    const double limit = contact::shakedown_limit_p0_over_k(contact::shakedown_contact_of(patch.a_m, patch.b_m), f);
    r.contact.shakedown_margin = limit / (patch.p0_Pa / m.shear_yield_Pa) - 1;
  }

  if (cache.rates.size() >= kCachedRates) cache.rates.erase(cache.rates.begin());
  cache.rates.emplace_back(key, r);
  return r;
}

// the worn nodes' part of a rate (body1's, then body2's)
Eigen::ArrayXd node_rates(const WearModel& m, const WearRate& r) { return r.dstate_dN.head(m.n1 + m.n2).array(); }

// the reference body's nodes and its segment in the state
const Eigen::ArrayXd& reference_nodes(const WearModel& m) { return m.law1 ? m.profiles.body1.y_m : m.profiles.body2.y_m; }
Eigen::ArrayXd reference_segment(const WearModel& m, const Eigen::ArrayXd& nodes) {
  return m.law1 ? nodes.head(m.n1) : nodes.segment(m.n1, m.n2);
}

// the correction applied to the fast rate (FidelityCorrection): per node, a ratio where the fast model wears at
// the correction and the difference held where it does not; the energy scaled as the reference body's worn area
void apply_correction(const WearModel& m, const FidelityCorrection& c, WearRate& r) {
  const Eigen::ArrayXd f = node_rates(m, r);
  Eigen::ArrayXd out(f.size());
  for (const auto& [offset, n] : {std::pair{0, m.n1}, std::pair{m.n1, m.n2}}) {
    if (n == 0) continue;
    const Eigen::ArrayXd x0 = c.exact_rate.segment(offset, n).array();
    const Eigen::ArrayXd f0 = c.fast_rate.segment(offset, n).array();
    const double floor = kCorrectionFloor * f0.abs().maxCoeff();
    if (!(floor > 0)) {  // the fast model did not wear this body at all: the exact rate held
      out.segment(offset, n) = x0;
      continue;
    }
    const Eigen::ArrayXd ratio = (x0 + floor) / (f0 + floor);
    out.segment(offset, n) = (f.segment(offset, n) * ratio + (x0 - f0 * ratio)).max(0.0);
  }
  const Eigen::ArrayXd& y = reference_nodes(m);
  const double fast_area = profile_area_m2(reference_segment(m, f), y);
  const double scale = fast_area > 0 ? profile_area_m2(reference_segment(m, out), y) / fast_area
                                     : (c.fast_energy_J > 0 ? c.exact_energy_J / c.fast_energy_J : 1.0);
  r.dstate_dN.head(m.n1 + m.n2) = out.matrix();
  r.dstate_dN(m.energy_index()) *= scale;
  r.energy_per_revolution_J *= scale;
  r.contact.power_W *= scale;
}

// the strips' energy per duty cycle on the reference body's nodes (conserving, unsmoothed), per revolution
Eigen::ArrayXd node_energy_per_revolution(const WearModel& m, const WearRate& r) {
  return r.cycles_per_revolution * strips_to_nodes(r.strip_energy_J_per_m, r.strip_y0_m, r.strip_dy_m, reference_nodes(m));
}

// the fast rate's error against the exact one on the same state (FidelityError)
FidelityError rate_error(const WearModel& m, double N, const WearRate& fast, const WearRate& exact) {
  FidelityError e;
  e.N = N;
  e.power_rel = fast.energy_per_revolution_J / exact.energy_per_revolution_J - 1;
  e.exact_energy_J = exact.energy_per_revolution_J;
  const Eigen::ArrayXd& y = reference_nodes(m);
  const Eigen::ArrayXd uf = node_energy_per_revolution(m, fast), ux = node_energy_per_revolution(m, exact);
  e.power_l1 = profile_area_m2((uf - ux).abs(), y) / profile_area_m2(ux.abs(), y);
  return e;
}

// the exact physics' rate on the state, in its own cache (its half-space solves cold: a function of the state)
// how far the worn gap's shape has moved between two states: the spread (largest minus smallest) of the depth's
// change over each worn body's nodes across the contact (a depth worn evenly across it moves the body, not the
// contact), the larger of the bodies'
double shape_change_m(const WearModel& m, const Eigen::VectorXd& state, const Eigen::VectorXd& before,
                      const NormalState& n) {
  double spread = 0;
  for (const auto& [offset, count, y] : {std::tuple{0, m.n1, &m.profiles.body1.y_m},
                                         std::tuple{m.n1, m.n2, &m.profiles.body2.y_m}}) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int i = 0; i < count; ++i) {
      if ((*y)(i) < n.contact_y_min_m || (*y)(i) > n.contact_y_max_m) continue;
      const double d = state(offset + i) - before(offset + i);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    if (hi >= lo) spread = std::max(spread, hi - lo);
  }
  return spread;
}

void exact_wear_cache(WearCache& cache) {
  if (cache.exact_physics.empty()) {
    cache.exact_physics.emplace_back();
    cache.exact_physics.front().halfspace_warm_start = false;
  }
}
WearRate exact_wear_rate(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  exact_wear_cache(cache);
  return fast_wear_rate(m.exact_physics.front(), state, cache.exact_physics.front());
}

// the fast models on the exact physics' grid (the correction's like with like): WearModel::correction_fast on
// a coarser correction grid, else the case's own
WearRate like_fast_wear_rate(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  if (m.correction_fast.empty()) return fast_wear_rate(m, state, cache);
  if (cache.correction_fast.empty()) cache.correction_fast.emplace_back();
  return fast_wear_rate(m.correction_fast.front(), state, cache.correction_fast.front());
}
NormalState like_fast_normal_state(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  if (m.correction_fast.empty()) return solved_normal_state(m, state, cache);
  if (cache.correction_fast.empty()) cache.correction_fast.emplace_back();
  return solved_normal_state(m.correction_fast.front(), state, cache.correction_fast.front());
}

}  // namespace

NormalState exact_normal_state(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  if (!m.limits_physics.empty()) {
    if (cache.limits_physics.empty()) {
      cache.limits_physics.emplace_back();
      cache.limits_physics.front().halfspace_warm_start = false;
    }
    return solved_normal_state(m.limits_physics.front(), state, cache.limits_physics.front());
  }
  exact_wear_cache(cache);
  return solved_normal_state(m.exact_physics.front(), state, cache.exact_physics.front());
}

bool has_exact_physics(const WearModel& m) {
  if (m.conditions.empty()) return !m.exact_physics.empty();
  return std::any_of(m.conditions.begin(), m.conditions.end(), [](const WearModel& mk) { return !mk.exact_physics.empty(); });
}

bool correction_made(const WearModel& m, const WearCache& cache) {
  if (m.conditions.empty()) return cache.correction.valid;
  if (cache.conditions.size() != m.conditions.size()) return false;
  return std::all_of(cache.conditions.begin(), cache.conditions.end(), [](const WearCache& ck) { return ck.correction.valid; });
}

long exact_solves(const WearModel& m, const WearCache& cache) {
  long n = cache.correction.solves;
  if (!m.conditions.empty())
    for (const WearCache& ck : cache.conditions) n += ck.correction.solves;
  return n;
}

WearRate wear_rate(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  ++cache.counters.rate_evaluations;
  if (!m.conditions.empty()) return collective_rate(m, state, cache);
  WearRate r = fast_wear_rate(m, state, cache);
  if (m.fidelity == contact::Fidelity::Corrected && cache.correction.valid) apply_correction(m, cache.correction, r);
  return r;
}

bool update_correction(const WearModel& m, double N, const Eigen::VectorXd& state, WearCache& cache) {
  if (!m.conditions.empty()) {
    // a collective: each running condition on its own schedule, the estimate combined over them
    if (m.fidelity != contact::Fidelity::Corrected) return false;
    prepare_condition_caches(m, cache);
    const std::vector<LifeCounters> before = condition_counters(cache);
    bool any = false;
    for (std::size_t k = 0; k < m.conditions.size(); ++k)
      any = update_correction(m.conditions[k], N, state, cache.conditions[k]) || any;
    add_condition_solves(cache, before);
    cache.error = collective_error(m, cache);
    return any;
  }
  if (m.fidelity != contact::Fidelity::Corrected || m.exact_physics.empty()) return false;
  FidelityCorrection& c = cache.correction;
  const WearRate fast = fast_wear_rate(m, state, cache);
  if (c.valid) {
    // the schedule: the worn profile, or the fast models' own power, moved by more than the tolerance
    const double moved_m = shape_change_m(m, state, c.state, solved_normal_state(m, state, cache));
    const double power_moved = std::abs(fast.energy_per_revolution_J / c.fast_energy_J - 1);
    if (moved_m <= m.correction_tolerance * c.approach_m && power_moved <= m.correction_tolerance) return false;
    spdlog::debug("wear: the worn gap's shape moved {:.4g} m, the fast power {:.3g}", moved_m, power_moved);
  }
  const WearRate exact = exact_wear_rate(m, state, cache);
  const WearRate like = like_fast_wear_rate(m, state, cache);  // the fast models on the exact physics' grid
  c.valid = true;
  c.N = N;
  c.state = state;
  c.exact_rate = node_rates(m, exact).matrix();
  c.fast_rate = node_rates(m, like).matrix();
  c.exact_energy_J = exact.energy_per_revolution_J;
  c.fast_energy_J = fast.energy_per_revolution_J;
  const NormalState& exact_normal = cache.exact_physics.front().normal;
  const NormalState fast_normal = like_fast_normal_state(m, state, cache);
  c.approach_m = exact_normal.approach_m;
  c.edge_offset_m = exact_normal.edge_limit_m - fast_normal.edge_limit_m;
  c.pressure_offset_Pa = exact_normal.patch.p0_Pa - fast_normal.patch.p0_Pa;
  // the switch to the exact physics' own limits (docs/fidelity.md, "The limits"): the half-space edge value is the
  // approach x the distance of the contact's lateral edge past the end / the contact's half-width, the fast one a
  // gap; the two are different functions of the state, so the offset above holds only while the exact contact's
  // edge is more than kNearEdge half-widths from the end (its drift between corrections is well below that)
  c.exact_limits = c.exact_limits || (m.limits.edge && exact_normal.edge_limit_m > -kNearEdge * c.approach_m) ||
                   (m.limits.max_pressure_Pa > 0 &&
                    exact_normal.patch.p0_Pa > (1 - kNearEdge * m.correction_tolerance) * m.limits.max_pressure_Pa);
  ++c.solves;
  cache.error = rate_error(m, N, like, exact);
  spdlog::debug("wear: correction {} at N {:.6g}: fast power {:+.3g} %, per-strip L1 {:.3g} %; approach {:.4g} m, "
                "exact edge value {:.4g} m (offset {:.4g}), exact limits {}",
                c.solves, N, 100 * cache.error.power_rel, 100 * cache.error.power_l1, c.approach_m,
                exact_normal.edge_limit_m, c.edge_offset_m, c.exact_limits);
  return true;
}

FidelityError fast_model_error(const WearModel& m, double N, const Eigen::VectorXd& state, WearCache& cache) {
  if (!m.conditions.empty()) {  // each condition's, combined (collective_error); its solves in each condition's count
    prepare_condition_caches(m, cache);
    const std::vector<LifeCounters> before = condition_counters(cache);
    for (std::size_t k = 0; k < m.conditions.size(); ++k) {
      WearCache& ck = cache.conditions[k];
      ck.error = fast_model_error(m.conditions[k], N, state, ck);
      if (!m.conditions[k].exact_physics.empty()) ++ck.correction.solves;
    }
    add_condition_solves(cache, before);
    return collective_error(m, cache);
  }
  if (m.exact_physics.empty()) return {};
  return rate_error(m, N, like_fast_wear_rate(m, state, cache), exact_wear_rate(m, state, cache));
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

double max_damage(const WearModel& m, const Eigen::VectorXd& state) {
  return m.nD > 0 ? state.segment(m.damage_index(), m.nD).maxCoeff() / m.damage_scale_m : 0.0;
}

double max_damage_y_m(const WearModel& m, const Eigen::VectorXd& state) {
  if (m.nD == 0) return std::numeric_limits<double>::quiet_NaN();
  Eigen::Index i = 0;
  if (!(state.segment(m.damage_index(), m.nD).maxCoeff(&i) > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (m.law1 ? m.profiles.body1.y_m : m.profiles.body2.y_m)(i);
}

// ---- the life ----

namespace {

enum Limit { kDepth, kPressure, kEdge, kFatigue, kShakedown, kScuffing, kLimits };

// The wear is carried by the worn bodies' profile nodes: a contact narrower than a few node spacings
// would put a strip's wear on one node and the next solve could not see the worn shape. Throws
// contact::CaseError at the profile's key, naming what the user can set (wear_case.h).
constexpr int kMinNodesAcrossContact = 4;
// each running condition's model and cache (a collective's, or the model's own), their solves counted
template <class F>
void for_each_condition(const WearModel& m, WearCache& cache, F f) {
  if (m.conditions.empty()) return f(m, cache);
  prepare_condition_caches(m, cache);
  const std::vector<LifeCounters> before = condition_counters(cache);
  for (std::size_t k = 0; k < m.conditions.size(); ++k) f(m.conditions[k], cache.conditions[k]);
  add_condition_solves(cache, before);
}

void check_profile_resolves_contact(const WearCase& c, const WearModel& m, const NormalState& n) {
  const double width = n.contact_y_max_m - n.contact_y_min_m;
  for (int body : {1, 2}) {
    if ((body == 1 ? m.n1 : m.n2) == 0) continue;
    const Eigen::ArrayXd& y = body == 1 ? m.profiles.body1.y_m : m.profiles.body2.y_m;
    const double spacing = (y.tail(y.size() - 1) - y.head(y.size() - 1)).maxCoeff();
    wear::check_profile_resolves_contact(c, body, spacing, width, kMinNodesAcrossContact);
  }
}

// what ends the life by the worn geometry, if e (or an exception nested in it: wear::integrate nests
// what f threw) is a LifeEndingGeometry
LifeFailure geometry_failure(const std::exception& e) {
  if (dynamic_cast<const UnresolvedContact*>(&e)) return LifeFailure::UnresolvedContact;
  if (dynamic_cast<const WornThrough*>(&e)) return LifeFailure::WornThrough;
  if (dynamic_cast<const NormalNotConverged*>(&e)) return LifeFailure::NormalNotConverged;
  try {
    std::rethrow_if_nested(e);
  } catch (const std::exception& inner) {
    return geometry_failure(inner);
  } catch (...) {
  }
  return LifeFailure::None;
}

// The lifetime limits as signed, continuous functions of the state, g_k(h) < 0 inside the life: a sign
// change ends it, located by the integrator's root finding. A limit that is off is -1.
Eigen::VectorXd limit_values(const WearModel& m, const Eigen::VectorXd& h, WearCache& cache) {
  ++cache.counters.limit_evaluations;
  Eigen::VectorXd g = Eigen::VectorXd::Constant(kLimits, -1.0);
  if (m.limits.max_depth_m > 0) g(kDepth) = max_depth_m(m, h) - m.limits.max_depth_m;
  // fatigue: the largest damage reaches 1 (linear in the state: located on the integrator's dense output)
  if (m.nD > 0) g(kFatigue) = max_damage(m, h) - 1;
  // shakedown: the load factor leaves Johnson's map (the margin, read from the rate at h, crosses 0)
  if (m.limits.shakedown) g(kShakedown) = -wear_rate(m, h, cache).contact.shakedown_margin;
  // scuffing: the contact temperature reaches Blok's critical one (K)
  if (m.limits.scuffing) g(kScuffing) = -wear_rate(m, h, cache).contact.scuffing_margin_K;
  if (m.limits.max_pressure_Pa <= 0 && !m.limits.edge) return g;
  // a collective's: the highest peak pressure and the widest contact of its running conditions
  bool first = true;
  for_each_condition(m, cache, [&](const WearModel& mk, WearCache& ck) {
    // the corrected fidelity: the exact physics' limits, as the fast ones plus the last correction's offsets, or
    // from the switch (FidelityCorrection::exact_limits) the exact physics' normal solve itself
    const FidelityCorrection& k = ck.correction;
    const bool exact_limits = mk.fidelity == contact::Fidelity::Corrected && k.valid && k.exact_limits;
    const bool corrected = mk.fidelity == contact::Fidelity::Corrected && k.valid && !k.exact_limits;
    // (on a coarser correction grid, the exact physics' normal solve on the case's grid: the life ends where that
    // says, not the coarse grid's edge; WearModel::limits_physics)
    const NormalState n = exact_limits ? exact_normal_state(mk, h, ck) : solved_normal_state(mk, h, ck);
    const double pressure = n.patch.p0_Pa + (corrected ? k.pressure_offset_Pa : 0.0) - m.limits.max_pressure_Pa;
    if (m.limits.max_pressure_Pa > 0) g(kPressure) = first ? pressure : std::max(g(kPressure), pressure);
    if (m.limits.edge) {
      const double edge = n.edge_limit_m + (corrected ? k.edge_offset_m : 0.0);
      g(kEdge) = first ? edge : std::max(g(kEdge), edge);
    }
    first = false;
  });
  return g;
}

// the roller's life as the driver's problem: dh/dN = wear_rate, the limits depth, pressure and edge, the
// cache's solve counts; the worn geometry ending the life (a contact the strips cannot resolve, a body
// worn through) ends it at its last accepted step, failed
LifeProblem life_problem(const WearModel& m, const WearCase& c, WearCache& cache) {
  LifeProblem p;
  p.rate = [&m, &cache](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) {
    dhdN = wear_rate(m, h, cache).dstate_dN;
  };
  p.limits = {LifeEnd::MaxDepth, LifeEnd::MaxPressure, LifeEnd::Edge, LifeEnd::Fatigue, LifeEnd::Shakedown,
              LifeEnd::Scuffing};
  p.limit_values = [&m, &cache](double, const Eigen::VectorXd& h, Eigen::VectorXd& g) {
    g = limit_values(m, h, cache);
  };
  p.options = integrator_options(c.wear.stepping);
  p.revolutions = c.wear.revolutions;
  p.budget_key = "wear.revolutions";
  p.snapshots_revolutions = c.wear.snapshots_revolutions;
  p.solves = [&cache] { return cache.counters; };
  // the corrected fidelity's schedule: a new correction restarts the integration at its step end
  if (m.fidelity == contact::Fidelity::Corrected)
    p.refresh = [&m, &cache](double N, const Eigen::VectorXd& h) { return update_correction(m, N, h, cache); };
  p.failure_of = [](const std::exception& e, double N_last) {
    const LifeFailure failure = geometry_failure(e);
    if (failure != LifeFailure::None)
      spdlog::warn("wear: {}; the life ends at N {:.10g}, its last accepted step", e.what(), N_last);
    return failure;
  };
  return p;
}

}  // namespace

LifeResult run_life(const WearModel& m, const WearCase& c, const LifeStart& start, const LifeHooks& hooks,
                    WearCache& cache) {
  LifeStart from = start;
  if (from.state.size() == 0) from.state = initial_state(m);

  LifeResult life;
  LifeDriverHooks driver;
  // the worn body's profile must resolve the contact: its nodes carry the wear
  driver.on_start = [&](double N, const Eigen::VectorXd& state) {
    for_each_condition(m, cache, [&](const WearModel& mk, WearCache& ck) {
      check_profile_resolves_contact(c, mk, solved_normal_state(mk, state, ck));
    });
    // the corrected fidelity's first correction (a resumed life has its checkpoint's)
    if (!correction_made(m, cache)) update_correction(m, N, state, cache);
  };
  // each accepted step reported with the contact at its end; the contact where the life ends
  driver.on_step = [&](const LifeStepEnd& e) {
    LifeStep s;
    s.N = e.N;
    s.state = e.state;
    s.contact = wear_rate(m, *e.state, cache).contact;
    s.counters = e.counters();
    s.step = s.counters.steps;
    s.info = e.info;
    return hooks.on_step ? hooks.on_step(s) : true;
  };
  driver.on_snapshot = hooks.on_snapshot;
  driver.on_end = [&](double N, const Eigen::VectorXd& state) {
    life.contact = wear_rate(m, state, cache).contact;
    // the fast fidelity's error estimate: one exact-physics solve on the final worn state (the corrected one's
    // is its last correction's); a solve that fails leaves it NaN
    if (m.fidelity == contact::Fidelity::Fast && m.error_estimate && has_exact_physics(m)) try {
        cache.error = fast_model_error(m, N, state, cache);
        if (m.conditions.empty()) ++cache.correction.solves;
      } catch (const std::exception& e) {
        spdlog::info("wear: no error estimate at the end of the life: {}", e.what());
      }
  };
  static_cast<LifeOutcome&>(life) = integrate_life(life_problem(m, c, cache), from, driver);
  life.error = cache.error;
  life.exact_solves = exact_solves(m, cache);
  if (life.ended_by == LifeEnd::Edge)
    spdlog::info("wear: the contact has spread to the edge of the narrower body at {:.6g} revolutions (step {}); "
                 "the life ends there (wear.limits.edge)",
                 life.N, life.counters.steps);
  return life;
}

}  // namespace wear
