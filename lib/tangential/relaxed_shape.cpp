// The relaxed model's shape factor and strip weights (equations in relaxed_shape.h).
#include "lib/tangential/relaxed_shape.h"

#include <algorithm>
#include <cmath>

#include "lib/tangential/tangential.h"

namespace contact {

namespace {

// f(e) of relaxed_shape.h: the strip weights fade as the strips saturate
double level_fade(double e) { return 1 - e * e * e; }

double shape_factor_of(const ContactPatch& patch) {
  const Eigen::ArrayXd& aj = patch.half_length_m;
  const Eigen::ArrayXd& y = patch.grid.y_m;
  if (!(patch.a_m > 0 && patch.b_m > 0) || aj.size() == 0 || aj.size() != y.size()) return 1.0;
  const double sum_a = aj.sum();
  if (!(sum_a > 0)) return 1.0;
  const double yc = (aj * y).sum() / sum_a;
  const Eigen::ArrayXd u = (y - yc) / patch.b_m;
  const Eigen::ArrayXd e = patch.a_m * (1 - u.square()).max(0.0).sqrt();
  const double sum_e = e.sum(), sum_e2 = e.square().sum();
  if (!(sum_e > 0 && sum_e2 > 0)) return 1.0;
  return (aj.square().sum() / sum_a) / (sum_e2 / sum_e);
}

// The factor and the strips' weights (a / a_j)^p of the last patch seen on this thread: a transient run solves one
// patch at many steps, and the weights' logarithms and exponentials cost more than the closed-form solve itself.
// The memo is keyed on the patch's values (semi-axes, strip half-lengths and positions compared exactly), never on
// its address, so a patch changed in place is seen.
struct ShapeMemo {
  double a_m = -1, b_m = -1;
  Eigen::ArrayXd half_length_m, y_m;
  double S = 1;
  Eigen::ArrayXd log_ratio;  // log(a / a_j), 0 where a_j = 0 (no power there); empty for a degenerate patch
  double p = 0;              // the exponent the weights below were made for
  Eigen::ArrayXd weights;    // (a / a_j)^p
};

const ShapeMemo& shape_of(const ContactPatch& patch) {
  thread_local ShapeMemo m;
  const Eigen::ArrayXd& aj = patch.half_length_m;
  const Eigen::ArrayXd& y = patch.grid.y_m;
  if (m.a_m == patch.a_m && m.b_m == patch.b_m && m.half_length_m.size() == aj.size() && m.y_m.size() == y.size() &&
      (m.half_length_m == aj).all() && (m.y_m == y).all())
    return m;
  m.a_m = patch.a_m;
  m.b_m = patch.b_m;
  m.half_length_m = aj;
  m.y_m = y;
  m.S = shape_factor_of(patch);
  m.log_ratio.resize(0);
  m.weights.resize(0);
  m.p = 0;
  if (patch.a_m > 0 && patch.b_m > 0 && aj.size() > 0) {
    m.log_ratio = (aj > 0).select((patch.a_m / aj).log(), 0.0);
    // a patch whose half lengths are mirror-symmetric to kMirrorTol (a Hertz patch: to a few ulps) gets mirror
    // weights to the bit, so that the march's mirrored strips (first_mirrored_strip) stay mirror copies
    const Eigen::Index ny = m.log_ratio.size();
    if ((aj - aj.reverse()).abs().maxCoeff() <= kMirrorTol * aj.abs().maxCoeff())
      for (Eigen::Index j = 0; j < ny / 2; ++j) m.log_ratio(ny - 1 - j) = m.log_ratio(j);
  }
  return m;
}

// the weights (a / a_j)^p of the memo's patch, made again only when p changes (a steady run or a constant creepage
// keeps it)
const Eigen::ArrayXd& weights_of(const ContactPatch& patch, double p) {
  ShapeMemo& m = const_cast<ShapeMemo&>(shape_of(patch));
  if (m.log_ratio.size() == 0) {
    m.weights.resize(0);
    return m.weights;
  }
  if (m.weights.size() != m.log_ratio.size() || m.p != p) {
    m.weights = (p * m.log_ratio).exp();
    m.p = p;
  }
  return m.weights;
}

}  // namespace

double relaxed_shape_factor(const ContactPatch& patch) { return shape_of(patch).S; }

double relaxed_strip_power_exponent(double a_over_b, double level, double spin_share) {
  const double p0 = std::clamp(1 - a_over_b / 2, 0.0, 1.0);
  const double e = std::clamp(level, 0.0, 1.0);
  const double g = 1 - std::clamp(spin_share, 0.0, 1.0);
  return p0 * level_fade(e) * g;
}

void redistribute_strip_power(TangentialSolution& s, const ContactPatch& patch, double level, double spin_share) {
  Eigen::ArrayXd& P = s.strip_power_W_per_m;
  if (P.size() == 0 || !(patch.a_m > 0 && patch.b_m > 0)) return;
  const double p = relaxed_strip_power_exponent(patch.a_m / patch.b_m, level, spin_share);
  if (!(p > 0)) return;  // a/b >= 2, full slip or pure spin: the springs' distribution
  const Eigen::ArrayXd w = (patch.half_length_m > 0).select(weights_of(patch, p), 0.0);
  if (w.size() != P.size()) return;  // a degenerate patch, or no strips
  const double before = P.sum(), after = (P * w).sum();
  if (!(before > 0 && after > 0)) return;
  const Eigen::ArrayXd k = w * (before / after);
  P *= k;
  if (s.power_W_per_m2.cols() == k.size())
    for (Eigen::Index j = 0; j < k.size(); ++j) s.power_W_per_m2.col(j) *= k(j);
}

}  // namespace contact
