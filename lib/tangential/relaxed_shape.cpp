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
