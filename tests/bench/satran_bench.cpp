// Satran on the paper's start-up run: 80 x 80 grid, 200 steps (docs/physics.md §3; the paper reports
// 42 s for it), beside a plain loop of the classic upwind update at CFL = 1 kept here as the
// baseline the product is compared against (docs/benchmarks.md):
//   tau*_i = tau_{i+1} - (xi/L1 - phi y/L3, eta/L2 + phi x_i/L3) dx,  clipped to mu p(x_i),
//   s_i = V L (tau_i - tau*_i) / dx,  P = -sum tau . s dx dy,  F = sum tau dx dy,
// on the cell edges of each strip, from rest, with the forces and the power summed every step.
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "lib/normal/hertz.h"
#include "lib/tangential/satran.h"

namespace {

using namespace contact;

constexpr int kSteps = 200;
constexpr double kSpeed = 1.8;  // m/s: cases/paper-startup.yaml's final speed

TransientCase paper_startup(int n, bool all_creepages) {
  TransientCase c;
  c.bodies = {{0.020, 0.500}, {0.025, kFlat}};
  c.materials = {{210e9, 0.28}, {210e9, 0.28}};
  c.mu = 0.3;
  c.inputs.speed_m_per_s = constant_history(kSpeed);
  c.inputs.xi = constant_history(1e-3);
  c.inputs.eta = constant_history(all_creepages ? 5e-4 : 0.0);
  c.inputs.phi_per_m = constant_history(all_creepages ? 0.5 : 0.0);
  c.inputs.normal_load_N = constant_history(1500);
  c.settings.grid = {n, n};
  const ContactPatch p = solve_normal_hertz(c.bodies, c.materials, 1500, c.settings.grid);
  c.settings.t_end_s = kSteps * p.grid.dx_m / kSpeed;  // 200 shift steps of one dx each
  return c;
}

// args: n, all creepages, the skips as bits (TransientSkips): 1 the mirror images (pure xi on the paper's
// symmetric patch steps half the strips), 2 the lateral work (pure xi: no tau_y in the stick pass)
void BM_SatranShift(benchmark::State& st) {
  TransientCase c = paper_startup(static_cast<int>(st.range(0)), st.range(1) != 0);
  c.settings.skips.mirrored = (st.range(2) & 1) != 0;
  c.settings.skips.lateral = (st.range(2) & 2) != 0;
  double sink = 0;
  int steps = 0;
  for (auto _ : st) {
    const TransientResult r = run_transient(c);
    sink += r.dissipated_J;
    steps = r.steps;
  }
  benchmark::DoNotOptimize(sink);
  st.counters["steps"] = steps;
}
BENCHMARK(BM_SatranShift)
    ->Args({80, 0, 3})
    ->Args({80, 0, 1})
    ->Args({80, 0, 2})
    ->Args({80, 0, 0})
    ->Args({80, 1, 3})
    ->Args({20, 1, 3})
    ->Unit(benchmark::kMillisecond);

// the baseline: plain classic upwind at CFL 1, node by node
void BM_BaselineClassicUpwindLoop(benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  const bool all = st.range(1) != 0;
  const TransientCase c = paper_startup(n, all);
  const ContactPatch p = solve_normal_hertz(c.bodies, c.materials, 1500, c.settings.grid);
  const Creepages cr{1e-3, all ? 5e-4 : 0.0, all ? 0.5 : 0.0};
  const TangentialProblem pb = make_tangential_problem(p, c.materials, cr, c.mu, kSpeed);
  const Grid& g = p.grid;
  const double dx = g.dx_m, VL = kSpeed * pb.L_m_per_Pa;
  Eigen::ArrayXXd tx = Eigen::ArrayXXd::Zero(g.nx + 1, g.ny), ty = tx;
  double sink = 0;
  for (auto _ : st) {
    tx.setZero();
    ty.setZero();
    for (int step = 0; step < kSteps; ++step) {
      double Fx = 0, Fy = 0, P = 0;
      for (int j = 0; j < g.ny; ++j) {
        const double a = p.half_length_m(j), y = g.y_m(j);
        const double ax = cr.xi / pb.flex.L1_m_per_Pa - cr.phi_per_m * y / pb.flex.L3_m_per_Pa;
        const double by = cr.eta / pb.flex.L2_m_per_Pa, cy = cr.phi_per_m / pb.flex.L3_m_per_Pa;
        // from the trailing side, so that node i+1 still holds the previous step's value
        for (int i = 0; i < g.nx; ++i) {
          const double x = g.x_edge(i);
          if (!(x > -a && x < a)) continue;
          const double px = tx(i + 1, j) - ax * dx, py = ty(i + 1, j) - (by + cy * x) * dx;
          const double bound = c.mu * p.edge_pressure_Pa(i, j);
          const double nrm = std::sqrt(px * px + py * py);
          const double scale = nrm > bound ? bound / nrm : 1.0;
          tx(i, j) = px * scale;
          ty(i, j) = py * scale;
          const double sx = VL * (tx(i, j) - px) / dx, sy = VL * (ty(i, j) - py) / dx;
          Fx += tx(i, j) * dx;
          Fy += ty(i, j) * dx;
          P -= (tx(i, j) * sx + ty(i, j) * sy) * dx;
        }
      }
      sink += (Fx + Fy + P) * g.dy_m;
    }
  }
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(BM_BaselineClassicUpwindLoop)->Args({80, 0})->Args({80, 1})->Args({20, 1})->Unit(benchmark::kMillisecond);

}  // namespace
