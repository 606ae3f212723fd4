// One interval of the consistent strip march (the derivation is at the top of lib/steady.cpp):
// from the traction at the upstream node x_hi to the downstream node x_lo, with the integrals of
// the reconstruction over the interval. The steady solver chains it along each strip; Satran's
// shift scheme applies it to the previous step's node values (PHYSICS.md §3-4).
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

// exact stick solution over t = x_hi - x in [0, t] from tau at x_hi
[[gnu::always_inline]] inline void add_stick(const StripRates& r, const StripNode& hi, double x_hi, double beta, double gamma,
                      double t, IntervalSums& s) {
  const double t2 = t * t, t3 = t2 * t;
  s.Ix += hi.tx * t - r.alpha_Pa_per_m * t2 / 2;
  const double iy = hi.ty * t - beta * t2 / 2 + gamma * t3 / 3;
  s.Iy += iy;
  s.Ixy += x_hi * iy - (hi.ty * t2 / 2 - beta * t3 / 3 + gamma * t3 * t / 4);
  s.stick_length_m += t;
}

}  // namespace detail

[[gnu::always_inline]] inline StripNode march_interval(const StripRates& r, const StripNode& hi, const IntervalGeometry& geo,
                                IntervalSums& s) {
  const double x_hi = geo.x_hi, x_lo = geo.x_lo, h = x_hi - x_lo, a = r.a_m;
  const double alpha = r.alpha_Pa_per_m;
  const double beta = r.eta_L2_Pa_per_m + r.phi_L3_Pa_per_m2 * x_hi;  // d tau_y/dx at x_hi
  const double gamma = r.phi_L3_Pa_per_m2 / 2;

  // stick prediction at x_lo (Kalker's rule decides stick or slip there)
  const double px = hi.tx - alpha * h;
  const double py = hi.ty - beta * h + gamma * h * h;
  const double g_lo = geo.bound_lo_Pa;
  if (px * px + py * py <= g_lo * g_lo) {
    detail::add_stick(r, hi, x_hi, beta, gamma, h, s);
    return {px, py, hi.ex, hi.ey, true};
  }

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
  const double x_s = x_hi - t_s, hs = x_s - x_lo;

  // slip direction at x_lo: d psi/ds = -|d| sin(psi)/g exactly, d frozen at the midpoint
  double ex = ex0, ey = ey0;
  const double dx_m = alpha, dy_m = beta + r.phi_L3_Pa_per_m2 * ((x_s + x_lo) / 2 - x_hi);
  const double ux = -dx_m, uy = -dy_m;  // -d, not yet normalised
  const double s0u = ux * ey0 - uy * ex0;
  if (s0u != 0 && G > 0) {
    const double dn = std::sqrt(dx_m * dx_m + dy_m * dy_m), inv_dn = 1 / dn;
    const double c0 = (ex0 * ux + ey0 * uy) * inv_dn, s0 = s0u * inv_dn;
    // integral of ds/g over the slip part: exact at the strip ends and at a crossing, midpoint inside
    double inv_g = 0;
    if (t_s > 0 || x_hi >= a || x_lo <= -a) {
      inv_g = a / G * (std::asin(std::clamp(x_s / a, -1.0, 1.0)) - std::asin(std::clamp(x_lo / a, -1.0, 1.0)));
    } else {
      const double um = (x_s + x_lo) / (2 * a);
      inv_g = hs / (G * std::sqrt(1 - um * um));
    }
    const double k = std::exp(-dn * inv_g);  // tan(psi/2) decays by this factor
    const double c1 = 1 + c0, ks = k * s0;
    const double norm = c1 * c1 + ks * ks;
    if (norm > 1e-300) {
      const double scale = inv_dn / norm;
      const double A = (c1 * c1 - ks * ks) * scale, B = 2 * ks * c1 * scale;
      ex = A * ux - B * uy;
      ey = A * uy + B * ux;
    }
  }
  const StripNode lo{g_lo * ex, g_lo * ey, ex, ey, false};

  // |tau| = mu p exactly over the slip part, direction the mean of its end directions
  double Ip = geo.load_N_per_m, Ixp = geo.moment_N;
  if (t_s > 0) {
    Ip = r.peak_Pa * a * (semi_ellipse_integral(x_s / a) - semi_ellipse_integral(x_lo / a));
    Ixp = r.peak_Pa * a * a * (semi_ellipse_moment(x_s / a) - semi_ellipse_moment(x_lo / a));
  }
  const double mx = r.mu * (ex0 + ex) / 2, my = r.mu * (ey0 + ey) / 2;
  s.Ix += mx * Ip;
  s.Iy += my * Ip;
  s.Ixy += my * Ixp;
  // integral of s/(V L) = d - dtau/dx over the slip part
  s.slip_x += alpha * hs - (tx0 - lo.tx);
  s.slip_y += r.eta_L2_Pa_per_m * hs + r.phi_L3_Pa_per_m2 * (x_s * x_s - x_lo * x_lo) / 2 - (ty0 - lo.ty);
  return lo;
}

}  // namespace contact
