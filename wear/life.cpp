// The life driver (life.h).
#include "wear/life.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>

#include <spdlog/fmt/fmt.h>

#include "lib/enum_names.h"
#include "lib/errors.h"

namespace wear {

namespace {

// the report's words (lib/enum_names.h)
constexpr contact::EnumTable<LifeEnd, 12> kLifeEndWords = {
    {{LifeEnd::NotRun, "not_run"}, {LifeEnd::MaxDepth, "max_depth"}, {LifeEnd::MaxPressure, "max_pressure"},
     {LifeEnd::Edge, "edge"}, {LifeEnd::LiftLoss, "lift_loss"}, {LifeEnd::Fatigue, "fatigue"},
     {LifeEnd::Shakedown, "shakedown"}, {LifeEnd::Scuffing, "scuffing"}, {LifeEnd::Revolutions, "revolutions"},
     {LifeEnd::MaxSteps, "max_steps"}, {LifeEnd::Stopped, "stopped"}, {LifeEnd::Failed, "failed"}}};
constexpr contact::EnumTable<LifeFailure, 6> kLifeFailureWords = {
    {{LifeFailure::None, "none"}, {LifeFailure::Integrator, "integrator"},
     {LifeFailure::UnresolvedContact, "unresolved_contact"}, {LifeFailure::WornThrough, "worn_through"},
     {LifeFailure::NormalNotConverged, "normal_not_converged"}, {LifeFailure::Rate, "rate"}}};

// The counters of a life in progress: the start's, plus what this process's integrations and solves
// added. A continuation (a later segment, or a resumed run) starts at a step end whose f the life has
// already evaluated: the integrator's first evaluation there is not counted again.
struct LifeTally {
  const LifeProblem& p;
  LifeCounters start;          // the life's counters where this call began
  LifeCounters solves_start;   // the supplier's solve counts then
  LifeCounters segment_start;  // the life's integrator counts where the current segment began
  long repeated_evals = 0;     // 1 when the current segment continues from a step end

  LifeCounters solves() const { return p.solves ? p.solves() : LifeCounters{}; }
  // the solve counts: the start's plus what the supplier counted since
  void add_solves(LifeCounters& c) const {
    const LifeCounters now = solves();
    c.rate_evaluations = start.rate_evaluations + now.rate_evaluations - solves_start.rate_evaluations;
    c.limit_evaluations = start.limit_evaluations + now.limit_evaluations - solves_start.limit_evaluations;
    c.normal_solves = start.normal_solves + now.normal_solves - solves_start.normal_solves;
    c.tangential_solves = start.tangential_solves + now.tangential_solves - solves_start.tangential_solves;
  }
  // the life's counters, the current segment's integration having counted steps, rhs_evals and rejected
  LifeCounters at(long steps, long rhs_evals, long rejected) const {
    LifeCounters c;
    c.steps = segment_start.steps + steps;
    c.rejected = segment_start.rejected + rejected;
    c.rhs_evals = segment_start.rhs_evals + std::max(0L, rhs_evals - repeated_evals);
    add_solves(c);
    return c;
  }
  void begin_segment(const LifeCounters& life) {
    segment_start = life;
    repeated_evals = life.rhs_evals > 0 ? 1 : 0;
  }
};

// how the life ended, in words
struct LifeEnding {
  LifeEnd why = LifeEnd::NotRun;
  std::string message;
};

// the life ends here: why, in words, its counters closed after the caller's last look at it
LifeOutcome& end_life(const LifeTally& tally, const LifeDriverHooks& hooks, LifeOutcome& life,
                      const LifeEnding& ending) {
  life.ended_by = ending.why;
  life.message = ending.message;
  if (hooks.on_end) hooks.on_end(life.N, life.state);
  tally.add_solves(life.counters);
  return life;
}

// the integrator's status as the life's end (Kind::ReachedEnd: none, the life goes on)
std::optional<LifeEnd> life_end_of(const LifeProblem& p, const IntegratorResult& r) {
  switch (r.status.kind) {
    case IntegratorStatus::Kind::ReachedEnd: return std::nullopt;
    case IntegratorStatus::Kind::RootFound: return p.limits[static_cast<std::size_t>(r.status.roots.front())];
    case IntegratorStatus::Kind::Stopped: return LifeEnd::Stopped;
    case IntegratorStatus::Kind::MaxSteps: return LifeEnd::MaxSteps;
    case IntegratorStatus::Kind::Failed: return LifeEnd::Failed;
  }
  return LifeEnd::Failed;
}

int limit_count(const LifeProblem& p) { return static_cast<int>(p.limits.size()); }

// a limit already reached where the life starts (a resumed run, or an unworn contact at the edge), or where the
// rate's model changed (LifeProblem::refresh: its limits may move with it)
std::optional<LifeEnding> limit_reached_at_start(const LifeProblem& p, const LifeOutcome& life,
                                                 const char* where = "at the start") {
  if (p.limits.empty()) return std::nullopt;
  Eigen::VectorXd g = Eigen::VectorXd::Constant(limit_count(p), -1.0);
  p.limit_values(life.N, life.state, g);
  for (int k = 0; k < limit_count(p); ++k)
    if (g(k) >= 0) {
      const LifeEnd end = p.limits[static_cast<std::size_t>(k)];
      return LifeEnding{end, fmt::format("{} reached {}, N {:.10g}", to_string(end), where, life.N)};
    }
  return std::nullopt;
}

// the revolutions each integration runs to: each snapshot revolution ahead of N, then the budget
std::vector<double> segment_ends(const LifeProblem& p, double N) {
  std::vector<double> ends;
  for (double snapshot : p.snapshots_revolutions)
    if (snapshot > N) ends.push_back(snapshot);
  if (ends.empty() || ends.back() < p.revolutions) ends.push_back(p.revolutions);
  return ends;
}

// The wear from life.N to N_end, step by step (each reported to the hooks with the life's counters),
// up to N_end or the first limit, located. Returns how the life ended in it, or nothing at N_end. An
// exception that failure_of takes as the life's end ends it at its last accepted step, failed.
// restarted: the integration stopped at a step end where the rate's model changed (LifeProblem::refresh); the
// life goes on from there.
std::optional<LifeEnding> wear_until(const LifeProblem& p, const LifeDriverHooks& hooks, LifeTally& tally,
                                     double N_end, LifeOutcome& life, bool& restarted) {
  restarted = false;
  IntegratorOptions options = p.options;
  options.initial_step = life.next_step;
  options.max_steps = p.options.max_steps - life.counters.steps;
  if (options.max_steps <= 0)
    return LifeEnding{LifeEnd::MaxSteps, fmt::format("max_steps {} reached", p.options.max_steps)};
  tally.begin_segment(life.counters);

  // each accepted step, kept as the last accepted state
  LifeStart last{life.N, life.state, life.next_step, life.counters};
  bool stopped = false;
  const OnStep on_step = [&](const StepInfo& info, const Eigen::VectorXd& h) {
    LifeStepEnd s;
    s.N = info.N;
    s.state = &h;
    s.next_step = info.next_step;
    const LifeCounters integrated = tally.at(info.steps, info.rhs_evals, info.rejected);
    s.info = info;
    s.info.steps = integrated.steps;
    s.info.rhs_evals = integrated.rhs_evals;
    s.info.rejected = integrated.rejected;
    s.counters = [&] { return tally.at(info.steps, info.rhs_evals, info.rejected); };
    last = {s.N, h, info.next_step, integrated};
    const bool refreshed = p.refresh && p.refresh(s.N, h);
    const bool go_on = hooks.on_step ? hooks.on_step(s) : true;
    stopped = !go_on;
    restarted = go_on && refreshed;
    return go_on && !refreshed;
  };

  IntegratorResult r;
  try {
    r = integrate(p.rate, p.limit_values, limit_count(p), life.N, life.state, N_end, options, on_step);
  } catch (const std::exception& e) {
    const LifeFailure failure = p.failure_of ? p.failure_of(e, last.N) : LifeFailure::None;
    if (failure == LifeFailure::None) throw;
    life.N = last.N;
    life.state = last.state;
    life.counters = last.counters;
    life.failure = failure;
    return LifeEnding{LifeEnd::Failed, fmt::format("ended at N {:.10g}, the last accepted step: {}", life.N, e.what())};
  }
  life.N = r.N;
  life.state = r.h_m;
  life.counters = tally.at(r.steps, r.rhs_evals, r.rejected);
  if (r.next_step > 0) life.next_step = r.next_step;

  if (restarted && r.status.kind == IntegratorStatus::Kind::Stopped) return std::nullopt;
  restarted = false;
  const std::optional<LifeEnd> end = life_end_of(p, r);
  if (!end) return std::nullopt;
  if (*end == LifeEnd::Failed) life.failure = LifeFailure::Integrator;
  if (*end == LifeEnd::Stopped && stopped)
    return LifeEnding{*end, fmt::format("stopped after step {} at N {:.10g}", life.counters.steps, life.N)};
  if (r.status.kind != IntegratorStatus::Kind::RootFound) return LifeEnding{*end, r.status.message};
  return LifeEnding{*end, fmt::format("{} reached at N {:.10g}, in step {}", to_string(*end), life.N,
                                      life.counters.steps)};
}

}  // namespace

std::string to_string(LifeEnd e) { return contact::enum_name(kLifeEndWords, e); }

LifeEnd parse_life_end(const std::string& word) {
  if (const std::optional<LifeEnd> e = contact::enum_from_name(kLifeEndWords, word)) return *e;
  throw std::invalid_argument(fmt::format("'{}' is not how a life ends (one of {})", contact::clipped(word),
                                          contact::enum_names_list(kLifeEndWords)));
}

std::string to_string(LifeFailure f) { return contact::enum_name(kLifeFailureWords, f); }

LifeOutcome integrate_life(const LifeProblem& p, const LifeStart& start, const LifeDriverHooks& hooks) {
  LifeTally tally{p, start.counters, LifeCounters{}, start.counters, 0};
  tally.solves_start = tally.solves();

  // where the life starts: the unworn state, or a checkpoint's state and counters
  LifeOutcome life;
  life.N = start.N;
  life.state = start.state;
  life.next_step = start.next_step;
  life.counters = start.counters;
  if (hooks.on_start) hooks.on_start(life.N, life.state);
  if (const std::optional<LifeEnding> reached = limit_reached_at_start(p, life))
    return end_life(tally, hooks, life, *reached);

  // wear through each snapshot revolution, then to the budget: a limit, or a failure, ends the life
  for (const double N_end : segment_ends(p, life.N)) {
    if (N_end <= life.N) continue;  // a start at the budget's end (a checkpoint of its last step)
    for (bool restarted = true; restarted && N_end > life.N;) {
      if (const std::optional<LifeEnding> ending = wear_until(p, hooks, tally, N_end, life, restarted))
        return end_life(tally, hooks, life, *ending);
      if (restarted)
        if (const std::optional<LifeEnding> reached = limit_reached_at_start(p, life, "where the rate's model changed"))
          return end_life(tally, hooks, life, *reached);
    }
    const std::vector<double>& snapshots = p.snapshots_revolutions;
    if (hooks.on_snapshot && std::find(snapshots.begin(), snapshots.end(), N_end) != snapshots.end())
      hooks.on_snapshot(life.N, life.state);
  }
  return end_life(tally, hooks, life,
                  {LifeEnd::Revolutions, fmt::format("the life budget {} = {:.10g} reached with no limit", p.budget_key,
                                                     p.revolutions)});
}

}  // namespace wear
