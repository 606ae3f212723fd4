// The normal problem's timings on the paper's case (cases/paper.yaml, or the same values below if
// that file is missing): Hertz as strips, the semi-Hertzian solver on a crowned and on a worn
// roller, the two skips of solve_normal_on_profiles (Hertz on constant curvature; reuse of the last
// solution when the profiles' hash did not change) and the exact half-space solver on 64 x 64
// (docs/benchmarks.md, "Normal problem").
#include <benchmark/benchmark.h>

#include "tests/bench/bench_common.h"

#include <spdlog/spdlog.h>

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>

#include "lib/io/case.h"
#include "lib/elastic.h"
#include "lib/grid.h"
#include "lib/normal/halfspace.h"
#include "lib/normal/hertz.h"
#include "lib/patch.h"
#include "lib/normal/profile.h"
#include "lib/normal/semi_hertz.h"

namespace {

using namespace contact;

using bench::keep;
using bench::paper;
using bench::PaperCase;

// solve_normal_on_profiles logs a spdlog::info per Hertz skip: keep the output to warnings
const bool kQuiet = (spdlog::set_level(spdlog::level::warn), true);

constexpr double kRollerRy_m = 0.500;      // crown radius
constexpr double kRollerWidth_m = 0.020;   // roller width
constexpr double kPathWidth_m = 0.030;     // flat path, wider than the roller
constexpr double kWornBandHalf_m = 0.0015;  // flat_worn_crown_profile band

Profiles crowned_on_flat() {
  return {crowned_profile(kRollerRy_m, kRollerWidth_m), flat_profile(kPathWidth_m)};
}

Profiles worn_on_flat() {
  return {flat_worn_crown_profile(kRollerRy_m, kRollerWidth_m, kWornBandHalf_m), flat_profile(kPathWidth_m)};
}

GridSpec spec_of(const benchmark::State& state) {
  return GridSpec{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
}

// Hertz: the ellipse, then its strips (and cell pressures when nx > 1) on a grid over its box
void BM_HertzStrips(benchmark::State& state) {
  const PaperCase& c = paper();
  const GridSpec spec = spec_of(state);
  for (auto _ : state) {
    const HertzContact h = solve_hertz(c.bodies, c.pair, c.normal_load_N);
    const ContactPatch patch = hertz_patch(h, make_grid(h.a_m, h.b_m, spec));
    keep(patch.pressure_Pa.data());
    keep(patch.p0_Pa);
  }
}
BENCHMARK(BM_HertzStrips)->ArgNames({"nx", "ny"})->Args({1, 80})->Args({80, 80});

void semi_hertz(benchmark::State& state, const Profiles& profiles) {
  const PaperCase& c = paper();
  const GridSpec spec = spec_of(state);
  SemiHertzResult r;
  for (auto _ : state) {
    r = solve_semi_hertz(profiles, c.bodies.body1.Rx_m, c.bodies.body2.Rx_m, c.pair, c.normal_load_N, spec);
    keep(r.approach_m);
    keep(r.patch.pressure_Pa.data());
  }
  state.counters["evaluations"] = r.status.iterations;
  state.counters["delta_um"] = r.approach_m * 1e6;
}

void BM_SemiHertzCrowned(benchmark::State& state) {
  static const Profiles profiles = crowned_on_flat();
  semi_hertz(state, profiles);
}
BENCHMARK(BM_SemiHertzCrowned)->ArgNames({"nx", "ny"})->Args({1, 80})->Args({80, 80});

void BM_SemiHertzWornBand(benchmark::State& state) {
  static const Profiles profiles = worn_on_flat();
  semi_hertz(state, profiles);
}
BENCHMARK(BM_SemiHertzWornBand)->ArgNames({"nx", "ny"})->Args({1, 80})->Args({80, 80});

// the Hertz skip: on the crowned roller solve_normal_on_profiles fits both profiles' curvature and
// uses Hertz; compare with BM_SemiHertzCrowned on the same grid
void BM_NormalOnProfilesAuto(benchmark::State& state) {
  static const Profiles profiles = crowned_on_flat();
  const PaperCase& c = paper();
  const GridSpec spec = spec_of(state);
  SemiHertzResult r;
  for (auto _ : state) {
    r = solve_normal_on_profiles(profiles, c.bodies.body1.Rx_m, c.bodies.body2.Rx_m, c.pair, c.normal_load_N, spec);
    keep(r.approach_m);
    keep(r.patch.pressure_Pa.data());
  }
  state.counters["delta_um"] = r.approach_m * 1e6;
  if (r.solver != NormalSolverKind::Hertz) state.SkipWithError(("no Hertz skip: " + r.status.message).c_str());
}
BENCHMARK(BM_NormalOnProfilesAuto)->ArgNames({"nx", "ny"})->Args({1, 80})->Args({80, 80});

// the Hertz skip's decision alone, as solve_normal_on_profiles makes it on the crowned roller: both
// profiles tested for constant curvature, then both fitted again for the radii
void BM_ConstantCurvatureCheck(benchmark::State& state) {
  static const Profiles profiles = crowned_on_flat();
  bool constant = false;
  for (auto _ : state) {
    constant = has_constant_curvature(profiles.body1, 1e-3) && has_constant_curvature(profiles.body2, 1e-3);
    const ParabolaFit f1 = fit_parabola(profiles.body1), f2 = fit_parabola(profiles.body2);
    keep(constant);
    keep(f1.curvature_per_m);
    keep(f2.curvature_per_m);
  }
  if (!constant) state.SkipWithError("not constant curvature");
}
BENCHMARK(BM_ConstantCurvatureCheck);

// the reuse skip's cost: hash both profiles and compare with the hash of the last solve's profiles
// (arg 0: crowned roller, 1: worn band); the saving is a solve (BM_SemiHertz*) against this
void BM_ReuseByHash(benchmark::State& state) {
  static const Profiles crowned = crowned_on_flat();
  static const Profiles worn = worn_on_flat();
  const Profiles& profiles = state.range(0) == 0 ? crowned : worn;
  const std::uint64_t last = profile_hash(profiles);
  bool same = false;
  for (auto _ : state) {
    same = profile_hash(profiles) == last;
    keep(same);
  }
  state.counters["nodes"] = static_cast<double>(profiles.body1.y_m.size() + profiles.body2.y_m.size());
  if (!same) state.SkipWithError("hash changed");
}
BENCHMARK(BM_ReuseByHash)->ArgName("worn")->Arg(0)->Arg(1);

// the exact solver: n x n cells over 1.25 a x 1.25 b of the paper's Hertz ellipse, gap A x^2 + B y^2
void BM_Halfspace(benchmark::State& state) {
  const PaperCase& c = paper();
  const int n = static_cast<int>(state.range(0));
  const HertzContact h = solve_hertz(c.bodies, c.pair, c.normal_load_N);
  const Grid g = make_grid(1.25 * h.a_m, 1.25 * h.b_m, GridSpec{n, n});
  Eigen::ArrayXXd gap(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) gap(i, j) = h.A_per_m * g.x_m(i) * g.x_m(i) + h.B_per_m * g.y_m(j) * g.y_m(j);
  HalfspaceSolution s;
  for (auto _ : state) {
    s = solve_halfspace(g, gap, h.Estar_Pa, c.normal_load_N);
    keep(s.approach_m);
    keep(s.pressure_Pa.data());
  }
  state.counters["iterations"] = s.status.iterations;
  state.counters["residual"] = s.status.residual;
  if (!s.status.converged()) state.SkipWithError(("not converged: " + s.status.message).c_str());
}
BENCHMARK(BM_Halfspace)->Arg(64);

}  // namespace
