// One interval of the consistent strip march (the derivation is at the top of lib/steady.cpp):
// from the traction at the upstream node x_hi to the downstream node x_lo, with the integrals of
// the reconstruction over the interval. The steady solver chains it along each strip; Satran's
// shift scheme applies it to the previous step's node values (PHYSICS.md §3-4). march_slip_interval
// is its case of a slip node inside the strip with the turn of the slip direction given, so that the
// steady solver's slip stretches can take the turns of all their cells at once (slip_turns). The pieces
// of the stick solution are templates, so that Satran's shift step can take them for a block of
// intervals at once (SIMD).
#pragma once

#include <algorithm>
#include <cmath>

#include "lib/patch.h"
#include "lib/tangential.h"

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

struct StripNode {  // traction at a node
  double tx = 0, ty = 0;  // Pa
  double ex = 0, ey = 0;  // direction of tau, kept from the last slip (0 before any)
  bool stick = true;
};

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

// The stick solution from tau = (tx, ty) at x_hi, with t = x_hi - x (PHYSICS.md §3):
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

// the turn of the slip direction over a slip part: 1/|d| and the factor k = exp(-|d| integral ds/g)
// by which tan(psi/2) decays
struct SlipTurn {
  double inv_dn = 0, k = 1;
};

constexpr double kPi = 3.14159265358979323846;

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
  if (s0u != 0 && r.bound_Pa > 0) {
    const SlipTurn t = turn();
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
// lies inside the bound, and then the whole interval sticks (its integrals are added to s)
struct StickStep {
  double beta = 0, gamma = 0;  // d tau_y/dx at x_hi, and half the curvature of tau_y
  double px = 0, py = 0;       // the prediction at x_lo
  bool stick = false;
};

[[gnu::always_inline]] inline StickStep stick_step(const StripRates& r, const StripNode& hi, const IntervalGeometry& geo,
                                                   IntervalSums& s) {
  const double x_hi = geo.x_hi, h = x_hi - geo.x_lo;
  StickStep k;
  k.beta = stick_beta(r, x_hi);
  const StickPrediction<double> p = stick_prediction(r.alpha_Pa_per_m, hi.tx, hi.ty, h, stick_geometry(r, k.beta, h));
  k.gamma = r.phi_L3_Pa_per_m2 / 2;
  k.px = p.px;
  k.py = p.py;
  k.stick = k.px * k.px + k.py * k.py <= geo.bound_lo_Pa * geo.bound_lo_Pa;
  if (k.stick) add_stick(r, hi, x_hi, k.beta, k.gamma, h, s);
  return k;
}

}  // namespace detail

// march_slip_interval once Kalker's test has failed: the interval slips throughout
template <class TurnFn>
[[gnu::always_inline]] inline StripNode slip_throughout(const StripRates& r, const StripNode& hi,
                                                        const IntervalGeometry& geo, TurnFn&& turn, IntervalSums& s) {
  return detail::slip_part(r, geo, 0.0, detail::midpoint_dy(r, geo.x_hi, geo.x_hi, geo.x_lo), hi.tx, hi.ty, hi.ex,
                           hi.ey, geo.load_N_per_m, geo.moment_N, turn, s);
}

// march_interval for a slip node hi and an interval strictly inside the strip (-a < x_lo < x_hi < a),
// with the turn of the slip direction from turn(): interior_slip_turn, or slip_turns for all the
// cells of a slip stretch at once
template <class TurnFn>
[[gnu::always_inline]] inline StripNode march_slip_interval(const StripRates& r, const StripNode& hi,
                                                            const IntervalGeometry& geo, TurnFn&& turn,
                                                            IntervalSums& s) {
  const detail::StickStep k = detail::stick_step(r, hi, geo, s);
  if (k.stick) return {k.px, k.py, hi.ex, hi.ey, true};
  return slip_throughout(r, hi, geo, turn, s);
}

[[gnu::always_inline]] inline StripNode march_interval(const StripRates& r, const StripNode& hi, const IntervalGeometry& geo,
                                IntervalSums& s) {
  const double x_hi = geo.x_hi, x_lo = geo.x_lo, h = x_hi - x_lo, a = r.a_m;

  // from slip inside the strip, the slip direction turns by the midpoint rule
  if (!hi.stick && x_hi < a && x_lo > -a)
    return march_slip_interval(r, hi, geo, [&] { return detail::interior_slip_turn(r, x_hi, x_lo); }, s);

  const detail::StickStep k = detail::stick_step(r, hi, geo, s);
  if (k.stick) return {k.px, k.py, hi.ex, hi.ey, true};
  const double alpha = r.alpha_Pa_per_m, beta = k.beta, gamma = k.gamma, px = k.px, py = k.py;

  // slip at x_lo; from stick, the slip starts where the stick line crosses the bound
  const double G = r.bound_Pa;
  double t_s = 0, tx0 = hi.tx, ty0 = hi.ty, ex0 = hi.ex, ey0 = hi.ey;
  if (hi.stick) {
    const double Dx = (hi.tx - px) / h, Dy = (hi.ty - py) / h;  // chord of the stick line
    const double G2a2 = G * G / (a * a);
    const double qa = Dx * Dx + Dy * Dy + G2a2;
    const double qb = -2 * (hi.tx * Dx + hi.ty * Dy) - 2 * G2a2 * x_hi;
    const double qc = std::min(0.0, hi.tx * hi.tx + hi.ty * hi.ty - G * G + G2a2 * x_hi * x_hi);
    if (qa > 0) {
      const double root = std::sqrt(qb * qb - 4 * qa * qc);
      t_s = std::clamp(qb <= 0 ? (-qb + root) / (2 * qa) : (-2 * qc) / (qb + root), 0.0, h);
    }
    if (t_s > 0) {
      detail::add_stick(r, hi, x_hi, beta, gamma, t_s, s);
      tx0 = hi.tx - alpha * t_s;
      ty0 = hi.ty - beta * t_s + gamma * t_s * t_s;
    }
    const double n0 = std::sqrt(tx0 * tx0 + ty0 * ty0);
    const double np = std::sqrt(px * px + py * py);
    ex0 = n0 > 0 ? tx0 / n0 : px / np;
    ey0 = n0 > 0 ? ty0 / n0 : py / np;
  }
  const double x_s = x_hi - t_s;
  const double dy_m = detail::midpoint_dy(r, x_hi, x_s, x_lo);
  // from a crossing the integrals of ds/g, p and x p over the slip part are exact
  if (t_s > 0) {
    const detail::EllipsePoint ps(x_s / a), pl(x_lo / a);
    const double Ip = r.peak_Pa * a * (ps.integral() - pl.integral());
    const double Ixp = r.peak_Pa * a * a * (ps.moment() - pl.moment());
    auto turn = [&] { return detail::slip_turn(alpha, dy_m, a / G * (ps.asin_u - pl.asin_u)); };
    return detail::slip_part(r, geo, t_s, dy_m, tx0, ty0, ex0, ey0, Ip, Ixp, turn, s);
  }
  // slip throughout: the integral of ds/g is exact at the strip ends, by the midpoint rule inside
  auto turn = [&] {
    const double inv_g = x_hi >= a || x_lo <= -a
                             ? a / G * (detail::clamped_asin(x_s / a) - detail::clamped_asin(x_lo / a))
                             : detail::midpoint_inv_g(r, x_s, x_lo);
    return detail::slip_turn(alpha, dy_m, inv_g);
  };
  return detail::slip_part(r, geo, t_s, dy_m, tx0, ty0, ex0, ey0, geo.load_N_per_m, geo.moment_N, turn, s);
}

// The slip turns of the cells first down to last, as interior_slip_turn gives them (x[i] = x_edge(i)),
// all at once: independent of each other, their exponentials overlap.
inline void slip_turns(const StripRates& r, const double* x, int first, int last, detail::SlipTurn* turn) {
  for (int i = first; i >= last; --i) turn[i] = detail::interior_slip_turn(r, x[i + 1], x[i]);
}

}  // namespace contact
