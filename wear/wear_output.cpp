#include "wear/wear_output.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include <spdlog/fmt/fmt.h>

#include "lib/history.h"
#include "wear/collective.h"
#include "lib/csv_reader.h"
#include "lib/errors.h"
#include "lib/number.h"
#include "lib/numeric.h"

namespace wear {

using contact::kPi;

namespace {

// 3: what a life carries from step to step in named blocks only; 2 (read still): the corrected fidelity's
// correction in a line of its own
constexpr const char* kCheckpointMagic = "rollwear-wear-checkpoint 3";
constexpr const char* kCheckpointMagic2 = "rollwear-wear-checkpoint 2";

// every number at full precision: the shortest text that reads back as the same double (lib/number.h)
using contact::round_trip;

std::string law_text(const WearLaw& law) {
  switch (law.law) {
    case WearLawKind::Energy: return fmt::format("energy, k_E {} m^3/J", round_trip(law.k_E_m3_per_J));
    case WearLawKind::Archard:
      return fmt::format("archard, K {}, H {} Pa (k_E = K/(H mu))", round_trip(law.archard_k),
                         round_trip(law.hardness_Pa));
    case WearLawKind::Kth: return fmt::format("kth, H {} Pa", round_trip(law.hardness_Pa));
    case WearLawKind::Usfd: return fmt::format("usfd, rho {} kg/m^3", round_trip(law.density_kg_per_m3));
  }
  return to_string(law.law);
}

}  // namespace

double hours_per_revolution(const WearModel& m) {
  if (!m.conditions.empty()) {  // a collective: each condition's hours for its share of the revolutions
    double hours = 0;
    for (std::size_t k = 0; k < m.conditions.size(); ++k) hours += m.weights[k] * hours_per_revolution(m.conditions[k]);
    return hours;
  }
  double V = m.speed_m_per_s;
  if (m.transient) {
    const double T = m.transient->settings.t_end_s;
    V = contact::integral(m.transient->inputs.speed_m_per_s, 0, T) / T;
  }
  return V > 0 ? 2 * kPi * m.reference_radius_m / V / 3600 : 0;
}

std::string wear_summary_header(const WearModel& m) {
  std::string s = fmt::format("# case: {}\n", m.name);
  if (m.law1) s += fmt::format("# body1 wears: {}\n", law_text(*m.law1));
  if (m.law2) s += fmt::format("# body2 wears: {}\n", law_text(*m.law2));
  if (!m.conditions.empty()) {  // a load collective (wear/collective.h)
    std::string weights;
    for (const double w : m.weights) weights += (weights.empty() ? "" : ", ") + round_trip(w);
    s += fmt::format("# collective: {} running conditions, weights {}; a_m to power_W are the condition's with the "
                     "highest p0\n",
                     m.conditions.size(), weights);
  }
  s += fmt::format("# models: normal {}, tangential {}, fidelity {}\n", contact::to_string(m.normal_choice),
                   contact::to_string(m.scheme), contact::to_string(m.fidelity));
  s += fmt::format("# revolutions of body{} (R {} m); one row per accepted step, step 0 unworn\n", m.law1 ? 1 : 2,
                   round_trip(m.reference_radius_m));
  if (m.fatigue)
    s += fmt::format("# fatigue: {} (T-gamma threshold {} N, peak {} per pass at {} N, none from {} N); max_damage: "
                     "the largest Miner damage on body{}\n",
                     to_string(m.fatigue->law), round_trip(m.fatigue->burstow.threshold_N),
                     round_trip(m.fatigue->burstow.peak_damage), round_trip(m.fatigue->burstow.peak_at_N),
                     round_trip(m.fatigue->burstow.zero_at_N), m.law1 ? 1 : 2);
  s += "step,revolutions,hours,max_depth_m,worn_volume_m3,dissipated_J,a_m,b_m,p0_Pa,Fx_N,power_W,"
       "step_revolutions,error_estimate,rejected,rhs_evals";
  s += m.fatigue ? ",max_damage\n" : "\n";
  return s;
}

std::string wear_summary_row(const WearModel& m, const LifeStep& s, double hours_per_rev) {
  const Eigen::VectorXd& h = *s.state;
  std::string row = fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}", s.step, round_trip(s.N), round_trip(s.N * hours_per_rev),
                     round_trip(max_depth_m(m, h)), round_trip(worn_volume_m3(m, h, 1) + worn_volume_m3(m, h, 2)),
                     round_trip(dissipated_energy_J(m, h)), round_trip(s.contact.a_m), round_trip(s.contact.b_m), round_trip(s.contact.p0_Pa),
                     round_trip(s.contact.Fx_N), round_trip(s.contact.power_W), round_trip(s.info.step), round_trip(s.info.error_estimate),
                     s.info.rejected, s.info.rhs_evals);
  if (m.fatigue) row += "," + round_trip(max_damage(m, h));
  return row + "\n";
}

std::string wear_snapshot_csv(const WearModel& m, int body, double N, double hours, const Eigen::VectorXd& state) {
  const contact::Profile& p = body == 1 ? m.profiles.body1 : m.profiles.body2;
  const int n = body == 1 ? m.n1 : m.n2;
  const int offset = body == 1 ? 0 : m.n1;
  if (n == 0) throw std::invalid_argument(fmt::format("wear snapshot: body{} does not wear", body));
  std::string s = fmt::format("# case: {}\n# body: body{}\n# revolutions: {}\n# hours: {}\n", m.name, body, round_trip(N),
                              round_trip(hours));
  // with wear.fatigue, the reference body's (the first that wears) Miner damage at each node (docs/fatigue.md §2)
  const bool damage = m.nD > 0 && body == (m.law1 ? 1 : 2);
  if (damage && m.nD != n) throw std::logic_error("wear snapshot: the damage's nodes are not the reference body's");
  s += damage ? "y_m,z_original_m,z_m,depth_m,damage\n" : "y_m,z_original_m,z_m,depth_m\n";
  for (int i = 0; i < n; ++i) {
    const double d = state(offset + i);
    s += fmt::format("{},{},{},{}", round_trip(p.y_m(i)), round_trip(p.z_m(i)), round_trip(p.z_m(i) + d), round_trip(d));
    if (damage) s += "," + round_trip(state(m.damage_index() + i) / m.damage_scale_m);
    s += "\n";
  }
  return s;
}

std::filesystem::path wear_snapshot_path(int index, int body) {
  return std::filesystem::path("snapshots") / fmt::format("snapshot_{:04d}_body{}.csv", index, body);
}

std::string life_report_text(const LifeReport& r) {
  const auto number = [&](double v) { return r.digits > 0 ? fmt::format("{:.{}g}", v, r.digits) : round_trip(v); };
  std::string s;
  s += fmt::format("case: {}\n", r.case_name);
  s += fmt::format("ended_by: {}\n", to_string(r.ended_by));
  if (r.failure != LifeFailure::None) s += fmt::format("failure: {}\n", to_string(r.failure));
  s += fmt::format("message: {}\n", r.message);
  s += fmt::format("revolutions: {}\n", number(r.revolutions));
  s += fmt::format("hours: {}\n", number(r.hours));
  s += fmt::format("max_depth_m: {}\n", number(r.max_depth_m));
  s += fmt::format("dissipated_J: {}\n", number(r.dissipated_J));
  const LifeCounters& n = r.counters;
  s += fmt::format("steps: {}\nrejected_steps: {}\nrhs_evals: {}\n", n.steps, n.rejected, n.rhs_evals);
  s += fmt::format("resumed: {}\n", r.resumed ? "true" : "false");
  for (const auto& [key, value] : r.own) s += fmt::format("{}: {}\n", key, value);
  return s;
}

std::string error_estimate_of(const WearModel& m) {
  if (m.fidelity == contact::Fidelity::Exact) return "not estimated: the exact physics ran";
  if (!has_exact_physics(m)) {
    if (!m.conditions.empty() || !(m.mu > 0)) return "not estimated: mu = 0 (the exact theory needs friction)";
    return "not estimated: the transient duty cycle has no steady part (constant speed > 0, creepages and load)";
  }
  if (m.fidelity == contact::Fidelity::Fast && !m.error_estimate) return "not estimated: solver.error_estimate false";
  if (!m.conditions.empty()) {
    const bool transient = std::any_of(m.conditions.begin(), m.conditions.end(), [](const WearModel& mk) { return mk.transient.has_value(); });
    return std::string("each running condition's, energy-weighted") +
           (transient ? " (a transient condition's at its steady part)" : "");
  }
  if (m.steady_part)
    return fmt::format("the transient duty cycle's steady part (steady rolling at {} m/s, xi {}, eta {}, phi {} 1/m; "
                       "its start and stop not estimated)",
                       round_trip(m.steady_part->speed_m_per_s), round_trip(m.steady_part->creepages.xi),
                       round_trip(m.steady_part->creepages.eta), round_trip(m.steady_part->creepages.phi_per_m));
  return "the steady duty cycle";
}

std::vector<std::pair<std::string, std::string>> fidelity_report(const WearModel& m, const LifeResult& l) {
  std::vector<std::pair<std::string, std::string>> out;
  out.emplace_back("tangential_model", contact::to_string(m.scheme));
  out.emplace_back("fidelity", contact::to_string(m.fidelity));
  if (m.fidelity == contact::Fidelity::Corrected) out.emplace_back("correction_tolerance", round_trip(m.correction_tolerance));
  out.emplace_back("exact_solves", std::to_string(l.exact_solves));
  out.emplace_back("error_estimate_of", error_estimate_of(m));
  out.emplace_back("error_estimate_N", round_trip(l.error.N));
  out.emplace_back("error_power_rel", round_trip(l.error.power_rel));
  out.emplace_back("error_power_l1", round_trip(l.error.power_l1));
  return out;
}

std::vector<std::pair<std::string, std::string>> failure_margins(const WearModel& m, const LifeResult& l) {
  std::vector<std::pair<std::string, std::string>> out;
  if (!m.fatigue && !m.limits.shakedown && !m.limits.scuffing && !m.thermal && l.dang_van.empty()) return out;
  if (m.limits.max_depth_m > 0)
    out.emplace_back("depth_fraction", round_trip(max_depth_m(m, l.state) / m.limits.max_depth_m));
  if (m.fatigue) {
    out.emplace_back("fatigue_law", to_string(m.fatigue->law));
    out.emplace_back("max_damage", round_trip(max_damage(m, l.state)));
    out.emplace_back("max_damage_y_m", round_trip(max_damage_y_m(m, l.state)));
    out.emplace_back("max_tgamma_N", round_trip(l.contact.max_tgamma_N));
  }
  if (m.shear_yield_Pa > 0) out.emplace_back("shakedown_margin", round_trip(l.contact.shakedown_margin));
  if (m.thermal) {
    out.emplace_back("flash_rise_K", round_trip(l.contact.flash_rise_K));
    if (m.thermal->critical_temperature_C) out.emplace_back("scuffing_margin_K", round_trip(l.contact.scuffing_margin_K));
  }
  for (const LifeDangVan& d : l.dang_van) {  // on the final worn contact (wear/dang_van_life.h)
    const std::string body = fmt::format("dang_van_body{}_", d.body);
    out.emplace_back(body + "index", round_trip(d.field.index_max));
    out.emplace_back(body + "depth_m", round_trip(d.field.z_m));
    out.emplace_back(body + "y_m", round_trip(d.field.y_m));
    if (d.condition > 0) out.emplace_back(body + "condition", std::to_string(d.condition));
  }
  return out;
}

std::string wear_summary_error_line(const WearModel& m, const LifeResult& l) {
  return fmt::format("# error estimate ({} fidelity, {} exact-physics solves): at N {} the fast models' total power "
                     "relative error {}, per-strip power L1 {}; of {}\n",
                     contact::to_string(m.fidelity), l.exact_solves, round_trip(l.error.N),
                     round_trip(l.error.power_rel), round_trip(l.error.power_l1), error_estimate_of(m));
}

std::string wear_report_text(const WearModel& m, const WearReport& r) {
  const LifeResult& l = r.life;
  LifeReport report;
  report.case_name = r.case_name;
  report.ended_by = l.ended_by;
  report.failure = l.failure;
  report.message = l.message;
  report.revolutions = l.N;
  report.hours = l.N * r.hours_per_revolution;
  report.max_depth_m = max_depth_m(m, l.state);
  report.dissipated_J = dissipated_energy_J(m, l.state);
  report.counters = l.counters;
  report.resumed = r.resumed;
  auto& own = report.own;
  own.emplace_back("reference_body", fmt::format("body{}", m.law1 ? 1 : 2));
  if (m.law1) own.emplace_back("worn_volume_body1_m3", round_trip(worn_volume_m3(m, l.state, 1)));
  if (m.law2) own.emplace_back("worn_volume_body2_m3", round_trip(worn_volume_m3(m, l.state, 2)));
  own.emplace_back("p0_Pa", round_trip(l.contact.p0_Pa));
  own.emplace_back("a_m", round_trip(l.contact.a_m));
  own.emplace_back("b_m", round_trip(l.contact.b_m));
  own.emplace_back("normal_solver", contact::to_string(l.contact.normal_solver));
  // the lubricant's film and the regime law's mu and wear factor the life used: the case's, or each condition's
  const auto lubrication = [&own](const WearModel& c, const std::string& prefix) {
    if (!c.lubrication) return;
    own.emplace_back(prefix + "lambda", round_trip(c.lubrication->lambda));
    own.emplace_back(prefix + "lubrication_regime", contact::to_string(c.lubrication->regime));
    own.emplace_back(prefix + "asperity_share", round_trip(c.regime.asperity_share));
    own.emplace_back(prefix + "mu_used", round_trip(c.mu));
    own.emplace_back(prefix + "wear_factor_used", round_trip(c.wear_factor));
  };
  if (m.conditions.empty()) lubrication(m, "");
  for (std::size_t k = 0; k < m.conditions.size(); ++k) lubrication(m.conditions[k], fmt::format("condition{}_", k + 1));
  for (const auto& [key, value] : failure_margins(m, l)) own.emplace_back(key, value);
  for (const auto& [key, value] : fidelity_report(m, l)) own.emplace_back(key, value);
  const LifeCounters& n = l.counters;
  own.emplace_back("rate_evaluations", std::to_string(n.rate_evaluations));
  own.emplace_back("limit_evaluations", std::to_string(n.limit_evaluations));
  own.emplace_back("normal_solves", std::to_string(n.normal_solves));
  own.emplace_back("tangential_solves", std::to_string(n.tangential_solves));
  own.emplace_back("wall_s", fmt::format("{:.3f}", r.wall_s));
  return life_report_text(report);
}

// ---- checkpoint ----

std::uint64_t case_fingerprint(const std::string& case_text, const WearModel& m) {
  std::uint64_t h = contact::hash_words(case_text.data(), case_text.size());
  const std::int64_t n = m.state_size();
  h = contact::hash_words(&n, sizeof n, h);
  return h ^ contact::profile_hash(m.profiles);
}

void BlockWriter::put(const Eigen::ArrayXd& a) {
  put(static_cast<double>(a.size()));
  values.insert(values.end(), a.data(), a.data() + a.size());
}

void BlockWriter::put(const Eigen::ArrayXXd& a) {
  put(static_cast<double>(a.rows()));
  put(static_cast<double>(a.cols()));
  values.insert(values.end(), a.data(), a.data() + a.size());
}

CheckpointBlock BlockWriter::block(std::string name) const {
  return {std::move(name), Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()))};
}

double BlockReader::number() {
  if (at >= block.values.size())
    throw std::runtime_error(fmt::format("checkpoint block '{}' ends early ({} numbers)", block.name, block.values.size()));
  return block.values(at++);
}

long BlockReader::integer(long max) {
  const double v = number();
  if (!(v >= 0 && v <= static_cast<double>(max)) || v != std::floor(v))
    throw std::runtime_error(fmt::format("checkpoint block '{}': expected a whole number up to {} at its number {}, got {}",
                                         block.name, max, at, v));
  return static_cast<long>(v);
}

namespace {
constexpr long kMaxBlockArray = 100000000;
}

Eigen::ArrayXd BlockReader::array() {
  const long n = integer(kMaxBlockArray);
  Eigen::ArrayXd a(n);
  for (long i = 0; i < n; ++i) a(i) = number();
  return a;
}

Eigen::ArrayXXd BlockReader::array2d() {
  const long rows = integer(kMaxBlockArray), cols = integer(kMaxBlockArray);
  if (rows * cols > kMaxBlockArray)
    throw std::runtime_error(fmt::format("checkpoint block '{}': an array of {} x {}", block.name, rows, cols));
  Eigen::ArrayXXd a(rows, cols);
  for (Eigen::Index i = 0; i < a.size(); ++i) a.data()[i] = number();
  return a;
}

void BlockReader::finish() const {
  if (at != block.values.size())
    throw std::runtime_error(fmt::format("checkpoint block '{}' has {} numbers, {} expected", block.name,
                                         block.values.size(), at));
}

const CheckpointBlock* find_block(const std::vector<CheckpointBlock>& blocks, const std::string& name) {
  for (const CheckpointBlock& b : blocks)
    if (b.name == name) return &b;
  return nullptr;
}

namespace {

constexpr const char* kCorrectionBlock = "correction";
constexpr const char* kErrorBlock = "error";
constexpr const char* kHalfspaceNormalBlock = "halfspace_normal";

CheckpointBlock correction_block(const FidelityCorrection& k) {
  BlockWriter w;
  for (const double v : {k.N, k.exact_energy_J, k.fast_energy_J, k.approach_m, k.edge_offset_m, k.pressure_offset_Pa})
    w.put(v);
  w.put(k.exact_limits ? 1.0 : 0.0);
  w.put(static_cast<double>(k.solves));
  for (const Eigen::VectorXd* v : {&k.state, &k.exact_rate, &k.fast_rate}) w.put(Eigen::ArrayXd(v->array()));
  return w.block(kCorrectionBlock);
}

// state_size the model's state, worn_nodes its worn nodes (the rates': the state less the energy and any fatigue damage)
FidelityCorrection correction_of(const CheckpointBlock& b, Eigen::Index state_size, Eigen::Index worn_nodes) {
  BlockReader r{b};
  FidelityCorrection k;
  k.valid = true;
  for (double* v : {&k.N, &k.exact_energy_J, &k.fast_energy_J, &k.approach_m, &k.edge_offset_m, &k.pressure_offset_Pa})
    *v = r.number();
  k.exact_limits = r.integer(1) != 0;
  k.solves = r.integer(std::numeric_limits<int>::max());
  k.state = r.array().matrix();
  k.exact_rate = r.array().matrix();
  k.fast_rate = r.array().matrix();
  r.finish();
  if (k.state.size() != state_size || k.exact_rate.size() != worn_nodes || k.fast_rate.size() != worn_nodes)
    throw std::runtime_error(fmt::format("checkpoint block '{}': its state has {} values, the case's {}", b.name,
                                         k.state.size(), state_size));
  return k;
}

CheckpointBlock error_block(const FidelityError& e, const std::string& name = kErrorBlock) {
  BlockWriter w;
  for (const double v : {e.N, e.power_rel, e.power_l1, e.exact_energy_J}) w.put(v);
  return w.block(name);
}

// (a block of three numbers, without the exact energy: written before the collectives were corrected)
FidelityError error_of(const CheckpointBlock& b) {
  BlockReader r{b};
  FidelityError e;
  for (double* v : {&e.N, &e.power_rel, &e.power_l1}) *v = r.number();
  if (b.values.size() > 3) e.exact_energy_J = r.number();
  r.finish();
  return e;
}

// a grid, every member (not rebuilt: the numbers are the solve's)
void put(BlockWriter& w, const contact::Grid& g) {
  for (const double v : {static_cast<double>(g.nx), static_cast<double>(g.ny), g.half_x_m, g.half_y_m, g.dx_m, g.dy_m})
    w.put(v);
  w.put(g.x_m);
  w.put(g.y_m);
}
contact::Grid take_grid(BlockReader& r) {
  contact::Grid g;
  g.nx = static_cast<int>(r.integer(kMaxBlockArray));
  g.ny = static_cast<int>(r.integer(kMaxBlockArray));
  for (double* v : {&g.half_x_m, &g.half_y_m, &g.dx_m, &g.dy_m}) *v = r.number();
  g.x_m = r.array();
  g.y_m = r.array();
  if (g.x_m.size() != g.nx || g.y_m.size() != g.ny)
    throw std::runtime_error(fmt::format("checkpoint block '{}': a grid of {} x {} with {} x {} cell centres",
                                         r.block.name, g.nx, g.ny, g.x_m.size(), g.y_m.size()));
  return g;
}

// The last half-space solve of a cache (NormalState, its patch and its half-space's grids and pressures) and
// its key (the worn profiles' hash, in two halves of 32 bits: each a double exactly)
CheckpointBlock halfspace_normal_block(const WearCache& cache, const std::string& name) {
  const NormalState& n = cache.normal;
  BlockWriter w;
  w.put(static_cast<double>(cache.normal_key >> 32));
  w.put(static_cast<double>(cache.normal_key & 0xffffffffULL));
  for (const double v : {n.grid_y0_m, n.contact_y_min_m, n.contact_y_max_m, n.approach_m, n.reaches_edge ? 1.0 : 0.0,
                         n.edge_margin_m, n.edge_limit_m})
    w.put(v);
  const contact::ContactPatch& p = n.patch;
  for (const double v : {p.a_m, p.b_m, p.p0_Pa, p.normal_load_N, p.approach_m}) w.put(v);
  put(w, p.grid);
  for (const Eigen::ArrayXd* a : {&p.half_length_m, &p.strip_peak_Pa, &p.strip_xi_offset}) w.put(*a);
  for (const Eigen::ArrayXXd* a : {&p.pressure_Pa, &p.pressure_moment_Pa_m, &p.edge_pressure_Pa}) w.put(*a);
  const contact::HalfspaceOnProfiles& h = n.halfspace;
  put(w, h.coarse_grid);
  w.put(h.coarse_y0_m);
  w.put(h.coarse_pressure_Pa);
  put(w, h.grid);
  w.put(h.grid_y0_m);
  w.put(h.pressure_Pa);
  for (const double v : {h.contact_y_min_m, h.contact_y_max_m, h.reference_y_m, h.reaches_border ? 1.0 : 0.0,
                         h.edge_value_m, static_cast<double>(h.solves), static_cast<double>(h.iterations)})
    w.put(v);
  return w.block(name);
}

void restore_halfspace_normal(const CheckpointBlock& b, WearCache& cache) {
  BlockReader r{b};
  const std::uint64_t hi = static_cast<std::uint64_t>(r.integer(0xffffffffL));
  const std::uint64_t lo = static_cast<std::uint64_t>(r.integer(0xffffffffL));
  NormalState n;
  n.solver = contact::NormalSolverKind::Halfspace;
  for (double* v : {&n.grid_y0_m, &n.contact_y_min_m, &n.contact_y_max_m, &n.approach_m}) *v = r.number();
  n.reaches_edge = r.integer(1) != 0;
  for (double* v : {&n.edge_margin_m, &n.edge_limit_m}) *v = r.number();
  contact::ContactPatch& p = n.patch;
  for (double* v : {&p.a_m, &p.b_m, &p.p0_Pa, &p.normal_load_N, &p.approach_m}) *v = r.number();
  p.grid = take_grid(r);
  for (Eigen::ArrayXd* a : {&p.half_length_m, &p.strip_peak_Pa, &p.strip_xi_offset}) *a = r.array();
  for (Eigen::ArrayXXd* a : {&p.pressure_Pa, &p.pressure_moment_Pa_m, &p.edge_pressure_Pa}) *a = r.array2d();
  contact::HalfspaceOnProfiles& h = n.halfspace;
  h.coarse_grid = take_grid(r);
  h.coarse_y0_m = r.number();
  h.coarse_pressure_Pa = r.array2d();
  h.grid = take_grid(r);
  h.grid_y0_m = r.number();
  h.pressure_Pa = r.array2d();
  for (double* v : {&h.contact_y_min_m, &h.contact_y_max_m, &h.reference_y_m}) *v = r.number();
  h.reaches_border = r.integer(1) != 0;
  h.edge_value_m = r.number();
  h.solves = static_cast<int>(r.integer(std::numeric_limits<int>::max()));
  h.iterations = static_cast<int>(r.integer(std::numeric_limits<int>::max()));
  r.finish();
  if (h.coarse_pressure_Pa.rows() != h.coarse_grid.nx || h.coarse_pressure_Pa.cols() != h.coarse_grid.ny ||
      h.pressure_Pa.rows() != h.grid.nx || h.pressure_Pa.cols() != h.grid.ny)
    throw std::runtime_error(fmt::format("checkpoint block '{}': pressures not on their grids", b.name));
  cache.normal_key = hi << 32 | lo;
  cache.normal = std::move(n);
  cache.normal_valid = true;
}

// a collective's running condition k's block name; the case's own: kHalfspaceNormalBlock
std::string condition_block_name(std::size_t k) { return fmt::format("{}_{}", kHalfspaceNormalBlock, k); }

}  // namespace

std::vector<CheckpointBlock> wear_cache_blocks(const WearCache& cache) {
  std::vector<CheckpointBlock> out;
  if (cache.correction.valid) {
    out.push_back(correction_block(cache.correction));
    out.push_back(error_block(cache.error));
  }
  const auto halfspace = [&](const WearCache& ck, const std::string& name) {
    if (ck.normal_valid && ck.normal.solver == contact::NormalSolverKind::Halfspace)
      out.push_back(halfspace_normal_block(ck, name));
  };
  halfspace(cache, kHalfspaceNormalBlock);
  for (std::size_t k = 0; k < cache.conditions.size(); ++k) halfspace(cache.conditions[k], condition_block_name(k));
  // a collective's conditions' corrections (the corrected fidelity)
  for (std::size_t k = 0; k < cache.conditions.size(); ++k)
    if (const FidelityCorrection& ck = cache.conditions[k].correction; ck.valid) {
      CheckpointBlock b = correction_block(ck);
      b.name = fmt::format("{}_{}", kCorrectionBlock, k);
      out.push_back(std::move(b));
      out.push_back(error_block(cache.conditions[k].error, fmt::format("{}_{}", kErrorBlock, k)));
    }
  return out;
}

void restore_wear_cache(const WearModel& m, const std::vector<CheckpointBlock>& blocks, WearCache& cache) {
  if (const CheckpointBlock* b = find_block(blocks, kCorrectionBlock)) cache.correction = correction_of(*b, m.state_size(), m.n1 + m.n2);
  if (const CheckpointBlock* b = find_block(blocks, kErrorBlock)) cache.error = error_of(*b);
  if (const CheckpointBlock* b = find_block(blocks, kHalfspaceNormalBlock)) restore_halfspace_normal(*b, cache);
  if (m.conditions.empty()) return;
  prepare_condition_caches(m, cache);
  for (std::size_t k = 0; k < m.conditions.size(); ++k) {
    WearCache& ck = cache.conditions[k];
    if (const CheckpointBlock* b = find_block(blocks, condition_block_name(k))) restore_halfspace_normal(*b, ck);
    const WearModel& mk = m.conditions[k];
    if (const CheckpointBlock* b = find_block(blocks, fmt::format("{}_{}", kCorrectionBlock, k)))
      ck.correction = correction_of(*b, mk.state_size(), mk.n1 + mk.n2);
    if (const CheckpointBlock* b = find_block(blocks, fmt::format("{}_{}", kErrorBlock, k))) ck.error = error_of(*b);
  }
  if (m.fidelity == contact::Fidelity::Corrected) cache.error = collective_error(m, cache);
}

std::string checkpoint_text(const Checkpoint& c) {
  const LifeStart& s = c.start;
  std::string t = std::string(kCheckpointMagic) + "\n";
  t += fmt::format("case_hash {:016x}\n", c.case_hash);
  t += fmt::format("N {:a}\n", s.N);
  t += fmt::format("next_step {:a}\n", s.next_step);
  const LifeCounters& n = s.counters;
  t += fmt::format("steps {}\nrhs_evals {}\nrejected {}\n", n.steps, n.rhs_evals, n.rejected);
  t += fmt::format("rate_evaluations {}\nlimit_evaluations {}\n", n.rate_evaluations, n.limit_evaluations);
  t += fmt::format("normal_solves {}\ntangential_solves {}\n", n.normal_solves, n.tangential_solves);
  t += fmt::format("snapshots_written {}\n", c.snapshots_written);
  t += fmt::format("wall_s {:a}\n", c.wall_s);
  t += fmt::format("state {}\n", s.state.size());
  for (Eigen::Index i = 0; i < s.state.size(); ++i) t += fmt::format("{:a}\n", s.state(i));
  for (const CheckpointBlock& b : c.blocks) {
    t += fmt::format("block {} {}\n", b.name, b.values.size());
    for (Eigen::Index i = 0; i < b.values.size(); ++i) t += fmt::format("{:a}\n", b.values(i));
  }
  t += "end\n";
  return t;
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot read the checkpoint");
  int line_no = 0;
  std::string line;
  const auto fail = [&](const std::string& what) -> void {
    throw std::runtime_error(fmt::format("{}:{}: {}", path.string(), line_no, what));
  };
  const auto next = [&]() {
    if (!std::getline(in, line)) {
      ++line_no;
      fail("the checkpoint ends early (a torn file?)");
    }
    ++line_no;
  };
  const auto number = [&](const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0') fail("expected a number, got '" + text + "'");
    return v;
  };
  const auto field = [&](const std::string& key) {
    next();
    if (line.compare(0, key.size() + 1, key + " ") != 0) fail("expected '" + key + " ...', got '" + line + "'");
    return line.substr(key.size() + 1);
  };
  next();
  const bool version2 = line == kCheckpointMagic2;
  if (line != kCheckpointMagic && !version2)
    fail("not a rollwear wear checkpoint (expected '" + std::string(kCheckpointMagic) + "')");
  Checkpoint c;
  c.case_hash = std::stoull(field("case_hash"), nullptr, 16);
  c.start.N = number(field("N"));
  c.start.next_step = number(field("next_step"));
  LifeCounters& counts = c.start.counters;
  const auto count = [&](const char* key) { return static_cast<long>(number(field(key))); };
  counts.steps = count("steps");
  counts.rhs_evals = count("rhs_evals");
  counts.rejected = count("rejected");
  counts.rate_evaluations = count("rate_evaluations");
  counts.limit_evaluations = count("limit_evaluations");
  counts.normal_solves = count("normal_solves");
  counts.tangential_solves = count("tangential_solves");
  c.snapshots_written = static_cast<int>(number(field("snapshots_written")));
  c.wall_s = number(field("wall_s"));
  const long n = static_cast<long>(number(field("state")));
  if (n < 1 || n > 100000000) fail("bad state size " + std::to_string(n));
  c.start.state.resize(n);
  for (long i = 0; i < n; ++i) {
    next();
    c.start.state(i) = number(line);
  }
  // the named blocks, each "block NAME COUNT" and its numbers, then the end
  for (next(); line.compare(0, 6, "block ") == 0; next()) {
    std::istringstream words(line.substr(6));
    CheckpointBlock b;
    std::string count_word, rest;
    if (!(words >> b.name >> count_word) || (words >> rest)) fail("expected 'block NAME COUNT', got '" + line + "'");
    const long size = static_cast<long>(number(count_word));
    if (size < 0 || size > 100000000) fail("bad block size " + count_word);
    b.values.resize(size);
    for (long i = 0; i < size; ++i) {
      next();
      b.values(i) = number(line);
    }
    c.blocks.push_back(std::move(b));
  }
  // version 2: the corrected fidelity's correction and error estimate in lines of their own, read into their blocks
  if (version2 && line.rfind("correction ", 0) == 0) {
    std::istringstream in_line(line.substr(11));
    std::string N, exact_J, fast_J, approach, edge, pressure;
    long solves = 0, size = 0;
    int exact_limits = 0;
    if (!(in_line >> N >> exact_J >> fast_J >> approach >> edge >> pressure >> exact_limits >> solves >> size) ||
        size != n)
      fail("bad correction line '" + line + "'");
    FidelityCorrection k;
    k.valid = true;
    k.N = number(N);
    k.exact_energy_J = number(exact_J);
    k.fast_energy_J = number(fast_J);
    k.approach_m = number(approach);
    k.edge_offset_m = number(edge);
    k.pressure_offset_Pa = number(pressure);
    k.exact_limits = exact_limits != 0;
    k.solves = solves;
    k.state.resize(n);
    for (long i = 0; i < n; ++i) {
      next();
      k.state(i) = number(line);
    }
    k.exact_rate.resize(n - 1);  // version 2 had no fatigue damage: the rates are the state less the energy
    k.fast_rate.resize(n - 1);
    for (long i = 0; i + 1 < n; ++i) {
      next();
      const std::size_t space = line.find(' ');
      if (space == std::string::npos) fail("expected two numbers, got '" + line + "'");
      k.exact_rate(i) = number(line.substr(0, space));
      k.fast_rate(i) = number(line.substr(space + 1));
    }
    next();
    std::istringstream err(line);
    std::string word, eN, rel, l1;
    if (!(err >> word >> eN >> rel >> l1) || word != "error") fail("expected 'error ...', got '" + line + "'");
    c.blocks.push_back(correction_block(k));
    c.blocks.push_back(error_block({number(eN), number(rel), number(l1)}));
    next();
  }
  if (line != "end") fail("expected 'end', got '" + line + "'");
  return c;
}

std::string summary_up_to(const std::filesystem::path& path, long steps) {
  // the rows' steps from the one CSV reader (lib/csv_reader.h); the text kept is the file's own, line
  // for line up to the last row kept, so that a resumed summary is byte for byte the uninterrupted one
  contact::CsvTable t;
  try {
    t = contact::read_csv_table(path.string());
  } catch (const std::runtime_error&) {
    throw std::runtime_error(path.string() + ": cannot read the summary of the run to resume");
  }
  if (t.header.empty() || t.header[0] != "step")
    throw std::runtime_error(fmt::format("{}: not a wear summary (no header row starting with 'step')", path.string()));
  long last = -1;
  int last_line = t.header_line;  // the last line kept
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const std::string& cell = t.rows[k][0];
    long step = 0;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), step);
    if (ec != std::errc() || end != cell.data() + cell.size())
      throw std::runtime_error(fmt::format("{}:{}: expected a step number, got '{}'", path.string(), t.row_lines[k],
                                           contact::clipped(cell)));
    if (step > steps) break;
    last = step;
    last_line = t.row_lines[k];
  }
  if (last != steps)
    throw std::runtime_error(fmt::format("{}: the summary ends at step {}, the checkpoint is at step {}", path.string(),
                                         last, steps));
  std::ifstream in(path, std::ios::binary);
  std::string out, line;
  for (int number = 1; number <= last_line && std::getline(in, line); ++number) out += line + "\n";
  return out;
}

}  // namespace wear
