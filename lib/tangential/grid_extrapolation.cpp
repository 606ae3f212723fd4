// Richardson extrapolation of the exact steady solution over grids h and 2h (grid_extrapolation.h; the
// derivation and its checks: docs/exact-theory.md §4, "Grid extrapolation").
#include "lib/tangential/grid_extrapolation.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace contact {

ContactPatch halved_patch(const ContactPatch& p) {
  const Grid& g = p.grid;
  if (g.nx < 4 || g.ny < 4 || g.nx % 2 != 0 || g.ny % 2 != 0)
    throw std::invalid_argument("grid extrapolation: the grid needs an even number of cells each way, at least 4 (" +
                                std::to_string(g.nx) + " x " + std::to_string(g.ny) + ")");
  ContactPatch c;
  c.a_m = p.a_m;
  c.b_m = p.b_m;
  c.p0_Pa = p.p0_Pa;
  c.normal_load_N = p.normal_load_N;
  c.approach_m = p.approach_m;
  c.grid = g;
  c.grid.nx = g.nx / 2;
  c.grid.ny = g.ny / 2;
  c.grid.dx_m = 2 * g.dx_m;
  c.grid.dy_m = 2 * g.dy_m;
  c.grid.x_m = Eigen::ArrayXd(c.grid.nx);
  c.grid.y_m = Eigen::ArrayXd(c.grid.ny);
  for (int i = 0; i < c.grid.nx; ++i) c.grid.x_m(i) = 0.5 * (g.x_m(2 * i) + g.x_m(2 * i + 1));
  for (int j = 0; j < c.grid.ny; ++j) c.grid.y_m(j) = 0.5 * (g.y_m(2 * j) + g.y_m(2 * j + 1));
  // the mean pressure of each 2 x 2 block: the block's load
  c.pressure_Pa = Eigen::ArrayXXd(c.grid.nx, c.grid.ny);
  for (int j = 0; j < c.grid.ny; ++j)
    for (int i = 0; i < c.grid.nx; ++i)
      c.pressure_Pa(i, j) = 0.25 * (p.pressure_Pa(2 * i, 2 * j) + p.pressure_Pa(2 * i + 1, 2 * j) +
                                    p.pressure_Pa(2 * i, 2 * j + 1) + p.pressure_Pa(2 * i + 1, 2 * j + 1));
  if (p.strip_xi_offset.size() == g.ny) {
    c.strip_xi_offset = Eigen::ArrayXd(c.grid.ny);
    for (int j = 0; j < c.grid.ny; ++j) c.strip_xi_offset(j) = 0.5 * (p.strip_xi_offset(2 * j) + p.strip_xi_offset(2 * j + 1));
  }
  // the strips' semi-ellipses (half_length_m, strip_peak_Pa) are not defined on merged cells: left empty
  return c;
}

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
