// Shakedown map and surface fatigue index (docs/subsurface.md §4).
#include "lib/subsurface/shakedown.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lib/numeric.h"

namespace contact {

const char* to_string(ShakedownContact c) { return c == ShakedownContact::Line ? "line" : "point"; }

ShakedownContact shakedown_contact_of(double a_m, double b_m) {
  const double lo = std::min(a_m, b_m), hi = std::max(a_m, b_m);
  return hi > 0 && lo / hi >= kPointContactAspect ? ShakedownContact::Point : ShakedownContact::Line;
}

double shakedown_limit_p0_over_k(ShakedownContact c, double f) {
  if (!(f >= 0)) throw std::invalid_argument(fmt::format("shakedown: traction coefficient must be >= 0, got {}", f));
  const double subsurface = c == ShakedownContact::Line ? kLineShakedownP0OverK : kPointShakedownP0OverK;
  return f > 0 ? std::min(subsurface, 1 / f) : subsurface;
}

FatigueIndicators fatigue_indicators(const ContactPatch& patch, const TangentialSolution& s, double k) {
  if (!(k >= kShearYieldMin_Pa && k <= kShearYieldMax_Pa))
    throw std::invalid_argument(fmt::format("shakedown: the shear yield stress must be in [{:g}, {:g}] Pa, got {}",
                                            kShearYieldMin_Pa, kShearYieldMax_Pa, k));
  if (!(patch.normal_load_N > 0 && patch.p0_Pa > 0))
    throw std::invalid_argument("shakedown: the contact carries no load");
  FatigueIndicators out;
  out.shear_yield_Pa = k;
  out.contact = shakedown_contact_of(patch.a_m, patch.b_m);
  out.traction_coefficient = std::hypot(s.Fx_N, s.Fy_N) / patch.normal_load_N;
  out.p0_over_k = patch.p0_Pa / k;
  out.limit_p0_over_k = shakedown_limit_p0_over_k(out.contact, out.traction_coefficient);
  const double subsurface = out.contact == ShakedownContact::Line ? kLineShakedownP0OverK : kPointShakedownP0OverK;
  out.surface_limit = out.limit_p0_over_k < subsurface;
  out.margin = out.limit_p0_over_k / out.p0_over_k - 1;
  out.FI_surf = out.traction_coefficient - 2 * kPi * patch.a_m * patch.b_m * k / (3 * patch.normal_load_N);

  // per cell, over the loaded cells
  const Grid& g = patch.grid;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.cell_index = Eigen::ArrayXXd::Constant(g.nx, g.ny, nan);
  out.cell_index_max = -std::numeric_limits<double>::infinity();
  const bool traction = s.tau_x_Pa.rows() == g.nx && s.tau_x_Pa.cols() == g.ny;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double p = patch.pressure_Pa(i, j);
      if (!(p > 0)) continue;
      const double tau = traction ? std::hypot(s.tau_x_Pa(i, j), s.tau_y_Pa(i, j)) : 0.0;
      const double v = (tau - k) / p;
      out.cell_index(i, j) = v;
      if (v > out.cell_index_max) out.cell_index_max = v, out.cell_x_m = g.x_m(i), out.cell_y_m = g.y_m(j);
    }
  return out;
}

}  // namespace contact
