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

class Output {
 public:
  Output(TangentialSolution& s, int j) : s_(s), j_(j) {}
  void cell(int i, double tx_mean, double ty_mean, double sx, double sy, double power, int state) {
    s_.tau_x_Pa(i, j_) = tx_mean;
    s_.tau_y_Pa(i, j_) = ty_mean;
    s_.slip_x_m_per_s(i, j_) = sx;
    s_.slip_y_m_per_s(i, j_) = sy;
    s_.power_W_per_m2(i, j_) = power;
    s_.state(i, j_) = state;
  }

 private:
  TangentialSolution& s_;
  int j_;
};

StripTotals march_consistent(const ContactPatch& patch, const TangentialProblem& pb, int j, Output out) {
  const Grid& g = patch.grid;
  const double a = patch.half_length_m(j);
  const double y = g.y_m(j);
  const Creepages& cr = pb.creepages;
  const double alpha = cr.xi / pb.flex.L1_m_per_Pa - cr.phi_per_m * y / pb.flex.L3_m_per_Pa;
  const double eta_L2 = cr.eta / pb.flex.L2_m_per_Pa;
  const double phi_L3 = cr.phi_per_m / pb.flex.L3_m_per_Pa;
  const double gamma = phi_L3 / 2;
  const double VL = pb.speed_m_per_s * pb.L_m_per_Pa;
  const double G = pb.mu * patch.strip_peak_Pa(j);  // peak of the traction bound
  const double mu = pb.mu;

  StripTotals st;
  double tx = 0, ty = 0;  // tau at the upstream node x_hi
  bool hi_stick = true;   // the leading node sticks (tau = 0 = bound)
  const int i_top = std::min(g.nx - 1, static_cast<int>(std::floor((a + g.half_x_m) / g.dx_m)));
  const int i_bot = std::max(0, static_cast<int>(std::floor((-a + g.half_x_m) / g.dx_m)));
  for (int i = i_top; i >= i_bot; --i) {
    const double x_hi = std::min(g.x_edge(i + 1), a);
    const double x_lo = std::max(g.x_edge(i), -a);
    const double h = x_hi - x_lo;
    if (!(h > 0)) continue;
    const double g_lo = x_lo > -a ? mu * patch.edge_pressure_Pa(i, j) : 0.0;
    const double beta = eta_L2 + phi_L3 * x_hi;

    // stick prediction at the downstream node
    const double px = tx - alpha * h;
    const double py = ty - beta * h + gamma * h * h;
    const double n2 = px * px + py * py;

    double Ix = 0, Iy = 0, Ixy = 0;  // integrals of tau_x, tau_y, x tau_y over the interval
    double stick_len = 0, slip_sx = 0, slip_sy = 0;
    double tx_lo = px, ty_lo = py;
    // exact stick solution over t in [0, t] from (tx, ty) at x_hi
    auto add_stick = [&](double t) {
      const double t2 = t * t, t3 = t2 * t;
      Ix += tx * t - alpha * t2 / 2;
      const double iy = ty * t - beta * t2 / 2 + gamma * t3 / 3;
      Iy += iy;
      Ixy += x_hi * iy - (ty * t2 / 2 - beta * t3 / 3 + gamma * t3 * t / 4);
      stick_len += t;
    };
    if (n2 <= g_lo * g_lo) {
      add_stick(h);  // stick -> stick, or slip -> stick
      hi_stick = true;
    } else {
      const double n = std::sqrt(n2);
      double ex_lo = px / n, ey_lo = py / n;
      tx_lo = g_lo * ex_lo;
      ty_lo = g_lo * ey_lo;
      // start of slip within the interval: the crossing of the stick line with the bound
      double t_s = 0, sx0 = tx, sy0 = ty;
      if (hi_stick) {
        const double Dx = (tx - px) / h, Dy = (ty - py) / h;  // chord of the stick line
        const double G2a2 = G * G / (a * a);
        const double qa = Dx * Dx + Dy * Dy + G2a2;
        const double qb = -2 * (tx * Dx + ty * Dy) - 2 * G2a2 * x_hi;
        const double qc = std::min(0.0, tx * tx + ty * ty - G * G + G2a2 * x_hi * x_hi);
        if (qa > 0) {
          const double root = std::sqrt(qb * qb - 4 * qa * qc);
          t_s = qb <= 0 ? (-qb + root) / (2 * qa) : (-2 * qc) / (qb + root);
          t_s = std::clamp(t_s, 0.0, h);
        }
        if (t_s > 0) {
          add_stick(t_s);
          sx0 = tx - alpha * t_s;
          sy0 = ty - beta * t_s + gamma * t_s * t_s;
        }
      }
      // slip part [x_lo, x_s]: |tau| = mu p exactly, direction the mean of its end directions
      const double x_s = x_hi - t_s;
      double Ip = 0, Ixp = 0;  // integrals of p and x p over the slip part
      if (t_s == 0) {
        Ip = patch.pressure_Pa(i, j) * g.dx_m;
        Ixp = patch.pressure_moment_Pa_m(i, j) * g.dx_m;
      } else {
        const double pj = patch.strip_peak_Pa(j);
        Ip = pj * a * (semi_ellipse_integral(x_s / a) - semi_ellipse_integral(x_lo / a));
        Ixp = pj * a * a * (semi_ellipse_moment(x_s / a) - semi_ellipse_moment(x_lo / a));
      }
      const double n0 = std::sqrt(sx0 * sx0 + sy0 * sy0);
      const double ex0 = n0 > 0 ? sx0 / n0 : ex_lo, ey0 = n0 > 0 ? sy0 / n0 : ey_lo;
      if (n0 > 0 && G > 0) {
        // direction at x_lo from the slip-direction equation with d taken at the midpoint:
        // tan(psi/2) decays by exp(-|d| integral ds/g), psi the angle between tau and -d
        const double xm = (x_s + x_lo) / 2;
        const double dx_m = alpha, dy_m = beta + phi_L3 * (xm - x_hi);
        const double dn = std::hypot(dx_m, dy_m);
        if (dn > 0) {
          const double ux = -dx_m / dn, uy = -dy_m / dn;
          const double c0 = ex0 * ux + ey0 * uy, s0 = ux * ey0 - uy * ex0;
          if (s0 != 0) {
            const double inv_g = a / G * (std::asin(std::clamp(x_s / a, -1.0, 1.0)) -
                                          std::asin(std::clamp(x_lo / a, -1.0, 1.0)));
            const double decay = std::exp(-dn * inv_g);
            const double t0 = c0 >= 0 ? s0 / (1 + c0) : (1 - c0) / s0;
            const double t1 = t0 * decay, w = 1 / (1 + t1 * t1);
            const double c1 = (1 - t1 * t1) * w, s1 = 2 * t1 * w;
            ex_lo = c1 * ux - s1 * uy;
            ey_lo = c1 * uy + s1 * ux;
            tx_lo = g_lo * ex_lo;
            ty_lo = g_lo * ey_lo;
          }
        }
      }
      const double ex = (ex0 + ex_lo) / 2, ey = (ey0 + ey_lo) / 2;
      Ix += mu * ex * Ip;
      Iy += mu * ey * Ip;
      Ixy += mu * ey * Ixp;
      // mean slip over the part in contact: integral of s = c - V L dtau/dx over the slip part
      const double hs = x_s - x_lo;
      slip_sx = VL * (alpha * hs - (sx0 - tx_lo)) / h;
      slip_sy = VL * (eta_L2 * hs + phi_L3 * (x_s * x_s - x_lo * x_lo) / 2 - (sy0 - ty_lo)) / h;
      hi_stick = false;
    }

    // dissipated power of the interval: -integral(tau . s dx)
    const double creep = -VL * (alpha * Ix + eta_L2 * Iy + phi_L3 * Ixy);
    const double D = creep + VL * ((tx * tx + ty * ty) - (tx_lo * tx_lo + ty_lo * ty_lo)) / 2;
    out.cell(i, Ix / g.dx_m, Iy / g.dx_m, slip_sx, slip_sy, D / g.dx_m, stick_len >= h / 2 ? 1 : 2);
    st.Fx += Ix;
    st.Fy += Iy;
    st.Mz += Ixy - y * Ix;
    st.power += D;
    st.creep_power += creep;
    st.stick_length += stick_len;
    tx = tx_lo;
    ty = ty_lo;
  }
  st.trailing = VL * (tx * tx + ty * ty) / 2;
  return st;
}

StripTotals march_classic(const ContactPatch& patch, const TangentialProblem& pb, int j, Output out) {
  const Grid& g = patch.grid;
  const double a = patch.half_length_m(j);
  const double y = g.y_m(j);
  const Creepages& cr = pb.creepages;
  const double alpha = cr.xi / pb.flex.L1_m_per_Pa - cr.phi_per_m * y / pb.flex.L3_m_per_Pa;
  const double eta_L2 = cr.eta / pb.flex.L2_m_per_Pa;
  const double phi_L3 = cr.phi_per_m / pb.flex.L3_m_per_Pa;
  const double VL = pb.speed_m_per_s * pb.L_m_per_Pa;
  const double G = pb.mu * patch.strip_peak_Pa(j);
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

TangentialSolution solve_steady(const ContactPatch& patch, const TangentialProblem& problem,
                                TangentialScheme scheme) {
  const Grid& g = patch.grid;
  TangentialSolution s;
  s.tau_x_Pa = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  s.tau_y_Pa = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  s.slip_x_m_per_s = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  s.slip_y_m_per_s = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  s.power_W_per_m2 = Eigen::ArrayXXd::Zero(g.nx, g.ny);
  s.state = Eigen::ArrayXXi::Zero(g.nx, g.ny);
  s.strip_power_W_per_m = Eigen::ArrayXd::Zero(g.ny);
  s.strip_creep_power_W_per_m = Eigen::ArrayXd::Zero(g.ny);
  s.strip_trailing_W_per_m = Eigen::ArrayXd::Zero(g.ny);
  s.strip_force_x_N_per_m = Eigen::ArrayXd::Zero(g.ny);
  s.strip_force_y_N_per_m = Eigen::ArrayXd::Zero(g.ny);

  double stick_area = 0, area = 0;
  for (int j = 0; j < g.ny; ++j) {
    if (!(patch.half_length_m(j) > 0)) continue;
    const StripTotals st = scheme == TangentialScheme::Classic ? march_classic(patch, problem, j, Output(s, j))
                                                               : march_consistent(patch, problem, j, Output(s, j));
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
  const Creepages& c = problem.creepages;
  s.creep_work_W = problem.speed_m_per_s * (c.xi * s.Fx_N + c.eta * s.Fy_N + c.phi_per_m * s.Mz_N_m);
  spdlog::debug("steady ({}, {} x {}): Fx {:.6e} N, Fy {:.6e} N, Mz {:.6e} N m, P {:.6e} W, stick {:.3f}",
                to_string(scheme), g.nx, g.ny, s.Fx_N, s.Fy_N, s.Mz_N_m, s.power_W, s.stick_fraction);
  return s;
}

}  // namespace contact
