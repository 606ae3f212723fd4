// One interval of the consistent strip march (the derivation is at the top of lib/tangential/steady.cpp):
// from the traction at the upstream node x_hi to the downstream node x_lo, with the integrals of
// the reconstruction over the interval. The steady solver chains it along each strip; Satran's
// shift scheme applies it to the previous step's node values (docs/physics.md §3-4). march_slip_interval
// is its case of a slip node inside the strip with the turn of the slip direction given, so that the
// steady solver's slip stretches can take the turns of all their cells at once (slip_turns). The pieces
// of the stick solution are templates, so that Satran's shift step can take them for a block of
// intervals at once (SIMD). Kalker's test holds on the whole interval, not only at x_lo: with spin the
// stick solution is a parabola that can leave the bound between two nodes (stick_excess, first_crossing),
// and a slip part can stop dissipating inside an interval and stick again (slip_on, restick).
#pragma once

#include <algorithm>
#include <cmath>

#include "lib/patch.h"
#include "lib/numeric.h"
#include "lib/tangential/strip_node.h"
#include "lib/tangential/tangential.h"

namespace contact {

// constants of one strip for one set of creepages; in stick d tau/dx = (alpha, eta_L2 + phi_L3 x)
struct StripRates {
  double a_m = 0, y_m = 0;
  double alpha_Pa_per_m = 0;  // xi_j/L1 - phi y/L3, xi_j including the Heathcote offset
  double eta_L2_Pa_per_m = 0;  // eta/L2
  double phi_L3_Pa_per_m2 = 0;  // phi/L3
  double mu = 0;
  double peak_Pa = 0;   // p_j
  double bound_Pa = 0;  // G = mu p_j, the peak of the traction bound
};

StripRates strip_rates(const ContactPatch& patch, const TangentialProblem& problem, int j);

struct IntervalGeometry {
  double x_hi = 0, x_lo = 0;  // x_hi > x_lo, both within [-a_j, a_j]
  double bound_lo_Pa = 0;     // mu p(x_lo)
  double load_N_per_m = 0;    // integral of p over the interval
  double moment_N = 0;        // integral of x p over the interval
};

struct IntervalSums {
  double Ix = 0, Iy = 0, Ixy = 0;  // integrals of tau_x, tau_y, x tau_y
  double stick_length_m = 0;
  double slip_x = 0, slip_y = 0;   // integral of s/(V L) over the interval (m)
};

// into += s: the sums of a stretch of intervals, or of an interval's parts
inline void add_interval_sums(IntervalSums& into, const IntervalSums& s) {
  into.Ix += s.Ix;
  into.Iy += s.Iy;
  into.Ixy += s.Ixy;
  into.stick_length_m += s.stick_length_m;
  into.slip_x += s.slip_x;
  into.slip_y += s.slip_y;
}

// -integral(tau . s dx) / (V L) of an interval: zero in stick, telescoping along a strip
inline double dissipation_per_VL(const StripRates& r, const StripNode& hi, const StripNode& lo,
                                 const IntervalSums& s) {
  return -(r.alpha_Pa_per_m * s.Ix + r.eta_L2_Pa_per_m * s.Iy + r.phi_L3_Pa_per_m2 * s.Ixy) +
         ((hi.tx * hi.tx + hi.ty * hi.ty) - (lo.tx * lo.tx + lo.ty * lo.ty)) / 2;
}

// -integral(tau . c dx) / (V L)
inline double creep_power_per_VL(const StripRates& r, const IntervalSums& s) {
  return -(r.alpha_Pa_per_m * s.Ix + r.eta_L2_Pa_per_m * s.Iy + r.phi_L3_Pa_per_m2 * s.Ixy);
}

namespace detail {

// The stick solution from tau = (tx, ty) at x_hi, with t = x_hi - x (docs/physics.md §3):
//   tau_x = tx - alpha t,  tau_y = ty - beta t + gamma t^2,  beta = eta/L2 + (phi/L3) x_hi, gamma = phi/(2 L3).
// Over an interval [x_hi - t, x_hi], the terms that involve neither tau at x_hi nor alpha (which varies
// with y) are the same on every strip: the interval's StickGeometry and StickMoments. T is double for
// one interval, or an Eigen array for a block of intervals (G: of the geometry, which may be a map of
// it): the same arithmetic lane by lane, so a block gives each interval's values to the bit.

// beta = d tau_y/dx at x_hi
template <class T>
[[gnu::always_inline]] inline T stick_beta(const StripRates& r, const T& x_hi) {
  return r.eta_L2_Pa_per_m + r.phi_L3_Pa_per_m2 * x_hi;
}

// the terms beta t and gamma t^2 of the prediction at x_lo
template <class T>
struct StickGeometry {
  T beta_t, gamma_t2;
};

template <class T>
[[gnu::always_inline]] inline StickGeometry<T> stick_geometry(const StripRates& r, const T& beta, const T& t) {
  return {beta * t, r.phi_L3_Pa_per_m2 / 2 * t * t};
}

// the terms t^2/2, beta t^2/2, gamma t^3/3, beta t^3/3 and gamma t^4/4 of the integrals
template <class T>
struct StickMoments {
  T t2_2, beta_t2_2, gamma_t3_3, beta_t3_3, gamma_t4_4;
};

template <class T>
[[gnu::always_inline]] inline StickMoments<T> stick_moments(const T& beta, double gamma, const T& t) {
  const T t2 = t * t, t3 = t2 * t;
  return {t2 / 2, beta * t2 / 2, gamma * t3 / 3, beta * t3 / 3, gamma * t3 * t / 4};
}

// the prediction at x_lo
template <class T>
struct StickPrediction {
  T px, py;
};

template <class T, class G>
[[gnu::always_inline]] inline StickPrediction<T> stick_prediction(double alpha, const T& tx, const T& ty, const G& t,
                                                                  const StickGeometry<G>& g) {
  return {tx - alpha * t, ty - g.beta_t + g.gamma_t2};
}

// the exact integrals of tau_x, tau_y and x tau_y over the interval
template <class T>
struct StickIntegrals {
  T Ix, Iy, Ixy;
};

template <class T, class G>
[[gnu::always_inline]] inline StickIntegrals<T> stick_integrals(double alpha, const T& tx, const T& ty, const G& x_hi,
                                                                const G& t, const StickMoments<G>& m) {
  const T iy = ty * t - m.beta_t2_2 + m.gamma_t3_3;
  return {tx * t - alpha * m.t2_2, iy, x_hi * iy - (ty * m.t2_2 - m.beta_t3_3 + m.gamma_t4_4)};
}

// exact stick solution over t = x_hi - x in [0, t] from tau at x_hi
[[gnu::always_inline]] inline void add_stick(const StripRates& r, const StripNode& hi, double x_hi, double beta, double gamma,
                      double t, IntervalSums& s) {
  const StickIntegrals<double> I =
      stick_integrals(r.alpha_Pa_per_m, hi.tx, hi.ty, x_hi, t, stick_moments(beta, gamma, t));
  s.Ix += I.Ix;
  s.Iy += I.Iy;
  s.Ixy += I.Ixy;
  s.stick_length_m += t;
}

// Kalker's test on the whole interval. Over s = t/h in [0, 1] the stick solution is
//   tau(s) = tau_hi - D s + Gm s^2 e_y,  D = (alpha h, beta h),  Gm = gamma h^2,
// and the bound of the semi-ellipse g = G sqrt(1 - x^2/a^2), x = x_hi - h s, has
//   g^2(s) = g_hi^2 + 2 k x_hi h s - k h^2 s^2,  k = G^2/a^2,
// so the excess F(s) = |tau|^2 - g^2 is a quartic in s:
//   F = d0 + d1 s + d2 s^2 + d3 s^3 + d4 s^4,  d0 = |tau_hi|^2 - g_hi^2,
//   d1 = -2 (tau_hi . D) - 2 k x_hi h,  d2 = |D|^2 + 2 tau_y,hi Gm + k h^2,  d3 = -2 D_y Gm,  d4 = Gm^2.
// The interval sticks if F <= 0 on all of [0, 1]. Without spin (Gm = 0) F is a convex quadratic
// (d2 > 0), so F <= 0 at both nodes means F <= 0 in between: Kalker's test at x_lo is the whole test.
// With spin it is not, and F is tested in Bernstein form on [0, 1], whose coefficients
//   b0 = d0, b1 = d0 + d1/4, b2 = d0 + d1/2 + d2/6, b3 = d0 + 3 d1/4 + d2/2 + d3/4, b4 = F(1)
// bound F from above (F is a convex combination of them): b1, b2, b3 <= 0 with the node tests (b0, b4)
// is a sufficient pass, exact to rounding in the cases that matter. Where it fails, first_crossing
// finds the first s where F > 0 by subdividing (de Casteljau) and a bracketed Newton step.
// The upstream node lies within its bound (a slip node on it, to rounding): d0 is taken as min(d0, 0),
// and as 0 for a slip node on the bound (spin_sticks), so that the test asks only whether the stick
// solution leaves the bound after x_hi.

// the strip's bound as a quadratic in x: g^2 = G2 - k x^2
struct BoundQuadratic {
  double G2 = 0, k = 0;  // G^2 = (mu p_j)^2 (Pa^2), k = G^2/a^2 (Pa^2/m^2)
};

inline BoundQuadratic bound_quadratic(const StripRates& r) {
  const double G2 = r.bound_Pa * r.bound_Pa;
  return {G2, r.a_m > 0 ? G2 / (r.a_m * r.a_m) : 0.0};
}

// min(v, 0) and max(a, b), lane by lane for an Eigen array of a block (SIMD min and max: they may differ
// from the scalar ones in the sign of a zero, which no test below sees)
[[gnu::always_inline]] inline double nonpositive(double v) { return v > 0 ? 0.0 : v; }
template <class D>
[[gnu::always_inline]] inline auto nonpositive(const Eigen::ArrayBase<D>& v) {
  using A = typename D::PlainObject;
  return A(v.min(0.0));
}
[[gnu::always_inline]] inline double larger(double a, double b) { return a < b ? b : a; }
template <class D>
[[gnu::always_inline]] inline auto larger(const Eigen::ArrayBase<D>& a, const Eigen::ArrayBase<D>& b) {
  using A = typename D::PlainObject;
  return A(a.max(b));
}

// the excess F(s) = |tau|^2 - g^2 of the stick solution over an interval: its power coefficients
template <class T>
struct StickExcess {
  T d0, d1, d2, d3, d4;  // F(s) = d0 + d1 s + d2 s^2 + d3 s^3 + d4 s^4, d0 <= 0
};

template <class T, class G>
[[gnu::always_inline]] inline StickExcess<T> stick_excess(double alpha, const BoundQuadratic& q, const T& tx,
                                                          const T& ty, const G& x_hi, const G& h,
                                                          const StickGeometry<G>& sg) {
  const T Dx = alpha * h, Dy = sg.beta_t, Gm = sg.gamma_t2;
  const T g_hi2 = q.G2 - q.k * x_hi * x_hi;
  const T d0 = tx * tx + ty * ty - g_hi2;
  return {nonpositive(d0), -2.0 * (tx * Dx + ty * Dy) - 2.0 * q.k * x_hi * h,
          Dx * Dx + Dy * Dy + 2.0 * ty * Gm + q.k * h * h, -2.0 * Dy * Gm, Gm * Gm};
}

// the largest of the Bernstein coefficients b1, b2, b3 of F on [0, 1]: <= 0 means F <= max(b0, b4)
template <class T>
[[gnu::always_inline]] inline T hull_excess(const StickExcess<T>& e) {
  const T b1 = e.d0 + e.d1 * 0.25;
  const T b2 = e.d0 + e.d1 * 0.5 + e.d2 * (1.0 / 6);
  const T b3 = e.d0 + e.d1 * 0.75 + e.d2 * 0.5 + e.d3 * 0.25;
  return larger(b1, larger(b2, b3));
}

constexpr double kNoCrossing = 2;  // first_crossing: F <= 0 on all of [0, 1]

// The first s in [0, 1] where F > 0 (kNoCrossing if none, to rounding). F(0) = d0 <= 0. Pieces of
// [0, 1] are taken from the left: a piece whose Bernstein coefficients are all <= 0 has F <= 0; a piece
// whose coefficients increase (F increasing) or are convex (F convex), with F <= 0 at its left end and
// > 0 at its right end, holds one root, the first crossing, found by Newton's method kept inside the
// bracket; any other piece is halved.
[[gnu::noinline]] inline double first_crossing(const StickExcess<double>& e) {
  const double d[5] = {e.d0, e.d1, e.d2, e.d3, e.d4};
  // on the bound at s = 0: the first nonzero term says whether F rises at once
  if (d[0] == 0) {
    for (int i = 1; i < 5; ++i)
      if (d[i] != 0) {
        if (d[i] > 0) return 0;
        break;
      }
  }
  auto F = [&](double s) { return d[0] + s * (d[1] + s * (d[2] + s * (d[3] + s * d[4]))); };
  auto dF = [&](double s) { return d[1] + s * (2 * d[2] + s * (3 * d[3] + s * 4 * d[4])); };
  // the rounding of F(s): F is 0 within it
  auto F_rounding = [&](double s) {
    const double size = std::abs(d[3]) + s * std::abs(d[4]);
    return 8e-16 * (std::abs(d[0]) + s * (std::abs(d[1]) + s * (std::abs(d[2]) + s * size)));
  };
  // the root of F in (lo, hi], F(lo) <= 0 < F(hi), F's only one there; Newton's method starts from the
  // root of F's quadratic part (the crossing without spin) where that lies inside the bracket
  auto root = [&](double lo, double hi) {
    if (F(lo) > 0) return lo;
    if (F(hi) <= 0) return hi;
    double s = hi;
    if (d[2] > 0) {
      const double q = std::sqrt(std::max(0.0, d[1] * d[1] - 4 * d[2] * d[0]));
      const double s_q = d[1] <= 0 ? (-d[1] + q) / (2 * d[2]) : (-2 * d[0]) / (d[1] + q);
      if (s_q > lo && s_q < hi) s = s_q;
    }
    for (int it = 0; it < 100; ++it) {
      const double f = F(s);
      if (std::abs(f) <= F_rounding(s)) return s;
      if (f > 0) {
        hi = s;
      } else {
        lo = s;
      }
      const double slope = dF(s);
      double next = slope > 0 ? s - f / slope : lo + (hi - lo) / 2;
      if (!(next > lo && next < hi)) next = lo + (hi - lo) / 2;
      if (std::abs(next - s) <= 4e-16 * next || hi - lo <= 4e-16 * hi) return next;
      s = next;
    }
    return s;
  };

  struct Piece {
    double s0, s1, b[5];
    int depth;
  };
  constexpr int kMaxDepth = 48;  // a piece of 2^-48: a tangency within rounding
  Piece stack[kMaxDepth + 2];
  int n = 0;
  stack[n++] = {0, 1,
                {d[0], d[0] + d[1] * 0.25, d[0] + d[1] * 0.5 + d[2] * (1.0 / 6),
                 d[0] + d[1] * 0.75 + d[2] * 0.5 + d[3] * 0.25, d[0] + d[1] + d[2] + d[3] + d[4]},
                0};
  while (n > 0) {
    const Piece p = stack[--n];
    const double* b = p.b;
    if (std::max({b[0], b[1], b[2], b[3], b[4]}) <= 0) continue;  // F <= 0 on the piece
    const bool rising = b[0] <= b[1] && b[1] <= b[2] && b[2] <= b[3] && b[3] <= b[4];
    const bool convex = b[2] - b[1] >= b[1] - b[0] && b[3] - b[2] >= b[2] - b[1] && b[4] - b[3] >= b[3] - b[2];
    if (b[4] > 0 && (rising || convex || p.depth >= kMaxDepth)) return root(p.s0, p.s1);
    if (p.depth >= kMaxDepth) continue;
    // halve (de Casteljau): the left piece is taken first
    Piece left{p.s0, (p.s0 + p.s1) / 2, {}, p.depth + 1}, right{left.s1, p.s1, {}, p.depth + 1};
    double w[5] = {b[0], b[1], b[2], b[3], b[4]};
    left.b[0] = w[0];
    right.b[4] = w[4];
    for (int level = 1; level <= 4; ++level) {
      for (int i = 0; i + level <= 4; ++i) w[i] = (w[i] + w[i + 1]) / 2;
      left.b[level] = w[0];
      right.b[4 - level] = w[4 - level];
    }
    stack[n++] = right;
    stack[n++] = left;
  }
  return kNoCrossing;
}

// the direction in which the stick solution leaves t: tau(t) = (tx, ty), or where that is 0, its
// first derivative in t that is not
[[gnu::noinline]] inline void leaving_direction(double alpha, double beta, double gamma, double t, double tx,
                                                double ty, double& ex, double& ey) {
  double vx = tx, vy = ty;
  if (vx == 0 && vy == 0) {
    vx = -alpha;
    vy = -beta + 2 * gamma * t;
  }
  if (vx == 0 && vy == 0) vy = gamma;
  const double n = std::sqrt(vx * vx + vy * vy);
  ex = vx / n;
  ey = vy / n;
}

// the turn of the slip direction over a slip part: 1/|d| and the factor k = exp(-|d| integral ds/g)
// by which tan(psi/2) decays
struct SlipTurn {
  double inv_dn = 0, k = 1;
};

// asin of u clamped to [-1, 1], +-pi/2 at the ends without a call
[[gnu::always_inline]] inline double clamped_asin(double u) {
  return u >= 1 ? kPi / 2 : u <= -1 ? -kPi / 2 : std::asin(u);
}

// u = x/a on the unit semi-ellipse, clamped to [-1, 1], with asin u and sqrt(1 - u^2) computed once for
// the integrals of ds/g, p and x p (the same arithmetic as semi_ellipse_integral, semi_ellipse_moment)
struct EllipsePoint {
  double u, w, asin_u;
  explicit EllipsePoint(double x_over_a)
      : u(std::clamp(x_over_a, -1.0, 1.0)), w(std::sqrt(1 - u * u)), asin_u(clamped_asin(x_over_a)) {}
  double integral() const { return (u * w + asin_u) / 2 + kPi / 4; }  // of sqrt(1 - u^2) from -1
  double moment() const {                                               // of u sqrt(1 - u^2) from -1
    const double w2 = 1 - u * u;
    return -w2 * w / 3;
  }
};

// the turn over a slip part with d = (alpha, dy_m) and the integral inv_g of ds/g over it
[[gnu::always_inline]] inline SlipTurn slip_turn(double alpha, double dy_m, double inv_g) {
  const double dn = std::sqrt(alpha * alpha + dy_m * dy_m);
  return {1 / dn, std::exp(-dn * inv_g)};
}

// the integral of ds/g over [x_lo, x_s] inside the strip by the midpoint rule
[[gnu::always_inline]] inline double midpoint_inv_g(const StripRates& r, double x_s, double x_lo) {
  const double um = (x_s + x_lo) / (2 * r.a_m);
  return (x_s - x_lo) / (r.bound_Pa * std::sqrt(1 - um * um));
}

// d_y at the midpoint of [x_lo, x_s], written from x_hi as the march writes it
[[gnu::always_inline]] inline double midpoint_dy(const StripRates& r, double x_hi, double x_s, double x_lo) {
  const double beta = r.eta_L2_Pa_per_m + r.phi_L3_Pa_per_m2 * x_hi;  // d tau_y/dx at x_hi
  return beta + r.phi_L3_Pa_per_m2 * ((x_s + x_lo) / 2 - x_hi);
}

// the turn over an interval strictly inside the strip that slips throughout
[[gnu::always_inline]] inline SlipTurn interior_slip_turn(const StripRates& r, double x_hi, double x_lo) {
  return slip_turn(r.alpha_Pa_per_m, midpoint_dy(r, x_hi, x_hi, x_lo), midpoint_inv_g(r, x_hi, x_lo));
}

// the slip direction at the end of a slip part that starts along e0 = (ex0, ey0), with u = -d = (ux, uy)
// (not normalised) frozen over it and its turn t: d psi/ds = -|d| sin(psi)/g solved exactly,
// tan(psi/2) decaying by t.k; s0u = u x e0 (!= 0: e0 is not along u, else e stays e0)
[[gnu::always_inline]] inline void turned_direction(double ex0, double ey0, double ux, double uy, double s0u,
                                                    const SlipTurn& t, double& ex, double& ey) {
  const double c0 = (ex0 * ux + ey0 * uy) * t.inv_dn, s0 = s0u * t.inv_dn;
  const double c1 = 1 + c0, ks = t.k * s0;
  const double norm = c1 * c1 + ks * ks;
  if (norm > 1e-300) {
    const double scale = t.inv_dn / norm;
    const double A = (c1 * c1 - ks * ks) * scale, B = 2 * ks * c1 * scale;
    ex = A * ux - B * uy;
    ey = A * uy + B * ux;
  }
}

// the slip part of an interval, from x_s = x_hi - t_s (traction tau0, direction e0) to x_lo, with
// d = (alpha, dy_m) frozen at its midpoint and Ip, Ixp the integrals of p and x p over it; turn() gives
// its SlipTurn, asked for only when e0 turns
template <class TurnFn>
[[gnu::always_inline]] inline StripNode slip_part(const StripRates& r, const IntervalGeometry& geo,
                                                  double t_s, double dy_m, double tx0, double ty0, double ex0,
                                                  double ey0, double Ip, double Ixp, TurnFn&& turn,
                                                  IntervalSums& s) {
  const double x_s = geo.x_hi - t_s, x_lo = geo.x_lo, hs = x_s - x_lo;
  const double alpha = r.alpha_Pa_per_m;

  // slip direction at x_lo: d psi/ds = -|d| sin(psi)/g exactly, d frozen at the midpoint
  double ex = ex0, ey = ey0;
  const double ux = -alpha, uy = -dy_m;  // -d, not yet normalised
  const double s0u = ux * ey0 - uy * ex0;
  if (s0u != 0 && r.bound_Pa > 0) turned_direction(ex0, ey0, ux, uy, s0u, turn(), ex, ey);
  const StripNode lo{geo.bound_lo_Pa * ex, geo.bound_lo_Pa * ey, ex, ey, false};

  // |tau| = mu p exactly over the slip part, direction the mean of its end directions
  const double mx = r.mu * (ex0 + ex) / 2, my = r.mu * (ey0 + ey) / 2;
  s.Ix += mx * Ip;
  s.Iy += my * Ip;
  s.Ixy += my * Ixp;
  // integral of s/(V L) = d - dtau/dx over the slip part
  s.slip_x += alpha * hs - (tx0 - lo.tx);
  s.slip_y += r.eta_L2_Pa_per_m * hs + r.phi_L3_Pa_per_m2 * (x_s * x_s - x_lo * x_lo) / 2 - (ty0 - lo.ty);
  return lo;
}

}  // namespace detail

namespace detail {

// the stick prediction at x_lo from tau at x_hi; Kalker's rule: the node sticks if the prediction
// lies inside the bound, and then, if the stick solution stays inside it over the whole interval (a
// question only with spin), the whole interval sticks (its integrals are added to s)
struct StickStep {
  double beta = 0, gamma = 0;  // d tau_y/dx at x_hi, and half the curvature of tau_y
  double px = 0, py = 0;       // the prediction at x_lo
  bool node = false;           // Kalker's test at x_lo passes
  bool stick = false;          // the interval sticks throughout
  double s_cross = -1;         // with spin, where it does not: the first crossing (x_hi - x_s)/h, 0 for a
                               // slip that goes on, > 1 for none found; -1: not asked (stick_then_slip)
};

// a slip node on its bound, to rounding (d0 of stick_excess); a slip node can lie inside it where a
// transient rescales tau (Satran, when L changes), and it then sticks like a stick node
constexpr double kOnBound = 1e-12;  // of G^2

template <class T>
[[gnu::always_inline]] inline auto on_bound(const T& d0, const BoundQuadratic& q) {
  return d0 >= -kOnBound * q.G2;
}

// What spin_sticks decides for an interval from a slip node, short of first_crossing: it sticks
// throughout (kSticks), its slip goes on (kSlips: slip_throughout), or the whole kernel must look
// (kKernel). node: Kalker's test at x_lo passed. Where it did not, d0 and d1 settle it.
enum class SlipNodeStep { kSticks, kSlips, kKernel };
[[gnu::always_inline]] inline SlipNodeStep slip_node_step(const StripRates& r, const BoundQuadratic& q,
                                                          const StripNode& hi, double x_hi, double h,
                                                          const StickGeometry<double>& sg, bool node) {
  if (!node) {  // d0 and d1 alone, as stick_excess has them
    const double Dx = r.alpha_Pa_per_m * h, Dy = sg.beta_t;
    const double d0 = nonpositive(hi.tx * hi.tx + hi.ty * hi.ty - (q.G2 - q.k * x_hi * x_hi));
    const double d1 = -2.0 * (hi.tx * Dx + hi.ty * Dy) - 2.0 * q.k * x_hi * h;
    return on_bound(d0, q) && d1 > 0 ? SlipNodeStep::kSlips : SlipNodeStep::kKernel;
  }
  StickExcess<double> e = stick_excess(r.alpha_Pa_per_m, q, hi.tx, hi.ty, x_hi, h, sg);
  const bool slipping = on_bound(e.d0, q);
  if (slipping) e.d0 = 0;
  if (hull_excess(e) <= 0) return SlipNodeStep::kSticks;
  if (slipping && e.d1 > 0) return SlipNodeStep::kSlips;
  return SlipNodeStep::kKernel;
}

// Spin, Kalker's test on the whole interval, asked where the node test passes or the upstream node
// slips. A slip node on the bound has d0 = 0, and F'(0) = d1 = 2 h g (g' - e . d) is the slip's
// dissipation density there: the slip goes on while it is positive; where it is not, the material
// sticks again at x_hi, and the stick solution is followed to its first crossing (possibly through
// the inside of the bound to its other side), as from a stick node.
[[gnu::noinline]] inline bool spin_sticks(const StripRates& r, const StripNode& hi, double x_hi, double h,
                                          const StickGeometry<double>& sg, StickStep& k) {
  const BoundQuadratic q = bound_quadratic(r);
  if (!hi.stick) {
    const SlipNodeStep step = slip_node_step(r, q, hi, x_hi, h, sg, k.node);
    if (step == SlipNodeStep::kSticks) return true;
    if (step == SlipNodeStep::kSlips) {
      k.s_cross = 0;
      return false;
    }
  }
  StickExcess<double> e = stick_excess(r.alpha_Pa_per_m, q, hi.tx, hi.ty, x_hi, h, sg);
  if (!hi.stick && on_bound(e.d0, q)) e.d0 = 0;
  if (hi.stick && k.node && hull_excess(e) <= 0) return true;
  k.s_cross = first_crossing(e);
  return k.node && k.s_cross > 1;
}

// Kalker's test for the interval from hi: at x_lo, and with spin (kSpin, gamma != 0) on its interior
template <bool kSpin>
[[gnu::always_inline]] inline StickStep stick_step(const StripRates& r, const StripNode& hi, const IntervalGeometry& geo,
                                                   IntervalSums& s) {
  const double x_hi = geo.x_hi, h = x_hi - geo.x_lo;
  StickStep k;
  k.beta = stick_beta(r, x_hi);
  const StickGeometry<double> sg = stick_geometry(r, k.beta, h);
  const StickPrediction<double> p = stick_prediction(r.alpha_Pa_per_m, hi.tx, hi.ty, h, sg);
  k.gamma = r.phi_L3_Pa_per_m2 / 2;
  k.px = p.px;
  k.py = p.py;
  k.node = k.px * k.px + k.py * k.py <= geo.bound_lo_Pa * geo.bound_lo_Pa;
  k.stick = k.node;
  if constexpr (kSpin) {
    if (k.node || !hi.stick) k.stick = spin_sticks(r, hi, x_hi, h, sg, k);
  }
  if (k.stick) add_stick(r, hi, x_hi, k.beta, k.gamma, h, s);
  return k;
}

}  // namespace detail

// With spin the march asks more of each interval (detail::spin_sticks); it is compiled for both cases,
// chosen once for a problem (phi/L3 is the same on every strip), so that without spin it does nothing more.
inline bool has_spin(const StripRates& r) { return r.phi_L3_Pa_per_m2 / 2 != 0; }

namespace detail {

// ---- spin: a slip part that stops dissipating sticks again inside the interval ("restick") ----
// On a slip part tau = g e, and s = V L (d - dtau/dx) = -V L lambda e with lambda = g' - e . d (g' = dg/dx,
// d = (alpha, eta/L2 + phi x/L3)): the slip's dissipation density is -tau . s = V L g lambda. It is >= 0
// while the part slips; where it falls to 0, the slip stops and the material sticks again. With g^2 =
// G^2 - k x^2, g g' = -k x, so
//   g lambda = -k x - g e . d(x),
// and at a slip node d1 of stick_excess is 2 h times it (the stick solution leaves the bound at once
// while it is > 0). Without spin it cannot fall to 0 downstream: d is constant, e turns towards -d (e . d
// falls) and g' grows downstream (g is concave), so lambda grows. With spin d_y turns along the strip.

// g lambda at x on the bound g, along e (Pa^2/m)
[[gnu::always_inline]] inline double slip_density(const StripRates& r, const BoundQuadratic& q, double x, double g,
                                                  double ex, double ey) {
  return -q.k * x - g * (r.alpha_Pa_per_m * ex + (r.eta_L2_Pa_per_m + r.phi_L3_Pa_per_m2 * x) * ey);
}

// A slip part from x_c (traction tau_c, direction e_c) towards x_end < x_c, with d frozen at the midpoint
// x_m of [x_end, x_c] (u = -d_m) and the exact integrals of ds/g, p and x p: its direction e(x) at any x in
// between (tan(psi/2) decays with the integral of ds/g from x_c, psi the angle between e and u), and its
// density g lambda there with the exact d(x). A part ended at x (slip_to) ends along e(x), the same
// arithmetic, so that where the root finder saw the slip stop, the part ends on it.
struct SlipPath {
  const StripRates& r;
  BoundQuadratic q;
  double x_c, tx_c, ty_c, ex_c, ey_c;
  double x_m, dy_m, ux, uy, s0u;
  EllipsePoint pc;

  SlipPath(const StripRates& rates, const BoundQuadratic& bq, double x, double tx, double ty, double ex, double ey,
           double x_end)
      : r(rates), q(bq), x_c(x), tx_c(tx), ty_c(ty), ex_c(ex), ey_c(ey), x_m((x + x_end) / 2),
        dy_m(midpoint_dy(rates, x, x, x_end)), ux(-rates.alpha_Pa_per_m), uy(-dy_m), s0u(ux * ey - uy * ex),
        pc(x / rates.a_m) {}

  SlipTurn turn(const EllipsePoint& px) const {
    return slip_turn(r.alpha_Pa_per_m, dy_m, r.a_m / r.bound_Pa * (pc.asin_u - px.asin_u));
  }
  struct Point {
    double x, g, ex, ey, density;
  };
  Point at(double x) const {
    const EllipsePoint px(x / r.a_m);
    Point p{x, r.bound_Pa * px.w, ex_c, ey_c, 0};
    if (s0u != 0 && r.bound_Pa > 0) turned_direction(ex_c, ey_c, ux, uy, s0u, turn(px), p.ex, p.ey);
    p.density = slip_density(r, q, x, p.g, p.ex, p.ey);
    return p;
  }
  // A lower bound of lambda = density/g on [x_b, x_a] from its upper end a: there g' >= g'(x_a) (g is
  // concave), -e . d_m = |d_m| cos psi >= its value at x_a (|psi| only falls downstream), and
  // -e . (d - d_m) >= -|phi/L3| |x - x_m|. Without a bound at x_a (g = 0) -infinity.
  double lambda_below(const Point& a, double x_b) const {
    if (!(a.g > 0)) return -HUGE_VAL;
    const double spread = std::max(std::abs(a.x - x_m), std::abs(x_b - x_m));
    return -q.k * a.x / a.g + (ux * a.ex + uy * a.ey) - std::abs(r.phi_L3_Pa_per_m2) * spread;
  }
  // the part from x_c down to x_e, ending on the bound g_e there (sums added to s)
  StripNode slip_to(double x_e, double g_e, IntervalSums& s) const {
    const EllipsePoint pe(x_e / r.a_m);
    const double a = r.a_m;
    IntervalGeometry geo;
    geo.x_hi = x_c;
    geo.x_lo = x_e;
    geo.bound_lo_Pa = g_e;
    const double Ip = r.peak_Pa * a * (pc.integral() - pe.integral());
    const double Ixp = r.peak_Pa * a * a * (pc.moment() - pe.moment());
    return slip_part(r, geo, 0.0, dy_m, tx_c, ty_c, ex_c, ey_c, Ip, Ixp, [&] { return turn(pe); }, s);
  }
};

// Where a slip part's density first falls below 0 on (x_lo, x_c): a bracket [b, a], density(a) >= 0 >
// density(b), or false if it stays >= 0. Pieces of the part are taken from upstream: a piece whose lower
// bound of lambda (lambda_below) is >= 0 slips on throughout; any other is halved, down to 2^-kStopDepth of
// the part, and the first piece of that size whose lower end's density is < 0 is the bracket. (A dip below
// 0 between two samples 2^-kStopDepth of the part apart is not looked for.)
constexpr int kStopDepth = 5;
inline bool slip_stop_bracket(const SlipPath& path, double x_lo, SlipPath::Point& a, SlipPath::Point& b) {
  struct Piece {
    SlipPath::Point hi, lo;
    int depth;
  };
  Piece stack[kStopDepth + 2];
  int n = 0;
  stack[n++] = {path.at(path.x_c), path.at(x_lo), 0};
  if (stack[0].hi.density < 0) {  // stops at once (rounding): the bracket is the point
    a = b = stack[0].hi;
    return true;
  }
  while (n > 0) {
    const Piece p = stack[--n];
    if (path.lambda_below(p.hi, p.lo.x) >= 0) continue;
    const double x_mid = p.hi.x + (p.lo.x - p.hi.x) / 2;
    if (p.depth >= kStopDepth || !(x_mid < p.hi.x && x_mid > p.lo.x)) {
      if (!(p.lo.density < 0)) continue;
      a = p.hi;
      b = p.lo;
      return true;
    }
    const SlipPath::Point mid = path.at(x_mid);
    stack[n++] = {mid, p.lo, p.depth + 1};  // the lower half after the upper one
    stack[n++] = {p.hi, mid, p.depth + 1};
  }
  return false;
}

// the root of a slip part's density in a bracket [b, a] (density(a) >= 0 > density(b)), to rounding of a_j:
// the end of the final bracket on the side where the density is < 0, so that the part ends where its slip
// has stopped
inline double slip_stop(const SlipPath& path, SlipPath::Point a, SlipPath::Point b) {
  if (!(a.density > 0)) return a.x;
  const RootResult root = find_root_bracketed([&](double x) { return path.at(x).density; }, b.x, a.x, b.density,
                                              a.density, 4e-16 * path.r.a_m);
  return root.lo;  // f(lo) keeps the sign of f(b): the side where the slip has stopped (or the root itself)
}

constexpr int kRestickParts = 4;  // slip parts in one interval, at most (the last one slips on to x_lo)

// A slip part from x_c (tau_c, e_c) to geo.x_lo whose lower bound of lambda (slip_on) did not clear it: where
// its density falls below 0 (slip_stop_bracket) it ends at the root x_r (slip_stop), and the material sticks
// from there. The stick solution from x_r starts on the bound and goes inside it (its excess F has F(0) = 0
// and F'(0) = 2 h g lambda <= 0); it is followed to its first crossing with the bound (first_crossing), where
// the material slips again along tau, and so on to x_lo. False, with nothing added to s, if the first part
// slips on to x_lo; else lo is the node at x_lo.
[[gnu::noinline]] inline bool restick(const StripRates& r, const IntervalGeometry& geo, double x_c, double tx,
                                      double ty, double ex, double ey, IntervalSums& s, StripNode& lo) {
  const BoundQuadratic q = bound_quadratic(r);
  const double alpha = r.alpha_Pa_per_m, gamma = r.phi_L3_Pa_per_m2 / 2, x_lo = geo.x_lo;
  for (int part = 1;; ++part) {
    const SlipPath path(r, q, x_c, tx, ty, ex, ey, x_lo);
    SlipPath::Point pa, pb;
    if (part == kRestickParts || !slip_stop_bracket(path, x_lo, pa, pb)) {
      if (part == 1) return false;
      lo = path.slip_to(x_lo, geo.bound_lo_Pa, s);
      return true;
    }
    // the part ends on the bound at x_r (of length 0 where it stops at once: a node that a transient's
    // rescaling left off its bound comes onto it, as a slip part from it would take it)
    const double x_r = slip_stop(path, pa, pb);
    const StripNode on = path.slip_to(x_r, path.at(x_r).g, s);
    // stick from x_r, inside the bound at first
    const double h = x_r - x_lo, beta = stick_beta(r, x_r);
    const StickGeometry<double> sg = stick_geometry(r, beta, h);
    StickExcess<double> e = stick_excess(alpha, q, on.tx, on.ty, x_r, h, sg);
    e.d0 = 0;
    e.d1 = nonpositive(e.d1);
    const double s_cross = first_crossing(e);
    if (s_cross >= 1) {
      add_stick(r, on, x_r, beta, gamma, h, s);
      const StickPrediction<double> p = stick_prediction(alpha, on.tx, on.ty, h, sg);
      lo = {p.px, p.py, on.ex, on.ey, true};
      return true;
    }
    const double t_c = s_cross * h;
    add_stick(r, on, x_r, beta, gamma, t_c, s);
    tx = on.tx - alpha * t_c;
    ty = on.ty - beta * t_c + gamma * t_c * t_c;
    leaving_direction(alpha, beta, gamma, t_c, tx, ty, ex, ey);
    x_c = x_r - t_c;
  }
}

// A slip part from x_s = geo.x_hi - t_s to geo.x_lo (slip_part's arguments). With spin (kSpin) it is first
// cleared at once where lambda_below holds over the whole part (a few operations; g > 0 at x_s, e0 its
// direction there, d_m = (alpha, dy_m)); where it does not, restick looks for where its slip stops.
template <bool kSpin, class TurnFn>
[[gnu::always_inline]] inline StripNode slip_on(const StripRates& r, const IntervalGeometry& geo, double t_s,
                                                double dy_m, double tx0, double ty0, double ex0, double ey0, double Ip,
                                                double Ixp, TurnFn&& turn, IntervalSums& s) {
  if constexpr (!kSpin) {
    return slip_part(r, geo, t_s, dy_m, tx0, ty0, ex0, ey0, Ip, Ixp, turn, s);
  } else {
    IntervalSums part;
    const StripNode lo = slip_part(r, geo, t_s, dy_m, tx0, ty0, ex0, ey0, Ip, Ixp, turn, part);
    const double x_s = geo.x_hi - t_s, u = x_s / r.a_m;
    const double g_s = r.bound_Pa * std::sqrt(std::max(0.0, 1 - u * u));
    const double lambda_s = -(r.alpha_Pa_per_m * ex0 + dy_m * ey0) -
                            std::abs(r.phi_L3_Pa_per_m2) * (x_s - geo.x_lo) / 2;  // + g'(x_s) below
    if (r.bound_Pa > 0 && !(g_s > 0 && g_s * lambda_s - bound_quadratic(r).k * x_s >= 0)) {
      StripNode re;
      if (restick(r, geo, x_s, tx0, ty0, ex0, ey0, s, re)) return re;
    }
    add_interval_sums(s, part);
    return lo;
  }
}

}  // namespace detail

// march_slip_interval once Kalker's test has failed: the interval slips throughout (with spin, until its
// slip stops dissipating: detail::slip_on); kSpin = has_spin(r)
template <bool kSpin, class TurnFn>
[[gnu::always_inline]] inline StripNode slip_throughout(const StripRates& r, const StripNode& hi,
                                                        const IntervalGeometry& geo, TurnFn&& turn, IntervalSums& s) {
  return detail::slip_on<kSpin>(r, geo, 0.0, detail::midpoint_dy(r, geo.x_hi, geo.x_hi, geo.x_lo), hi.tx, hi.ty,
                                hi.ex, hi.ey, geo.load_N_per_m, geo.moment_N, turn, s);
}

namespace detail {

// spin: the first crossing t_s of the parabola with the bound (stick_step found it unless a stick node
// failed at x_lo); none, or past x_lo, only by rounding where the node test failed: stick up to x_lo
[[gnu::noinline]] inline double spin_crossing_time(const StripRates& r, const StripNode& hi, double x_hi, double h,
                                                   const StickStep& k) {
  double s_cross = k.s_cross;
  if (s_cross < 0)
    s_cross = first_crossing(stick_excess(r.alpha_Pa_per_m, bound_quadratic(r), hi.tx, hi.ty, x_hi, h,
                                          stick_geometry(r, k.beta, h)));
  return std::min(s_cross, 1.0) * h;
}

// The interval does not stick throughout: stick from x_hi to the crossing x_s = x_hi - t_s of the stick
// solution with the bound, slip from there to x_lo. From a stick node the crossing is located on the
// stick solution (without spin a quadratic in t, exact; with spin the first root of the quartic F).
// From a slip node whose stick solution fails at x_lo the interval slips throughout (t_s = 0), but with
// spin only while the slip dissipates at x_hi (spin_sticks); else it sticks up to the crossing. With spin
// the slip part sticks again where it stops dissipating (slip_on).
template <bool kSpin>
[[gnu::always_inline]] inline StripNode stick_then_slip(const StripRates& r, const StripNode& hi,
                                                        const IntervalGeometry& geo, const StickStep& k,
                                                        IntervalSums& s) {
  const double x_hi = geo.x_hi, x_lo = geo.x_lo, h = x_hi - x_lo, a = r.a_m;
  const double alpha = r.alpha_Pa_per_m, beta = k.beta, gamma = k.gamma, px = k.px, py = k.py;

  // slip at x_lo; from stick, the slip starts where the stick solution crosses the bound
  const double G = r.bound_Pa;
  double t_s = 0, tx0 = hi.tx, ty0 = hi.ty, ex0 = hi.ex, ey0 = hi.ey;
  if constexpr (kSpin) {
    // the first crossing of the parabola; the slip starts along tau there
    t_s = spin_crossing_time(r, hi, x_hi, h, k);
    if (t_s > 0) {
      add_stick(r, hi, x_hi, beta, gamma, t_s, s);
      tx0 = hi.tx - alpha * t_s;
      ty0 = hi.ty - beta * t_s + gamma * t_s * t_s;
    }
    if (hi.stick || t_s > 0) leaving_direction(alpha, beta, gamma, t_s, tx0, ty0, ex0, ey0);
  } else if (hi.stick) {
    // the crossing of the stick line, straight without spin, a quadratic in t
    const double Dx = (hi.tx - px) / h, Dy = (hi.ty - py) / h;
    const double G2a2 = G * G / (a * a);
    const double qa = Dx * Dx + Dy * Dy + G2a2;
    const double qb = -2 * (hi.tx * Dx + hi.ty * Dy) - 2 * G2a2 * x_hi;
    const double qc = std::min(0.0, hi.tx * hi.tx + hi.ty * hi.ty - G * G + G2a2 * x_hi * x_hi);
    if (qa > 0) {
      const double root = std::sqrt(qb * qb - 4 * qa * qc);
      t_s = std::clamp(qb <= 0 ? (-qb + root) / (2 * qa) : (-2 * qc) / (qb + root), 0.0, h);
    }
    if (t_s > 0) {
      add_stick(r, hi, x_hi, beta, gamma, t_s, s);
      tx0 = hi.tx - alpha * t_s;
      ty0 = hi.ty - beta * t_s + gamma * t_s * t_s;
    }
    const double n0 = std::sqrt(tx0 * tx0 + ty0 * ty0);
    const double np = std::sqrt(px * px + py * py);
    ex0 = n0 > 0 ? tx0 / n0 : px / np;
    ey0 = n0 > 0 ? ty0 / n0 : py / np;
  }
  const double x_s = x_hi - t_s;
  const double dy_m = midpoint_dy(r, x_hi, x_s, x_lo);
  // from a crossing the integrals of ds/g, p and x p over the slip part are exact
  if (t_s > 0) {
    const EllipsePoint ps(x_s / a), pl(x_lo / a);
    const double Ip = r.peak_Pa * a * (ps.integral() - pl.integral());
    const double Ixp = r.peak_Pa * a * a * (ps.moment() - pl.moment());
    auto turn = [&] { return slip_turn(alpha, dy_m, a / G * (ps.asin_u - pl.asin_u)); };
    return slip_on<kSpin>(r, geo, t_s, dy_m, tx0, ty0, ex0, ey0, Ip, Ixp, turn, s);
  }
  // slip throughout: the integral of ds/g is exact at the strip ends, by the midpoint rule inside
  auto turn = [&] {
    const double inv_g = x_hi >= a || x_lo <= -a ? a / G * (clamped_asin(x_s / a) - clamped_asin(x_lo / a))
                                                 : midpoint_inv_g(r, x_s, x_lo);
    return slip_turn(alpha, dy_m, inv_g);
  };
  return slip_on<kSpin>(r, geo, t_s, dy_m, tx0, ty0, ex0, ey0, geo.load_N_per_m, geo.moment_N, turn, s);
}

// stick_then_slip for an interval from a slip node that sticks again at x_hi and crosses the bound
// inside the interval (spin), kept out of the slip loops
[[gnu::noinline]] inline StripNode spin_stick_then_slip(const StripRates& r, const StripNode& hi,
                                                        const IntervalGeometry& geo, const StickStep& k,
                                                        IntervalSums& s) {
  return stick_then_slip<true>(r, hi, geo, k, s);
}

}  // namespace detail

// march_interval for a slip node hi and an interval strictly inside the strip (-a < x_lo < x_hi < a),
// with the turn of the slip direction from turn(): interior_slip_turn, or slip_turns for all the
// cells of a slip stretch at once; kSpin = has_spin(r)
template <bool kSpin, class TurnFn>
[[gnu::always_inline]] inline StripNode march_slip_interval(const StripRates& r, const StripNode& hi,
                                                            const IntervalGeometry& geo, TurnFn&& turn,
                                                            IntervalSums& s) {
  const detail::StickStep k = detail::stick_step<kSpin>(r, hi, geo, s);
  if (k.stick) return {k.px, k.py, hi.ex, hi.ey, true};
  if constexpr (kSpin) {
    if (k.s_cross > 0) return detail::spin_stick_then_slip(r, hi, geo, k, s);  // sticks again, then crosses
  }
  return slip_throughout<kSpin>(r, hi, geo, turn, s);
}

// one interval of the consistent march from the node hi at x_hi; kSpin = has_spin(r)
template <bool kSpin>
[[gnu::always_inline]] inline StripNode march_interval(const StripRates& r, const StripNode& hi,
                                                       const IntervalGeometry& geo, IntervalSums& s) {
  const double x_hi = geo.x_hi, x_lo = geo.x_lo, a = r.a_m;

  // from slip inside the strip, the slip direction turns by the midpoint rule
  if (!hi.stick && x_hi < a && x_lo > -a)
    return march_slip_interval<kSpin>(r, hi, geo, [&] { return detail::interior_slip_turn(r, x_hi, x_lo); }, s);

  const detail::StickStep k = detail::stick_step<kSpin>(r, hi, geo, s);
  if (k.stick) return {k.px, k.py, hi.ex, hi.ey, true};
  return detail::stick_then_slip<kSpin>(r, hi, geo, k, s);
}

// the same, with or without spin as r has it
inline StripNode march_interval(const StripRates& r, const StripNode& hi, const IntervalGeometry& geo,
                                IntervalSums& s) {
  return has_spin(r) ? march_interval<true>(r, hi, geo, s) : march_interval<false>(r, hi, geo, s);
}

// The slip turns of the cells first down to last, as interior_slip_turn gives them (x[i] = x_edge(i)),
// all at once: independent of each other, their exponentials overlap.
inline void slip_turns(const StripRates& r, const double* x, int first, int last, detail::SlipTurn* turn) {
  for (int i = first; i >= last; --i) turn[i] = detail::interior_slip_turn(r, x[i + 1], x[i]);
}

}  // namespace contact
