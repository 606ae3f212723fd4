// The exact theory's steady solve and rolling step (lib/tangential/exact.h) on the paper's case (cases/paper.yaml:
// Hertz contact, mu, speed), xi = 1e-3, one thread (docs/exact-theory.md, "Speed"). Each run first
// solves the same problem to tol 1e-12 (untimed) and reports the relative difference of the timed
// solve's forces from it (counter dF_rel; the goal is <= 1e-5) and its iteration counts.
//   build/bench/tests/bench/exact_bench          (arguments: cells a side, -log10 of the tolerance)
#include <benchmark/benchmark.h>

#include "tests/bench/bench_common.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "lib/elastic.h"
#include "lib/normal/hertz.h"
#include "lib/tangential/exact.h"

namespace {

using namespace contact;

using bench::keep;
using bench::paper;

constexpr double kXi = 1e-3;
// the solve's tolerance on the fixed-point residual is 10^-range(1): the forces must come out within
// 1e-5 of the 1e-12 solve's (the counter dF_rel shows it on each run)

void exact_steady(benchmark::State& state, double mu) {
  const int n = static_cast<int>(state.range(0));
  const auto& c = paper();
  const ContactPatch patch = solve_normal_hertz(c.bodies, c.pair, c.normal_load_N, {n, n});
  const double G = combined_shear_modulus_Pa(c.pair), nu = combined_poisson(c.pair);
  ExactOptions tight;
  tight.tol = 1e-12;
  tight.stick_tol = 1e-12;
  const ExactSolution ref = solve_exact_steady(patch, G, nu, {kXi, 0, 0}, mu, c.speed_m_per_s, tight);
  ExactOptions o;
  o.tol = std::pow(10.0, -static_cast<double>(state.range(1)));
  o.stick_tol = o.tol;
  ExactSolution s;
  for (auto _ : state) {
    s = solve_exact_steady(patch, G, nu, {kXi, 0, 0}, mu, c.speed_m_per_s, o);
    keep(s.fields.Fx_N);
  }
  const double F = std::hypot(ref.fields.Fx_N, ref.fields.Fy_N);
  state.counters["Fx_N"] = s.fields.Fx_N;
  state.counters["dF_rel"] =
      std::max(std::abs(s.fields.Fx_N - ref.fields.Fx_N), std::abs(s.fields.Fy_N - ref.fields.Fy_N)) / F;
  state.counters["gmres"] = s.status.iterations;
  state.counters["newton"] = s.active_set_iterations;
  state.counters["converged"] = s.status.converged() && ref.status.converged() ? 1 : 0;
}

// the paper's mu (0.3): stick and slip
void BM_ExactSteady(benchmark::State& state) { exact_steady(state, paper().mu); }
// mu = 1e4: full stick, the linear theory (one GMRES solve)
void BM_ExactSteadyFullStick(benchmark::State& state) { exact_steady(state, 1e4); }

// the steady solve started from the solution of a slightly different contact (a life's last evaluation):
// the normal load lower by range(2) per mille (the Hertz patch's grid shrinks with it) and xi lower by
// range(2) per mille; the counters as BM_ExactSteady's, cold_gmres the same solve's GMRES iterations cold
void BM_ExactSteadyWarm(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double change = 1e-3 * static_cast<double>(state.range(2));
  const auto& c = paper();
  const ContactPatch patch = solve_normal_hertz(c.bodies, c.pair, c.normal_load_N, {n, n});
  const ContactPatch before = solve_normal_hertz(c.bodies, c.pair, c.normal_load_N * (1 + change), {n, n});
  const double G = combined_shear_modulus_Pa(c.pair), nu = combined_poisson(c.pair);
  ExactOptions o;
  o.tol = std::pow(10.0, -static_cast<double>(state.range(1)));
  o.stick_tol = o.tol;
  const ExactSolution start = solve_exact_steady(before, G, nu, {kXi * (1 + change), 0, 0}, c.mu, c.speed_m_per_s, o);
  const ExactSolution cold = solve_exact_steady(patch, G, nu, {kXi, 0, 0}, c.mu, c.speed_m_per_s, o);
  ExactOptions tight;
  tight.tol = 1e-12;
  tight.stick_tol = 1e-12;
  const ExactSolution ref = solve_exact_steady(patch, G, nu, {kXi, 0, 0}, c.mu, c.speed_m_per_s, tight);
  ExactSolution s;
  for (auto _ : state) {
    s = solve_exact_steady(patch, G, nu, {kXi, 0, 0}, c.mu, c.speed_m_per_s, o, &start);
    keep(s.fields.Fx_N);
  }
  const double F = std::hypot(ref.fields.Fx_N, ref.fields.Fy_N);
  state.counters["Fx_N"] = s.fields.Fx_N;
  state.counters["dF_rel"] =
      std::max(std::abs(s.fields.Fx_N - ref.fields.Fx_N), std::abs(s.fields.Fy_N - ref.fields.Fy_N)) / F;
  state.counters["gmres"] = s.status.iterations;
  state.counters["cold_gmres"] = cold.status.iterations;
  state.counters["newton"] = s.active_set_iterations;
  state.counters["converged"] = s.status.converged() && ref.status.converged() ? 1 : 0;
}

// one rolling step by dq = dx at q = 2a after a start from rest (the state reached untimed), warm
// started from the previous step as a transient run does; the steps before it with the same options
void rolling_step(benchmark::State& state, const ExactOptions& o) {
  const int n = static_cast<int>(state.range(0));
  const auto& c = paper();
  const ContactPatch patch = solve_normal_hertz(c.bodies, c.pair, c.normal_load_N, {n, n});
  const double G = combined_shear_modulus_Pa(c.pair), nu = combined_poisson(c.pair);
  ExactSolution prev;
  for (int k = 1; k < n; ++k)  // q = 2a - dx
    prev = solve_exact_rolling_step(patch, G, nu, {kXi, 0, 0}, c.mu, c.speed_m_per_s, k == 1 ? nullptr : &prev, o);
  ExactOptions tight;
  tight.tol = 1e-12;
  tight.stick_tol = 1e-12;
  const ExactSolution ref = solve_exact_rolling_step(patch, G, nu, {kXi, 0, 0}, c.mu, c.speed_m_per_s, &prev, tight);
  ExactSolution s;
  for (auto _ : state) {
    s = solve_exact_rolling_step(patch, G, nu, {kXi, 0, 0}, c.mu, c.speed_m_per_s, &prev, o);
    keep(s.fields.Fx_N);
  }
  state.counters["Fx_N"] = s.fields.Fx_N;
  state.counters["dF_rel"] = std::abs(s.fields.Fx_N - ref.fields.Fx_N) / std::abs(ref.fields.Fx_N);
  state.counters["gmres"] = s.status.iterations;
  state.counters["newton"] = s.active_set_iterations;
  state.counters["products"] = s.products;
  state.counters["converged"] = s.status.converged() && ref.status.converged() ? 1 : 0;
}

// arguments: cells a side, -log10 of the tolerance, -log10 of the linear solves' floor (0: the tolerance)
void BM_ExactRollingStep(benchmark::State& state) {
  ExactOptions o;
  o.tol = std::pow(10.0, -static_cast<double>(state.range(1)));
  o.stick_tol = state.range(2) > 0 ? std::pow(10.0, -static_cast<double>(state.range(2))) : o.tol;
  rolling_step(state, o);
}
// the tolerance and the linear floor as numbers (argument: cells a side)
void BM_ExactRollingStepAt(benchmark::State& state, double tol, double linear_floor) {
  ExactOptions o;
  o.tol = tol;
  o.stick_tol = linear_floor;
  rolling_step(state, o);
}

BENCHMARK_CAPTURE(BM_ExactRollingStepAt, tol1e-2_linear0.3, 1e-2, 0.3)->Arg(80)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExactRollingStep)
    ->Args({80, 1, 0})->Args({80, 2, 0})->Args({80, 3, 0})->Args({80, 4, 0})
    ->Args({80, 2, 1})->Args({80, 3, 1})->Args({80, 3, 2})->Args({80, 4, 1})
    ->Unit(benchmark::kMillisecond);
// tol 1e-4: the forces within 1e-5 of the 1e-12 solve; 1e-9: ExactOptions' default, what `rollwear contact` runs
BENCHMARK(BM_ExactSteady)
    ->Args({40, 4})->Args({80, 4})->Args({160, 4})->Args({40, 6})->Args({80, 6})
    ->Args({40, 9})->Args({80, 9})->Args({160, 9})
    ->Unit(benchmark::kMillisecond);
// arguments: cells a side, -log10 of the tolerance, the change of load and xi in per mille
BENCHMARK(BM_ExactSteadyWarm)->Args({80, 4, 1})->Args({80, 4, 3})->Args({80, 4, 10})->Args({80, 9, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExactSteadyFullStick)->Args({80, 6})->Unit(benchmark::kMillisecond);

}  // namespace
