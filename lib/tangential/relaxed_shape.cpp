// The relaxed model's shape factor (equations in relaxed_shape.h).
#include "lib/tangential/relaxed_shape.h"

#include <algorithm>
#include <cmath>

namespace contact {

double relaxed_shape_factor(const ContactPatch& patch) {
  const Eigen::ArrayXd& aj = patch.half_length_m;
  const Eigen::ArrayXd& y = patch.grid.y_m;
  if (!(patch.a_m > 0 && patch.b_m > 0) || aj.size() == 0 || aj.size() != y.size()) return 1.0;
  const double sum_a = aj.sum();
  if (!(sum_a > 0)) return 1.0;
  const double yc = (aj * y).sum() / sum_a;
  double sum_e = 0, sum_e2 = 0;
  for (Eigen::Index j = 0; j < y.size(); ++j) {
    const double u = (y(j) - yc) / patch.b_m;
    const double e = patch.a_m * std::sqrt(std::max(0.0, 1 - u * u));
    sum_e += e;
    sum_e2 += e * e;
  }
  if (!(sum_e > 0 && sum_e2 > 0)) return 1.0;
  return (aj.square().sum() / sum_a) / (sum_e2 / sum_e);
}

}  // namespace contact

#include "lib/tangential/tangential.h"

namespace contact {

double relaxed_strip_power_exponent(double a_over_b) { return std::clamp(1 - a_over_b / 2, 0.0, 1.0); }

void redistribute_strip_power(TangentialSolution& s, const ContactPatch& patch) {
  if (!(patch.a_m > 0 && patch.b_m > 0)) return;
  const double p = relaxed_strip_power_exponent(patch.a_m / patch.b_m);
  Eigen::ArrayXd& P = s.strip_power_W_per_m;
  const Eigen::ArrayXd& aj = patch.half_length_m;
  if (p == 0 || P.size() == 0 || P.size() != aj.size()) return;
  const Eigen::ArrayXd w = (aj > 0).select((patch.a_m / aj).pow(p), 0.0);
  const double before = P.sum(), after = (P * w).sum();
  if (!(before > 0 && after > 0)) return;
  const Eigen::ArrayXd k = w * (before / after);
  P *= k;
  if (s.power_W_per_m2.cols() == k.size())
    for (Eigen::Index j = 0; j < k.size(); ++j) s.power_W_per_m2.col(j) *= k(j);
}

}  // namespace contact
