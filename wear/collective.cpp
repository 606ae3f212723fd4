// A load collective in one life (wear/collective.h, docs/wear-loop.md "Load collectives").
#include "wear/collective.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <thread>
#include <utility>

#include "lib/errors.h"
#include "lib/io/yaml_reader.h"
#include "lib/number.h"

namespace wear {

using contact::CaseError;

std::vector<WearCondition> read_collective(const contact::YamlValue& list, const contact::ContactCase& base) {
  const std::vector<contact::YamlValue> entries =
      list.elements("a list of running conditions, e.g. - { weight: 0.7 } and - { weight: 0.3, load: { normal_load_N: 2500 } }");
  if (entries.empty()) list.fail("needs at least one running condition, e.g. - { weight: 1 }");
  std::vector<WearCondition> out;
  double sum = 0;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    WearCondition cond;
    cond.contact = base;
    cond.location = entries[k].location();
    const std::string path = "wear.collective[" + std::to_string(k + 1) + "]";
    contact::KeyLocations read;
    contact::YamlValue(entries[k].node(), entries[k].file(), path, &read).mapping([&](contact::YamlMap& m) {
      m.required("weight", cond.weight, [](double w) -> std::string {
        return w > 0 && std::isfinite(w) ? "" : "must be > 0 and finite (the condition's share of the revolutions)";
      });
      contact::read_running_condition(m, cond.contact);
    });
    // the condition's keys are where the case's were: a cross-key message points at the condition's line
    for (const auto& [key, where] : read)
      if (key.rfind(path + ".", 0) == 0) cond.contact.locations[key.substr(path.size() + 1)] = where;
    sum += cond.weight;
    out.push_back(std::move(cond));
  }
  if (!(std::abs(sum - 1) <= kCollectiveWeightSumTolerance))
    list.fail("the weights sum to " + contact::round_trip(sum) + ", not 1: each weight is its condition's share of "
              "the revolutions, and the shares must add up to 1");
  return out;
}

WearCase condition_case(const WearCase& c, std::size_t k) {
  WearCase cc;
  cc.contact = c.wear.collective.at(k).contact;
  cc.wear = c.wear;
  cc.wear.collective.clear();
  return cc;
}

void validate_collective(const WearCase& c) {
  for (std::size_t k = 0; k < c.wear.collective.size(); ++k) {
    try {
      const WearCase cc = condition_case(c, k);
      contact::validate(cc.contact);
      validate(cc);
    } catch (const CaseError& e) {
      throw CaseError(std::string(e.what()) + " (in wear.collective[" + std::to_string(k + 1) + "], the running "
                      "condition at " + c.wear.collective[k].location + ")");
    }
  }
}

WearModel make_collective_model(const WearCase& c) {
  validate(c);
  WearModel m = make_wear_model(condition_case(c, 0));
  // a collective's rate is its conditions', each corrected by its own exact physics: none of its own
  m.exact_physics.clear();
  m.correction_fast.clear();
  m.limits_physics.clear();
  m.steady_part.reset();
  for (std::size_t k = 0; k < c.wear.collective.size(); ++k) {
    WearModel mk = make_wear_model(condition_case(c, k));
    mk.energy_scale = m.energy_scale;  // one scale for the state's energy: the conditions' energies add
    m.conditions.push_back(std::move(mk));
    m.weights.push_back(c.wear.collective[k].weight);
  }
  return m;
}

void prepare_condition_caches(const WearModel& m, WearCache& cache) {
  if (cache.conditions.size() == m.conditions.size()) return;
  cache.conditions.clear();
  cache.conditions.resize(m.conditions.size());
  for (WearCache& ck : cache.conditions) ck.reuse = cache.reuse;
}

std::vector<LifeCounters> condition_counters(const WearCache& cache) {
  std::vector<LifeCounters> c;
  for (const WearCache& ck : cache.conditions) c.push_back(ck.counters);
  return c;
}

void add_condition_solves(WearCache& cache, const std::vector<LifeCounters>& before) {
  for (std::size_t k = 0; k < cache.conditions.size(); ++k) {
    cache.counters.normal_solves += cache.conditions[k].counters.normal_solves - before[k].normal_solves;
    cache.counters.tangential_solves += cache.conditions[k].counters.tangential_solves - before[k].tangential_solves;
  }
}

int collective_threads(const WearModel& m) {
  const int n = static_cast<int>(m.conditions.size());
  const int wanted = m.collective_threads > 0 ? m.collective_threads
                                              : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return std::max(1, std::min(wanted, n));
}

WearRate collective_rate(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache) {
  prepare_condition_caches(m, cache);
  const std::vector<LifeCounters> before = condition_counters(cache);
  const std::size_t n = m.conditions.size();
  std::vector<WearRate> rates(n);
  std::vector<std::exception_ptr> errors(n);
  const int threads = collective_threads(m);
  // thread t evaluates the conditions k = t, t + threads, ...; each condition has its own model and cache
  const auto evaluate = [&](std::size_t first) {
    for (std::size_t k = first; k < n; k += static_cast<std::size_t>(threads)) {
      try {
        rates[k] = wear_rate(m.conditions[k], state, cache.conditions[k]);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(evaluate, static_cast<std::size_t>(t));
  evaluate(0);
  for (std::thread& t : pool) t.join();
  add_condition_solves(cache, before);
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);

  // the weighted sum, in the conditions' order
  WearRate r;
  std::size_t severest = 0;
  for (std::size_t k = 1; k < n; ++k)
    if (rates[k].contact.p0_Pa > rates[severest].contact.p0_Pa) severest = k;
  r = rates[severest];  // the strips and the contact reported: the condition with the highest peak pressure
  r.dstate_dN = m.weights[0] * rates[0].dstate_dN;
  r.energy_per_revolution_J = m.weights[0] * rates[0].energy_per_revolution_J;
  r.cycles_per_revolution = m.weights[0] * rates[0].cycles_per_revolution;
  for (std::size_t k = 1; k < n; ++k) {
    r.dstate_dN += m.weights[k] * rates[k].dstate_dN;
    r.energy_per_revolution_J += m.weights[k] * rates[k].energy_per_revolution_J;
    r.cycles_per_revolution += m.weights[k] * rates[k].cycles_per_revolution;
    r.contact.edge_margin_m = std::min(r.contact.edge_margin_m, rates[k].contact.edge_margin_m);
    r.contact.edge_limit_m = std::max(r.contact.edge_limit_m, rates[k].contact.edge_limit_m);
  }
  r.contact.edge_margin_m = std::min(r.contact.edge_margin_m, rates[0].contact.edge_margin_m);
  r.contact.edge_limit_m = std::max(r.contact.edge_limit_m, rates[0].contact.edge_limit_m);
  return r;
}

FidelityError collective_error(const WearModel& m, const WearCache& cache) {
  FidelityError e;
  if (cache.conditions.size() != m.conditions.size() || m.conditions.empty()) return e;
  double N = std::numeric_limits<double>::infinity(), energy = 0, fast = 0, l1 = 0;
  for (std::size_t k = 0; k < m.conditions.size(); ++k) {
    const FidelityError& ek = cache.conditions[k].error;
    if (!(std::isfinite(ek.N) && std::isfinite(ek.power_rel) && std::isfinite(ek.power_l1) &&
          std::isfinite(ek.exact_energy_J)))
      return e;
    N = std::min(N, ek.N);
    const double w = m.weights[k] * ek.exact_energy_J;
    energy += w;
    fast += w * (1 + ek.power_rel);
    l1 += w * ek.power_l1;
  }
  e.N = N;
  e.exact_energy_J = energy;
  e.power_rel = fast / energy - 1;
  e.power_l1 = l1 / energy;
  return e;
}

}  // namespace wear
