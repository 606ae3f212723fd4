// The default tangential model (relaxed, lib/tangential/relaxed.h) against Kalker's exact theory in-house
// (lib/tangential/exact.h) at held-out points: drawn by a seeded generator over the creepage direction, the
// saturation level, a/b and Poisson's ratio, never near the nodes its tables were fitted on
// (lib/tangential/relaxed_table.h, relaxed_mix_table.h). The targets (issue 25, docs/accuracy-vs-exact.md,
// "Held-out points"; not loosened): steady Fx and Fy within 2 % of the exact |(Fx, Fy)|, Mz within 5 % of the
// exact |Mz|, the total power within 2 % of the exact creep work; transients within 3 % of the steady value at
// every rolled distance. Where the model misses a target the tests hold the measured distribution as a
// regression guard (each bound names the target and the miss); the doc's tables come from the lines these
// tests print (scripts/heldout-report).
// Contact: fast_model_report's (tests/bench/fast_model_report.cpp): a Hertz ellipse of a/b with b = 1 mm,
// p0 = 1 GPa, steel E = 210 GPa with the drawn nu on both bodies, mu = 0.3, V = 1 m/s.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "lib/elastic.h"
#include "lib/grid.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "lib/tangential/exact.h"
#include "lib/tangential/kalker.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/relaxed_mix_table.h"
#include "tests/ellipse_patch.h"

namespace contact {
namespace {

constexpr double kMu = 0.3, kV = 1.0;
constexpr std::uint64_t kSeed = 20261129;  // the generator's seed (docs/accuracy-vs-exact.md, "Held-out points")
// a point is rejected within this distance of a node of the mix table (node_distance)
constexpr double kMinNodeDistance = 0.2;

// the targets (issue 25), not loosened
constexpr double kForceTarget = 0.02;       // Fx, Fy: of the exact |(Fx, Fy)|
constexpr double kMomentTarget = 0.05;      // Mz: of the exact |Mz|
constexpr double kPowerTarget = 0.02;       // total power: of the exact creep work
constexpr double kTransientTarget = 0.03;  // of the steady value, at every rolled distance

ElasticPair steel(double nu) { return {{210e9, nu}, {210e9, nu}}; }

using rollwear_test::ellipse_patch;

// uniform in [0, 1) from the 53 high bits of mt19937_64, whose sequence the standard fixes (its distributions
// are the library's own: not portable)
struct Draw {
  std::mt19937_64 g;
  explicit Draw(std::uint64_t seed) : g(seed) {}
  double unit() { return static_cast<double>(g() >> 11) * 0x1.0p-53; }
  double in(double lo, double hi) { return lo + (hi - lo) * unit(); }
};

// A held-out point: the contact's a/b and nu, the share k of saturation (the simplified theory's closed form
// |F|/(mu N) = 1 - (1 - e)^3 for a Hertz contact: e = 1 - (1 - k)^(1/3), the level of docs/accuracy-vs-exact.md),
// and the direction of the creepage vector in levels u = G a b (C11 xi, C22 eta, C23 sqrt(ab) phi)/(3 mu N) (a
// unit vector; e = |u|)
struct HeldOut {
  double ab = 1, nu = 0.28, k = 0.5;
  std::array<double, 3> dir{1, 0, 0};
  double e() const { return 1 - std::cbrt(1 - k); }
};

// the table's angles of u (relaxed.cpp's): theta from the xi axis in [0, 90], psi of (eta, phi) in [0, 180)
// (the symmetries F(-xi, eta, phi) = (-Fx, Fy, Mz) and F(xi, -eta, -phi) = (Fx, -Fy, -Mz))
std::array<double, 2> table_angles_deg(const std::array<double, 3>& u) {
  const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  const double theta = std::acos(std::clamp(std::abs(u[0]) / n, 0.0, 1.0)) * 180 / kPi;
  double psi = std::atan2(u[2], u[1]) * 180 / kPi;
  if (psi < 0) psi += 180;
  if (psi >= 180) psi -= 180;
  return {theta, psi};
}

// the distance of v from the nearest of the ascending nodes xs, in units of the interval it lies in (0 on a node,
// 0.5 midway; beyond the ends in units of the end interval)
double interval_distance(const double* xs, int n, double v) {
  if (v <= xs[0]) return (xs[0] - v) / (xs[1] - xs[0]);
  if (v >= xs[n - 1]) return (v - xs[n - 1]) / (xs[n - 1] - xs[n - 2]);
  int i = 0;
  while (v > xs[i + 1]) ++i;
  return std::min(v - xs[i], xs[i + 1] - v) / (xs[i + 1] - xs[i]);
}

// the distance of a point from the mix table's nodes (relaxed_mix_table.h: a/b in log, theta, psi with 180 deg
// the node 0 mirrored, e), the Euclidean norm of the four interval distances: a point is on a node only when it
// is near one in every coordinate at once (a circle, a/b = 1, is a node's a/b; its direction and level need
// not be). nu is not a table coordinate (the tables are fitted at 0.28).
double node_distance(const HeldOut& h) {
  namespace M = relaxed_mix_table;
  double lab[M::kNab];
  for (int i = 0; i < M::kNab; ++i) lab[i] = std::log(M::kAb[i]);
  double psi_nodes[M::kNpsi + 1];
  for (int i = 0; i < M::kNpsi; ++i) psi_nodes[i] = M::kPsiDeg[i];
  psi_nodes[M::kNpsi] = 180;
  const auto [theta, psi] = table_angles_deg(h.dir);
  const double d[4] = {interval_distance(lab, M::kNab, std::log(h.ab)),
                       interval_distance(M::kThetaDeg, M::kNtheta, theta),
                       interval_distance(psi_nodes, M::kNpsi + 1, psi), interval_distance(M::kE, M::kNe, h.e())};
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + d[3] * d[3]);
}

// a unit vector uniform on the sphere
std::array<double, 3> draw_direction(Draw& r) {
  const double z = r.in(-1, 1), t = r.in(0, 2 * kPi), s = std::sqrt(1 - z * z);
  return {z, s * std::cos(t), s * std::sin(t)};
}

// n points: a/b log-uniform in [0.05, 5] (every sixth a circle, a/b = 1), nu uniform in [0.25, 0.35], k uniform in
// [0.10, 0.95], the direction uniform on the sphere of u; a draw within kMinNodeDistance of a node is rejected
// and drawn again. `axis` >= 0: the direction's component on that axis (0 xi, 1 eta, 2 phi) at least 0.5 in
// magnitude (the steps of one creepage below).
std::vector<HeldOut> draw_held_out(std::uint64_t seed, int n, int axis = -1, int* rejected = nullptr) {
  Draw r(seed);
  std::vector<HeldOut> v;
  while (static_cast<int>(v.size()) < n) {
    HeldOut h;
    h.ab = v.size() % 6 == 5 ? 1.0 : std::exp(r.in(std::log(0.05), std::log(5.0)));
    h.nu = r.in(0.25, 0.35);
    h.k = r.in(0.10, 0.95);
    do h.dir = draw_direction(r);
    while (axis >= 0 && std::abs(h.dir[axis]) < 0.5);
    if (node_distance(h) < kMinNodeDistance) {
      if (rejected) ++*rejected;
      continue;
    }
    v.push_back(h);
  }
  return v;
}

// the creepages of the point's level e in its direction on the patch
Creepages creepages_of(const HeldOut& h, const ContactPatch& p, double e) {
  const ElasticPair pair = steel(h.nu);
  const KalkerCoefficients C = kalker_coefficients(p.a_m, p.b_m, combined_poisson(pair));
  const double unit = 3 * kMu * p.normal_load_N / (combined_shear_modulus_Pa(pair) * p.a_m * p.b_m);
  return {e * h.dir[0] * unit / C.C11, e * h.dir[1] * unit / C.C22,
          e * h.dir[2] * unit / (std::sqrt(p.a_m * p.b_m) * C.C23)};
}

// the exact |Mz| as the scale of Mz's error, floored where Mz vanishes (fast_model_report's in_targets):
// 1e-3 |(Fx, Fy)| sqrt(ab)
double moment_scale(double Mz, double F, const ContactPatch& p) {
  return std::max(std::abs(Mz), 1e-3 * F * std::sqrt(p.a_m * p.b_m));
}

// the model's steady errors at one point, as fractions: Fx, Fy of the exact |(Fx, Fy)|, Mz of the exact |Mz|,
// the total power of the exact creep work
struct SteadyErrors {
  double Fx = 0, Fy = 0, Mz = 0, P = 0;
  double Mz_of_force = 0;  // Mz's error over |(Fx, Fy)| sqrt(ab) (a scale that does not vanish with Mz)
  bool converged = true;
};

// exact_out (optional): the exact Fx, Fy, Mz
SteadyErrors steady_errors(const HeldOut& h, int n, double* exact_out = nullptr) {
  const ContactPatch p = ellipse_patch(h.ab, n);
  const ElasticPair pair = steel(h.nu);
  const Creepages c = creepages_of(h, p, h.e());
  const ExactSolution ex = solve_exact_steady(p, combined_shear_modulus_Pa(pair), combined_poisson(pair), c, kMu, kV);
  const TangentialSolution m = solve_relaxed_steady(p, pair, c, kMu, kV, false);
  const double F = std::hypot(ex.fields.Fx_N, ex.fields.Fy_N);
  const double W = -ex.fields.creep_work_W;  // the exact creep work, positive (its power, docs/exact-theory.md §4)
  if (exact_out) exact_out[0] = ex.fields.Fx_N, exact_out[1] = ex.fields.Fy_N, exact_out[2] = ex.fields.Mz_N_m;
  return {(m.Fx_N - ex.fields.Fx_N) / F, (m.Fy_N - ex.fields.Fy_N) / F,
          (m.Mz_N_m - ex.fields.Mz_N_m) / moment_scale(ex.fields.Mz_N_m, F, p), (m.power_W - W) / W,
          (m.Mz_N_m - ex.fields.Mz_N_m) / (F * std::sqrt(p.a_m * p.b_m)), ex.status.converged()};
}

// the q-quantile of v (nearest rank)
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(std::ceil(q * v.size())) - (q > 0 ? 1 : 0));
  return v[i];
}

struct Distribution {
  double median = 0, p90 = 0, max = 0;
  int within = 0;  // points within the target
};

Distribution distribution(const std::vector<double>& abs_errors, double target) {
  Distribution d{quantile(abs_errors, 0.5), quantile(abs_errors, 0.9),
                 *std::max_element(abs_errors.begin(), abs_errors.end()), 0};
  for (double x : abs_errors) d.within += x <= target;
  return d;
}

void print_distribution(const char* what, const std::vector<double>& errors, double target) {
  const Distribution d = distribution(errors, target);
  std::printf("HD %s median %.2f p90 %.2f max %.2f within %d of %zu (target %.0f %%)\n", what, 100 * d.median,
              100 * d.p90, 100 * d.max, d.within, errors.size(), 100 * target);
}

// the steady check's size and grid
constexpr int kSteadyPoints = 60;
constexpr int kSteadyCells = 80;  // the grid the tables were fitted on; its own error: StressHeldout.ExactGrid...

// --- the generator (quick) ---

// The generator is seeded, covers the ranges (circles, both ends of a/b and of the level, all three creepages
// mixed) and keeps off the table's nodes.
TEST(Heldout, GeneratorIsSeededCoversTheRangesAndKeepsOffTheNodes) {
  int rejected = 0;
  const std::vector<HeldOut> v = draw_held_out(kSeed, kSteadyPoints, -1, &rejected);
  const std::vector<HeldOut> again = draw_held_out(kSeed, kSteadyPoints);
  ASSERT_EQ(v.size(), again.size());
  int circles = 0, narrow = 0, long_ = 0, low = 0, high = 0, mixed = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const HeldOut& h = v[i];
    EXPECT_EQ(h.ab, again[i].ab);
    EXPECT_EQ(h.dir, again[i].dir);
    EXPECT_GE(node_distance(h), kMinNodeDistance);
    EXPECT_TRUE(h.ab >= 0.05 && h.ab <= 5 && h.nu >= 0.25 && h.nu <= 0.35 && h.k >= 0.1 && h.k <= 0.95);
    circles += h.ab == 1;
    narrow += h.ab < 0.1;
    long_ += h.ab > 3;
    low += h.k < 0.3;
    high += h.k > 0.8;
    mixed += std::min({std::abs(h.dir[0]), std::abs(h.dir[1]), std::abs(h.dir[2])}) > 0.2;
  }
  EXPECT_EQ(circles, kSteadyPoints / 6);
  EXPECT_GT(narrow, 0);
  EXPECT_GT(long_, 0);
  EXPECT_GT(low, 0);
  EXPECT_GT(high, 0);
  EXPECT_GT(mixed, kSteadyPoints / 4);
  // the rejection is live: a node itself is rejected (a/b 1, theta 45, psi 45, e 0.3)
  HeldOut on;
  on.ab = 1;
  on.k = 1 - std::pow(1 - 0.3, 3);
  on.dir = {std::cos(kPi / 4), std::sin(kPi / 4) * std::cos(kPi / 4), std::sin(kPi / 4) * std::sin(kPi / 4)};
  EXPECT_LT(node_distance(on), 1e-9);
  std::printf("HG seed %llu points %d rejected %d\n", static_cast<unsigned long long>(kSeed), kSteadyPoints, rejected);
}


// --- steady, held out (stress: about a minute) ---

// kSteadyPoints held-out points, the model against the exact solver on kSteadyCells^2 cells. Printed per point
// ("HS"), and the distributions ("HD"), for scripts/heldout-report.
TEST(StressHeldout, SteadyForcesMomentAndPowerAtHeldOutPoints) {
  const std::vector<HeldOut> v = draw_held_out(kSeed, kSteadyPoints);
  std::vector<double> fx, fy, mz, pw, mzf;
  int unconverged = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const HeldOut& h = v[i];
    double ex[3];
    const SteadyErrors s = steady_errors(h, kSteadyCells, ex);
    unconverged += !s.converged;
    const auto [theta, psi] = table_angles_deg(h.dir);
    std::printf("HS %zu ab %.4f nu %.4f k %.3f e %.4f u %+.3f %+.3f %+.3f theta %.1f psi %.1f dist %.2f "
                "Fx %+.2f Fy %+.2f Mz %+.2f P %+.2f MzF %+.2f exact %.5e %.5e %.5e%s\n",
                i, h.ab, h.nu, h.k, h.e(), h.dir[0], h.dir[1], h.dir[2], theta, psi, node_distance(h), 100 * s.Fx,
                100 * s.Fy, 100 * s.Mz, 100 * s.P, 100 * s.Mz_of_force, ex[0], ex[1], ex[2],
                s.converged ? "" : " unconverged");
    std::fflush(stdout);
    fx.push_back(std::abs(s.Fx));
    fy.push_back(std::abs(s.Fy));
    mz.push_back(std::abs(s.Mz));
    pw.push_back(std::abs(s.P));
    mzf.push_back(std::abs(s.Mz_of_force));
  }
  print_distribution("Fx", fx, kForceTarget);
  print_distribution("Fy", fy, kForceTarget);
  print_distribution("Mz", mz, kMomentTarget);
  print_distribution("P", pw, kPowerTarget);
  EXPECT_EQ(unconverged, 0);
  // The targets in the median: met.
  const Distribution dfx = distribution(fx, kForceTarget), dfy = distribution(fy, kForceTarget),
                     dmz = distribution(mz, kMomentTarget), dp = distribution(pw, kPowerTarget);
  EXPECT_LE(dfx.median, kForceTarget);
  EXPECT_LE(dfy.median, kForceTarget);
  EXPECT_LE(dmz.median, kMomentTarget);
  EXPECT_LE(dp.median, kPowerTarget);
  // Where it misses, the measured distribution (seed kSeed, 80^2, docs/accuracy-vs-exact.md "Held-out points")
  // as a regression guard, one point of slack in the counts:
  // Fx: target 2 %, 57 of 60 within, the worst 2.79 % (a/b 4.1, beyond the table; 2.31 % a/b 0.70 e 0.46).
  EXPECT_GE(dfx.within, 56);
  EXPECT_LE(dfx.max, 0.030);
  // Fy: target 2 %, 49 of 60 within, 90th percentile 3.26 %, the worst 23.6 % (a/b 4.1 under spin; 7.0 % a/b 0.06
  // at 82 % of saturation).
  EXPECT_GE(dfy.within, 48);
  EXPECT_LE(dfy.p90, 0.035);
  EXPECT_LE(dfy.max, 0.25);
  // Mz: target 5 % of |Mz|, 45 of 60 within, 90th percentile 15.0 %; where the exact Mz nearly cancels (a/b 1.56,
  // |Mz| 9e-4 N m against |(Fx, Fy)| sqrt(ab) 1.1 N m) 2807 % of it: bounded in units of |(Fx, Fy)| sqrt(ab)
  // instead, the worst 13.9 % (a/b 0.052).
  EXPECT_GE(dmz.within, 44);
  EXPECT_LE(dmz.p90, 0.16);
  EXPECT_LE(*std::max_element(mzf.begin(), mzf.end()), 0.15);
  // P: target 2 % of the exact creep work, 48 of 60 within, the worst 23.6 % (a/b 3.9 under spin: its Mz).
  EXPECT_GE(dp.within, 47);
  EXPECT_LE(dp.max, 0.25);
}

// The quick suite's instance: the first kQuickPoints points of the same draw, where the model meets the force
// targets (Fx, Fy within 2 %) and misses Mz and P at three of them (Mz 15.6 %, 15.0 %, 5.8 %; P 2.2 %, 5.7 %, the
// spin-dominated points of a/b 0.75-1.33): those at their measured bounds.
TEST(Heldout, FirstPointsMeetTheForceTargets) {
  constexpr int kQuickPoints = 10;
  const std::vector<HeldOut> v = draw_held_out(kSeed, kQuickPoints);
  double worst_mz = 0, worst_p = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const SteadyErrors s = steady_errors(v[i], kSteadyCells);
    ASSERT_TRUE(s.converged) << "point " << i;
    EXPECT_LE(std::abs(s.Fx), kForceTarget) << "point " << i;
    EXPECT_LE(std::abs(s.Fy), kForceTarget) << "point " << i;
    worst_mz = std::max(worst_mz, std::abs(s.Mz));
    worst_p = std::max(worst_p, std::abs(s.P));
  }
  EXPECT_LE(worst_mz, 0.17);  // target 5 %: missed by 10.6 points (15.6 %)
  EXPECT_LE(worst_p, 0.062);  // target 2 %: missed by 3.7 points (5.7 %)
}

// The exact solver's own grid error at the held-out points, and the model against the finer exact solutions: every
// point on 40^2, 80^2 and 160^2 cells ("HE": Fx, Fy, Mz per grid; the model's errors against 160^2 and against the
// first-order extrapolation 2 F(160) - F(80)). The exact solution converges at first order in the cell size
// (docs/exact-theory.md §4), so the 80^2 solution's error is about its difference from 160^2, and the ratio of the
// successive differences about 2.
TEST(StressHeldout, ExactGridErrorAndTheModelAgainstTheFinerGrids) {
  const std::vector<HeldOut> v = draw_held_out(kSeed, kSteadyPoints);
  std::vector<double> grid_force, grid_moment, model_force, model_moment, model_power;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const HeldOut& h = v[i];
    const ElasticPair pair = steel(h.nu);
    double F[3][4];  // grid (40, 80, 160) x (Fx, Fy, Mz, creep work)
    for (int g = 0; g < 3; ++g) {
      const ContactPatch p = ellipse_patch(h.ab, 40 << g);
      const ExactSolution ex = solve_exact_steady(p, combined_shear_modulus_Pa(pair), combined_poisson(pair),
                                                  creepages_of(h, p, h.e()), kMu, kV);
      ASSERT_TRUE(ex.status.converged()) << "point " << i << " on " << (40 << g) << "^2";
      F[g][0] = ex.fields.Fx_N, F[g][1] = ex.fields.Fy_N, F[g][2] = ex.fields.Mz_N_m, F[g][3] = -ex.fields.creep_work_W;
    }
    const ContactPatch p = ellipse_patch(h.ab, kSteadyCells);
    const TangentialSolution m =
        solve_relaxed_steady(p, pair, creepages_of(h, p, h.e()), kMu, kV, false);
    const double R = std::hypot(F[2][0], F[2][1]);
    const double Ms = moment_scale(F[2][2], R, p);
    double X[4];  // extrapolated
    for (int k = 0; k < 4; ++k) X[k] = 2 * F[2][k] - F[1][k];
    const double dF80 = std::max(std::abs(F[1][0] - F[2][0]), std::abs(F[1][1] - F[2][1])) / R;
    const double dM80 = std::abs(F[1][2] - F[2][2]) / Ms;
    const double eF = std::max(std::abs(m.Fx_N - X[0]), std::abs(m.Fy_N - X[1])) / R;
    const double eM = std::abs(m.Mz_N_m - X[2]) / Ms, eP = std::abs(m.power_W - X[3]) / X[3];
    std::printf("HE %zu ab %.4f k %.3f grid80 F %.2f Mz %.2f W %+.2f ratio Fx %.2f Fy %.2f | model vs 160: Fx %+.2f "
                "Fy %+.2f Mz %+.2f P %+.2f | vs extrapolated: F %.2f Mz %.2f P %.2f\n",
                i, h.ab, h.k, 100 * dF80, 100 * dM80, 100 * (F[1][3] - F[2][3]) / F[2][3],
                (F[0][0] - F[1][0]) / (F[1][0] - F[2][0]), (F[0][1] - F[1][1]) / (F[1][1] - F[2][1]),
                100 * (m.Fx_N - F[2][0]) / R, 100 * (m.Fy_N - F[2][1]) / R, 100 * (m.Mz_N_m - F[2][2]) / Ms,
                100 * (m.power_W - F[2][3]) / F[2][3], 100 * eF, 100 * eM, 100 * eP);
    std::fflush(stdout);
    grid_force.push_back(dF80);
    grid_moment.push_back(dM80);
    model_force.push_back(eF);
    model_moment.push_back(eM);
    model_power.push_back(eP);
  }
  print_distribution("grid80-F", grid_force, kForceTarget);
  print_distribution("grid80-Mz", grid_moment, kMomentTarget);
  print_distribution("X-F", model_force, kForceTarget);
  print_distribution("X-Mz", model_moment, kMomentTarget);
  print_distribution("X-P", model_power, kPowerTarget);
  // The exact 80^2 solution's own error (its difference from 160^2, of |(Fx, Fy)|): median 0.25 %, 90th percentile
  // 0.49 %, the worst 2.5 % (a/b 4.1 at 90 % of saturation); the model's tables are fitted to 80^2, so against the
  // extrapolated exact theory it misses more: Fx and Fy within 2 % at 45 of 60 (against 80^2: 57 and 49), the
  // power at 43. Guards (one point of slack in the counts):
  const Distribution g = distribution(grid_force, kForceTarget), xf = distribution(model_force, kForceTarget),
                     xp = distribution(model_power, kPowerTarget);
  EXPECT_LE(g.p90, 0.006);
  EXPECT_LE(g.max, 0.028);
  EXPECT_GE(xf.within, 44);
  EXPECT_GE(xp.within, 42);
}

// --- transients, held out (stress) ---

// A transient run: from rest (axis -1) or from the steady state at c0 to c1 (a step of one creepage, axis 0 xi,
// 1 eta, 2 phi), rolled by dq = dx over kRunLength a with the exact rolling step and the relaxed model's step.
// Errors as fractions of the exact steady value at c1 on the same grid: max over q of |F_model - F_exact| over the
// exact |(Fx, Fy)| (Fx, Fy), of |Mz| for Mz; "shape": the same with the model's run scaled by the ratio of the
// exact steady |(Fx, Fy)| to the model's (its transient alone, without its steady offset on this grid).
struct TransientErrors {
  double Fx = 0, Fy = 0, Mz = 0, shape = 0;
  double Mz_of_force = 0;  // Mz's over |(Fx, Fy)| sqrt(ab)
  bool converged = true;
};

constexpr int kTransientCells = 40;    // the relaxation lengths' grid (docs/accuracy-vs-exact.md)
constexpr double kRunLength = 12;      // rolled distance over a
constexpr int kTransientRuns = 32;     // 8 start-ups and 8 steps each of xi, eta, phi

TransientErrors transient_errors(const HeldOut& h, int axis, double step_factor, int n) {
  const ContactPatch p = ellipse_patch(h.ab, n);
  const ElasticPair pair = steel(h.nu);
  const double G = combined_shear_modulus_Pa(pair), nu = combined_poisson(pair), dx = p.grid.dx_m;
  const Creepages c1 = creepages_of(h, p, h.e());
  Creepages c0 = c1;
  if (axis == 0) c0.xi *= step_factor;
  if (axis == 1) c0.eta *= step_factor;
  if (axis == 2) c0.phi_per_m *= step_factor;
  TransientErrors r;
  const ExactSolution ss = solve_exact_steady(p, G, nu, c1, kMu, kV);
  const TangentialSolution ms = solve_relaxed_steady(p, pair, c1, kMu, kV, false);
  r.converged = ss.status.converged();
  const double F = std::hypot(ss.fields.Fx_N, ss.fields.Fy_N);
  const double Ms = moment_scale(ss.fields.Mz_N_m, F, p);
  const double scale = F / std::hypot(ms.Fx_N, ms.Fy_N);
  ExactSolution prev;
  bool have = false;
  RelaxedState st = relaxed_rest();
  if (axis >= 0) {
    prev = solve_exact_steady(p, G, nu, c0, kMu, kV);
    r.converged = r.converged && prev.status.converged();
    have = true;
    st = relaxed_steady_state(c0);
  }
  const ExactOptions o = exact_run_options();
  const int steps = static_cast<int>(std::lround(kRunLength * p.a_m / dx));
  for (int k = 1; k <= steps; ++k) {
    ExactSolution s = solve_exact_rolling_step(p, G, nu, c1, kMu, kV, have ? &prev : nullptr, o);
    r.converged = r.converged && s.status.converged();
    const TangentialSolution m = relaxed_step(p, pair, c1, kMu, kV, dx, st);
    r.Fx = std::max(r.Fx, std::abs(m.Fx_N - s.fields.Fx_N) / F);
    r.Fy = std::max(r.Fy, std::abs(m.Fy_N - s.fields.Fy_N) / F);
    r.Mz = std::max(r.Mz, std::abs(m.Mz_N_m - s.fields.Mz_N_m) / Ms);
    r.Mz_of_force = std::max(r.Mz_of_force, std::abs(m.Mz_N_m - s.fields.Mz_N_m) / (F * std::sqrt(p.a_m * p.b_m)));
    r.shape = std::max(r.shape, std::hypot(scale * m.Fx_N - s.fields.Fx_N, scale * m.Fy_N - s.fields.Fy_N) / F);
    prev = std::move(s);
    have = true;
  }
  return r;
}

// The runs: for each kind (start-up, step of xi, eta, phi) its own seeded draw (the step's creepage at least half
// of the direction), the step from that creepage times a factor uniform in [-1, 0.5] (a reversal to a halving).
struct TransientRun {
  HeldOut h;
  int axis = -1;
  double factor = 1;
};

std::vector<TransientRun> transient_runs() {
  std::vector<TransientRun> runs;
  const int per = kTransientRuns / 4;
  for (int axis = -1; axis < 3; ++axis) {
    const std::vector<HeldOut> v = draw_held_out(kSeed + 1 + static_cast<std::uint64_t>(axis + 1), per, axis);
    Draw f(kSeed + 11 + static_cast<std::uint64_t>(axis + 1));
    for (int i = 0; i < per; ++i) {
      TransientRun t{v[static_cast<std::size_t>(i)], axis, axis >= 0 ? f.in(-1, 0.5) : 1.0};
      if (i == per - 1) t.h.ab = 1;  // a circle in every kind
      runs.push_back(t);
    }
  }
  return runs;
}

TEST(StressHeldout, TransientsAtHeldOutPoints) {
  const char* kind[] = {"start", "step xi", "step eta", "step phi"};
  {  // the harness on a fitted node: the start-up of pure xi at 50 %, a/b 0.1, nu 0.28, whose error the
     // start-up table of docs/accuracy-vs-exact.md gives as 0.8 % (fast_model_report startup 0.1 40 0.5, to 20a)
    HeldOut node;
    node.ab = 0.1, node.k = 0.5, node.dir = {1, 0, 0};
    const TransientErrors e = transient_errors(node, -1, 1, kTransientCells);
    std::printf("HC start pure xi 50 %% a/b 0.1 Fx %.2f\n", 100 * e.Fx);
  }
  std::vector<double> fx, fy, mz, shape;
  double startup_fy = 0;  // the largest Fy error of the start-ups from rest
  int unconverged = 0;
  for (const TransientRun& t : transient_runs()) {
    const TransientErrors e = transient_errors(t.h, t.axis, t.factor, kTransientCells);
    unconverged += !e.converged;
    std::printf("HT %s ab %.4f nu %.4f k %.3f u %+.3f %+.3f %+.3f from %.3f Fx %.2f Fy %.2f Mz %.2f shape %.2f "
                "MzF %.2f%s\n",
                kind[t.axis + 1], t.h.ab, t.h.nu, t.h.k, t.h.dir[0], t.h.dir[1], t.h.dir[2], t.factor, 100 * e.Fx,
                100 * e.Fy, 100 * e.Mz, 100 * e.shape, 100 * e.Mz_of_force, e.converged ? "" : " unconverged");
    std::fflush(stdout);
    fx.push_back(e.Fx);
    fy.push_back(e.Fy);
    mz.push_back(e.Mz);
    shape.push_back(e.shape);
    if (t.axis < 0) startup_fy = std::max(startup_fy, e.Fy);
  }
  print_distribution("T-Fx", fx, kTransientTarget);
  print_distribution("T-Fy", fy, kTransientTarget);
  print_distribution("T-Mz", mz, kTransientTarget);
  print_distribution("T-shape", shape, kTransientTarget);
  EXPECT_EQ(unconverged, 0);
  // The target (3 % of the steady value at every rolled distance) is missed; the measured distribution (seed
  // kSeed + 1 ... + 4, 40^2, dq = dx, 12a; docs/accuracy-vs-exact.md "Held-out points") as a regression guard,
  // one run of slack in the counts. With the second stage for eta and spin (relaxed.h) the medians of Fy and Mz
  // fell (8.7 to 6.5 %, 38 to 11 %) and the start-ups' Fy (34 to 15 % at worst); the counts within 3 % did not move.
  const Distribution dfx = distribution(fx, kTransientTarget), dfy = distribution(fy, kTransientTarget),
                     dmz = distribution(mz, kTransientTarget);
  // Fx: 17 of 32 within, median 2.86 %, the worst 62.8 % (a step of spin reversing it with eta, a/b 0.38); steps
  // of xi that reverse it 7-15 % (the first stage's, unchanged).
  EXPECT_GE(dfx.within, 16);
  EXPECT_LE(dfx.median, kTransientTarget);
  EXPECT_LE(dfx.max, 0.65);
  // Fy: 7 of 32 within, median 6.5 %, the worst 98.8 % (the same step of spin: reversed under eta near 50 % of
  // saturation, where the second stage's linear share overshoots); start-ups 1.5-15.1 %.
  EXPECT_GE(dfy.within, 6);
  EXPECT_LE(dfy.median, 0.07);
  EXPECT_LE(dfy.max, 1.0);
  EXPECT_LE(startup_fy, 0.16);
  // Mz: 6 of 32 within, median 11.3 % of |Mz_ss|, 90th percentile 51 %.
  EXPECT_GE(dmz.within, 5);
  EXPECT_LE(dmz.median, 0.12);
  EXPECT_LE(dmz.p90, 0.52);
}

}  // namespace
}  // namespace contact
