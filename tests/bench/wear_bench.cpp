// The wear loop's benchmark: the paper's case (cases/paper-wear.yaml) to its 0.1 mm depth
// limit. Goal: <= 1 s wall on one core. Reports the ARKODE steps, the evaluations of dh/dN and the
// normal and tangential solves of one life as counters, and where the life ended.
//   cmake --preset bench && cmake --build --preset bench -j2 --target wear_bench
//   build/bench/tests/bench/wear_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>

#include "tests/bench/bench_common.h"
#include "wear/wear_loop.h"

namespace {

void BM_PaperWearToDepthLimit(benchmark::State& state) {
  const wear::WearCase c = wear::read_wear_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper-wear.yaml");
  const wear::WearModel m = wear::make_wear_model(c);
  wear::LifeResult life;
  for (auto _ : state) {
    wear::WearCache cache;  // a fresh run each time: nothing reused across lives
    life = wear::run_life(m, c, wear::LifeStart{}, wear::LifeHooks{}, cache);
    bench::keep(life.N);
  }
  const wear::LifeCounters& counters = life.counters;
  state.counters["steps"] = static_cast<double>(counters.steps);
  state.counters["rejected"] = static_cast<double>(counters.rejected);
  state.counters["rhs_evals"] = static_cast<double>(counters.rhs_evals);
  state.counters["normal_solves"] = static_cast<double>(counters.normal_solves);
  state.counters["tangential_solves"] = static_cast<double>(counters.tangential_solves);
  state.counters["revolutions"] = life.N;
  state.counters["max_depth_um"] = wear::max_depth_m(m, life.state) * 1e6;
  state.SetLabel("ended by " + wear::to_string(life.ended_by));
}
BENCHMARK(BM_PaperWearToDepthLimit)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
