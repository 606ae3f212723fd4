// The cost of the result files' numbers (docs/benchmarks.md): a value formatted as the CSV files write it
// (lib/number.h: std::to_chars, the shortest text that reads back exactly) against snprintf("%.17g"), a
// format string parsed at run time for every value, and a whole 80 x 80 snapshot (snapshot_csv: five
// fields and the cell coordinates per row). ns_per_value: the time over the values written.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "lib/io/case.h"
#include "lib/io/csv.h"
#include "lib/number.h"

namespace {

using namespace contact;

// values as a snapshot holds them: tractions of 1e8 Pa, slips of 1e-3 m/s, with every digit set
std::vector<double> field_values(int n) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng) * (i % 2 ? 3e8 : 2e-3);
  return v;
}

constexpr int kValues = 4096;

void BM_RoundTripNumber(benchmark::State& st) {
  const std::vector<double> v = field_values(kValues);
  std::string out;
  for (auto _ : st) {
    out.clear();
    for (double x : v) {
      append_round_trip(out, x);
      out.push_back(',');
    }
    benchmark::DoNotOptimize(out.data());
  }
  st.counters["ns_per_value"] =
      benchmark::Counter(1e-9 * kValues, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_RoundTripNumber);

void BM_SnprintfG17(benchmark::State& st) {
  const std::vector<double> v = field_values(kValues);
  std::string out;
  char buf[32];
  for (auto _ : st) {
    out.clear();
    for (double x : v) {
      out.append(buf, std::snprintf(buf, sizeof buf, "%.17g", x));
      out.push_back(',');
    }
    benchmark::DoNotOptimize(out.data());
  }
  st.counters["ns_per_value"] =
      benchmark::Counter(1e-9 * kValues, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_SnprintfG17);

// a snapshot of the paper's 80 x 80 grid: 80 x 80 rows of x, y and five fields
void BM_SnapshotCsv(benchmark::State& st) {
  const int n = 80;
  Grid g;
  g.nx = g.ny = n;
  g.half_x_m = g.half_y_m = 1e-3;
  g.dx_m = g.dy_m = 2e-3 / n;
  g.x_m = Eigen::ArrayXd::LinSpaced(n, -1e-3 + 1e-3 / n, 1e-3 - 1e-3 / n);
  g.y_m = g.x_m;
  const std::vector<double> v = field_values(n * n);
  const Eigen::ArrayXXd f = Eigen::Map<const Eigen::ArrayXXd>(v.data(), n, n);
  Snapshot s;
  s.pressure_Pa = s.tau_x_Pa = s.tau_y_Pa = s.slip_x_m_per_s = s.slip_y_m_per_s = f;
  size_t bytes = 0;
  for (auto _ : st) {
    const std::string text = snapshot_csv(g, s);
    bytes = text.size();
    benchmark::DoNotOptimize(text.data());
  }
  st.counters["bytes"] = static_cast<double>(bytes);
  st.counters["ns_per_value"] = benchmark::Counter(1e-9 * n * n * 7, benchmark::Counter::kIsIterationInvariantRate |
                                                                           benchmark::Counter::kInvert);
}
BENCHMARK(BM_SnapshotCsv)->Unit(benchmark::kMillisecond);

// the solve of `rollwear transient cases/paper-startup.yaml` (with and without the snapshot fields): what
// the command's wall time is held against (docs/benchmarks.md, "Outputs")
void BM_PaperStartupSolve(benchmark::State& st) {
  const ContactCase c = read_contact_case(ROLLWEAR_SOURCE_DIR "/cases/paper-startup.yaml");
  TransientCase t = transient_case_of(c);
  if (st.range(0) == 0) t.settings.snapshot_times_s.clear();
  double sink = 0;
  for (auto _ : st) sink += run_transient(t).dissipated_J;
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(BM_PaperStartupSolve)->ArgName("fields")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
