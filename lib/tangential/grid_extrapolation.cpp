// Richardson extrapolation of the exact steady solution over grids h and 2h (grid_extrapolation.h; the
// derivation and its checks: docs/exact-theory.md §4, "Grid extrapolation").
#include "lib/tangential/grid_extrapolation.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace contact {

ExtrapolatedExactSolution solve_exact_steady_extrapolated(const ContactPatch& patch, double G_Pa, double nu,
                                                          const Creepages& creepages, double mu, double speed_m_per_s,
                                                          double order, const ExactOptions& opt) {
  if (!(std::isfinite(order) && order > 0))
    throw std::invalid_argument("grid extrapolation: the order must be positive and finite (" + std::to_string(order) +
                                ")");
  const ContactPatch coarse_patch = halved_patch(patch);
  ExtrapolatedExactSolution r;
  r.fine = solve_exact_steady(patch, G_Pa, nu, creepages, mu, speed_m_per_s, opt);
  r.fields = r.fine.fields;
  r.status = r.fine.status;
  if (!r.fine.status.converged()) return r;
  r.coarse = solve_exact_steady(coarse_patch, G_Pa, nu, creepages, mu, speed_m_per_s, opt);
  if (!r.coarse.status.converged()) {
    r.status = r.coarse.status;
    r.status.message = "coarse grid of the extrapolation: " + r.status.message;
    return r;
  }
  r.status.message += "; on half the cells: " + r.coarse.status.message + " (grid extrapolation)";
  const TangentialSolution &h = r.fine.fields, &c = r.coarse.fields;
  // Richardson: Q_h + (Q_h - Q_2h)/(2^p - 1)
  const double w = 1 / (std::pow(2.0, order) - 1);
  const auto extrapolate = [w](double fine, double coarse) { return fine + w * (fine - coarse); };
  TangentialSolution& e = r.fields;
  e.Fx_N = extrapolate(h.Fx_N, c.Fx_N);
  e.Fy_N = extrapolate(h.Fy_N, c.Fy_N);
  e.Mz_N_m = extrapolate(h.Mz_N_m, c.Mz_N_m);
  e.creep_work_W = extrapolate(h.creep_work_W, c.creep_work_W);
  e.power_W = extrapolate(h.power_W, c.power_W);
  // per strip: the fine grid's distribution at the extrapolated level (its shape converges faster than its level,
  // which is the forces' first-order error, nearly the same in every strip: docs/exact-theory.md §4)
  const double level = h.power_W > 0 && e.power_W > 0 ? e.power_W / h.power_W : 1.0;
  e.strip_power_W_per_m = h.strip_power_W_per_m * level;
  e.power_W_per_m2 = h.power_W_per_m2 * level;
  return r;
}

}  // namespace contact
