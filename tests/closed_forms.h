// Closed forms the tests and the benchmarks check the solvers against (one copy for both).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace rollwear_test {

// docs/physics.md §4, start from rest, pure xi: |tau(x, q)| = min(k min(q, a - x), g(x)), g = mu p.
// The strip force, integrated exactly piece by piece between the break points of the min.
inline double strip_force_from_rest(double a, double p, double k, double mu, double q) {
  if (!(a > 0)) return 0;  // a strip out of contact
  const double G = mu * p;
  auto g = [&](double x) { return G * std::sqrt(std::max(0.0, 1 - x * x / (a * a))); };
  auto tau = [&](double x) { return std::min(k * std::min(q, a - x), g(x)); };
  auto S = [&](double x) {
    const double u = std::clamp(x / a, -1.0, 1.0);
    return (u * std::sqrt(1 - u * u) + std::asin(u)) / 2;
  };
  // break points: a - q, the crossings of the line with g, and of the level k q with g
  std::vector<double> b{-a, a};
  if (q < 2 * a) b.push_back(a - q);
  const double m = G / (k * a);
  b.push_back(a * (1 - m * m) / (1 + m * m));
  if (k * q < G) {
    const double xc = a * std::sqrt(1 - (k * q / G) * (k * q / G));
    b.push_back(xc);
    b.push_back(-xc);
  }
  std::sort(b.begin(), b.end());
  double F = 0;
  for (size_t i = 1; i < b.size(); ++i) {
    const double x0 = std::max(-a, b[i - 1]), x1 = std::min(a, b[i]);
    if (!(x1 > x0)) continue;
    const double xm = (x0 + x1) / 2, t = tau(xm);
    if (t == g(xm)) F += G * a * (S(x1) - S(x0));                                          // slip: the bound
    else if (xm >= a - q) F += k * ((a - x0) * (a - x0) - (a - x1) * (a - x1)) / 2;       // stick line
    else F += k * q * (x1 - x0);                                                            // not yet strained past q
  }
  return F;
}

// Hertz's circular contact, frictionless, on its axis (Johnson, Contact Mechanics, §3.4; docs/subsurface.md §3):
// sigma_z = -p0 / (1 + z^2/a^2),
// sigma_r = -p0 [(1 + nu)(1 - (z/a) atan(a/z)) - 1 / (2 (1 + z^2/a^2))], z > 0, stresses / p0.
struct AxisStress {
  double radial = 0, normal = 0;  // sigma_r (= sigma_x = sigma_y), sigma_z, over p0
};
inline AxisStress hertz_circle_axis_stress(double z_over_a, double nu) {
  const double z = z_over_a, s = 1 + z * z;
  return {-((1 + nu) * (1 - z * std::atan(1 / z)) - 1 / (2 * s)), -1 / s};
}
// Hertz's line contact (plane strain, half-width a), frictionless, on its axis (McEwen; Johnson §4.2):
// sigma_x = -p0 [(1 + 2 z^2/a^2) / sqrt(1 + z^2/a^2) - 2 z/a], sigma_z = -p0 / sqrt(1 + z^2/a^2).
inline AxisStress hertz_line_axis_stress(double z_over_a) {
  const double z = z_over_a, r = std::sqrt(1 + z * z);
  return {-((1 + 2 * z * z) / r - 2 * z), -1 / r};
}
// the largest of f on [lo, hi] for a unimodal f (golden section): {argument, value}
template <class F>
std::pair<double, double> golden_maximum(F f, double lo, double hi, double tol = 1e-10) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double a = lo, b = hi, c = b - g * (b - a), d = a + g * (b - a);
  while (b - a > tol) {
    if (f(c) > f(d)) b = d; else a = c;
    c = b - g * (b - a), d = a + g * (b - a);
  }
  const double x = (a + b) / 2;
  return {x, f(x)};
}

}  // namespace rollwear_test
