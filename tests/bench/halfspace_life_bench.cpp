// The half-space normal problem as a wear life evaluates it (solver.normal halfspace, docs/halfspace.md
// "In a wear life"): on the paper's roller worn by its shipped life (cases/paper-wear.yaml, the default
// path, to 3.0e7 revolutions: a crown worn flat about 45 um deep across its contact), 80 x 80, solved
//   cold  from nothing: the coarse solve over the overlap, the fine one on its box, the patch, the edge value;
//   warm  from the previous evaluation's solution, the same life at 2.9e7 revolutions (a step of the
//         life's size earlier): the same stages, each started from that solution's pressures.
// Issue 24's target: warm <= 5 ms. Counters: half-space solves and conjugate-gradient iterations per
// evaluation, and the fine grid's box.
//   cmake --preset bench && cmake --build --preset bench -j2 --target halfspace_life_bench
//   build/bench/tests/bench/halfspace_life_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <spdlog/spdlog.h>

#include <string>

#include "lib/normal/normal.h"
#include "tests/bench/bench_common.h"
#include "wear/wear_loop.h"

namespace {

const bool kQuiet = (spdlog::set_level(spdlog::level::warn), true);

struct WornRoller {
  wear::WearModel model;
  contact::Profiles previous, current;  // worn to 2.9e7 and 3.0e7 revolutions
};

contact::Profiles worn_to(const wear::WearCase& c, const wear::WearModel& m, double N) {
  wear::WearCase k = c;
  k.wear.revolutions = N;
  k.wear.snapshots_revolutions.clear();
  k.wear.limits = wear::WearLimits{0, 0, false};
  wear::WearCache cache;
  const wear::LifeResult life = wear::run_life(m, k, wear::LifeStart{}, wear::LifeHooks{}, cache);
  return wear::worn_profiles(m, life.state);
}

const WornRoller& roller() {
  static const WornRoller r = [] {
    const wear::WearCase c = wear::read_wear_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper-wear.yaml");
    WornRoller w;
    w.model = wear::make_wear_model(c);
    w.previous = worn_to(c, w.model, 2.9e7);
    w.current = worn_to(c, w.model, 3.0e7);
    return w;
  }();
  return r;
}

contact::NormalProblem problem_on(const WornRoller& r, const contact::Profiles& profiles, int n) {
  contact::NormalProblem p;
  p.choice = contact::NormalChoice::Halfspace;
  p.bodies = {{r.model.Rx1_m, contact::kFlat}, {r.model.Rx2_m, contact::kFlat}};
  p.profiles = &profiles;
  p.worn = true;
  p.pair = r.model.materials;
  p.normal_load_N = r.model.normal_load_N;
  p.grid = {n, n};
  p.semi_hertz = r.model.normal_options;
  return p;
}

void report(benchmark::State& state, const contact::NormalSolution& s) {
  state.counters["solves"] = s.halfspace.solves;
  state.counters["iterations"] = s.halfspace.iterations;
  state.counters["box_x_mm"] = s.patch.grid.half_x_m * 1e3;
  state.counters["box_y_mm"] = s.patch.grid.half_y_m * 1e3;
  state.counters["p0_MPa"] = s.patch.p0_Pa * 1e-6;
  if (!s.solve_converged) state.SkipWithError(("not converged: " + s.status.message).c_str());
}

void BM_WornHalfspace(benchmark::State& state) {
  const WornRoller& r = roller();
  const int n = static_cast<int>(state.range(0));
  const bool warm = state.range(1) != 0;
  const contact::NormalSolution before = contact::solve_normal(problem_on(r, r.previous, n));
  contact::NormalProblem p = problem_on(r, r.current, n);
  if (warm) p.halfspace_start = &before.halfspace;
  contact::NormalSolution s;
  for (auto _ : state) {
    s = contact::solve_normal(p);
    bench::keep(s.patch.approach_m);
  }
  report(state, s);
}
BENCHMARK(BM_WornHalfspace)->ArgNames({"n", "warm"})->Args({80, 0})->Args({80, 1})->Unit(benchmark::kMillisecond);

// the paper's life to its end on the half-space at 40 x 40, with and without the warm start
void BM_PaperWearHalfspaceLife(benchmark::State& state) {
  wear::WearCase c = wear::read_wear_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper-wear.yaml");
  c.contact.solver.normal = contact::NormalChoice::Halfspace;
  c.contact.solver.nx = c.contact.solver.ny = static_cast<int>(state.range(0));
  const wear::WearModel m = wear::make_wear_model(c);
  wear::LifeResult life;
  wear::WearCache last;
  for (auto _ : state) {
    wear::WearCache cache;
    cache.halfspace_warm_start = state.range(1) != 0;
    life = wear::run_life(m, c, wear::LifeStart{}, wear::LifeHooks{}, cache);
    bench::keep(life.N);
    last = cache;
  }
  state.counters["revolutions"] = life.N;
  state.counters["normal_solves"] = static_cast<double>(life.counters.normal_solves);
  state.counters["hs_solves"] = static_cast<double>(last.halfspace_solves);
  state.counters["hs_iterations"] = static_cast<double>(last.halfspace_iterations);
  state.counters["steps"] = static_cast<double>(life.counters.steps);
  state.counters["rejected"] = static_cast<double>(life.counters.rejected);
}
BENCHMARK(BM_PaperWearHalfspaceLife)
    ->ArgNames({"n", "warm"})
    ->Args({40, 0})
    ->Args({40, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
