// Closed forms the tests and the benchmarks check the solvers against (one copy for both).
#pragma once

#include <algorithm>
#include <cmath>
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

}  // namespace rollwear_test
