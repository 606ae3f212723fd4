// Principal stresses and equivalent stresses (docs/subsurface.md §2).
#include "lib/subsurface/stress_measures.h"

#include <algorithm>
#include <cmath>

#include "lib/numeric.h"

namespace contact {

std::array<double, 3> principal_stresses(const StressTensor& s) {
  // the deviator's invariants J2, J3 and Lode's angle: sigma_k = m + 2 sqrt(J2/3) cos(theta - 2 pi k/3)
  const double m = (s.xx + s.yy + s.zz) / 3;
  const double a = s.xx - m, b = s.yy - m, c = s.zz - m;
  const double off = s.xy * s.xy + s.xz * s.xz + s.yz * s.yz;
  const double J2 = (a * a + b * b + c * c) / 2 + off;
  if (!(J2 > 0)) return {m, m, m};
  const double J3 = a * b * c + 2 * s.xy * s.xz * s.yz - a * s.yz * s.yz - b * s.xz * s.xz - c * s.xy * s.xy;
  const double r = std::sqrt(J2 / 3);
  const double cos3 = std::clamp(J3 / (2 * r * r * r), -1.0, 1.0);
  const double theta = std::acos(cos3) / 3;  // in [0, pi/3]: cos(theta) is the largest of the three
  return {m + 2 * r * std::cos(theta), m + 2 * r * std::cos(theta - 2 * kPi / 3),
          m + 2 * r * std::cos(theta + 2 * kPi / 3)};
}

double von_mises_Pa(const StressTensor& s) {
  const double d1 = s.xx - s.yy, d2 = s.yy - s.zz, d3 = s.zz - s.xx;
  return std::sqrt((d1 * d1 + d2 * d2 + d3 * d3) / 2 + 3 * (s.xy * s.xy + s.xz * s.xz + s.yz * s.yz));
}

double tresca_Pa(const StressTensor& s) {
  const std::array<double, 3> p = principal_stresses(s);
  return (p[0] - p[2]) / 2;
}

}  // namespace contact
