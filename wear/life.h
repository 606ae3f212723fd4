// One life (docs/wear-loop.md, docs/cam-follower.md §12): the worn state x of a pair of bodies obeys
// dx/dN = f(x) in the revolutions N of a reference body, integrated by the project's integrator
// (wear/integrator.h) from a start (the unworn state, or an accepted step's end saved by a checkpoint)
// through the snapshot revolutions to the budget, until a limit ends it. Each limit is a signed,
// continuous function g_k(x) (< 0 inside the life), so the integrator's root finding locates where it
// is reached. The driver holds what every life shares: the segments between snapshots, the limits
// located, the counters over the whole life (a resumed run's included), and how a life ends.
//
// Its users supply their rate and their limits as data (LifeProblem): the roller's wear loop and the
// load collectives (wear/wear_loop.h: depth, peak pressure, edge) and the cam (cam/cam_life.h: depth,
// lift loss). Physics only: no files, no folders, no signals (the caller's hooks write and stop).
#pragma once

#include <Eigen/Core>

#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "wear/integrator.h"

namespace wear {

// what ended a life; the default is the pessimistic one
enum class LifeEnd {
  NotRun,       // the life did not finish (default)
  MaxDepth,     // the deepest wear reached the depth limit (located)
  MaxPressure,  // the peak pressure exceeded its limit (located; the roller's wear loop)
  Edge,         // the contact reached the end of the profiles' overlap (located; the roller's wear loop)
  LiftLoss,     // the follower's lift dropped by its limit at some cam angle (located; the cam)
  Fatigue,      // the fatigue damage reached 1 somewhere on the reference body (located; wear.fatigue, docs/fatigue.md)
  Shakedown,    // the load left Johnson's shakedown map (located; wear.limits.shakedown)
  Scuffing,     // the flash temperature reached Blok's critical temperature (located; wear.limits.scuffing)
  Revolutions,  // the budget of revolutions, with no limit reached
  MaxSteps,     // the stepping's max_steps
  Stopped,      // the caller's on_step returned false
  Failed,       // the integrator gave up, or the rate could not be evaluated: the state is the last accepted step's
};
// why a life Failed (None for every other end)
enum class LifeFailure {
  None,
  Integrator,          // ARKODE gave up (repeated error test failures, too much accuracy asked)
  UnresolvedContact,   // wear::UnresolvedContact
  WornThrough,         // wear::WornThrough
  NormalNotConverged,  // wear::NormalNotConverged
  Rate,                // the rate's producer threw (the cam's revolution)
};
// the report's words: max_depth, max_pressure, edge, lift_loss, fatigue, shakedown, scuffing, revolutions, max_steps, stopped,
// failed, not_run
std::string to_string(LifeEnd e);
// the inverse of to_string; throws std::invalid_argument naming the word and the valid ones
LifeEnd parse_life_end(const std::string& word);
std::string to_string(LifeFailure f);

// A life's counters, in one place: what the integrator did (steps, rejected steps, evaluations of f)
// and what the evaluations cost (solves). A resumed run starts from the checkpoint's counters, so every
// count covers the whole life, all processes of a resumed run included (docs/wear-loop.md, "Counters").
struct LifeCounters {
  long steps = 0;              // accepted steps (the step a limit cut short included)
  long rejected = 0;           // steps that failed the error test (adaptive) or were halved (fixed)
  long rhs_evals = 0;          // evaluations of f the integrator made; a continuation's first one, at the
                               // state the last step already evaluated, is not counted again
  long rate_evaluations = 0;   // calls of the rate, cached or not (integrator, limits, report rows)
  long limit_evaluations = 0;  // evaluations of the limit functions (root finding's probes included)
  long normal_solves = 0;      // normal problems solved (cache misses)
  long tangential_solves = 0;  // steady solves, Satran duty cycles or cam revolutions (cache misses)
};

// where a life starts: the unworn state, or a checkpoint
struct LifeStart {
  double N = 0;
  Eigen::VectorXd state;
  double next_step = 0;   // adaptive: the step to try first (a checkpoint's), 0 = ARKODE's estimate
  LifeCounters counters;  // so far (a checkpoint's)
};

// what a life integrates and what ends it, as data
struct LifeProblem {
  Rhs rate;                     // dx/dN = f(x) (N is not read)
  std::vector<LifeEnd> limits;  // limit k ends the life as limits[k]
  Roots limit_values;           // g_k(x), k < limits.size(): < 0 inside the life, -1 for a limit that is off
  IntegratorOptions options;    // max_steps counts over the whole life
  double revolutions = 0;       // the budget
  std::string budget_key;       // its key, for the message ("wear.revolutions")
  std::vector<double> snapshots_revolutions;  // increasing: the life stops at each ahead of its start
  // the supplier's solve counts in this process (rate_evaluations, limit_evaluations, normal_solves,
  // tangential_solves; the rest is not read): the life's are the start's plus what they added since
  std::function<LifeCounters()> solves;
  // An exception thrown by the rate or the limits (nested in the integrator's, which names N) that ends
  // the life Failed at its last accepted step N_last: its kind (the supplier may say so in the log);
  // LifeFailure::None rethrows it
  std::function<LifeFailure(const std::exception& e, double N_last)> failure_of;
  // At each accepted step's end, before the caller's hook: true when the rate's model changed there (the
  // corrected fidelity's new correction, wear/wear_loop.h): the integration restarts from that step end, as it
  // does at a snapshot, so that no step mixes two models (an embedded pair's first stage is its last one's)
  std::function<bool(double N, const Eigen::VectorXd& state)> refresh;
};

// an accepted step's end
struct LifeStepEnd {
  double N = 0;
  const Eigen::VectorXd* state = nullptr;
  StepInfo info;                          // this step, its counters over the whole life
  double next_step = 0;                   // the step to resume with (StepInfo::next_step)
  std::function<LifeCounters()> counters;  // the life's up to now (solves made in the hook included)
};

struct LifeDriverHooks {
  // where the life starts, before anything else (the solves made there are the life's)
  std::function<void(double N, const Eigen::VectorXd& state)> on_start;
  std::function<bool(const LifeStepEnd&)> on_step;                          // false stops the life
  std::function<void(double N, const Eigen::VectorXd& state)> on_snapshot;  // at each snapshot revolution
  // where the life ends, before its counters are closed (a last evaluation there is counted)
  std::function<void(double N, const Eigen::VectorXd& state)> on_end;
};

struct LifeOutcome {
  LifeEnd ended_by = LifeEnd::NotRun;
  LifeFailure failure = LifeFailure::None;
  std::string message;
  double N = 0;
  Eigen::VectorXd state;
  double next_step = 0;
  LifeCounters counters;  // over the whole life (a resumed run's start included)
};

// Integrates from start (its state sized as the problem's rate) through each snapshot revolution
// ahead of it to the first limit, located, or the budget. A limit already reached at the start ends
// the life there. Throws what the rate or the limits throw when failure_of says None, and
// std::invalid_argument for bad options.
LifeOutcome integrate_life(const LifeProblem& p, const LifeStart& start, const LifeDriverHooks& hooks = {});

}  // namespace wear
