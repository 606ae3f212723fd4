// Hertz's elliptic contact (equations at the top of hertz.h).
//
// The ellipse: with r = (larger curvature)/(smaller curvature) >= 1, k = minor/major is the root in
// (0, 1) of  h(k) = (E(e)/k^2 - K(e)) - r (K(e) - E(e)),  e = sqrt(1 - k^2),  found by Newton's
// method safeguarded by bisection (h > 0 as k -> 0, h < 0 as k -> 1 for r > 1), with
//   dK/de = E/(e k^2) - K/e,   dE/de = (E - K)/e,   de/dk = -k/e.
//
// Strips: a_j = a sqrt(1 - (y_j/b)^2). Strip j carries the load of its whole cell row,
//   F_j = (pi/2) p0 a  integral over the row of (1 - y^2/b^2) dy,
// so p_j = F_j / ((pi/2) a_j dy); the row's load is exact and the field integrates to F.
#include "lib/normal/hertz.h"
#include "lib/numeric.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace contact {

namespace {

double curvature_per_m(double R_m, const char* name) {
  if (R_m == 0 || std::isnan(R_m))
    throw std::invalid_argument(std::string(name) + ": radius must be nonzero (use inf for a flat body)");
  return std::isinf(R_m) ? 0.0 : 1 / R_m;
}

// k = minor/major semi-axis of the ellipse for a curvature ratio r > 1. Newton safeguarded by
// bisection, not find_root_bracketed (lib/numeric.h): h(1) = 0 for every r (the circle, where both
// brackets of h vanish), so [lo, 1] is no sign change, and excluding k = 1 by hand would need a bound
// on the root that depends on r - 1 (down to 1e-12).
double axis_ratio(double r) {
  auto h_and_slope = [r](double k, double& slope) {
    const double e = std::sqrt(1 - k * k);
    const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    const double dK_de = E / (e * k * k) - K / e, dE_de = (E - K) / e, de_dk = -k / e;
    const double dK = dK_de * de_dk, dE = dE_de * de_dk;
    slope = -2 * E / (k * k * k) + dE / (k * k) - dK - r * (dK - dE);
    return (E / (k * k) - K) - r * (K - E);
  };
  double lo = 1e-12, hi = 1.0;  // h(lo) > 0 > h(hi)
  double k = std::clamp(std::pow(r, -2.0 / 3.0), 1e-6, 1 - 1e-6);
  for (int it = 0; it < 200; ++it) {
    double slope = 0;
    const double h = h_and_slope(k, slope);
    if (h > 0) lo = k; else hi = k;
    double next = k - h / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (std::abs(next - k) <= 1e-15 * k) return next;
    k = next;
  }
  throw std::runtime_error("hertz: the ellipse's axis ratio did not converge for curvature ratio " +
                           std::to_string(r));
}

}  // namespace

HertzContact solve_hertz(const Bodies& bodies, const ElasticPair& pair, double normal_load_N) {
  check_material(pair.body1, "body1");
  check_material(pair.body2, "body2");
  if (!(normal_load_N > 0) || !std::isfinite(normal_load_N))
    throw std::invalid_argument("hertz: normal load must be positive and finite, got " +
                                std::to_string(normal_load_N) + " N");
  HertzContact h;
  h.A_per_m = (curvature_per_m(bodies.body1.Rx_m, "body1.Rx") + curvature_per_m(bodies.body2.Rx_m, "body2.Rx")) / 2;
  h.B_per_m = (curvature_per_m(bodies.body1.Ry_m, "body1.Ry") + curvature_per_m(bodies.body2.Ry_m, "body2.Ry")) / 2;
  if (!(h.A_per_m > 0) || !(h.B_per_m > 0))
    throw std::invalid_argument("hertz: conforming or flat contact (A = " + std::to_string(h.A_per_m) +
                                " 1/m, B = " + std::to_string(h.B_per_m) +
                                " 1/m; both must be positive): Hertz cannot treat it");
  h.Estar_Pa = effective_modulus_Pa(pair);
  h.normal_load_N = normal_load_N;
  const double F = normal_load_N, Es = h.Estar_Pa;

  const double larger = std::max(h.A_per_m, h.B_per_m), smaller = std::min(h.A_per_m, h.B_per_m);
  const double r = larger / smaller;
  double major = 0, minor = 0;
  if (r - 1 < 1e-12) {
    // circular limit: a^3 = 3 F R / (4 E*), delta = a^2 / R, R = 1/(2A)
    const double R = 1 / (h.A_per_m + h.B_per_m);
    major = minor = std::cbrt(3 * F * R / (4 * Es));
    h.approach_m = major * major / R;
    h.eccentricity = 0;
  } else {
    const double k = axis_ratio(r);
    const double e2 = 1 - k * k, e = std::sqrt(e2);
    const double K = std::comp_ellint_1(e), E = std::comp_ellint_2(e);
    major = std::cbrt(3 * F * (K - E) / (2 * kPi * smaller * Es * e2));
    minor = k * major;
    h.approach_m = 3 * F * K / (2 * kPi * Es * major);
    h.eccentricity = e;
  }
  // the semi-axis along the larger curvature is the smaller one
  h.a_m = h.A_per_m >= h.B_per_m ? minor : major;
  h.b_m = h.A_per_m >= h.B_per_m ? major : minor;
  h.p0_Pa = 3 * F / (2 * kPi * h.a_m * h.b_m);
  // per solve: the ellipse exists and carries F (2/3 pi a b p0 = F by construction)
  ROLLWEAR_ASSERT(h.a_m > 0 && h.b_m > 0 && std::isfinite(h.p0_Pa) && h.approach_m > 0,
                  "a " + std::to_string(h.a_m) + " m, b " + std::to_string(h.b_m) + " m, p0 " +
                      std::to_string(h.p0_Pa) + " Pa, approach " + std::to_string(h.approach_m) + " m");
  return h;
}

ContactPatch hertz_patch(const HertzContact& h, const Grid& grid) {
  ContactPatch patch;
  patch.a_m = h.a_m;
  patch.b_m = h.b_m;
  patch.p0_Pa = h.p0_Pa;
  patch.normal_load_N = h.normal_load_N;
  patch.approach_m = h.approach_m;
  patch.grid = grid;
  patch.half_length_m = Eigen::ArrayXd::Zero(grid.ny);
  patch.strip_peak_Pa = Eigen::ArrayXd::Zero(grid.ny);

  // each strip carries its row's load: antiderivative of (1 - y^2/b^2), clamped to |y| <= b
  const double b = h.b_m;
  auto row_weight = [b](double y) {
    const double s = std::clamp(y / b, -1.0, 1.0);
    return b * (s - s * s * s / 3);
  };
  double carried_N = 0;
  for (int j = 0; j < grid.ny; ++j) {
    const double s = grid.y_m(j) / b;
    if (std::abs(s) >= 1) continue;
    const double a_j = h.a_m * std::sqrt(1 - s * s);
    const double row_load_N_per_m = kPi / 2 * h.p0_Pa * h.a_m *
                                    (row_weight(grid.y_edge(j + 1)) - row_weight(grid.y_edge(j))) / grid.dy_m;
    patch.half_length_m(j) = a_j;
    patch.strip_peak_Pa(j) = row_load_N_per_m / (kPi / 2 * a_j);
    carried_N += row_load_N_per_m * grid.dy_m;
  }
  // rows whose centre lies outside the ellipse carry nothing: hand their load to the others
  if (!(carried_N > 0))
    throw std::invalid_argument("hertz: the grid's strips miss the contact ellipse (b = " + std::to_string(b) +
                                " m, grid half-width " + std::to_string(grid.half_y_m) + " m)");
  patch.strip_peak_Pa *= h.normal_load_N / carried_N;
  // per solve: the strips carry the load, (pi/2) p_j a_j dy summed over the rows, to rounding
  const double strips_N = (kPi / 2 * patch.strip_peak_Pa * patch.half_length_m).sum() * grid.dy_m;
  ROLLWEAR_ASSERT(std::abs(strips_N - h.normal_load_N) <= 1e-9 * h.normal_load_N && patch.strip_peak_Pa.minCoeff() >= 0,
                  "the strips carry " + std::to_string(strips_N) + " N of " + std::to_string(h.normal_load_N) + " N");
  fill_strip_pressures(patch);
  return patch;
}

ContactPatch solve_normal_hertz(const Bodies& bodies, const ElasticPair& pair, double normal_load_N,
                                const GridSpec& spec) {
  const HertzContact h = solve_hertz(bodies, pair, normal_load_N);
  spdlog::debug("hertz: a {:.6e} m, b {:.6e} m, p0 {:.6e} Pa, approach {:.6e} m", h.a_m, h.b_m, h.p0_Pa,
                h.approach_m);
  return hertz_patch(h, make_grid(h.a_m, h.b_m, spec));
}

}  // namespace contact
