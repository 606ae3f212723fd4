// The contact engine's timings on the paper's case (cases/paper.yaml, or the same values below if
// that file is missing): Hertz alone, the normal problem on a grid, the steady tangential solver
// with both schemes, and a plain cell-by-cell loop of classic FASTSIM as the baseline the product is
// compared against (docs/benchmarks.md).
//
// The baseline (Kalker's FASTSIM, docs/physics.md §3) marches each strip from the leading edge with
//   tau_pred = tau_prev - (xi/L1 - phi y/L3, eta/L2 + phi x/L3) dx,
//   tau = tau_pred clipped to |tau| <= g = mu p_j sqrt(1 - (x/a_j)^2) at the cell centre,
//   s = V L (tau - tau_pred) / dx,   P = -sum tau . s dx dy.
#include <benchmark/benchmark.h>

#include "tests/bench/bench_common.h"

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>

#include "lib/io/case.h"
#include "lib/elastic.h"
#include "lib/normal/hertz.h"
#include "lib/patch.h"
#include "lib/tangential/steady.h"
#include "lib/tangential/tangential.h"

namespace {

using namespace contact;

using bench::keep;
using bench::paper;
using bench::PaperCase;

Creepages creepages_named(const std::string& name) {
  if (name == "xi") return {1e-3, 0, 0};
  return {1e-3, 5e-4, 0.5};  // "all"
}

// the normal problem on an n x n grid and the tangential problem for the named creepages
struct Inputs {
  ContactPatch patch;
  TangentialProblem problem;
};

Inputs inputs(int n, const std::string& creep) {
  const PaperCase& c = paper();
  Inputs in;
  in.patch = solve_normal_hertz(c.bodies, c.pair, c.normal_load_N, GridSpec{n, n});
  in.problem = make_tangential_problem(in.patch, c.pair, creepages_named(creep), c.mu, c.speed_m_per_s);
  return in;
}

struct BaselineTotals {
  double Fx_N = 0, Fy_N = 0, power_W = 0;
};

// classic FASTSIM, cell by cell, on the cell centres
BaselineTotals classic_fastsim_loop(const ContactPatch& patch, const TangentialProblem& problem,
                                    Eigen::ArrayXXd& tau_x_Pa, Eigen::ArrayXXd& tau_y_Pa) {
  const Grid& g = patch.grid;
  const double xi = problem.creepages.xi, eta = problem.creepages.eta;
  const double phi = problem.creepages.phi_per_m;
  const double L1 = problem.flex.L1_m_per_Pa, L2 = problem.flex.L2_m_per_Pa;
  const double L3 = problem.flex.L3_m_per_Pa, L = problem.L_m_per_Pa;
  const double V = problem.speed_m_per_s, mu = problem.mu;
  const double dx = g.dx_m, dy = g.dy_m;

  BaselineTotals t;
  tau_x_Pa.setZero(g.nx, g.ny);
  tau_y_Pa.setZero(g.nx, g.ny);
  for (int j = 0; j < g.ny; ++j) {
    const double a = patch.half_length_m(j), p = patch.strip_peak_Pa(j), y = g.y_m(j);
    if (!(a > 0)) continue;
    double tx = 0, ty = 0;  // traction at the previous cell; 0 at the leading edge
    for (int i = g.nx - 1; i >= 0; --i) {
      const double x = g.x_m(i);
      if (!(std::abs(x) < a)) continue;
      // stick: the traction grows along the march
      const double px = tx - (xi / L1 - phi * y / L3) * dx;
      const double py = ty - (eta / L2 + phi * x / L3) * dx;
      // slip: clip to the traction bound, keeping the direction
      const double u = x / a;
      const double bound = mu * p * std::sqrt(1 - u * u);
      const double norm = std::hypot(px, py);
      const double scale = norm > bound ? bound / norm : 1.0;
      tx = px * scale;
      ty = py * scale;
      // slip velocity and dissipated power
      const double sx = V * L * (tx - px) / dx, sy = V * L * (ty - py) / dx;
      t.Fx_N += tx * dx * dy;
      t.Fy_N += ty * dx * dy;
      t.power_W -= (tx * sx + ty * sy) * dx * dy;
      tau_x_Pa(i, j) = tx;
      tau_y_Pa(i, j) = ty;
    }
  }
  return t;
}

void BM_Hertz(benchmark::State& state) {
  const PaperCase& c = paper();
  for (auto _ : state) keep(solve_hertz(c.bodies, c.pair, c.normal_load_N));
}
BENCHMARK(BM_Hertz);

void BM_HertzPatch(benchmark::State& state) {
  const PaperCase& c = paper();
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const ContactPatch patch = solve_normal_hertz(c.bodies, c.pair, c.normal_load_N, GridSpec{n, n});
    keep(patch.pressure_Pa.data());
  }
  state.counters["cells/s"] = benchmark::Counter(n * n, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_HertzPatch)->ArgName("nx")->Arg(20)->Arg(80);

void steady(benchmark::State& state, TangentialScheme scheme, int n, const std::string& creep) {
  const Inputs in = inputs(n, creep);
  TangentialSolution s;
  for (auto _ : state) {
    s = solve_steady(in.patch, in.problem, scheme);
    keep(s.Fx_N);
    keep(s.power_W);
  }
  state.counters["cells/s"] = benchmark::Counter(n * n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["Fx_N"] = s.Fx_N;
  state.counters["P_W"] = s.power_W;
}

void baseline(benchmark::State& state, int n, const std::string& creep) {
  const Inputs in = inputs(n, creep);
  BaselineTotals t;
  for (auto _ : state) {
    Eigen::ArrayXXd tau_x_Pa, tau_y_Pa;
    t = classic_fastsim_loop(in.patch, in.problem, tau_x_Pa, tau_y_Pa);
    keep(t);
    keep(tau_x_Pa.data());
    keep(tau_y_Pa.data());
    benchmark::ClobberMemory();
  }
  state.counters["cells/s"] = benchmark::Counter(n * n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["Fx_N"] = t.Fx_N;
  state.counters["P_W"] = t.power_W;
}

// BM_Steady/<scheme>/<n>/<creep> and BM_BaselineClassicLoop/<n>/<creep>
[[maybe_unused]] const bool kRegistered = [] {
  for (const int n : {20, 80}) {
    for (const char* creep : {"xi", "all"}) {
      const std::string tail = "/" + std::to_string(n) + "/" + creep;
      for (const auto& [scheme, label] : {std::pair{TangentialScheme::Consistent, "consistent"},
                                          std::pair{TangentialScheme::Classic, "classic"}}) {
        const std::string name = "BM_Steady/" + std::string(label) + tail;
        benchmark::RegisterBenchmark(name.c_str(), steady, scheme, n, std::string(creep));
      }
      const std::string name = "BM_BaselineClassicLoop" + tail;
      benchmark::RegisterBenchmark(name.c_str(), baseline, n, std::string(creep));
    }
  }
  return true;
}();

}  // namespace
