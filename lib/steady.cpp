// Steady rolling on strips (PHYSICS.md §3-4).
//
// Consistent scheme. Node values of tau sit at the cell edges inside the strip and at the exact
// strip ends +-a_j; each interval between two nodes is the part of one cell in contact. Marching
// from the leading node (tau = 0) with t = x_hi - x, the stick solution is exact:
//   tau_x(t) = tau_x(x_hi) - alpha t,            alpha = xi/L1 - phi y/L3,
//   tau_y(t) = tau_y(x_hi) - beta t + gamma t^2,  beta = eta/L2 + phi x_hi/L3, gamma = phi/(2 L3).
// The node x_lo sticks if that prediction lies inside the bound mu p(x_lo) (Kalker's rule); otherwise
// it is clipped to the bound keeping its direction. Within an interval:
//   stick -> stick or slip -> stick: the exact stick solution throughout (|stick| - bound is convex
//     along the interval, so stick at both ends means stick in between);
//   stick -> slip: the crossing of the stick line with the semi-elliptic bound is located exactly
//     (a quadratic in t on the chord; exact without spin), stick before it, slip after;
//   slip part: |tau| = g = mu p integrated exactly, direction the mean of the end directions. The
//     direction at the downstream node solves the slip-direction equation exactly for the creep
//     rate d = (alpha, beta) frozen at the interval's midpoint: with psi the angle between tau and
//     -d and s the distance downstream, d psi/ds = -|d| sin(psi)/g, so
//       tan(psi_lo/2) = tan(psi_hi/2) exp(-|d| integral ds/g),  integral ds/g = (a/(mu p_j)) [asin(x/a)],
//     finite up to the trailing edge. (Kalker's clip of tau - d h is the explicit Euler step of this
//     equation and converges at first order with spin; this converges at about 1.7.)
// The dissipated power is -integral(tau . s dx) of this reconstruction, s = c - V L dtau/dx:
//   D = V L [ -alpha Ix - (eta/L2) Iy - (phi/L3) Ixy + (|tau_hi|^2 - |tau_lo|^2)/2 ]
// with Ix, Iy, Ixy the integrals of tau_x, tau_y, x tau_y over the interval. It is zero on stick
// intervals (to rounding), and summed over a strip it telescopes to the balance of §4:
//   P_l = -integral(tau . c dx) - V L |tau(-a_j)|^2 / 2.
// For pure xi the reconstruction is the closed form of §4, so Fx and P are exact along x on any grid.
//
// Classic scheme: Kalker's FASTSIM on the cell centres, tau_pred = tau_prev - (c/(V L)) dx, bound at
// the centre, s = V L (tau - tau_pred)/dx, P = -sum tau . s dx dy (PHYSICS.md §3, §5).
#include "lib/steady.h"

#include "lib/strip_march.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

namespace contact {

namespace {

struct StripTotals {
  double Fx = 0, Fy = 0, Mz = 0;  // per unit width
  double power = 0, creep_power = 0, trailing = 0;
  double stick_length = 0;
};

// the fields of one strip, written only when asked for
struct FieldWriter {
  TangentialSolution* s = nullptr;
  int j = 0;
  double dx = 0, VL = 0;
  // one interval of the consistent march: means over the cell (tractions, power) and over the part
  // in contact (slip)
  void interval(int i, const IntervalSums& sums, double h, double D) const {
    if (!s) return;
    s->tau_x_Pa(i, j) = sums.Ix / dx;
    s->tau_y_Pa(i, j) = sums.Iy / dx;
    s->slip_x_m_per_s(i, j) = VL * sums.slip_x / h;
    s->slip_y_m_per_s(i, j) = VL * sums.slip_y / h;
    s->power_W_per_m2(i, j) = D / dx;
    s->state(i, j) = sums.stick_length_m >= h / 2 ? 1 : 2;
  }
  void cell(int i, double tx, double ty, double sx, double sy, double power, int state) const {
    if (!s) return;
    s->tau_x_Pa(i, j) = tx;
    s->tau_y_Pa(i, j) = ty;
    s->slip_x_m_per_s(i, j) = sx;
    s->slip_y_m_per_s(i, j) = sy;
    s->power_W_per_m2(i, j) = power;
    s->state(i, j) = state;
  }
};

StripTotals march_consistent(const ContactPatch& patch, const TangentialProblem& pb, int j, FieldWriter out) {
  const Grid& g = patch.grid;
  const StripRates r = strip_rates(patch, pb, j);
  const double a = r.a_m, VL = pb.speed_m_per_s * pb.L_m_per_Pa;

  StripTotals st;
  StripNode node;  // the leading edge: tau = 0 = bound, stick
  const int i_top = std::min(g.nx - 1, static_cast<int>(std::floor((a + g.half_x_m) / g.dx_m)));
  const int i_bot = std::max(0, static_cast<int>(std::floor((-a + g.half_x_m) / g.dx_m)));
  for (int i = i_top; i >= i_bot; --i) {
    IntervalGeometry geo;
    geo.x_hi = std::min(g.x_edge(i + 1), a);
    geo.x_lo = std::max(g.x_edge(i), -a);
    if (!(geo.x_hi > geo.x_lo)) continue;
    geo.bound_lo_Pa = geo.x_lo > -a ? r.mu * patch.edge_pressure_Pa(i, j) : 0.0;
    geo.load_N_per_m = patch.pressure_Pa(i, j) * g.dx_m;
    geo.moment_N = patch.pressure_moment_Pa_m(i, j) * g.dx_m;

    IntervalSums sums;
    const StripNode lo = march_interval(r, node, geo, sums);

    // dissipated power of the interval: -integral(tau . s dx)
    const double creep = VL * creep_power_per_VL(r, sums);
    const double D = VL * dissipation_per_VL(r, node, lo, sums);
    out.interval(i, sums, geo.x_hi - geo.x_lo, D);
    st.Fx += sums.Ix;
    st.Fy += sums.Iy;
    st.Mz += sums.Ixy - r.y_m * sums.Ix;
    st.power += D;
    st.creep_power += creep;
    st.stick_length += sums.stick_length_m;
    node = lo;
  }
  st.trailing = VL * (node.tx * node.tx + node.ty * node.ty) / 2;
  return st;
}

StripTotals march_classic(const ContactPatch& patch, const TangentialProblem& pb, int j, FieldWriter out) {
  const Grid& g = patch.grid;
  const StripRates r = strip_rates(patch, pb, j);
  const double a = r.a_m, y = r.y_m, alpha = r.alpha_Pa_per_m;
  const double eta_L2 = r.eta_L2_Pa_per_m, phi_L3 = r.phi_L3_Pa_per_m2;
  const double VL = pb.speed_m_per_s * pb.L_m_per_Pa;
  const double G = r.bound_Pa;
  const double dx = g.dx_m;

  StripTotals st;
  double tx = 0, ty = 0;
  for (int i = g.nx - 1; i >= 0; --i) {
    const double x = g.x_m(i);
    if (std::abs(x) >= a) continue;
    const double u = x / a;
    const double bound = G * std::sqrt(1 - u * u);
    const double px = tx - alpha * dx;
    const double py = ty - (eta_L2 + phi_L3 * x) * dx;
    const double n = std::sqrt(px * px + py * py);
    const bool slip = n > bound;
    tx = slip ? px * bound / n : px;
    ty = slip ? py * bound / n : py;
    const double sx = VL * (tx - px) / dx, sy = VL * (ty - py) / dx;
    const double power = -(tx * sx + ty * sy);
    out.cell(i, tx, ty, sx, sy, power, slip ? 2 : 1);
    st.Fx += tx * dx;
    st.Fy += ty * dx;
    st.Mz += (x * ty - y * tx) * dx;
    st.power += power * dx;
    st.creep_power += -VL * (alpha * tx + (eta_L2 + phi_L3 * x) * ty) * dx;
    if (!slip) st.stick_length += dx;
  }
  st.trailing = VL * (tx * tx + ty * ty) / 2;
  return st;
}

}  // namespace

StripRates strip_rates(const ContactPatch& patch, const TangentialProblem& pb, int j) {
  const Creepages& c = pb.creepages;
  const double xi = c.xi + (patch.strip_xi_offset.size() > j ? patch.strip_xi_offset(j) : 0.0);
  StripRates r;
  r.a_m = patch.half_length_m(j);
  r.y_m = patch.grid.y_m(j);
  r.alpha_Pa_per_m = xi / pb.flex.L1_m_per_Pa - c.phi_per_m * r.y_m / pb.flex.L3_m_per_Pa;
  r.eta_L2_Pa_per_m = c.eta / pb.flex.L2_m_per_Pa;
  r.phi_L3_Pa_per_m2 = c.phi_per_m / pb.flex.L3_m_per_Pa;
  r.mu = pb.mu;
  r.peak_Pa = patch.strip_peak_Pa(j);
  r.bound_Pa = pb.mu * r.peak_Pa;
  return r;
}

TangentialSolution solve_steady(const ContactPatch& patch, const TangentialProblem& problem,
                                TangentialScheme scheme, const SteadyOptions& options) {
  const Grid& g = patch.grid;
  TangentialSolution s;
  if (options.fields) {
    s.tau_x_Pa = Eigen::ArrayXXd::Zero(g.nx, g.ny);
    s.tau_y_Pa = Eigen::ArrayXXd::Zero(g.nx, g.ny);
    s.slip_x_m_per_s = Eigen::ArrayXXd::Zero(g.nx, g.ny);
    s.slip_y_m_per_s = Eigen::ArrayXXd::Zero(g.nx, g.ny);
    s.power_W_per_m2 = Eigen::ArrayXXd::Zero(g.nx, g.ny);
    s.state = Eigen::ArrayXXi::Zero(g.nx, g.ny);
  }
  s.strip_power_W_per_m = Eigen::ArrayXd::Zero(g.ny);
  s.strip_creep_power_W_per_m = Eigen::ArrayXd::Zero(g.ny);
  s.strip_trailing_W_per_m = Eigen::ArrayXd::Zero(g.ny);
  s.strip_force_x_N_per_m = Eigen::ArrayXd::Zero(g.ny);
  s.strip_force_y_N_per_m = Eigen::ArrayXd::Zero(g.ny);

  double stick_area = 0, area = 0;
  for (int j = 0; j < g.ny; ++j) {
    if (!(patch.half_length_m(j) > 0)) continue;
    const FieldWriter out{options.fields ? &s : nullptr, j, g.dx_m, problem.speed_m_per_s * problem.L_m_per_Pa};
    const StripTotals st = scheme == TangentialScheme::Classic ? march_classic(patch, problem, j, out)
                                                               : march_consistent(patch, problem, j, out);
    s.strip_power_W_per_m(j) = st.power;
    s.strip_creep_power_W_per_m(j) = st.creep_power;
    s.strip_trailing_W_per_m(j) = st.trailing;
    s.strip_force_x_N_per_m(j) = st.Fx;
    s.strip_force_y_N_per_m(j) = st.Fy;
    s.Fx_N += st.Fx * g.dy_m;
    s.Fy_N += st.Fy * g.dy_m;
    s.Mz_N_m += st.Mz * g.dy_m;
    s.power_W += st.power * g.dy_m;
    stick_area += st.stick_length * g.dy_m;
    area += 2 * patch.half_length_m(j) * g.dy_m;
  }
  s.stick_fraction = area > 0 ? stick_area / area : 0;
  // work of the creep forces, with the local xi of each strip where the rolling radius varies
  const Creepages& c = problem.creepages;
  double xi_Fx = c.xi * s.Fx_N;
  if (patch.strip_xi_offset.size() == g.ny)
    xi_Fx += (patch.strip_xi_offset * s.strip_force_x_N_per_m).sum() * g.dy_m;
  s.creep_work_W = problem.speed_m_per_s * (xi_Fx + c.eta * s.Fy_N + c.phi_per_m * s.Mz_N_m);
  spdlog::debug("steady ({}, {} x {}): Fx {:.6e} N, Fy {:.6e} N, Mz {:.6e} N m, P {:.6e} W, stick {:.3f}",
                to_string(scheme), g.nx, g.ny, s.Fx_N, s.Fy_N, s.Mz_N_m, s.power_W, s.stick_fraction);
  return s;
}

}  // namespace contact
