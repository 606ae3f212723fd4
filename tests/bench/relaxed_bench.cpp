// The relaxed model's cost against the simplified theory it wraps (docs/accuracy-vs-exact.md, "Default"):
// the steady solve on the paper's contact (cases/paper.yaml, 80 x 80; pure xi, the closed-form path, and
// xi, eta, phi, the march), and the paper's start-up (cases/paper-startup.yaml, 80 x 80, 110 shift steps):
// Satran's run against the relaxed model's run, no fields.
//   cmake --preset bench && cmake --build --preset bench --target relaxed_bench &&
//   build/bench/tests/bench/relaxed_bench --benchmark_repetitions=7 --benchmark_enable_random_interleaving=true
//     --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <string>

#include "lib/io/case.h"
#include "lib/normal/hertz.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/steady.h"

namespace {

using namespace contact;

const ElasticPair kSteel{{210e9, 0.28}, {210e9, 0.28}};

ContactPatch paper_patch() {
  return solve_normal_hertz({{20e-3, 500e-3}, {25e-3, kFlat}}, kSteel, 1500, GridSpec{80, 80});
}

Creepages creepages(int mix) { return mix ? Creepages{1e-3, 5e-4, 0.5} : Creepages{1e-3, 0, 0}; }

void BM_SteadyConsistent(benchmark::State& st) {
  const ContactPatch p = paper_patch();
  const Creepages c = creepages(static_cast<int>(st.range(0)));
  SteadyOptions o;
  o.fields = false;
  for (auto _ : st) {
    const TangentialProblem pb = make_tangential_problem(p, kSteel, c, 0.3, 1.0);
    benchmark::DoNotOptimize(solve_steady(p, pb, TangentialScheme::Consistent, o).Fx_N);
  }
}
BENCHMARK(BM_SteadyConsistent)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_SteadyRelaxed(benchmark::State& st) {
  const ContactPatch p = paper_patch();
  const Creepages c = creepages(static_cast<int>(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(solve_relaxed_steady(p, kSteel, c, 0.3, 1.0, false).Fx_N);
}
BENCHMARK(BM_SteadyRelaxed)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

TransientCase startup() {
  TransientCase t = transient_case_of(read_contact_case(ROLLWEAR_SOURCE_DIR "/cases/paper-startup.yaml"));
  t.settings.snapshot_times_s.clear();
  return t;
}

void BM_StartupSatran(benchmark::State& st) {
  const TransientCase t = startup();
  for (auto _ : st) benchmark::DoNotOptimize(run_transient(t).dissipated_J);
}
BENCHMARK(BM_StartupSatran)->Unit(benchmark::kMillisecond);

void BM_StartupRelaxed(benchmark::State& st) {
  const TransientCase t = startup();
  for (auto _ : st) benchmark::DoNotOptimize(run_relaxed_transient(t).dissipated_J);
}
BENCHMARK(BM_StartupRelaxed)->Unit(benchmark::kMillisecond);

}  // namespace
