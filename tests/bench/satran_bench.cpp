// Satran on the paper's start-up run: 80 x 80 grid, 200 steps (docs/physics.md §3; the paper reports
// 42 s for it), beside three loops of the classic upwind update at CFL = 1 as baselines
// (docs/benchmarks.md):
//   tau*_i = tau_{i+1} - (xi/L1 - phi y/L3, eta/L2 + phi x_i/L3) dx,  clipped to mu p(x_i),
//   s_i = V L (tau_i - tau*_i) / dx,  P = -sum tau . s dx dy,  F = sum tau dx dy,
// on the cell edges of each strip, from rest, with the forces and the power summed every step.
//   BM_BareXiLoop: the practical limit for the pure-xi run: contiguous strips, the bound g = mu p
//     precomputed, every node of every strip updated and clamped (no test for the contact), then the
//     arrays swapped;
//   BM_BareXiEtaPhiLoop: the same with two traction components, the spin term and the two-component clamp;
//   BM_BaselineClassicUpwindLoop: the older baseline (Eigen arrays, per-node pressure lookups, a test
//     for the contact at every node), about 5x the bare loop: not a limit anyone would aim at.
// Ratios are reported against the bare loops (docs/benchmarks.md).
#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <algorithm>
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
// symmetric patch steps half the strips), 2 the lateral work (pure xi: no tau_y in the stick pass), 4 the
// steady strips (a strip the last step left as it was is not stepped again on the same inputs); the
// threads (TransientSettings::threads, 1 unless given). ns_per_cell_step: the time over steps x nx x ny;
// stick: the mean stick fraction over the steps (a run untimed before the timed ones), which says how much of
// the work is the stick pass. rolled80: the rolled distance in dx of the 80 x 80 grid (0: kSteps of the run's
// own dx, so that the same 200 steps roll 5 contact lengths at 40 x 40 and 0.6 at 320 x 320).
void satran_shift(benchmark::State& st, int rolled80) {
  const int n = static_cast<int>(st.range(0));
  TransientCase c = paper_startup(n, st.range(1) != 0);
  if (rolled80 > 0) c.settings.t_end_s *= static_cast<double>(rolled80) * n / (80.0 * kSteps);
  c.settings.skips.mirrored = (st.range(2) & 1) != 0;
  c.settings.skips.lateral = (st.range(2) & 2) != 0;
  c.settings.skips.steady_strips = (st.range(2) & 4) != 0;
  c.settings.threads = st.range(3) > 0 ? static_cast<int>(st.range(3)) : 1;
  double stick = 0;
  int records = 0;
  run_transient(c, [&](const TransientRecord& rec, const Eigen::ArrayXd&) {
    stick += rec.stick_fraction;
    ++records;
  });
  double sink = 0;
  int steps = 0;
  for (auto _ : st) {
    const TransientResult r = run_transient(c);
    sink += r.dissipated_J;
    steps = r.steps;
  }
  benchmark::DoNotOptimize(sink);
  st.counters["steps"] = steps;
  st.counters["stick"] = records > 0 ? stick / records : 0;
  st.counters["ns_per_cell_step"] =
      benchmark::Counter(1e-9 * steps * n * n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
void BM_SatranShift(benchmark::State& st) { satran_shift(st, 0); }
// the same rolled distance at every grid: the paper run's 200 dx of the 80 x 80 grid (2.5 contact lengths)
void BM_SatranShiftSameRolling(benchmark::State& st) { satran_shift(st, kSteps); }
BENCHMARK(BM_SatranShift)
    ->Args({80, 0, 7, 1})
    ->Args({80, 0, 3, 1})
    ->Args({80, 0, 1, 1})
    ->Args({80, 0, 2, 1})
    ->Args({80, 0, 4, 1})
    ->Args({80, 0, 0, 1})
    ->Args({80, 1, 7, 1})
    ->Args({80, 1, 3, 1})
    ->Args({80, 1, 0, 1})
    ->Args({20, 1, 7, 1})
    ->Unit(benchmark::kMillisecond);
// the cost per cell-step from start-stop-wear's grid (40 x 40) to 320 x 320, pure xi with the mirror and
// lateral skips (the steady strips' skip off: every step computed) and with every skip off, on one thread
BENCHMARK(BM_SatranShift)
    ->Args({40, 0, 3, 1})
    ->Args({320, 0, 3, 1})
    ->Args({40, 0, 0, 1})
    ->Args({320, 0, 0, 1})
    ->Name("BM_SatranShiftPerCell")
    ->Unit(benchmark::kMillisecond);
// the cost per cell-step over the same rolled distance (the same share of stick and slip at both grids)
BENCHMARK(BM_SatranShiftSameRolling)
    ->Args({40, 0, 3, 1})
    ->Args({320, 0, 3, 1})
    ->Args({40, 0, 0, 1})
    ->Args({320, 0, 0, 1})
    ->Unit(benchmark::kMillisecond);
// the strips of a large grid on one and two threads: wall time (UseRealTime), the steady strips' skip off
BENCHMARK(BM_SatranShift)
    ->Args({320, 1, 3, 1})
    ->Args({320, 1, 3, 2})
    ->Args({320, 0, 3, 1})
    ->Args({320, 0, 3, 2})
    ->Args({160, 1, 3, 1})
    ->Args({160, 1, 3, 2})
    ->Name("BM_SatranShiftThreads")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// xi, eta, phi with the speed varying: a ramp from kSpeed/2 to kSpeed over the run, which rolls the
// same 200 dx (docs/physics.md §3), every skip as shipped, and without the steady strips' skip (every
// strip stepped at every step)
void BM_SatranShiftVaryingSpeed(benchmark::State& st) {
  TransientCase c = paper_startup(80, true);
  const double T = c.settings.t_end_s * kSpeed / (0.75 * kSpeed);  // mean speed 0.75 kSpeed
  c.inputs.speed_m_per_s = ramp_history(0.0, 0.5 * kSpeed, T, kSpeed);
  c.settings.t_end_s = T;
  c.settings.skips.steady_strips = st.range(0) != 0;
  c.settings.threads = 1;
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
BENCHMARK(BM_SatranShiftVaryingSpeed)->ArgName("steady_strips")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// the older baseline: plain classic upwind at CFL 1, node by node
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
// the bare loops: tau_new[i] = clamp(tau[i] + (tau[i-1] - tau[i]) - V dt xi/L1, -g[i], g[i]) at CFL 1
// (V dt = dx), node 0 of each strip the leading edge (tau = 0 entering); per strip the force sum tau dx
// and the dissipated power -sum tau V L (tau - tau*) are summed every step, then the arrays swapped
struct BareSetup {
  int nx = 0, ny = 0;
  double dx = 0, dy = 0, VL = 0;
  double ax0 = 0, by = 0, cy = 0, phi_L3 = 0;  // xi/L1, eta/L2, phi/L3 (per m of rolling)
  std::vector<double> g, x, y;                 // g: (nx+1) x ny bound mu p, node k of strip j at k + j (nx+1)
};

BareSetup bare_setup(bool all) {
  const TransientCase c = paper_startup(80, all);
  const ContactPatch p = solve_normal_hertz(c.bodies, c.materials, 1500, c.settings.grid);
  const Creepages cr{1e-3, all ? 5e-4 : 0.0, all ? 0.5 : 0.0};
  const TangentialProblem pb = make_tangential_problem(p, c.materials, cr, c.mu, kSpeed);
  const Grid& gr = p.grid;
  BareSetup b;
  b.nx = gr.nx;
  b.ny = gr.ny;
  b.dx = gr.dx_m;
  b.dy = gr.dy_m;
  b.VL = kSpeed * pb.L_m_per_Pa;
  b.ax0 = cr.xi / pb.flex.L1_m_per_Pa;
  b.by = cr.eta / pb.flex.L2_m_per_Pa;
  b.phi_L3 = cr.phi_per_m / pb.flex.L3_m_per_Pa;
  b.g.assign(static_cast<size_t>(b.nx + 1) * b.ny, 0.0);
  b.x.resize(b.nx + 1);
  b.y.resize(b.ny);
  for (int k = 0; k <= b.nx; ++k) b.x[k] = gr.x_edge(b.nx - k);  // node k = edge nx - k: leading first
  for (int j = 0; j < b.ny; ++j) {
    b.y[j] = gr.y_m(j);
    for (int k = 1; k <= b.nx; ++k) b.g[k + j * (b.nx + 1)] = c.mu * p.edge_pressure_Pa(b.nx - k, j);
  }
  return b;
}

void BM_BareXiLoop(benchmark::State& st) {
  const BareSetup b = bare_setup(false);
  const int n1 = b.nx + 1;
  std::vector<double> tau(b.g.size()), tau_new(b.g.size()), F(b.ny), P(b.ny);
  const double shift = b.dx * b.ax0;  // V dt xi/L1 with V dt = dx
  double sink = 0;
  for (auto _ : st) {
    std::fill(tau.begin(), tau.end(), 0.0);
    std::fill(tau_new.begin(), tau_new.end(), 0.0);
    for (int step = 0; step < kSteps; ++step) {
      for (int j = 0; j < b.ny; ++j) {
        const double* t = tau.data() + j * n1;
        const double* g = b.g.data() + j * n1;
        double* tn = tau_new.data() + j * n1;
        double f = 0, pw = 0;
        for (int i = 1; i < n1; ++i) {
          const double pred = t[i] + (t[i - 1] - t[i]) - shift;
          const double v = std::min(std::max(pred, -g[i]), g[i]);
          tn[i] = v;
          f += v;
          pw -= v * (v - pred);
        }
        F[j] = f * b.dx * b.dy;
        P[j] = pw * b.VL * b.dy;
      }
      std::swap(tau, tau_new);
      sink += F[b.ny / 2] + P[b.ny / 2];
    }
  }
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(BM_BareXiLoop)->Unit(benchmark::kMillisecond);

void BM_BareXiEtaPhiLoop(benchmark::State& st) {
  const BareSetup b = bare_setup(true);
  const int n1 = b.nx + 1;
  std::vector<double> tx(b.g.size()), ty(b.g.size()), txn(b.g.size()), tyn(b.g.size()), Fx(b.ny), Fy(b.ny),
      P(b.ny);
  double sink = 0;
  for (auto _ : st) {
    for (auto* v : {&tx, &ty, &txn, &tyn}) std::fill(v->begin(), v->end(), 0.0);
    for (int step = 0; step < kSteps; ++step) {
      for (int j = 0; j < b.ny; ++j) {
        const double* ox = tx.data() + j * n1;
        const double* oy = ty.data() + j * n1;
        const double* g = b.g.data() + j * n1;
        double* nxp = txn.data() + j * n1;
        double* nyp = tyn.data() + j * n1;
        const double sx = b.dx * (b.ax0 - b.phi_L3 * b.y[j]);  // V dt (xi/L1 - phi y/L3)
        double fx = 0, fy = 0, pw = 0;
        for (int i = 1; i < n1; ++i) {
          const double px = ox[i] + (ox[i - 1] - ox[i]) - sx;
          const double py = oy[i] + (oy[i - 1] - oy[i]) - b.dx * (b.by + b.phi_L3 * b.x[i]);
          const double nrm = std::sqrt(px * px + py * py);
          const double scale = nrm > g[i] ? g[i] / nrm : 1.0;
          const double vx = px * scale, vy = py * scale;
          nxp[i] = vx;
          nyp[i] = vy;
          fx += vx;
          fy += vy;
          pw -= vx * (vx - px) + vy * (vy - py);
        }
        Fx[j] = fx * b.dx * b.dy;
        Fy[j] = fy * b.dx * b.dy;
        P[j] = pw * b.VL * b.dy;
      }
      std::swap(tx, txn);
      std::swap(ty, tyn);
      sink += Fx[b.ny / 2] + Fy[b.ny / 2] + P[b.ny / 2];
    }
  }
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(BM_BareXiEtaPhiLoop)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_BaselineClassicUpwindLoop)->Args({80, 0})->Args({80, 1})->Args({20, 1})->Unit(benchmark::kMillisecond);

}  // namespace
