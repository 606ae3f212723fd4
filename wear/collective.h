// A load collective (wear.collective; docs/wear-loop.md, "Load collectives"): several running conditions
// in one life, each with its share of the reference body's revolutions. A condition is the case with some
// of its load, kinematics (speed, creepages), friction and transient keys replaced:
//
//   wear:
//     collective:
//       - { weight: 0.6 }                                              # the case as written
//       - { weight: 0.3, load: { normal_load_N: 2500 }, kinematics: { xi: 2.0e-3 } }
//       - { weight: 0.1, friction: { mu: 0.15 }, transient: { scheme: shift, t_end_s: 0.503 },
//           kinematics: { speed_m_per_s: { table: [[0, 0], [1.0e-3, 1.8], [0.501, 1.8], [0.502, 0]] } } }
//
// At every evaluation of the wear rate, each condition's rate is evaluated on the same worn profiles (its
// own normal and tangential solves, its own cache) and the rates are summed by weight, in the conditions'
// order:   dh/dN = sum_k w_k f_k(h)   (w_k: the share of revolutions run under condition k, sum 1).
// The conditions' evaluations may run on several threads; the sum's order is fixed, so the life is the
// same to the bit for any thread count. A collective of one condition of weight 1 is the case's own
// life to the bit (1 x f = f). The lifetime limits read every condition: the peak pressure is the
// largest condition's, the edge limit the widest contact's.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

#include "lib/io/case.h"
#include "wear/wear_case.h"
#include "wear/wear_loop.h"

namespace contact {
class YamlValue;  // lib/io/yaml_reader.h (yaml-cpp stays out of the wear loop's includes)
}  // namespace contact

namespace wear {

// the weights must add up to 1 within this (shares of the revolutions written as decimals, e.g. 0.7,
// 0.2, 0.1, add up to 1 only to rounding)
constexpr double kCollectiveWeightSumTolerance = 1e-9;

// wear.collective's list read over copies of the case's contact (`base`): CaseError (file, line, key
// wear.collective[k].KEY) for a key the case reader refuses, a weight that is not > 0 and finite, or
// weights that do not add up to 1. The conditions' keys take the condition's line in its locations.
std::vector<WearCondition> read_collective(const contact::YamlValue& list, const contact::ContactCase& base);

// condition k's case: its contact, the wear section without the collective
WearCase condition_case(const WearCase& c, std::size_t k);

// validate(WearCase) of each condition; a refusal is the reader's message at the condition's line,
// naming the condition
void validate_collective(const WearCase& c);

// the model of a collective case: condition 0's model holding every condition's model and weight (one
// energy scale, the first condition's)
WearModel make_collective_model(const WearCase& c);

// the conditions' caches inside a collective's cache, made on first use
void prepare_condition_caches(const WearModel& m, WearCache& cache);
// the solves the conditions' caches counted since `before` (their counters then), added to `cache`
std::vector<LifeCounters> condition_counters(const WearCache& cache);
void add_condition_solves(WearCache& cache, const std::vector<LifeCounters>& before);

// the threads a collective's rate runs on: m.collective_threads, 0 = one per condition up to the cores
int collective_threads(const WearModel& m);

// the collective's rate (m.conditions not empty): sum_k w_k f_k in k's order; the contact reported is
// the condition's with the highest peak pressure, the edge margin the smallest and the edge limit the
// largest over the conditions. A condition's exception (the first in k's order) is rethrown.
WearRate collective_rate(const WearModel& m, const Eigen::VectorXd& state, WearCache& cache);

// The collective's error estimate (docs/fidelity.md) from its conditions' (each at its own last correction, or on
// the final state for the fast fidelity): N the oldest of theirs; the total power's relative error of the
// weighted sum, sum_k w_k E_k (1 + rel_k) / sum_k w_k E_k - 1 (E_k the exact physics' energy per revolution); the
// per-strip L1 as the energy-weighted mean of theirs, sum_k w_k E_k L1_k / sum_k w_k E_k, which bounds the
// weighted sum's L1 from above (the triangle inequality; equal where the conditions' errors have one sign at
// every node). NaN unless every condition has an estimate.
FidelityError collective_error(const WearModel& m, const WearCache& cache);

}  // namespace wear
