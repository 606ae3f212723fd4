// Semi-Hertzian normal problem: Kik-Piotrowski with an equivalent-ellipse correction (equations at
// the top of semi_hertz.h; the choice and its accuracy in docs/semi-hertz.md).
//
// Penetration ratio. Johnson (Contact Mechanics, 1985, section 4.2), for the ellipse with major
// semi-axis a_J, minor b_J, k = b_J/a_J, e^2 = 1 - k^2: the curvature along the major axis is
// C_maj = (p0 b_J / (E* e^2 a_J^2)) (K - E), along the minor C_min = (p0 b_J / (E* e^2 a_J^2))
// ((1/k^2) E - K), and delta = p0 b_J K / E*. Hence, with rho = C_min / C_maj >= 1,
//   rho = ((1/k^2) E - K) / (K - E),   eps_major = C_maj a_J^2 / delta = (K - E) / (e^2 K),
// and C_maj a_J^2 + C_min b_J^2 = delta (so eps_x + eps_y = 1), all explicit in k: a table over k
// gives eps_major and K against log(rho) without solving for k; it also gives Hertz's approach for
// the first guess of the root find (EllipseTable::approach).
//
// Quadrature of the Boussinesq integral: per patch [l, r], cells uniform in theta with
// y = (l + r)/2 + (r - l)/2 sin(theta), so that the sqrt edges of a(y) and p(y) become smooth. On a
// cell, p/p0 and a vary slowly (on the scale of the patch's width) and are taken at the cell's centre;
// the strip kernel, which varies on the scale a and is log-singular at the reference point, is
// integrated exactly through its tabulated antiderivative Psi (KernelTable below).
//
// Strips: the line load (pi/2) p(y) a(y) is proportional to g_+(y), piecewise linear, so each grid
// row's load is integrated exactly; p_j = row load / ((pi/2) a_j dy), a_j = a(y_j).
#include "lib/normal/semi_hertz.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/number.h"
#include "lib/normal/hertz.h"
#include "lib/numeric.h"

namespace contact {

namespace {

// invariants checked per solve: the strips' loads sum to F (rounding over the rows), and no strip
// peak exceeds the field's peak p0 (finding 5; the stress sweep holds it to 1e-12)
constexpr double kLoadBalanceRtol = 1e-9;
constexpr double kPeakRtol = 1e-9;
// the continuous rule blends the reference points of minima lying within this fraction of their own depth
// below their necks of the lowest (Solver::reference_minima)
constexpr double kMinimaBlend = 0.1;
// the root find aims at kPolish load_rtol (find_approach): the wear lives' convergence tests need the
// rates free of solver noise to 1e-10 (at 1e-3 the rtol-1e-6 life of paper-wear.yaml was 5e-5 off)
constexpr double kPolish = 1e-6;
constexpr double kJumpWidth = 1e-12;
// the Galerkin rule's cells on the pieces of the contact other than an outer point's own (Solver::galerkin_p0)
constexpr int kGalerkinFarCells = 4;  // the root find's bracket in ln delta: narrower is a jump of F(delta)

std::string num(double v) { return six_digits(v); }  // lib/number.h

// Hertz's ellipse against log(rho), rho = larger/smaller curvature >= 1: eps of the major semi-axis
// and K(e), so that with C the smaller curvature
//   delta = 3 F K / (2 pi E* major),  major^2 = eps delta / C
//   =>  delta = (3 F K sqrt(C) / (2 pi E* sqrt(eps)))^(2/3).
struct EllipseTable {
  std::vector<double> log_rho, eps, K;
  EllipseTable() {
    constexpr double kPiHalf = 1.5707963267948966;
    log_rho.push_back(0);  // circle: eps = 1/2, K = pi/2
    eps.push_back(0.5);
    K.push_back(kPiHalf);
    constexpr int kN = 4000;
    const double lk_hi = std::log(1 - 1e-3), lk_lo = std::log(1e-6);
    for (int i = 0; i < kN; ++i) {  // k from near 1 down to 1e-6: rho increases
      const double k = std::exp(lk_hi + (lk_lo - lk_hi) * i / (kN - 1));
      const double e2 = 1 - k * k, e = std::sqrt(e2);
      const double Kk = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
      log_rho.push_back(std::log((E / (k * k) - Kk) / (Kk - E)));
      eps.push_back((Kk - E) / (e2 * Kk));
      K.push_back(Kk);
    }
  }
  // linear interpolation of column c at log(rho) = lr >= 0 (clamped to the table)
  double at(const std::vector<double>& c, double lr) const {
    if (lr <= 0) return c.front();
    if (lr >= log_rho.back()) return c.back();
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(log_rho.begin(), log_rho.end(), lr) - log_rho.begin());
    const double t = (lr - log_rho[i - 1]) / (log_rho[i] - log_rho[i - 1]);
    return c[i - 1] + t * (c[i] - c[i - 1]);
  }
  // eps_y = B b^2 / delta for curvatures A (x) and B (y)
  double eps_y(double A, double B) const {
    const double lr = std::log(A / B);
    return lr >= 0 ? at(eps, lr) : 1 - at(eps, -lr);
  }
  double approach(double A, double B, double F, double Estar) const {
    const double lr = std::abs(std::log(A / B)), C = std::min(A, B);
    return std::cbrt(std::pow(3 * F * at(K, lr) / (2 * kPi * Estar), 2) * C / at(eps, lr));
  }
};

const EllipseTable& ellipse_table() {
  static const EllipseTable table;
  return table;
}

double curvature_per_m(double R_m, const char* name) {
  if (R_m == 0 || std::isnan(R_m))
    throw std::invalid_argument(std::string("semi-Hertz: ") + name + " must be nonzero (inf for flat), got " + num(R_m));
  return std::isinf(R_m) ? 0.0 : 1 / R_m;
}

// the undeformed gap, piecewise linear on the union of the profiles' nodes over their overlap
struct Gap {
  std::vector<double> y, h;  // h >= 0, min 0 at node imin
  double h_shift_m = 0;      // min of z1 + z2, subtracted
  std::size_t imin = 0;
};

// a profile's z at increasing positions y (inside its extent), marching a segment index from the
// segment holding y[0]
void sample_profile(const Profile& pr, const double* y, std::size_t n, double* z) {
  if (n == 0) return;
  const double* ys = pr.y_m.data();
  const Eigen::Index last = pr.y_m.size() - 2;
  Eigen::Index s = std::clamp<Eigen::Index>(std::upper_bound(ys, ys + last + 2, y[0]) - ys - 1, 0, last);
  for (std::size_t k = 0; k < n; ++k) {
    while (s < last && ys[s + 1] < y[k]) ++s;
    const double t = (y[k] - ys[s]) / (ys[s + 1] - ys[s]);
    z[k] = (1 - t) * pr.z_m(s) + t * pr.z_m(s + 1);
  }
}

// Merges the two profiles' nodes over their overlap. At a node of one profile that profile's z is
// exact and the other's is interpolated on its current segment: one pass over both.
Gap make_gap(const Profiles& p) {
  const Profile &p1 = p.body1, &p2 = p.body2;
  const Eigen::Index n1 = p1.y_m.size(), n2 = p2.y_m.size();
  const double *y1 = p1.y_m.data(), *y2 = p2.y_m.data(), *z1 = p1.z_m.data(), *z2 = p2.z_m.data();
  const double lo = std::max(y1[0], y2[0]), hi = std::min(y1[n1 - 1], y2[n2 - 1]);
  if (!(hi > lo))
    throw std::invalid_argument("semi-Hertz: the profiles do not overlap laterally: " + p1.source + " spans [" +
                                num(y1[0]) + ", " + num(y1[n1 - 1]) + "] m, " + p2.source + " [" + num(y2[0]) +
                                ", " + num(y2[n2 - 1]) + "] m");
  // i, j: the first node of each profile beyond the current position; the segments [i-1, i], [j-1, j]
  Eigen::Index i = std::upper_bound(y1, y1 + n1, lo) - y1, j = std::upper_bound(y2, y2 + n2, lo) - y2;
  auto interp = [](const double* y, const double* z, Eigen::Index k, double at) {
    const double t = (at - y[k - 1]) / (y[k] - y[k - 1]);
    return (1 - t) * z[k - 1] + t * z[k];
  };
  Gap g;
  const std::size_t cap = static_cast<std::size_t>((n1 - i) + (n2 - j) + 2);
  g.y.reserve(cap);
  g.h.reserve(cap);
  auto add = [&g](double y, double h) {
    g.y.push_back(y);
    g.h.push_back(h);
  };
  // the overlap's start: a node of the profile that starts later (i or j >= 1 there)
  add(lo, (i == 0 ? z1[0] : interp(y1, z1, std::min(i, n1 - 1), lo)) +
              (j == 0 ? z2[0] : interp(y2, z2, std::min(j, n2 - 1), lo)));
  while (i < n1 && j < n2) {
    const double y = std::min(y1[i], y2[j]);
    if (y >= hi) break;
    if (y1[i] == y2[j]) add(y, z1[i++] + z2[j++]);
    else if (y1[i] < y2[j]) add(y, z1[i++] + interp(y2, z2, j, y));
    else add(y, interp(y1, z1, i, y) + z2[j++]);
  }
  add(hi, interp(y1, z1, std::clamp<Eigen::Index>(i, 1, n1 - 1), hi) +
              interp(y2, z2, std::clamp<Eigen::Index>(j, 1, n2 - 1), hi));
  g.imin = static_cast<std::size_t>(std::min_element(g.h.begin(), g.h.end()) - g.h.begin());
  g.h_shift_m = g.h[g.imin];
  for (double& v : g.h) v -= g.h_shift_m;
  return g;
}

// integral of the positive part of the linear g over [y0, y1] (I0) and its first moment (I1)
inline void positive_segment(double y0, double y1, double g0, double g1, double& I0, double& I1) {
  if (g0 >= 0 && g1 >= 0) {
    const double d = y1 - y0;
    I0 += d * (g0 + g1) / 2;
    I1 += d * (g0 * (2 * y0 + y1) + g1 * (y0 + 2 * y1)) / 6;
  } else if (g0 > 0) {  // g1 < 0
    const double yc = y0 + (y1 - y0) * g0 / (g0 - g1), d = yc - y0;
    I0 += d * g0 / 2;
    I1 += d * g0 * (2 * y0 + yc) / 6;
  } else if (g1 > 0) {  // g0 < 0
    const double yc = y0 + (y1 - y0) * g0 / (g0 - g1), d = y1 - yc;
    I0 += d * g1 / 2;
    I1 += d * g1 * (yc + 2 * y1) / 6;
  }
}

// integral of sqrt(g_+) over a segment where g is linear
inline double sqrt_segment(double y0, double y1, double g0, double g1) {
  if (g0 <= 0 && g1 <= 0) return 0;
  if (g0 > 0 && g1 > 0) {
    const double s0 = std::sqrt(g0), s1 = std::sqrt(g1);
    return (y1 - y0) * (2.0 / 3) * (g0 + s0 * s1 + g1) / (s0 + s1);
  }
  const double yc = y0 + (y1 - y0) * g0 / (g0 - g1);
  return g0 > 0 ? (2.0 / 3) * std::sqrt(g0) * (yc - y0) : (2.0 / 3) * std::sqrt(g1) * (y1 - yc);
}

// The strip kernel I(a, eta) = integral over |x| < a of sqrt(1 - x^2/a^2) / sqrt(x^2 + eta^2) dx
// = I(1, eta/a) = 2 sqrt(1 + s^2) (K(k) - E(k)), s = eta/a, k = 1/sqrt(1 + s^2); K - E = K sum 2^(n-1) c_n^2
// by the arithmetic-geometric mean (no cancellation at either end).
double strip_kernel(double s) {
  const double r = std::sqrt(1 + s * s);
  double an = 1, gn = std::abs(s) / r, weight = 0.5, sum = 0.5 / (r * r);
  while (an - gn > 1e-15 * an) {
    const double cn = (an - gn) / 2, g_next = std::sqrt(an * gn);
    an = (an + gn) / 2;
    gn = g_next;
    weight *= 2;
    sum += weight * cn * cn;
  }
  return 2 * r * (kPi / (2 * an)) * sum;
}

// Psi(s) = integral of I(1, sigma) d sigma from 0 to s (odd in s), so that the integral of I(a, eta)
// over eta in [eta_l, eta_r] is a (Psi(eta_r/a) - Psi(eta_l/a)), log singularity included.
//   s -> 0:   I = 2 (ln(4/s) - 1) + O(s^2 ln s),  Psi = 2 s ln(4/s)
//   s -> inf: I = pi/(2s) + O(s^-3),              Psi = Psi(s1) + (pi/2) ln(s/s1)
// Tabulated in u = ln s with the exact slope dPsi/du = s I(1, s); cubic Hermite in between.
struct KernelTable {
  static constexpr int kN = 1201;
  static constexpr double kUmin = -13.815510557964274, kUmax = 13.815510557964274;  // ln 1e-6, ln 1e6
  static constexpr double kDu = (kUmax - kUmin) / (kN - 1);
  std::vector<double> psi, slope;
  KernelTable() : psi(kN), slope(kN) {
    // 8-point Gauss-Legendre on each step, in u
    static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    static const double w[4] = {0.3626837833783620, 0.3137066638691861, 0.2223810344533745, 0.1012285362903763};
    const double s0 = std::exp(kUmin);
    psi[0] = 2 * s0 * std::log(4 / s0);
    slope[0] = s0 * strip_kernel(s0);
    for (int i = 1; i < kN; ++i) {
      const double um = kUmin + (i - 0.5) * kDu;
      double step = 0;
      for (int q = 0; q < 4; ++q)
        for (double sign : {-1.0, 1.0}) {
          const double s = std::exp(um + sign * x[q] * kDu / 2);
          step += w[q] * s * strip_kernel(s);
        }
      const std::size_t k = static_cast<std::size_t>(i);
      const double s = std::exp(kUmin + i * kDu);
      psi[k] = psi[k - 1] + step * kDu / 2;
      slope[k] = s * strip_kernel(s);
    }
  }
  double operator()(double s) const {
    const double m = std::abs(s);
    if (m <= 0) return 0;
    const double u = std::log(m);
    double v;
    if (u < kUmin) {
      v = 2 * m * std::log(4 / m);
    } else if (u >= kUmax) {
      v = psi.back() + kPi / 2 * (u - kUmax);
    } else {
      const double f = (u - kUmin) / kDu;
      const std::size_t i = std::min(static_cast<std::size_t>(f), static_cast<std::size_t>(kN - 2));
      const double t = f - static_cast<double>(i), t2 = t * t, t3 = t2 * t;
      v = (2 * t3 - 3 * t2 + 1) * psi[i] + (t3 - 2 * t2 + t) * kDu * slope[i] + (-2 * t3 + 3 * t2) * psi[i + 1] +
          (t3 - t2) * kDu * slope[i + 1];
    }
    return s < 0 ? -v : v;
  }
};

struct ContactRun {  // a patch: nodes i0..i1 have g > 0; edges l, r exact
  std::size_t i0 = 0, i1 = 0;
  double l = 0, r = 0;
  double I0 = 0, I1 = 0;  // integral of g_+ and of y g_+ over the patch
};

// a reference point of the continuous rule: the basin centroid of one minimum of the gap, its weight
struct ReferencePoint {
  double y0 = 0, weight = 1;
};

struct Evaluation {
  double delta = 0, eps = 0.5, t = 0, B_e = 0, A_mod = 0;
  double G1 = 0;          // integral of g_+ over all patches
  double y0 = 0, h0 = 0;  // reference point and the gap there (the continuous rule: weighted means)
  std::vector<ReferencePoint> refs;  // the reference points blended (one, unless minima are nearly equal)
  double J = 0;           // integral of (p/p0) / r dA
  double S = 0;           // integral of p/p0 dA
  double p0 = 0, F = 0;
  std::vector<ContactRun> runs;
  bool reaches_edge = false;
};

class Solver {
 public:
  Solver(const Gap& gap, double A, double Estar, int cells, double kp_epsilon, int galerkin_points)
      : gap_(gap), A_(A), Estar_(Estar), cells_(cells), galerkin_points_(galerkin_points), kp_epsilon_(kp_epsilon) {
    const std::size_t segments = gap.y.size() - 1;
    for (std::size_t s = 0; s < segments; s += kBlock) {
      const auto first = gap.h.begin() + static_cast<std::ptrdiff_t>(s);
      const auto last = gap.h.begin() + static_cast<std::ptrdiff_t>(std::min(s + kBlock, segments) + 1);
      block_min_.push_back(*std::min_element(first, last));
    }
  }

  // eps = f(eps): B_e from the interpenetration at eps delta, eps of B_e's ellipse; secant steps on
  // f(eps) - eps (a contraction: plain steps also converge, slower). Returns B_e; eps in and out.
  double equivalent_ellipse(double delta, double& eps) {
    const EllipseTable& table = ellipse_table();
    double eps_prev = 0, phi_prev = 0, B_e = 0;
    for (int it = 0; it < 50; ++it) {
      const double t = eps * delta;
      const double be = 0.75 * positive_integral(t) / t;
      B_e = t / (be * be);
      const double phi = table.eps_y(A_, B_e) - eps;
      if (std::abs(phi) <= 1e-12) break;
      const double next = it > 0 && phi != phi_prev ? eps - phi * (eps - eps_prev) / (phi - phi_prev) : eps + phi;
      eps_prev = eps;
      phi_prev = phi;
      eps = std::clamp(next, 0.01, 0.99);
    }
    return B_e;
  }

  // The continuous rule's eps: two passes of eps = eps_y(A, B_e(eps delta)) from eps = 1/2, no fixed
  // point. Exact on constant curvature like the fixed point (B_e = B at any level), and a composition of
  // functions continuous in delta. The fixed point is not: where lobes merge as the level rises, the
  // wider contact lowers B_e, which raises eps and the level, and two fixed points coexist (the
  // warm-started iteration then picks one by history: F(delta) jumps, docs/semi-hertz.md). Returns B_e.
  double explicit_ellipse(double delta, double& eps) const {
    const EllipseTable& table = ellipse_table();
    double B_e = 0;
    eps = 0.5;
    for (int pass = 0; pass < 2; ++pass) {
      const double t = eps * delta;
      const double be = 0.75 * positive_integral(t) / t;
      B_e = t / (be * be);
      eps = table.eps_y(A_, B_e);
    }
    return B_e;
  }

  // everything at approach delta; eps_start: the last evaluation's eps (fixed point warm start)
  Evaluation evaluate(double delta, double eps_start, ApproachRule rule) {
    Evaluation ev;
    ev.delta = delta;
    double eps = eps_start;
    ev.B_e = rule == ApproachRule::SelfConsistent ? equivalent_ellipse(delta, eps) : explicit_ellipse(delta, eps);
    if (kp_epsilon_ > 0) eps = kp_epsilon_;  // Kik-Piotrowski as published: a = sqrt((eps delta - h)/A)
    ev.eps = eps;
    ev.t = eps * delta;
    ev.A_mod = kp_epsilon_ > 0 ? A_ : A_ * eps / (1 - eps);
    find_runs(ev);
    ev.S = kPi / 2 * ev.G1 / std::sqrt(ev.t * ev.A_mod);
    if (rule == ApproachRule::SelfConsistent) {
      // reference point: centroid of g_+ over the patch holding the gap's minimum
      const ContactRun* ref = &ev.runs.front();
      for (const ContactRun& run : ev.runs)
        if (run.i0 <= gap_.imin && gap_.imin <= run.i1) ref = &run;
      ev.y0 = ref->I1 / ref->I0;
      ev.refs.assign(1, {ev.y0, 1});
      ev.h0 = h_at(ev.t, ev.y0);
      boussinesq_integrals(ev, false, &ev.y0, &ev.J, 1);
      ev.p0 = kPi * Estar_ * (ev.delta - ev.h0) / ev.J;
    } else if (rule == ApproachRule::Galerkin) {
      galerkin_p0(ev);
    } else {
      // the basin centroid of each minimum that counts (reference_minima), p0 the weighted mean of theirs
      ev.refs.clear();
      for (const auto& [node, weight] : reference_minima(ev.t)) ev.refs.push_back({basin_centroid(ev.t, node), weight});
      y0s_.resize(ev.refs.size());
      Js_.resize(ev.refs.size());
      for (std::size_t k = 0; k < ev.refs.size(); ++k) y0s_[k] = ev.refs[k].y0;
      boussinesq_integrals(ev, true, y0s_.data(), Js_.data(), ev.refs.size());
      double p0w = 0, w = 0, y0w = 0, h0w = 0, Jw = 0;
      for (std::size_t k = 0; k < ev.refs.size(); ++k) {
        const double y0 = ev.refs[k].y0, h0 = h_at(ev.t, y0), J = Js_[k], weight = ev.refs[k].weight;
        p0w += weight * kPi * Estar_ * (ev.delta - h0) / J;
        y0w += weight * y0;
        h0w += weight * h0;
        Jw += weight * J;
        w += weight;
      }
      ev.p0 = p0w / w;
      ev.y0 = y0w / w;
      ev.h0 = h0w / w;
      ev.J = Jw / w;
      for (ReferencePoint& r : ev.refs) r.weight /= w;
    }
    ev.F = ev.p0 * ev.S;
    return ev;
  }

  // The Galerkin rule's p0: Hertz's field satisfies delta - h(y) = u_z(0, y) = (p0 / (pi E*)) J(y) at every y
  // of the contact, so any weighted mean of that condition gives the same p0 there; weighted by g_+ (the
  // line load's shape, vanishing at the edges) over the whole contact,
  //   p0 = pi E* sum_i W_i (delta - h(y_i)) / sum_i W_i J(y_i),  W_i = g_+(y_i) dy_i,
  // the outer points galerkin_points_ per piece (the pieces of the Boussinesq cells: patches cut at the
  // gap's necks), uniform in theta (y = mid + half sin theta, midpoints) like the cells: both sums by the
  // same points, so the quadrature of the outer integral cancels on Hertz's field. Each point and weight
  // moves continuously with delta and the profiles; a piece entering or leaving weighs g_+ -> 0. No
  // reference point, basin or blend enters p0. The Heathcote reference y0 is the centroid of g_+ over
  // the whole contact (the centre on Hertz's field).
  void galerkin_p0(Evaluation& ev) const {
    static const KernelTable psi;
    ys_.clear();
    ws_.clear();
    pieces_.clear();
    fine_.clear();
    coarse_.clear();
    const int m = galerkin_points_;
    const double dtheta = kPi / m;
    double N = 0, W = 0, I0 = 0, I1 = 0;
    for (const ContactRun& run : ev.runs) {
      I0 += run.I0;
      I1 += run.I1;
      const std::vector<double>& cuts = piece_cuts(run, true);
      for (std::size_t piece = 0; piece + 1 < cuts.size(); ++piece) {
        const double l = cuts[piece], r = cuts[piece + 1];
        const double mid = (l + r) / 2, half = (r - l) / 2;
        Piece pc;
        pc.first_point = ys_.size();
        std::size_t seg = std::max<std::size_t>(run.i0, 1);  // segment [seg-1, seg] holds y
        for (int i = 0; i < m; ++i) {
          const double theta = -kPi / 2 + (i + 0.5) * dtheta;
          const double y = mid + half * std::sin(theta);
          while (seg + 1 < gap_.y.size() && gap_.y[seg] < y) ++seg;
          const double g = g_on_segment(ev.t, seg, y);
          if (!(g > 0)) continue;
          const double w = g * half * std::cos(theta) * dtheta;
          ys_.push_back(y);
          ws_.push_back(w);
          N += w * (ev.delta - ev.t + g);  // delta - h = delta - t + g
          W += w;
        }
        pc.end_point = ys_.size();
        pc.first_fine = fine_.size();
        add_cells(ev, run, l, r, cells_, fine_);
        pc.end_fine = fine_.size();
        pc.first_coarse = coarse_.size();
        add_cells(ev, run, l, r, kGalerkinFarCells, coarse_);
        pc.end_coarse = coarse_.size();
        pieces_.push_back(pc);
      }
    }
    // J at each outer point: its own piece by the fine cells (the log singularity), the other pieces by
    // kGalerkinFarCells each (a fixed assignment: no switch as the contact changes)
    double D = 0;
    for (std::size_t p = 0; p < pieces_.size(); ++p) {
      for (std::size_t k = pieces_[p].first_point; k < pieces_[p].end_point; ++k) {
        const double y = ys_[k];
        double J = 0;
        for (std::size_t q = 0; q < pieces_.size(); ++q) {
          const bool own = q == p;
          const std::vector<Cell>& cells = own ? fine_ : coarse_;
          const std::size_t c0 = own ? pieces_[q].first_fine : pieces_[q].first_coarse;
          const std::size_t c1 = own ? pieces_[q].end_fine : pieces_[q].end_coarse;
          for (std::size_t c = c0; c < c1; ++c)
            J += cells[c].wa * (psi((cells[c].r - y) * cells[c].inv_a) - psi((cells[c].l - y) * cells[c].inv_a));
        }
        D += ws_[k] * J;
      }
    }
    ev.p0 = kPi * Estar_ * N / D;
    ev.J = D / W;
    ev.y0 = I1 / I0;
    ev.refs.assign(1, {ev.y0, 1});
    ev.h0 = h_at(ev.t, ev.y0);
  }

  // a Boussinesq cell: its edges, w a at its centre (w = sqrt(g/t) the pressure's lateral shape) and 1/a there
  struct Cell {
    double l, r, wa, inv_a;
  };
  struct Piece {
    std::size_t first_point, end_point, first_fine, end_fine, first_coarse, end_coarse;
  };
  // n cells over [l, r] within run, uniform in theta (as boussinesq_integrals lays them); cells where g <= 0
  // (rounding at an edge) are left out
  void add_cells(const Evaluation& ev, const ContactRun& run, double l, double r, int n, std::vector<Cell>& out) const {
    const double wa_per_g = 1 / std::sqrt(ev.t * ev.A_mod);
    const double mid = (l + r) / 2, half = (r - l) / 2;
    std::size_t seg = std::max<std::size_t>(run.i0, 1);
    double y_left = l;
    for (int c = 0; c < n; ++c) {
      const double y_c = mid + half * std::sin(-kPi / 2 + (c + 0.5) * kPi / n);
      const double y_right = c + 1 == n ? r : mid + half * std::sin(-kPi / 2 + (c + 1) * kPi / n);
      while (seg + 1 < gap_.y.size() && gap_.y[seg] < y_c) ++seg;
      const double g = g_on_segment(ev.t, seg, y_c);
      if (g > 0) out.push_back({y_left, y_right, g * wa_per_g, std::sqrt(ev.A_mod / g)});
      y_left = y_right;
    }
  }

  // The continuous rule's reference is the basin centroid of the gap's lowest minimum, unless another
  // minimum is nearly as low: where two minima swap, taking the lower one's made the contact jump (43 %
  // of one cam angle's dissipation, docs/semi-hertz.md). Every local minimum k of h below the level t
  // (a run of equal nodes counts once, by its first node) gets the weight
  //   w_k = s(1 - (h_k - h_min) / (kMinimaBlend P_k)),  s(x) = 0 (x <= 0), x^2 (3 - 2x) (0..1), 1 (x >= 1),
  // P_k = min(t, the lower of its two necks) - h_k (its depth below where it spills into a neighbour).
  // The lowest gets 1; one lower than it by more than kMinimaBlend of its own depth P_k gets 0 (the rule
  // is then the one-minimum rule, unchanged); at a swap both weigh 1. w_k is continuous in the depths and
  // in t: a minimum is born or dies with its neck (P_k = 0, w_k = 0), never with a finite weight.
  std::vector<std::pair<std::size_t, double>> reference_minima(double t) const {
    const std::vector<double>& h = gap_.h;
    const std::size_t n = h.size();
    std::vector<std::pair<std::size_t, double>> out;
    for (std::size_t i = 0; i < n; ++i) {
      if (i % kBlock == 0 && i / kBlock < block_min_.size() && block_min_[i / kBlock] >= t) {
        i += kBlock - 1;
        continue;
      }
      if (h[i] >= t || (i > 0 && h[i - 1] <= h[i])) continue;  // below t, and the first of its run
      std::size_t j = i;  // the run's last node
      while (j + 1 < n && h[j + 1] == h[i]) ++j;
      if (j + 1 < n && h[j + 1] < h[i]) continue;  // a step down, not a minimum
      if (i == gap_.imin) {
        out.emplace_back(i, 1.0);
        continue;
      }
      auto neck = [&](std::size_t from, int dir) {  // the first local maximum going dir, at most t
        std::size_t k = from;
        for (;;) {
          if ((dir < 0 && k == 0) || (dir > 0 && k + 1 == n)) return t;
          const std::size_t next = dir < 0 ? k - 1 : k + 1;
          if (h[next] < h[k] || h[next] >= t) return std::min(t, std::max(h[k], h[next]));
          k = next;
        }
      };
      const double depth = std::min(neck(i, -1), neck(j, +1)) - h[i];
      const double x = depth > 0 ? 1 - (h[i] - h[gap_.imin]) / (kMinimaBlend * depth) : 0;
      if (x > 0) out.emplace_back(i, x >= 1 ? 1.0 : x * x * (3 - 2 * x));
    }
    return out;
  }

  // h at y (linear between the gap's nodes; y within the gap), as t - g
  double h_at(double t, double y) const {
    const std::size_t s = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::lower_bound(gap_.y.begin(), gap_.y.end(), y) - gap_.y.begin()), 1,
        gap_.y.size() - 1);
    return t - g_on_segment(t, s, y);
  }

  // The basin rule's reference point: the centroid of m_+, m(y) = the smallest g on the way from the
  // gap's minimum to y. Where g falls monotonically away from the minimum, m = g: the lobe centroid.
  // Across a neck, the far side weighs at most g at the neck, which is 0 when the lobes merge, so y0
  // moves continuously with t (docs/semi-hertz.md, "Lobes merging"). On a segment going outward from
  // node i (m = c there, c <= g_i) to node k: m = c while g >= c, then g; c becomes min(c, g_k).
  double basin_centroid(double t, std::size_t start) const {
    const std::vector<double>& y = gap_.y;
    const std::vector<double>& h = gap_.h;
    double I0 = 0, I1 = 0;
    for (const int dir : {-1, +1}) {
      double c = t - h[start];
      for (std::size_t i = start; c > 0;) {
        if ((dir < 0 && i == 0) || (dir > 0 && i + 1 == y.size())) break;
        const std::size_t k = dir < 0 ? i - 1 : i + 1;
        const double ya = y[i], yb = y[k], ga = t - h[i], gb = t - h[k];
        const double yc = gb >= c ? yb : ya + (yb - ya) * (ga - c) / (ga - gb);  // where g falls to c
        // m = c on [ya, yc]
        const double lo = std::min(ya, yc), hi = std::max(ya, yc);
        I0 += c * (hi - lo);
        I1 += c * (hi - lo) * (lo + hi) / 2;
        // m = g on [yc, yb], from c to gb
        if (gb < c) {
          if (dir < 0) positive_segment(yb, yc, gb, c, I0, I1);
          else positive_segment(yc, yb, c, gb, I0, I1);
          c = gb;
        }
        i = k;
      }
    }
    return I1 / I0;
  }

  // g = t - h at y on the segment [s-1, s]
  double g_on_segment(double t, std::size_t s, double y) const {
    const double w = (y - gap_.y[s - 1]) / (gap_.y[s] - gap_.y[s - 1]);
    return t - (gap_.h[s - 1] + w * (gap_.h[s] - gap_.h[s - 1]));
  }

  // Marches increasing positions y through the gap: the integral of g_+ from the first node to y,
  // and g at y. Queries must not decrease.
  class March {
   public:
    March(const Gap& gap, double t) : gap_(gap), t_(t) {}
    double integral_to(double y) {
      const std::vector<double>& ys = gap_.y;
      advance_to(y);
      double part = acc_, I1 = 0;
      positive_segment(ys[s_], y, t_ - gap_.h[s_], g_at(y), part, I1);
      return part;
    }
    double g_at(double y) {
      const std::vector<double>& ys = gap_.y;
      advance_to(y);
      const double w = (y - ys[s_]) / (ys[s_ + 1] - ys[s_]);
      return t_ - (gap_.h[s_] + w * (gap_.h[s_ + 1] - gap_.h[s_]));
    }

   private:
    // to the segment holding y, the integral of g_+ taken over the segments passed
    void advance_to(double y) {
      const std::vector<double>& ys = gap_.y;
      while (s_ + 2 < ys.size() && ys[s_ + 1] <= y) {
        double I1 = 0;
        positive_segment(ys[s_], ys[s_ + 1], t_ - gap_.h[s_], t_ - gap_.h[s_ + 1], acc_, I1);
        ++s_;
      }
    }
    const Gap& gap_;
    double t_;
    std::size_t s_ = 0;  // segment [s_, s_ + 1]
    double acc_ = 0;     // integral of g_+ up to node s_
  };

 private:
  // integral of g_+ = (t - h)_+ over the whole gap, skipping blocks of segments where h >= t
  double positive_integral(double t) const {
    double I0 = 0, I1 = 0;
    const std::vector<double>& y = gap_.y;
    const std::vector<double>& h = gap_.h;
    for (std::size_t b = 0; b < block_min_.size(); ++b) {
      if (block_min_[b] >= t) continue;
      const std::size_t end = std::min((b + 1) * kBlock, y.size() - 1);
      for (std::size_t s = b * kBlock; s < end; ++s)
        if (h[s] < t || h[s + 1] < t) positive_segment(y[s], y[s + 1], t - h[s], t - h[s + 1], I0, I1);
    }
    return I0;
  }

  void find_runs(Evaluation& ev) const {
    const std::vector<double>& y = gap_.y;
    const std::vector<double>& h = gap_.h;
    const double t = ev.t;
    ev.G1 = 0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      if (i % kBlock == 0 && i / kBlock < block_min_.size() && block_min_[i / kBlock] >= t) {
        i += kBlock - 1;
        continue;
      }
      if (h[i] >= t) continue;
      ContactRun run;
      run.i0 = i;
      while (i + 1 < y.size() && h[i + 1] < t) ++i;
      run.i1 = i;
      const std::size_t i0 = run.i0, i1 = run.i1;
      // exact edges, where g crosses zero on the neighbouring segments
      run.l = i0 == 0 ? y[0] : y[i0 - 1] + (y[i0] - y[i0 - 1]) * (t - h[i0 - 1]) / (h[i0] - h[i0 - 1]);
      run.r = i1 + 1 == y.size() ? y[i1] : y[i1] + (y[i1 + 1] - y[i1]) * (h[i1] - t) / (h[i1] - h[i1 + 1]);
      if (i0 == 0 || i1 + 1 == y.size()) ev.reaches_edge = true;
      const std::size_t s0 = i0 == 0 ? 0 : i0 - 1, s1 = std::min(i1 + 1, y.size() - 1);
      for (std::size_t s = s0; s < s1; ++s) positive_segment(y[s], y[s + 1], t - h[s], t - h[s + 1], run.I0, run.I1);
      ev.G1 += run.I0;
      ev.runs.push_back(run);
    }
  }

  // J = integral of sqrt(g/t) sqrt(1 - x^2/a^2) / sqrt(x^2 + (y - y0)^2) dA: on each cell the slowly
  // varying w = sqrt(g/t) and a are taken at the centre, the kernel integrated exactly (Psi)
  // split_at_necks (the continuous rule): each patch is also cut at the gap's interior local maxima
  // (necks), each piece with its own cells, so that two lobes merging through a neck keep the cells
  // they had apart; with one set of cells over the merged patch J dropped by 26 % at the merge
  // (paper-wear.yaml with xi 0, docs/semi-hertz.md).
  // J at every reference point y0s[k] (into J[k]) in one pass over the cells: a cell's g, w and a once
  void boussinesq_integrals(const Evaluation& ev, bool split_at_necks, const double* y0s, double* J, std::size_t n_refs) const {
    static const KernelTable psi;
    std::fill(J, J + n_refs, 0.0);
    const double wa_per_g = 1 / std::sqrt(ev.t * ev.A_mod);  // w a = g / sqrt(t A_mod)
    for (const ContactRun& run : ev.runs) {
      const std::vector<double>& cuts = piece_cuts(run, split_at_necks);
      std::size_t seg = std::max<std::size_t>(run.i0, 1);  // segment [seg-1, seg] holds y_c
      for (std::size_t piece = 0; piece + 1 < cuts.size(); ++piece) {
        // every patch its own cells: shared out by width, a patch's count changed by rounding as the
        // patches grew, and J (so F(delta)) jumped with it (finding 6, docs/stress-suite.md)
        const int n = cells_;
        const double l = cuts[piece], r = cuts[piece + 1];
        const double mid = (l + r) / 2, half = (r - l) / 2;
        // sin and cos of theta by rotation, theta from -pi/2 in steps of pi/(2n): edges and centres
        const double c_step = std::cos(kPi / (2 * n)), s_step = std::sin(kPi / (2 * n));
        double sn = -1, cs = 0;
        double y_left = l;
        for (int c = 0; c < n; ++c) {
          const double sn_c = sn * c_step + cs * s_step, cs_c = cs * c_step - sn * s_step;
          sn = sn_c * c_step + cs_c * s_step;
          cs = cs_c * c_step - sn_c * s_step;
          const double y_c = mid + half * sn_c;
          const double y_right = c + 1 == n ? r : mid + half * sn;
          while (seg + 1 < gap_.y.size() && gap_.y[seg] < y_c) ++seg;
          const double g = g_on_segment(ev.t, seg, y_c);
          if (g > 0) {
            const double wa = g * wa_per_g, inv_a = std::sqrt(ev.A_mod / g);
            for (std::size_t k = 0; k < n_refs; ++k)
              J[k] += wa * (psi((y_right - y0s[k]) * inv_a) - psi((y_left - y0s[k]) * inv_a));
          }
          y_left = y_right;
        }
      }
    }
  }

  // the pieces of a patch that get their own cells: the patch, cut at the gap's interior local maxima
  // (necks) when split_at_necks; returns their edges (scratch, valid until the next call)
  const std::vector<double>& piece_cuts(const ContactRun& run, bool split_at_necks) const {
    cuts_.assign(1, run.l);
    if (split_at_necks)
      for (std::size_t k = std::max<std::size_t>(run.i0, 1); k <= run.i1 && k + 1 < gap_.y.size(); ++k)
        if (gap_.h[k] >= gap_.h[k - 1] && gap_.h[k] > gap_.h[k + 1] && gap_.y[k] > run.l && gap_.y[k] < run.r)
          cuts_.push_back(gap_.y[k]);
    cuts_.push_back(run.r);
    return cuts_;
  }

  const Gap& gap_;
  double A_, Estar_;
  int cells_;
  int galerkin_points_;  // the Galerkin rule's outer points per piece
  mutable std::vector<double> cuts_, y0s_, Js_, ys_, ws_;  // scratch, kept between evaluations
  mutable std::vector<Cell> fine_, coarse_;
  mutable std::vector<Piece> pieces_;
  double kp_epsilon_;  // > 0: fixed eps, no equivalent-ellipse correction
  // min of h over the nodes kBlock b ... kBlock (b + 1) (segments kBlock b ... kBlock (b + 1) - 1)
  static constexpr std::size_t kBlock = 16;
  std::vector<double> block_min_;
};


// ---- the stages of solve_semi_hertz ----

// the inputs refused before anything is solved; returns the rolling curvature A
double checked_rolling_curvature(const Profiles& profiles, double Rx1_m, double Rx2_m, const ElasticPair& pair,
                                 double normal_load_N, const GridSpec& spec, const SemiHertzOptions& options) {
  check_material(pair.body1, "body1");
  check_material(pair.body2, "body2");
  if (!(normal_load_N > 0) || !std::isfinite(normal_load_N))
    throw std::invalid_argument("semi-Hertz: normal load must be positive and finite, got " + num(normal_load_N) + " N");
  if (spec.nx < 1 || spec.ny < 1)
    throw std::invalid_argument("semi-Hertz: nx and ny must be at least 1, got " + std::to_string(spec.nx) + " x " +
                                std::to_string(spec.ny));
  if (!(options.kp_epsilon == 0 || (options.kp_epsilon > 0 && options.kp_epsilon < 1)))
    throw std::invalid_argument("semi-Hertz: kp_epsilon must be 0 (equivalent-ellipse correction) or in (0, 1), got " +
                                num(options.kp_epsilon));
  if (options.galerkin_points < 1)
    throw std::invalid_argument("semi-Hertz: galerkin_points must be at least 1, got " +
                                std::to_string(options.galerkin_points));
  if (options.quadrature_cells < 4)
    throw std::invalid_argument("semi-Hertz: quadrature_cells must be at least 4, got " +
                                std::to_string(options.quadrature_cells));
  const double A = (curvature_per_m(Rx1_m, "Rx1") + curvature_per_m(Rx2_m, "Rx2")) / 2;
  if (!(A > 0))
    throw std::invalid_argument("semi-Hertz: rolling curvature A = (1/Rx1 + 1/Rx2)/2 = " + num(A) +
                                " 1/m must be positive (Rx1 " + num(Rx1_m) + " m, Rx2 " + num(Rx2_m) + " m)");
  validate_profile(profiles.body1);
  validate_profile(profiles.body2);
  return A;
}

// the first approach: Hertz's ellipse with the equivalent curvature B_e of the gap, found at the
// approach of Hertz's circle with curvature A (exact on constant curvature, a good start otherwise)
ApproachRule rule_of(const SemiHertzOptions& options) {
  return options.galerkin_rule     ? ApproachRule::Galerkin
         : options.continuous_rule ? ApproachRule::Continuous
                                   : ApproachRule::SelfConsistent;
}

double first_approach(Solver& solver, double A, double F, double Estar, double& eps) {
  const double R = 1 / (2 * A), a = std::cbrt(3 * F * R / (4 * Estar));
  const double B_e = solver.equivalent_ellipse(a * a / R, eps);
  return ellipse_table().approach(A, B_e, F, Estar);
}

// the root find of F(delta) = F for one reference rule
struct ApproachSearch {
  Evaluation ev;        // the last evaluation (the root when converged)
  int evaluations = 0;
  double residual = std::numeric_limits<double>::infinity();  // F(delta)/F - 1 at ev
  bool converged = false;
  double lo = 0, hi = std::numeric_limits<double>::infinity();  // the bracket
  double residual_lo = 0, residual_hi = 0;
  double slope = 0;  // d ln F / d ln delta near the root (the last secant)
  bool bracketed() const { return lo > 0 && std::isfinite(hi); }
  // the bracket closed on a jump of F(delta) across the load (see find_approach)
  bool on_jump() const { return !converged && bracketed() && std::log(hi / lo) <= kJumpWidth; }
};

// The root of F(delta) = F, on f = ln(F(delta)/F) against x = ln delta (nearly linear: F is close to a
// power of delta): Newton steps with the secant slope of the last two evaluations (the first with the
// caller's slope, else Hertz's 3/2), at most a factor 4 in delta until two evaluations straddle the load,
// then kept inside that bracket; a step that leaves the bracket, or follows a step that did not halve
// |f|, is a bisection of the bracket, so it shrinks at least geometrically where F bends or is not
// monotone (the worn cam's F(delta) is not: docs/semi-hertz.md). It aims at |f| <= kPolish load_rtol:
// the wear loop differentiates the results in time, and a root anywhere within load_rtol would add
// noise of that order to its rates (WearLoop.WearAfterNRevolutionsConvergesAsToleranceTightens,
// WearLife.PaperWearConvergesToTheFixedDepthLife); the secant's superlinear steps get there with about
// one evaluation more. Converged: |F(delta)/F - 1| <=
// load_rtol at the best evaluation. The slope is not bounded above: on a nearly conformal worn gap
// F(delta) is continuous but steep (d ln F / d ln delta = 2.2e3 at the root of paper-wear.yaml with spin
// at 1.85e7 revolutions), and the old secant, its slope clamped to [0.5, 4], crawled into a bracket of
// 1e-9 of delta that it then took for a jump. A jump is now a bracket narrower than kJumpWidth (1e-12 of
// delta) with the residual above load_rtol at both ends: a continuous F would need d ln F / d ln delta
// > 1e6 there.
ApproachSearch find_approach(Solver& solver, double F, double delta, double eps, int max_evaluations,
                             const SemiHertzOptions& options, ApproachRule rule, double slope_guess = 0) {
  ApproachSearch s;
  const double target = std::log1p(kPolish * options.load_rtol), kStep = std::log(4.0);
  Evaluation best;
  double f_best = std::numeric_limits<double>::infinity(), f_lo = 0, f_hi = 0;
  auto evaluate = [&](double x) {
    const double d = std::exp(x);
    s.ev = solver.evaluate(d, eps, rule);
    ++s.evaluations;
    eps = s.ev.eps;
    const double f = std::log(s.ev.F / F);
    SPDLOG_TRACE("semi-Hertz: delta {:.9e} m -> F {:.9e} N (eps {:.6f})", d, s.ev.F, s.ev.eps);
    if (f < 0) {
      s.lo = d;
      f_lo = f;
    } else {
      s.hi = d;
      f_hi = f;
    }
    if (std::abs(f) < std::abs(f_best)) {
      f_best = f;
      best = s.ev;
    }
    return f;
  };
  double slope = slope_guess > 0 ? slope_guess : 1.5;  // Hertz: F ~ delta^(3/2)
  double x = std::log(delta), f = evaluate(x);
  bool crawling = false;
  while (std::abs(f) > target && s.evaluations < max_evaluations && !(s.bracketed() && std::log(s.hi / s.lo) <= kJumpWidth)) {
    double next = x - f / slope;
    if (s.bracketed()) {
      const double xl = std::log(s.lo), xh = std::log(s.hi);
      if (crawling || !(next > xl && next < xh)) next = (xl + xh) / 2;
    } else {
      next = std::clamp(next, x - kStep, x + kStep);
    }
    const double f_next = evaluate(next);
    const double secant = (f_next - f) / (next - x);
    if (secant > 0 && std::isfinite(secant)) slope = secant;  // else F does not rise there: keep the last
    crawling = std::abs(f_next) > 0.5 * std::abs(f);
    x = next;
    f = f_next;
  }
  s.ev = best;
  s.residual = std::expm1(f_best);
  s.converged = std::abs(s.residual) <= options.load_rtol;
  s.residual_lo = std::expm1(f_lo);
  s.residual_hi = std::expm1(f_hi);
  s.slope = slope;
  return s;
}

std::string jump_text(const ApproachSearch& s) {
  char msg[160];
  std::snprintf(msg, sizeof msg, "F(delta)/F - 1 jumps from %+.2e to %+.2e within delta [%.9e, %.9e] m",
                s.residual_lo, s.residual_hi, s.lo, s.hi);
  return msg;
}

// the result's diagnostics and status from the root find: Converged, MaxIterations (with a warning),
// or Failed where the contact reaches a body's edge (with a warning)
void describe_approach(const ApproachSearch& search, int evaluations, const std::string& remedy,
                       const SemiHertzOptions& options, const Gap& gap, const Profiles& profiles, SemiHertzResult& res) {
  const Evaluation& ev = search.ev;
  res.approach_m = ev.delta;
  res.epsilon = ev.eps;
  res.equivalent_B_per_m = ev.B_e;
  res.reference_y_m = ev.y0;
  res.patches = static_cast<int>(ev.runs.size());
  res.reaches_edge = ev.reaches_edge;
  res.contact_y_min_m = ev.runs.front().l;
  res.contact_y_max_m = ev.runs.back().r;
  res.status.iterations = evaluations;
  res.approach_slope = search.slope;
  res.status.residual = std::abs(search.residual);
  char msg[200];
  std::snprintf(msg, sizeof msg, "load residual %.1e %s tol %.1e after %d evaluations", std::abs(search.residual),
                search.converged ? "<=" : ">", options.load_rtol, evaluations);
  res.status.message = msg + remedy;
  res.load_jumps = search.on_jump();
  if (res.load_jumps) res.status.message += "; " + jump_text(search);
  res.status.kind = search.converged ? SolveStatus::Kind::Converged : SolveStatus::Kind::MaxIterations;
  // the caller decides what an unconverged or edge-reaching solve means: the status says it, no warning here
  if (!search.converged) spdlog::debug("semi-Hertz: approach not found: {}", res.status.message);
  if (ev.reaches_edge) {
    res.status.kind = SolveStatus::Kind::Failed;
    res.status.message = "contact [" + num(res.contact_y_min_m) + ", " + num(res.contact_y_max_m) +
                         "] m reaches the edge of the profiles' overlap [" + num(gap.y.front()) + ", " +
                         num(gap.y.back()) + "] m (" + profiles.body1.source + ", " + profiles.body2.source +
                         "): a body is narrower than the contact; " + res.status.message;
    spdlog::debug("semi-Hertz: {}", res.status.message);
  }
}

// The strips: grid over the contact's bounding box, each row carrying its load exactly.
// Row j carries line_load_per_g times the integral of g_+ over the row, exactly: its mean
// gbar_j of g_+ sets the load. The strip's half length is the midpoint's, a(y_j) = sqrt(g_j/A_mod),
// which gives p_j = p0 gbar_j / sqrt(t g_j). Where g_j is small against the row's g (a row cut
// by a patch's edge, or a neck between two lobes), that p_j exceeds every pressure of the field
// in the row: up to 7.9e13 Pa against p0 3.4e9 Pa (finding 5, docs/stress-suite.md), and the
// tangential solvers take mu p_j as the traction bound. So the strip's peak is capped at the
// field's largest peak over the row, p0 sqrt(gmax_j/t), and the strip lengthened to carry the
// row's load at it:
//   a_j = sqrt(max(g_j, gbar_j^2 / gmax_j) / A_mod),   so  p_j = min(midpoint's, p0 sqrt(gmax_j/t)).
// On a row where g is linear or concave (every row of a convex gap: Hertz, crowns, flat bands),
// gbar_j <= g_j <= gmax_j and the midpoint stands; it also stands on gently curved rows of a worn
// gap. Then a_j <= the row's largest a(y), p_j <= p0, and a row whose centre misses the contact
// keeps its own load: it no longer hands it to the nearest row in contact, which could lie in
// another patch. Returns the rows' loads (F(delta), to rounding); throws NoStripCentreError.
Eigen::ArrayXd fill_strips(const Gap& gap, const Evaluation& ev, const GridSpec& spec, const SemiHertzOptions& options,
                           SemiHertzResult& res) {
  ContactPatch& patch = res.patch;
  const double half_x = std::sqrt(ev.t / ev.A_mod);  // a at the gap's minimum, the longest strip
  const bool fixed = options.fixed_grid_y_hi_m > options.fixed_grid_y_lo_m;
  if (fixed && (res.contact_y_min_m < options.fixed_grid_y_lo_m || res.contact_y_max_m > options.fixed_grid_y_hi_m))
    throw std::invalid_argument(fmt::format("semi-Hertz: the contact [{}, {}] m leaves the fixed grid's extent [{}, {}] m",
                                            res.contact_y_min_m, res.contact_y_max_m, options.fixed_grid_y_lo_m,
                                            options.fixed_grid_y_hi_m));
  const double y_lo = fixed ? options.fixed_grid_y_lo_m : res.contact_y_min_m;
  const double y_hi = fixed ? options.fixed_grid_y_hi_m : res.contact_y_max_m;
  const double half_y = (y_hi - y_lo) / 2;
  res.grid_y0_m = (y_lo + y_hi) / 2;
  patch.grid = make_grid(half_x, half_y, spec);
  const Grid& g = patch.grid;
  patch.half_length_m = Eigen::ArrayXd::Zero(g.ny);
  patch.strip_peak_Pa = Eigen::ArrayXd::Zero(g.ny);
  Eigen::ArrayXd row_load_N = Eigen::ArrayXd::Zero(g.ny);
  bool centre_in_contact = false;
  const double line_load_per_g = ev.p0 * (kPi / 2) / std::sqrt(ev.t * ev.A_mod);  // (pi/2) p a = this * g
  Solver::March rows(gap, ev.t), centres(gap, ev.t), ends(gap, ev.t);
  double below = rows.integral_to(y_lo);
  std::size_t node = 0;  // the first gap node right of the current row's left edge
  double yl = y_lo;
  for (int j = 0; j < g.ny; ++j) {
    const double yr = j + 1 == g.ny ? y_hi : res.grid_y0_m + g.y_edge(j + 1);
    const double upto = rows.integral_to(yr);
    const double g_mean = (upto - below) / (yr - yl);
    row_load_N(j) = line_load_per_g * (upto - below);
    below = upto;
    // g's largest value on [yl, yr]: at an end or at a node (g is piecewise linear)
    double g_max = ends.g_at(yl);
    g_max = std::max(g_max, ends.g_at(yr));
    while (node < gap.y.size() && gap.y[node] <= yl) ++node;
    for (; node < gap.y.size() && gap.y[node] < yr; ++node) g_max = std::max(g_max, ev.t - gap.h[node]);
    yl = yr;
    const double g_centre = centres.g_at(res.grid_y0_m + g.y_m(j));
    centre_in_contact = centre_in_contact || g_centre > 0;
    if (g_mean > 0 && g_max > 0)
      patch.half_length_m(j) = std::sqrt(std::max(g_centre, g_mean * g_mean / g_max) / ev.A_mod);
    else
      row_load_N(j) = 0;  // a row between patches (its integral is rounding)
  }
  // a grid none of whose strip centres lies in the contact cannot resolve it (the wear loop refines)
  if (!centre_in_contact)
    throw NoStripCentreError("semi-Hertz: no strip centre lies in the contact: ny " + std::to_string(g.ny) +
                             " is too small for its " + std::to_string(res.patches) + " patches");
  return row_load_N;
}

// the equivalent ellipse for Kalker's coefficients: b half the contact's width, a = area / (pi b)
void fill_equivalent_ellipse(const Gap& gap, const Evaluation& ev, ContactPatch& patch) {
  double width = 0, area = 0;
  for (const ContactRun& run : ev.runs) {
    width += run.r - run.l;
    const std::size_t s0 = run.i0 == 0 ? 0 : static_cast<std::size_t>(run.i0 - 1);
    const std::size_t s1 = std::min(static_cast<std::size_t>(run.i1 + 1), gap.y.size() - 1);
    for (std::size_t s = s0; s < s1; ++s)
      area += 2 * sqrt_segment(gap.y[s], gap.y[s + 1], ev.t - gap.h[s], ev.t - gap.h[s + 1]) / std::sqrt(ev.A_mod);
  }
  patch.b_m = width / 2;
  patch.a_m = area / (kPi * patch.b_m);
}

}  // namespace

double hertz_lateral_epsilon(double A_per_m, double B_per_m) {
  if (!(A_per_m > 0) || !(B_per_m > 0))
    throw std::invalid_argument("hertz_lateral_epsilon: curvatures must be positive, got A " + num(A_per_m) +
                                " 1/m, B " + num(B_per_m) + " 1/m");
  return ellipse_table().eps_y(A_per_m, B_per_m);
}

Eigen::ArrayXd heathcote_xi_offset(const Profiles& profiles, double Rx1_m, double Rx2_m, const Eigen::ArrayXd& y_m,
                                   double reference_y_m) {
  const double c1 = curvature_per_m(Rx1_m, "Rx1"), c2 = curvature_per_m(Rx2_m, "Rx2");
  const double z1_ref = profile_z(profiles.body1, reference_y_m), z2_ref = profile_z(profiles.body2, reference_y_m);
  const std::size_t n = static_cast<std::size_t>(y_m.size());
  Eigen::ArrayXd z1(y_m.size()), z2(y_m.size());
  const bool increasing = n < 2 || (y_m.tail(y_m.size() - 1) > y_m.head(y_m.size() - 1)).all();
  if (increasing && n > 0) {  // march (after profile_z has checked both ends against the extents)
    for (const Profile* p : {&profiles.body1, &profiles.body2}) {
      profile_z(*p, y_m(0));
      profile_z(*p, y_m(y_m.size() - 1));
    }
    sample_profile(profiles.body1, y_m.data(), n, z1.data());
    sample_profile(profiles.body2, y_m.data(), n, z2.data());
  } else {
    for (Eigen::Index j = 0; j < y_m.size(); ++j) {
      z1(j) = profile_z(profiles.body1, y_m(j));
      z2(j) = profile_z(profiles.body2, y_m(j));
    }
  }
  return (z1 - z1_ref) * c1 - (z2 - z2_ref) * c2;
}

SemiHertzResult solve_semi_hertz(const Profiles& profiles, double Rx1_m, double Rx2_m, const ElasticPair& pair,
                                 double normal_load_N, const GridSpec& spec, const SemiHertzOptions& options) {
  const double A = checked_rolling_curvature(profiles, Rx1_m, Rx2_m, pair, normal_load_N, spec, options);
  const double Estar = effective_modulus_Pa(pair), F = normal_load_N;
  const Gap gap = make_gap(profiles);
  Solver solver(gap, A, Estar, options.quadrature_cells, options.kp_epsilon, options.galerkin_points);

  // the approach from the load by the self-consistent rule; where its F(delta) jumps across the load
  // (lobes merging: finding 6b, and the fixed point of eps) no approach carries the load by it, and the
  // continuous rule takes over from the bracket (semi_hertz.h, docs/semi-hertz.md)
  double eps = 0.5;
  double delta = options.initial_approach_m > 0 ? options.initial_approach_m : first_approach(solver, A, F, Estar, eps);
  SemiHertzResult res;
  res.rule = rule_of(options);
  ApproachSearch search =
      find_approach(solver, F, delta, eps, options.max_iterations, options, res.rule, options.initial_slope);
  int evaluations = search.evaluations;
  std::string remedy;
  if (res.rule == ApproachRule::SelfConsistent && !search.converged && search.bracketed()) {
    remedy = "; by the continuous rule: with the self-consistent one " + jump_text(search);
    res.rule = ApproachRule::Continuous;
    search = find_approach(solver, F, std::sqrt(search.lo * search.hi), search.ev.eps,
                           options.max_iterations, options, res.rule);
    evaluations += search.evaluations;
  }
  const Evaluation& ev = search.ev;
  describe_approach(search, evaluations, remedy, options, gap, profiles, res);

  // the strips carry their rows' loads, scaled to carry F exactly
  ContactPatch& patch = res.patch;
  Eigen::ArrayXd row_load_N = fill_strips(gap, ev, spec, options, res);
  const Grid& g = patch.grid;
  const double carried_N = row_load_N.sum();  // F(delta), to rounding
  const double scale = F / carried_N;         // exact to rounding (carried = F(delta) within load_rtol)
  ROLLWEAR_ASSERT(ev.p0 > 0 && std::isfinite(ev.p0) && carried_N > 0 && std::isfinite(carried_N),
                  fmt::format("p0 {} Pa, rows carry {} N at delta {} m", ev.p0, carried_N, ev.delta));
  row_load_N *= scale;
  for (int j = 0; j < g.ny; ++j)
    if (patch.half_length_m(j) > 0) patch.strip_peak_Pa(j) = row_load_N(j) / (kPi / 2 * patch.half_length_m(j) * g.dy_m);
  if (options.pressure_fields) fill_strip_pressures(patch);
  fill_equivalent_ellipse(gap, ev, patch);
  patch.p0_Pa = ev.p0 * scale;  // the peak of the field the strips carry (F, not F(delta))
  patch.normal_load_N = F;
  patch.approach_m = ev.delta;
  // per solve: the strips carry the load, no strip's peak is negative or above the field's peak (finding 5)
  ROLLWEAR_ASSERT(std::abs(row_load_N.sum() - F) <= kLoadBalanceRtol * F,
                  fmt::format("the strips carry {} N of {} N", row_load_N.sum(), F));
  ROLLWEAR_ASSERT(patch.strip_peak_Pa.minCoeff() >= 0 && patch.strip_peak_Pa.maxCoeff() <= patch.p0_Pa * (1 + kPeakRtol),
                  fmt::format("strip peaks in [{}, {}] Pa, p0 {} Pa", patch.strip_peak_Pa.minCoeff(),
                              patch.strip_peak_Pa.maxCoeff(), patch.p0_Pa));

  // Heathcote slip per strip, zero at the reference point
  // (linear in the reference's radii: the weighted mean of each reference point's offsets)
  if (options.heathcote_slip) {
    patch.strip_xi_offset = Eigen::ArrayXd::Zero(g.ny);
    for (const ReferencePoint& ref : ev.refs)
      patch.strip_xi_offset += ref.weight * heathcote_xi_offset(profiles, Rx1_m, Rx2_m, res.grid_y0_m + g.y_m, ref.y0);
  }

  spdlog::debug("semi-Hertz: delta {:.6e} m, eps {:.4f}, B_e {:.4e} 1/m, a {:.6e} m, b {:.6e} m, p0 {:.6e} Pa, "
                "{} patch(es), y [{:.6e}, {:.6e}] m, {}",
                res.approach_m, res.epsilon, res.equivalent_B_per_m, patch.a_m, patch.b_m, patch.p0_Pa, res.patches,
                res.contact_y_min_m, res.contact_y_max_m, res.status.message);
  return res;
}

Eigen::ArrayXd semi_hertz_load_N(const Profiles& profiles, double Rx1_m, double Rx2_m, const ElasticPair& pair,
                                 const Eigen::ArrayXd& approach_m, const SemiHertzOptions& options) {
  const double A = checked_rolling_curvature(profiles, Rx1_m, Rx2_m, pair, 1.0, {1, 1}, options);
  const Gap gap = make_gap(profiles);
  Solver solver(gap, A, effective_modulus_Pa(pair), options.quadrature_cells, options.kp_epsilon,
                options.galerkin_points);
  const ApproachRule rule = rule_of(options);
  Eigen::ArrayXd F(approach_m.size());
  for (Eigen::Index k = 0; k < approach_m.size(); ++k) {
    if (!(approach_m(k) > 0))
      throw std::invalid_argument("semi_hertz_load_N: the approach must be positive, got " + num(approach_m(k)) + " m");
    double eps = 0.5;
    F(k) = solver.evaluate(approach_m(k), eps, rule).F;
  }
  return F;
}

SemiHertzResult solve_normal_on_profiles(const Profiles& profiles, double Rx1_m, double Rx2_m, const ElasticPair& pair,
                                         double normal_load_N, const GridSpec& spec, const SemiHertzOptions& options,
                                         double curvature_rtol) {
  // constant curvature on both bodies: Hertz with the fitted radii, centred on the gap's vertex
  const ParabolaFit f1 = fit_parabola(profiles.body1), f2 = fit_parabola(profiles.body2);
  if (has_constant_curvature(f1, curvature_rtol) && has_constant_curvature(f2, curvature_rtol)) {
    const double c = f1.curvature_per_m + f2.curvature_per_m;  // gap's curvature 2B
    const double lo = std::max(profiles.body1.y_m(0), profiles.body2.y_m(0));
    const double hi = std::min(profiles.body1.y_m(profiles.body1.y_m.size() - 1),
                               profiles.body2.y_m(profiles.body2.y_m.size() - 1));
    if (c > 0) {
      // the gap's vertex: where z1' + z2' = 0
      const double y0 = (f1.curvature_per_m * f1.vertex_y_m + f2.curvature_per_m * f2.vertex_y_m) / c;
      const auto radius = [](double curvature) { return curvature == 0 ? kFlat : 1 / curvature; };
      const Bodies bodies{{Rx1_m, radius(f1.curvature_per_m)}, {Rx2_m, radius(f2.curvature_per_m)}};
      const HertzContact h = solve_hertz(bodies, pair, normal_load_N);
      if (y0 - h.b_m > lo && y0 + h.b_m < hi) {
        spdlog::debug("normal problem: both profiles have constant curvature within {:.1e} (Ry1 {:.6g} m, Ry2 {:.6g} m): "
                     "Hertz instead of semi-Hertz",
                     curvature_rtol, bodies.body1.Ry_m, bodies.body2.Ry_m);
        SemiHertzResult res;
        res.patch = hertz_patch(h, make_grid(h.a_m, h.b_m, spec));
        res.grid_y0_m = res.reference_y_m = y0;
        res.contact_y_min_m = y0 - h.b_m;
        res.contact_y_max_m = y0 + h.b_m;
        res.approach_m = h.approach_m;
        res.equivalent_B_per_m = h.B_per_m;
        res.epsilon = hertz_lateral_epsilon(h.A_per_m, h.B_per_m);
        res.patches = 1;
        res.status.kind = SolveStatus::Kind::Converged;
        res.status.message = "constant curvature: Hertz's closed form";
        res.solver = NormalSolverKind::Hertz;
        if (options.heathcote_slip)
          res.patch.strip_xi_offset = heathcote_xi_offset(profiles, Rx1_m, Rx2_m, y0 + res.patch.grid.y_m, y0);
        return res;
      }
    }
  }
  return solve_semi_hertz(profiles, Rx1_m, Rx2_m, pair, normal_load_N, spec, options);
}

}  // namespace contact
