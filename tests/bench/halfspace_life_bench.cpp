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

#include <cmath>
#include <string>

#include "lib/normal/halfspace.h"
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

// the fine solve alone, on the evaluation's final grid: cold, and from the previous evaluation's fine
// pressures interpolated onto it (what solve_normal's fine stage does); at the default tol 1e-9 and, to
// show what the tolerance costs, at 1e-6
void BM_WornHalfspaceFineOnly(benchmark::State& state) {
  const WornRoller& r = roller();
  const int n = static_cast<int>(state.range(0));
  const contact::NormalSolution before = contact::solve_normal(problem_on(r, r.previous, n));
  const contact::NormalSolution now = contact::solve_normal(problem_on(r, r.current, n));
  const contact::Grid& g = now.halfspace.grid;
  const double y0 = now.halfspace.grid_y0_m, A = (1 / r.model.Rx1_m + 1 / r.model.Rx2_m) / 2;
  Eigen::ArrayXXd gap(g.nx, g.ny);
  for (int j = 0; j < g.ny; ++j) {
    const double h = contact::profile_z(r.current.body1, y0 + g.y_m(j)) + contact::profile_z(r.current.body2, y0 + g.y_m(j));
    for (int i = 0; i < g.nx; ++i) gap(i, j) = h + A * g.x_m(i) * g.x_m(i);
  }
  gap -= gap.minCoeff();
  const Eigen::ArrayXXd start =
      contact::interpolate_pressure(before.halfspace.pressure_Pa, before.halfspace.grid, before.halfspace.grid_y0_m, g, y0);
  contact::HalfspaceOptions opt;
  if (state.range(1) != 0) opt.initial_pressure_Pa = &start;
  opt.tol = std::pow(10.0, -static_cast<double>(state.range(2)));  // 1e-9 is the default
  opt.precondition = state.range(3) != 0;
  const double Estar = contact::effective_modulus_Pa(r.model.materials);
  contact::HalfspaceSolution s;
  for (auto _ : state) {
    s = contact::solve_halfspace(g, gap, Estar, r.model.normal_load_N, opt);
    bench::keep(s.approach_m);
  }
  state.counters["iterations"] = s.status.iterations;
  state.counters["products"] = s.products;
  // against Polonsky & Keer's unpreconditioned iteration from the same start (the answer before the
  // preconditioner): pressures as a fraction of the peak, approach relative
  contact::HalfspaceOptions plain = opt;
  plain.precondition = false;
  const contact::HalfspaceSolution ref = contact::solve_halfspace(g, gap, Estar, r.model.normal_load_N, plain);
  state.counters["dp_of_peak"] = (s.pressure_Pa - ref.pressure_Pa).abs().maxCoeff() / ref.pressure_Pa.maxCoeff();
  state.counters["ddelta_rel"] = std::abs(s.approach_m - ref.approach_m) / ref.approach_m;
  // against a tight solve (tol 1e-12, preconditioned, from the same start): the strip loads (what a wear
  // life reads), largest change over the strips as a fraction of the largest strip load
  contact::HalfspaceOptions tight = opt;
  tight.tol = 1e-12;
  tight.precondition = true;
  const contact::HalfspaceSolution best = contact::solve_halfspace(g, gap, Estar, r.model.normal_load_N, tight);
  const Eigen::ArrayXd q = s.pressure_Pa.colwise().sum().transpose(), q_best = best.pressure_Pa.colwise().sum().transpose();
  state.counters["dq_strip_rel"] = (q - q_best).abs().maxCoeff() / q_best.maxCoeff();
  // cells loaded below 1e-6 of the peak (loaded only to the tolerance), in this solve and the tight one
  const double peak = s.pressure_Pa.maxCoeff();
  state.counters["faint_cells"] = static_cast<double>(((s.pressure_Pa > 0) && (s.pressure_Pa < 1e-6 * peak)).count());
  state.counters["faint_cells_tight"] =
      static_cast<double>(((best.pressure_Pa > 0) && (best.pressure_Pa < 1e-6 * best.pressure_Pa.maxCoeff())).count());
  if (!s.status.converged()) state.SkipWithError(("not converged: " + s.status.message).c_str());
}
BENCHMARK(BM_WornHalfspaceFineOnly)
    ->ArgNames({"n", "warm", "tol_exp", "pre"})
    ->Args({80, 0, 9, 0})
    ->Args({80, 1, 9, 0})
    ->Args({80, 0, 9, 1})
    ->Args({80, 1, 9, 1})
    ->Args({80, 1, 8, 1})
    ->Args({80, 1, 7, 1})
    ->Args({80, 0, 6, 1})
    ->Args({80, 1, 6, 1})
    ->Unit(benchmark::kMillisecond);

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
