// A wear life driven to its end (docs/wear-loop.md): the rows of its table and its snapshots handed out as they
// come, the same for `rollwear run` (into a folder, with its checkpoint: session/life_run.h), a sweep's case
// (session/sweep.h) and the Python module's run (in memory).
#pragma once

#include <functional>

#include <Eigen/Core>

#include "wear/wear_case.h"
#include "wear/wear_loop.h"

namespace session {

// what a wear life hands out as it goes
struct WearLifeObserver {
  // each row of the table: step 0's (a fresh start's unworn state), each accepted step's, and a limit's located
  // within a step (the life then ends between step ends: its state is the last row)
  std::function<void(const wear::LifeStep&)> on_row;
  // after each accepted step's row: false stops the life (LifeEnd::Stopped); empty: the life goes on
  std::function<bool(const wear::LifeStep&)> on_step;
  std::function<void(double N, const Eigen::VectorXd& state)> on_snapshot;  // at each snapshot revolution
};

// the unworn start of a life: the initial state, its contact (step 0's row, handed to on_row) and the counters
// of that first solve
wear::LifeStart fresh_wear_start(const wear::WearModel& m, wear::WearCache& cache, const WearLifeObserver& o);

// the life from `start` to the limit, the budget or a failure (wear::run_life), its rows handed out; with
// bodies.bodyN.dang_van and a life that did not fail, Dang Van's index on its final worn contact in
// LifeResult::dang_van (wear/dang_van_life.h: one more contact solve and its subsurface field, at the end)
wear::LifeResult drive_wear_life(const wear::WearModel& m, const wear::WearCase& c, const wear::LifeStart& start,
                                 wear::WearCache& cache, const WearLifeObserver& o);

}  // namespace session
