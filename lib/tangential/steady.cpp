// Steady rolling on strips (docs/physics.md §3-4).
//
// Consistent scheme. Node values of tau sit at the cell edges inside the strip and at the exact
// strip ends +-a_j; each interval between two nodes is the part of one cell in contact. Marching
// from the leading node (tau = 0) with t = x_hi - x, the stick solution is exact:
//   tau_x(t) = tau_x(x_hi) - alpha t,            alpha = xi/L1 - phi y/L3,
//   tau_y(t) = tau_y(x_hi) - beta t + gamma t^2,  beta = eta/L2 + phi x_hi/L3, gamma = phi/(2 L3).
// Kalker's rule: the interval sticks if the stick solution lies inside the bound g = mu p on all of
// it. With g^2 = G^2 (1 - x^2/a^2), the excess F = |tau_stick|^2 - g^2 is a polynomial in t:
//   without spin a quadratic, convex (its t^2 term |(alpha, beta)|^2 + G^2/a^2 > 0), so F <= 0 at both
//     nodes means F <= 0 in between: the test at x_lo (the prediction inside mu p(x_lo)) is the whole
//     test, and it costs nothing more;
//   with spin a quartic (the parabola's gamma t^2 term): the stick parabola can rise over the bound
//     between two nodes that pass, so the interior is tested too (lib/tangential/strip_march.h, stick_excess:
//     Bernstein coefficients of F bound it from above; where they do not settle it, first_crossing
//     finds F's first root by subdivision and a bracketed Newton step).
// Within an interval:
//   stick throughout (stick -> stick or slip -> stick): the exact stick solution;
//   stick -> slip: the first crossing of the stick solution with the semi-elliptic bound is located
//     (without spin a quadratic in t, exact; with spin the first root of the quartic F on the
//     parabola), stick before it, slip after, so the stick part never leaves the bound;
//   from a slip node: slip throughout if Kalker's test fails at x_lo. With spin the creep rate turns
//     along the strip, and the slip goes on only while it dissipates at x_hi: F'(0) = 2 h g (g' - e . d)
//     > 0 (the stick solution from the node leaves the bound at once); otherwise the material sticks
//     again at x_hi and the stick solution is followed to its first crossing, as from a stick node.
//   slip -> stick inside an interval (spin only): a slip part ends where its dissipation density
//     g lambda = -k x - g e . d(x) (k = G^2/a^2) falls to 0, located by a bracketed root find along the
//     slip part; the material sticks from there and the stick solution is followed to its first crossing,
//     then slips again (lib/tangential/strip_march.h, detail::restick). Without spin d is constant and the density
//     only grows downstream, so this never happens and nothing is asked.
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
// The march, arranged for speed (the same scheme; the kernel is lib/tangential/strip_march.h):
//   stick runs: consecutive stick intervals share one stick solution, the polynomials above from the
//     run's first node, so the run's integrals are add_stick's closed forms over the whole run and its
//     D is the formula above with the run's end nodes (it telescopes). Kalker's tests at the run's
//     nodes, and with spin between them (each interval's quartic from the run's solution at its upper
//     node, as the kernel takes it), are independent of each other: they go in vectorised blocks, and
//     a block passes at once when a bound of |tau| over it stays below its smallest bound by a margin
//     far above rounding (without spin |tau_s - (alpha, beta) t|, convex in t; with spin the ends'
//     |tau| plus the parabola's bulge over its chord, |gamma| (t_b - t_a)^2 / 4). The interval where a
//     test fails goes through the full kernel (the crossing).
//   slip stretches: consecutive slip intervals go one at a time (the direction of tau is a chain of
//     dependent operations); the turns of the direction (|d|, the exponential) depend on the geometry
//     alone and are computed for all the strip's remaining cells at once. The stretch's D is the
//     formula above with its end nodes.
//   two strips march in turn in one loop, so that the CPU overlaps their chains.
//   the march is compiled with and without spin (has_spin, the same for every strip of a problem):
//     without spin it asks nothing of the interior and costs what it did before the interior test.
// Writing the fields (per interval) changes none of the totals.
//
// Classic scheme: Kalker's FASTSIM on the cell centres, tau_pred = tau_prev - (c/(V L)) dx, bound at
// the centre, s = V L (tau - tau_pred)/dx, P = -sum tau . s dx dy (docs/physics.md §3, §5).
#include "lib/tangential/steady.h"

#include "lib/tangential/strip_march.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace contact {

namespace {

// a strip's totals (dissipated: its power, W/m) and what the steady solution also reports per strip
struct SteadyStrip : StripTotals {
  double creep_power = 0, trailing = 0;
};

// the stick solution from a node at x_s (docs/physics.md §3): tau_x linear, tau_y quadratic in t = x_s - x
struct StickLine {
  const StripRates& r;
  StripNode start;
  double x_s = 0, alpha = 0, beta = 0, gamma = 0;  // beta = d tau_y/dx at x_s, gamma = phi/(2 L3)
  StickLine(const StripRates& rates, const StripNode& node, double x)
      : r(rates), start(node), x_s(x), alpha(rates.alpha_Pa_per_m),
        beta(rates.eta_L2_Pa_per_m + rates.phi_L3_Pa_per_m2 * x), gamma(rates.phi_L3_Pa_per_m2 / 2) {}
  StripNode at(double x) const {
    const double t = x_s - x;
    return {start.tx - alpha * t, start.ty - beta * t + gamma * t * t, start.ex, start.ey, true};
  }
  // Kalker's rule at a node: the stick solution lies inside the bound g = mu p there
  bool sticks_at(double x, double g) const {
    const double t = x_s - x;
    const double px = start.tx - alpha * t, py = start.ty - beta * t + gamma * t * t;
    return px * px + py * py <= g * g;
  }
  // with spin, Kalker's rule between the nodes of the interval [x_lo, x_hi] of the run: the kernel's
  // interior test (detail::spin_sticks) from the stick solution at x_hi, as the kernel takes it
  // from that node
  bool sticks_between(double x_hi, double x_lo) const {
    if (gamma == 0) return true;  // the node tests are the whole test
    const StripNode hi = at(x_hi);
    const double h = x_hi - x_lo;
    const detail::StickExcess<double> e =
        detail::stick_excess(alpha, detail::bound_quadratic(r), hi.tx, hi.ty, x_hi, h,
                             detail::stick_geometry(r, detail::stick_beta(r, x_hi), h));
    return detail::hull_excess(e) <= 0 || detail::first_crossing(e) > 1;
  }
  // The first of the nodes x[k], k = first down to last + 1, where the stick solution leaves the
  // bound mu p (last if none): at the node, or with spin between it and the node above (x_s for
  // k = first). The tests are independent: they run in blocks of nodes, the last block shifted up to
  // end at last + 1 (its nodes above k pass again). A block whose stick solution stays clearly below
  // its smallest bound passes without the tests: for t in [t_a, t_b],
  //   |tau(t)| <= |tau_s - (alpha, beta) t| + |gamma| t^2,
  // the first term convex in t (largest at an end), the second growing; "clearly" is a margin far
  // above the rounding of the tests. With spin the block's intervals are covered, from the node above
  // it, with the parabola's bulge over its chord (parabola_below_bound), and the bound along them is
  // smallest at an end (g is concave in x).
  // (kSpin = has_spin: without spin the node tests alone)
  template <bool kSpin>
  int first_slip_node(const double* x, const double* edge_p, double mu, int first, int last) const {
    constexpr int kBlock = 16;
    using Block = Eigen::Array<double, kBlock, 1>;
    if (first - last < kBlock) {  // a short strip
      int k = first;
      if constexpr (kSpin) {
        while (k > last && sticks_at(x[k], mu * edge_p[k]) && sticks_between(k == first ? x_s : x[k + 1], x[k])) --k;
      } else {
        while (k > last && sticks_at(x[k], mu * edge_p[k])) --k;
      }
      return k;
    }
    constexpr bool spin = kSpin;
    for (int k = first; k > last; k -= kBlock) {
      const int base = std::max(k - kBlock + 1, last + 1);  // nodes base .. base + kBlock - 1
      const int top = base + kBlock - 1;
      const double g_min = mu * Block::Map(edge_p + base).minCoeff();
      if constexpr (!spin) {
        if (below_bound(x_s - x[top], x_s - x[base], g_min)) continue;
      } else {  // from the node above the block (edge_p is 0 outside the strip, as the bound at x_s = a)
        const double x_above = top == first ? x_s : x[top + 1];
        if (parabola_below_bound(x_s - x_above, x_s - x[base], std::min(g_min, mu * edge_p[top + 1]))) continue;
      }
      const Block t = x_s - Block::Map(x + base);
      const Block px = start.tx - alpha * t, py = start.ty - beta * t + gamma * t * t;
      const Block g = mu * Block::Map(edge_p + base);
      const Block lo2 = px * px + py * py;
      const Block excess = lo2 - g * g;  // > 0 where Kalker's test fails
      if constexpr (!spin) {
        if (excess.maxCoeff() > 0) {
          for (int q = kBlock - 1; q >= 0; --q)
            if (excess(q) > 0) return base + q;
        }
      } else {
        // between the nodes: a lane is clear where the run's stick solution stays below min(g_hi, g_lo) by
        // a margin far above rounding, |tau| <= max(|tau_hi|, |tau_lo|) + |gamma| h^2 / 4 (the parabola is
        // its chord plus gamma (t - t_hi)(t - t_lo) e_y); elsewhere sticks_between asks the kernel's test
        constexpr double kMargin = 1e-12;
        const double x_above = top == first ? x_s : x[top + 1];
        const StripNode above = at(x_above);
        Block hi2, g_hi, h;
        hi2.head(kBlock - 1) = lo2.tail(kBlock - 1);
        hi2(kBlock - 1) = above.tx * above.tx + above.ty * above.ty;
        g_hi.head(kBlock - 1) = g.tail(kBlock - 1);
        g_hi(kBlock - 1) = mu * edge_p[top + 1];
        h.head(kBlock - 1) = Block::Map(x + base + 1).head(kBlock - 1) - Block::Map(x + base).head(kBlock - 1);
        h(kBlock - 1) = x_above - x[top];
        const Block room = (g.min(g_hi) * (1 - kMargin) - std::abs(gamma) / 4 * h * h).max(0.0);
        const Block clear = lo2.max(hi2) - room * room;  // < 0: clear
        if (excess.maxCoeff() > 0 || clear.maxCoeff() >= 0) {
          for (int q = kBlock - 1; q >= 0; --q) {
            if (excess(q) > 0) return base + q;
            if (clear(q) >= 0 && !sticks_between(base + q == first ? x_s : x[base + q + 1], x[base + q]))
              return base + q;
          }
        }
      }
    }
    return last;
  }

 private:
  // with spin: over [t_a, t_b] the parabola is its chord plus gamma (t - t_a)(t - t_b) e_y, so
  //   |tau(t)| <= max(|tau(t_a)|, |tau(t_b)|) + |gamma| (t_b - t_a)^2 / 4,
  // and that stays below g_min by a margin far above rounding
  bool parabola_below_bound(double t_a, double t_b, double g_min) const {
    constexpr double kMargin = 1e-12;
    const double ax = start.tx - alpha * t_a, ay = start.ty - beta * t_a + gamma * t_a * t_a;
    const double bx = start.tx - alpha * t_b, by = start.ty - beta * t_b + gamma * t_b * t_b;
    const double bulge = std::abs(gamma) * (t_b - t_a) * (t_b - t_a) / 4;
    const double bound = std::sqrt(std::max(ax * ax + ay * ay, bx * bx + by * by)) + bulge;
    const double terms = std::abs(start.tx) + std::abs(start.ty) + (std::abs(alpha) + std::abs(beta)) * t_b +
                         std::abs(gamma) * t_b * t_b;
    return bound + kMargin * (bound + terms) < g_min;
  }
  // |tau| stays below g_min by a margin far above rounding for t in [t_a, t_b], 0 <= t_a <= t_b
  bool below_bound(double t_a, double t_b, double g_min) const {
    constexpr double kMargin = 1e-12;
    const double ax = start.tx - alpha * t_a, ay = start.ty - beta * t_a;
    const double bx = start.tx - alpha * t_b, by = start.ty - beta * t_b;
    const double curve = std::abs(gamma) * t_b * t_b;
    const double bound = std::sqrt(std::max(ax * ax + ay * ay, bx * bx + by * by)) + curve;
    // the size of the terms of the tests, for their rounding
    const double terms =
        std::abs(start.tx) + std::abs(start.ty) + (std::abs(alpha) + std::abs(beta)) * t_b + curve;
    return bound + kMargin * (bound + terms) < g_min;
  }
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
  // the cells of a stick run, first down to last: each interval from the run's stick solution
  void stick_run(const StripRates& r, const StickLine& line, const double* x, int first, int last) const {
    if (!s) return;
    StripNode hi = line.start;
    double x_hi = line.x_s;
    for (int i = first; i >= last; --i) {
      const double x_lo = x[i];
      const StripNode lo = line.at(x_lo);
      IntervalSums sums;
      const double beta = r.eta_L2_Pa_per_m + r.phi_L3_Pa_per_m2 * x_hi;
      detail::add_stick(r, hi, x_hi, beta, line.gamma, x_hi - x_lo, sums);
      interval(i, sums, x_hi - x_lo, VL * dissipation_per_VL(r, hi, lo, sums));
      hi = lo;
      x_hi = x_lo;
    }
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

// The consistent march along one strip, one step at a time: a step is a stick run and one interval
// through the full kernel, or one interval of a slip stretch. Two strips step in turn in one loop, so
// that the CPU overlaps their chains of dependent operations (the crossing into slip, the slip
// direction). kSpin = has_spin: with spin Kalker's test asks more of each interval.
template <bool kFields, bool kSpin>
class StripMarch {
 public:
  // x: the grid's nodes x_edge(i) (nx + 1); turn: room for the strip's slip turns (nx)
  StripMarch(const ContactPatch& patch, const TangentialProblem& pb, int j, const double* x,
             detail::SlipTurn* turn, FieldWriter out)
      : patch_(patch), r_(strip_rates(patch, pb, j)), j_(j), VL_(pb.speed_m_per_s * pb.L_m_per_Pa), x_(x),
        edge_p_(&patch.edge_pressure_Pa(0, j)), turn_(turn), out_(out) {
    // the intervals in contact, cells i_top down to i_bot, each of positive length: the interior
    // nodes x[i], i_bot < i <= i_top, lie strictly inside the strip
    const Grid& g = patch.grid;
    const double a = r_.a_m;
    int i_top = std::min(g.nx - 1, static_cast<int>(std::floor((a + g.half_x_m) / g.dx_m)));
    int i_bot = std::max(0, static_cast<int>(std::floor((-a + g.half_x_m) / g.dx_m)));
    if (!(a > 0)) i_top = i_bot - 1;
    while (i_top >= i_bot && !(x_hi_of(i_top) > x_lo_of(i_top))) --i_top;
    while (i_bot < i_top && !(x_hi_of(i_bot) > x_lo_of(i_bot))) ++i_bot;
    i_ = i_top;
    i_bot_ = i_bot;
    turns_to_ = i_bot;
  }

  bool done() const { return i_ < i_bot_; }

  // the node is in slip inside the strip: the next step is one interval of a slip stretch
  bool in_slip() const { return !node_.stick && i_ > i_bot_; }

  // one interval of a slip stretch, which runs from a slip node through the cells inside the strip
  // while they slip (the direction of tau carries over); the slip turns of all the cells down to the
  // trailing one are taken together, off the march
  [[gnu::always_inline]] void slip_interval() {
    if (!in_stretch_) {
      stretch_first_ = node_;
      stretch_ = IntervalSums{};
      in_stretch_ = true;
    }
    const int i = i_;
    auto turn = [&] {
      if (i > turns_to_) {
        slip_turns(r_, x_, i, i_bot_ + 1, turn_);
        turns_to_ = i;
      }
      return turn_[i];
    };
    const double dx = patch_.grid.dx_m;
    const IntervalGeometry geo{x_[i + 1], x_[i], r_.mu * edge_p_[i], patch_.pressure_Pa(i, j_) * dx,
                               patch_.pressure_moment_Pa_m(i, j_) * dx};
    IntervalSums cell;
    const StripNode lo = march_slip_interval<kSpin>(r_, node_, geo, turn, cell);
    if constexpr (kFields)
      out_.interval(i, cell, geo.x_hi - geo.x_lo, VL_ * dissipation_per_VL(r_, node_, lo, cell));
    add_interval_sums(stretch_, cell);
    node_ = lo;
    --i_;
    if (node_.stick || i_ == i_bot_) {
      add(stretch_first_, node_, stretch_);
      in_stretch_ = false;
    }
  }

  // a slip interval, or a stick run and one interval through the full kernel
  void step() {
    if (in_slip()) {
      slip_interval();
      return;
    }
    const double dx = patch_.grid.dx_m;

    // stick run: one stick solution from this node through every interior node that passes Kalker's
    // test; the tests are independent of each other, the run's integrals are closed forms
    if (node_.stick && i_ > i_bot_) {
      const StickLine line(r_, node_, x_hi_of(i_));
      const int k = line.template first_slip_node<kSpin>(x_, edge_p_, r_.mu, i_, i_bot_);
      if (k < i_) {  // intervals i down to k + 1 stick
        const double x_end = x_[k + 1];
        const StripNode end = line.at(x_end);
        IntervalSums sums;
        detail::add_stick(r_, node_, line.x_s, line.beta, line.gamma, line.x_s - x_end, sums);
        add(node_, end, sums);
        if constexpr (kFields) out_.stick_run(r_, line, x_, i_, k + 1);
        node_ = end;
        i_ = k;
      }
    }

    // one interval through the full kernel: the crossing into slip, or the trailing interval
    const int i = i_;
    IntervalGeometry geo;
    geo.x_hi = x_hi_of(i);
    geo.x_lo = x_lo_of(i);
    geo.bound_lo_Pa = geo.x_lo > -r_.a_m ? r_.mu * edge_p_[i] : 0.0;
    geo.load_N_per_m = patch_.pressure_Pa(i, j_) * dx;
    geo.moment_N = patch_.pressure_moment_Pa_m(i, j_) * dx;
    IntervalSums sums;
    const StripNode lo = march_interval<kSpin>(r_, node_, geo, sums);
    add(node_, lo, sums);
    if constexpr (kFields)
      out_.interval(i, sums, geo.x_hi - geo.x_lo, VL_ * dissipation_per_VL(r_, node_, lo, sums));
    node_ = lo;
    --i_;
  }

  // when done: the totals, with the elastic energy carried out at the trailing edge
  SteadyStrip totals() const {
    SteadyStrip st = st_;
    st.trailing = VL_ * (node_.tx * node_.tx + node_.ty * node_.ty) / 2;
    return st;
  }

 private:
  double x_hi_of(int i) const { return std::min(x_[i + 1], r_.a_m); }
  double x_lo_of(int i) const { return std::max(x_[i], -r_.a_m); }

  // totals of a stretch from node hi to node lo; its dissipated power is -integral(tau . s dx)
  void add(const StripNode& hi, const StripNode& lo, const IntervalSums& sums) {
    st_.Fx += sums.Ix;
    st_.Fy += sums.Iy;
    st_.Mz += sums.Ixy - r_.y_m * sums.Ix;
    st_.dissipated += VL_ * dissipation_per_VL(r_, hi, lo, sums);
    st_.creep_power += VL_ * creep_power_per_VL(r_, sums);
    st_.stick_length += sums.stick_length_m;
  }

  const ContactPatch& patch_;
  const StripRates r_;
  const int j_;
  const double VL_;
  const double* x_;
  const double* edge_p_;
  detail::SlipTurn* turn_;
  FieldWriter out_;

  int i_ = 0, i_bot_ = 0;  // the next interval is cell i_; the last is i_bot_
  int turns_to_ = 0;       // cells i_bot_ + 1 .. turns_to_ have their slip turn
  StripNode node_;         // the leading edge: tau = 0 = bound, stick
  bool in_stretch_ = false;
  StripNode stretch_first_;
  IntervalSums stretch_;
  SteadyStrip st_;
};

// Pure xi on strip j (eta = phi = 0): the consistent march's result in closed form (docs/physics.md §4).
// From the leading edge tau_x = -alpha t (t = a - x) sticks until it meets the bound g = G sqrt(1 - x^2/a^2),
//   alpha^2 t^2 = (G/a)^2 t (2a - t)   =>   t_s = 2 a G^2 / (a^2 alpha^2 + G^2),
// and slips on the bound from there to the trailing edge (the bound falls there faster than the stick line
// could, so it never sticks again): Fx = -alpha t_s^2/2 - sign(alpha) G a S(1 - t_s/a), S the integral of
// sqrt(1 - u^2) from -1. tau = 0 at both ends, so the strip's power is its creep power -V L alpha Fx.
// The march reaches the same numbers, since it integrates these pieces exactly on any grid.
SteadyStrip pure_xi_strip(const StripRates& r, double VL) {
  SteadyStrip st;
  const double a = r.a_m, alpha = r.alpha_Pa_per_m, G = r.bound_Pa;
  if (alpha == 0) {  // no creepage: no traction, all stick
    st.stick_length = 2 * a;
    return st;
  }
  const double t_s = 2 * a * G * G / (a * a * alpha * alpha + G * G);
  st.Fx = -alpha * t_s * t_s / 2 - std::copysign(G * a * semi_ellipse_integral(1 - t_s / a), alpha);
  st.Mz = -r.y_m * st.Fx;
  st.dissipated = st.creep_power = -VL * alpha * st.Fx;
  st.stick_length = t_s;
  return st;
}

// all strips below `strips` in closed form (pure xi)
std::vector<SteadyStrip> pure_xi_strips(const ContactPatch& patch, const TangentialProblem& pb, int strips) {
  std::vector<SteadyStrip> totals(patch.grid.ny);
  const double VL = pb.speed_m_per_s * pb.L_m_per_Pa;
  for (int j = 0; j < strips; ++j)
    if (patch.half_length_m(j) > 0) totals[j] = pure_xi_strip(strip_rates(patch, pb, j), VL);
  return totals;
}

// the consistent march of the strips below `strips`, two at a time
template <bool kFields, bool kSpin>
std::vector<SteadyStrip> march_consistent(const ContactPatch& patch, const TangentialProblem& pb,
                                          TangentialSolution& s, int strips) {
  const Grid& g = patch.grid;
  Eigen::ArrayXd x(g.nx + 1);
  for (int i = 0; i <= g.nx; ++i) x(i) = g.x_edge(i);
  std::vector<detail::SlipTurn> turns(2 * static_cast<size_t>(g.nx));
  const double VL = pb.speed_m_per_s * pb.L_m_per_Pa;
  auto strip = [&](int j, detail::SlipTurn* turn) {
    return StripMarch<kFields, kSpin>(patch, pb, j, x.data(), turn, {kFields ? &s : nullptr, j, g.dx_m, VL});
  };

  std::vector<SteadyStrip> totals(g.ny);
  int j = 0;
  for (; j + 1 < strips; j += 2) {
    StripMarch<kFields, kSpin> a = strip(j, turns.data()), b = strip(j + 1, turns.data() + g.nx);
    while (!a.done() || !b.done()) {
      while (a.in_slip() && b.in_slip()) {  // the common case, without the branches of step()
        a.slip_interval();
        b.slip_interval();
      }
      if (!a.done()) a.step();
      if (!b.done()) b.step();
    }
    totals[j] = a.totals();
    totals[j + 1] = b.totals();
  }
  if (j < strips) {
    StripMarch<kFields, kSpin> a = strip(j, turns.data());
    while (!a.done()) a.step();
    totals[j] = a.totals();
  }
  return totals;
}

// the march compiled with or without spin (phi/L3 is the same on every strip)
template <bool kFields>
std::vector<SteadyStrip> march_consistent_strips(const ContactPatch& patch, const TangentialProblem& pb,
                                                 TangentialSolution& s, int strips) {
  const bool spin = patch.grid.ny > 0 && has_spin(strip_rates(patch, pb, 0));
  return spin ? march_consistent<kFields, true>(patch, pb, s, strips)
              : march_consistent<kFields, false>(patch, pb, s, strips);
}

SteadyStrip march_classic(const ContactPatch& patch, const TangentialProblem& pb, int j, FieldWriter out) {
  const Grid& g = patch.grid;
  const StripRates r = strip_rates(patch, pb, j);
  const double a = r.a_m, y = r.y_m, alpha = r.alpha_Pa_per_m;
  const double eta_L2 = r.eta_L2_Pa_per_m, phi_L3 = r.phi_L3_Pa_per_m2;
  const double VL = pb.speed_m_per_s * pb.L_m_per_Pa;
  const double G = r.bound_Pa;
  const double dx = g.dx_m;

  SteadyStrip st;
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
    st.dissipated += power * dx;
    st.creep_power += -VL * (alpha * tx + (eta_L2 + phi_L3 * x) * ty) * dx;
    if (!slip) st.stick_length += dx;
    st.counted_length += dx;
  }
  st.trailing = VL * (tx * tx + ty * ty) / 2;
  return st;
}

// the classic march of the strips below `strips`
std::vector<SteadyStrip> march_classic_strips(const ContactPatch& patch, const TangentialProblem& pb,
                                              TangentialSolution& s, bool fields, int strips) {
  const Grid& g = patch.grid;
  const double VL = pb.speed_m_per_s * pb.L_m_per_Pa;
  std::vector<SteadyStrip> totals(g.ny);
  for (int j = 0; j < strips; ++j) {
    if (!(patch.half_length_m(j) > 0)) continue;
    totals[j] = march_classic(patch, pb, j, {fields ? &s : nullptr, j, g.dx_m, VL});
  }
  return totals;
}

}  // namespace

StripRates strip_rates(const ContactPatch& patch, const TangentialProblem& pb, int j) {
  const Creepages& c = pb.creepages;
  const double xi = c.xi + (patch.strip_xi_offset.size() > j ? patch.strip_xi_offset(j) : 0.0);
  StripRates r;
  r.a_m = patch.half_length_m(j);
  r.y_m = patch.grid.y_m(j);
  const double L3x = pb.L3x_m_per_Pa != 0 ? pb.L3x_m_per_Pa : pb.flex.L3_m_per_Pa;
  r.alpha_Pa_per_m = xi / pb.flex.L1_m_per_Pa - c.phi_per_m * r.y_m / L3x;
  r.eta_L2_Pa_per_m = c.eta / pb.flex.L2_m_per_Pa;
  r.phi_L3_Pa_per_m2 = c.phi_per_m / pb.flex.L3_m_per_Pa;
  r.mu = pb.mu;
  r.peak_Pa = patch.strip_peak_Pa(j);
  r.bound_Pa = pb.mu * r.peak_Pa;
  return r;
}

TangentialSolution solve_steady(const ContactPatch& patch, const TangentialProblem& problem,
                                TangentialScheme scheme, const SteadyOptions& options) {
  if (scheme == TangentialScheme::Exact)
    throw std::invalid_argument("solve_steady: the exact theory is not a scheme of the simplified theory; "
                                "solve_exact_steady (lib/tangential/exact.h) solves it");
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

  // the skips (SteadyOptions::skips): strips from `strips` up are mirror images; pure xi in closed form
  const Creepages& c = problem.creepages;
  const int strips = first_mirrored_strip(patch, c.phi_per_m, options.skips);
  const bool closed_form = options.skips && !options.fields && scheme == TangentialScheme::Consistent &&
                           c.eta == 0 && c.phi_per_m == 0;
  std::vector<SteadyStrip> totals =
      scheme == TangentialScheme::Classic ? march_classic_strips(patch, problem, s, options.fields, strips)
      : closed_form                       ? pure_xi_strips(patch, problem, strips)
      : options.fields                    ? march_consistent_strips<true>(patch, problem, s, strips)
                                          : march_consistent_strips<false>(patch, problem, s, strips);
  for (int j = strips; j < g.ny; ++j) {  // the mirror images: tau(x, -y) = tau(x, y)
    const int m = g.ny - 1 - j;
    totals[j] = totals[m];
    totals[j].Mz += (g.y_m(m) - g.y_m(j)) * totals[m].Fx;  // Mz = integral(x tau_y) - y Fx
    if (options.fields) {
      s.tau_x_Pa.col(j) = s.tau_x_Pa.col(m);
      s.tau_y_Pa.col(j) = s.tau_y_Pa.col(m);
      s.slip_x_m_per_s.col(j) = s.slip_x_m_per_s.col(m);
      s.slip_y_m_per_s.col(j) = s.slip_y_m_per_s.col(m);
      s.power_W_per_m2.col(j) = s.power_W_per_m2.col(m);
      s.state.col(j) = s.state.col(m);
    }
  }

  // the strips' invariants (strip_totals_hold): dissipation is a path integral of -tau . s (classic's cell
  // sums too), >= 0 beyond the rounding of the terms it is the difference of, V L (mu p_j)^2 2 a_j at most
  // (|tau| <= mu p_j along 2 a_j)
  auto energy_scale = [&](int j) {
    const double bound_j = problem.mu * patch.strip_peak_Pa(j);
    return problem.speed_m_per_s * problem.L_m_per_Pa * bound_j * bound_j * 2 * patch.half_length_m(j);
  };
  bool hold = true;
  for (int j = 0; j < g.ny; ++j) {
    if (!(patch.half_length_m(j) > 0)) continue;
    const SteadyStrip& st = totals[j];
    hold &= strip_totals_hold(patch, problem.mu, j, st, true, energy_scale(j));
    s.strip_power_W_per_m(j) = st.dissipated;
    s.strip_creep_power_W_per_m(j) = st.creep_power;
    s.strip_trailing_W_per_m(j) = st.trailing;
    s.strip_force_x_N_per_m(j) = st.Fx;
    s.strip_force_y_N_per_m(j) = st.Fy;
  }
  // classic counts dx per cell centre in contact
  const PatchTotals t = checked_patch_totals(patch, problem.mu, totals, hold, true, energy_scale);
  s.Fx_N = t.Fx_N;
  s.Fy_N = t.Fy_N;
  s.Mz_N_m = t.Mz_N_m;
  s.power_W = t.dissipated;
  s.stick_fraction = t.stick_fraction;
  // work of the creep forces, with the local xi of each strip where the rolling radius varies
  double xi_Fx = c.xi * s.Fx_N;
  if (patch.strip_xi_offset.size() == g.ny)
    xi_Fx += (patch.strip_xi_offset * s.strip_force_x_N_per_m).sum() * g.dy_m;
  s.creep_work_W = problem.speed_m_per_s * (xi_Fx + c.eta * s.Fy_N + c.phi_per_m * s.Mz_N_m);
  spdlog::debug("steady ({}, {} x {}): Fx {:.6e} N, Fy {:.6e} N, Mz {:.6e} N m, P {:.6e} W, stick {:.3f}",
                to_string(scheme), g.nx, g.ny, s.Fx_N, s.Fy_N, s.Mz_N_m, s.power_W, s.stick_fraction);
  return s;
}

}  // namespace contact
