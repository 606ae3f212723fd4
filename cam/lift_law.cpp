// Lift laws (docs/cam-follower.md §1).
#include "cam/lift_law.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_error.h"
#include "lib/numeric.h"

namespace cam {

using contact::kPi;

SegmentLaw parse_segment_law(const std::string& name) {
  if (name == "dwell") return SegmentLaw::Dwell;
  if (name == "cycloidal") return SegmentLaw::Cycloidal;
  if (name == "polynomial-345") return SegmentLaw::Polynomial345;
  if (name == "harmonic") return SegmentLaw::Harmonic;
  throw std::invalid_argument("must be one of cycloidal, polynomial-345, harmonic, dwell, got '" + name + "'");
}

const char* to_string(SegmentLaw law) {
  switch (law) {
    case SegmentLaw::Dwell: return "dwell";
    case SegmentLaw::Cycloidal: return "cycloidal";
    case SegmentLaw::Polynomial345: return "polynomial-345";
    case SegmentLaw::Harmonic: return "harmonic";
  }
  return "?";
}

LiftSample segment_lift(SegmentLaw law, double h, double beta, double u) {
  LiftSample r;
  switch (law) {
    case SegmentLaw::Dwell: return r;
    case SegmentLaw::Cycloidal:
      r.s_m = h * (u - std::sin(2 * kPi * u) / (2 * kPi));
      r.ds_m_per_rad = h / beta * (1 - std::cos(2 * kPi * u));
      r.d2s_m_per_rad2 = 2 * kPi * h / (beta * beta) * std::sin(2 * kPi * u);
      return r;
    case SegmentLaw::Polynomial345: {
      const double u2 = u * u, u3 = u2 * u;
      r.s_m = h * (10 * u3 - 15 * u3 * u + 6 * u3 * u2);
      r.ds_m_per_rad = h / beta * (30 * u2 - 60 * u3 + 30 * u2 * u2);
      r.d2s_m_per_rad2 = h / (beta * beta) * (60 * u - 180 * u2 + 120 * u3);
      return r;
    }
    case SegmentLaw::Harmonic:
      r.s_m = 0.5 * h * (1 - std::cos(kPi * u));
      r.ds_m_per_rad = 0.5 * kPi * h / beta * std::sin(kPi * u);
      r.d2s_m_per_rad2 = 0.5 * kPi * kPi * h / (beta * beta) * std::cos(kPi * u);
      return r;
  }
  return r;
}

namespace {

LiftSample segment_at(const Segment& g, double theta) {
  const double u = std::clamp((theta - g.start_rad) / g.duration_rad, 0.0, 1.0);
  LiftSample r = segment_lift(g.law, g.rise_m, g.duration_rad, u);
  r.s_m += g.s_start_m;
  return r;
}

double wrap(double theta) {
  double t = std::fmod(theta, 2 * kPi);
  if (t < 0) t += 2 * kPi;
  return t;
}

// centred quintic B-spline and its first two derivatives, support (-3, 3)
void bspline5(double t, double& b, double& db, double& d2b) {
  static const double kBinom[7] = {1, 6, 15, 20, 15, 6, 1};
  b = db = d2b = 0;
  for (int k = 0; k <= 6; ++k) {
    const double x = t + 3 - k;
    if (x <= 0) break;
    const double w = (k % 2 ? -1.0 : 1.0) * kBinom[k];
    const double x2 = x * x, x3 = x2 * x;
    b += w * x3 * x2 / 120;
    db += w * x2 * x2 / 24;
    d2b += w * x3 / 6;
  }
}

}  // namespace

LiftLaw make_dwell_rise_dwell_return(const DwellRiseDwellReturn& d) {
  if (!(d.lift_m > 0) || !std::isfinite(d.lift_m)) throw std::invalid_argument("lift must be > 0 and finite");
  if (!(d.rise_rad > 0) || !(d.return_rad > 0) || !(d.dwell_high_rad >= 0))
    throw std::invalid_argument("rise and return must last > 0, the high dwell >= 0");
  if (d.rise_law == SegmentLaw::Dwell || d.return_law == SegmentLaw::Dwell)
    throw std::invalid_argument("a rise or a return cannot be a dwell");
  const double low = 2 * kPi - d.rise_rad - d.dwell_high_rad - d.return_rad;
  if (low < -1e-12)
    throw std::invalid_argument(fmt::format("rise + high dwell + return = {:.6g} deg exceeds 360 deg",
                                            (2 * kPi - low) * kDegPerRad));
  LiftLaw law;
  double t = 0;
  const auto add = [&](SegmentLaw l, double beta, double s0, double h) {
    if (beta <= 0) return;
    law.segments.push_back({l, t, beta, s0, h});
    t += beta;
  };
  add(d.rise_law, d.rise_rad, 0, d.lift_m);
  add(SegmentLaw::Dwell, d.dwell_high_rad, d.lift_m, 0);
  add(d.return_law, d.return_rad, d.lift_m, -d.lift_m);
  add(SegmentLaw::Dwell, std::max(low, 0.0), 0, 0);
  law.segments.back().duration_rad = 2 * kPi - law.segments.back().start_rad;  // closes the revolution exactly

  // the largest acceleration: the peaks of the laws
  for (const Segment& g : law.segments) {
    const double b2 = g.duration_rad * g.duration_rad, h = std::abs(g.rise_m);
    double peak = 0;
    if (g.law == SegmentLaw::Cycloidal) peak = 2 * kPi * h / b2;
    if (g.law == SegmentLaw::Polynomial345) peak = 10 * std::sqrt(3.0) / 3 * h / b2;  // at u = (3 -+ sqrt 3)/6
    if (g.law == SegmentLaw::Harmonic) peak = 0.5 * kPi * kPi * h / b2;
    law.max_abs_d2s_m_per_rad2 = std::max(law.max_abs_d2s_m_per_rad2, peak);
  }
  // the acceleration must be continuous at every boundary, 2 pi -> 0 included
  const std::size_t n = law.segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Segment& left = law.segments[i];
    const Segment& right = law.segments[(i + 1) % n];
    const double at = (i + 1 == n) ? 0.0 : right.start_rad;
    const double a_left = segment_at(left, left.start_rad + left.duration_rad).d2s_m_per_rad2;
    const double a_right = segment_at(right, right.start_rad).d2s_m_per_rad2;
    if (std::abs(a_left - a_right) > kAccelerationJumpRtol * law.max_abs_d2s_m_per_rad2)
      // the key of the moving segment whose end acceleration does not vanish
      throw CamError(CamErrorKind::AccelerationJump, at,
                     (std::abs(a_left) >= std::abs(a_right) ? left : right).rise_m > 0 ? "lift.rise_law"
                                                                                       : "lift.return_law",
                     fmt::format("the acceleration jumps at cam angle {:.6g} deg from {:.6g} to {:.6g} m/rad^2 "
                                 "({} meets {}): use a law whose acceleration vanishes at its ends "
                                 "(cycloidal, polynomial-345), or harmonic rise and return of equal length "
                                 "without dwells",
                                 at * kDegPerRad, a_left, a_right, to_string(left.law), to_string(right.law)));
  }
  return law;
}

LiftLaw make_table_law(const std::vector<double>& lift_m, double tolerance) {
  const std::size_t n = lift_m.size();
  if (n < 8) throw std::invalid_argument(fmt::format("a lift table needs at least 8 points, got {}", n));
  for (double s : lift_m)
    if (!std::isfinite(s)) throw std::invalid_argument("a lift table's values must be finite");
  if (!(tolerance > 0)) throw std::invalid_argument("the table tolerance must be > 0");
  LiftLaw law;
  law.is_table = true;
  PeriodicQuinticSpline& sp = law.table;
  sp.h_rad = 2 * kPi / static_cast<double>(n);
  sp.lift_m = lift_m;
  // interpolation: (c_{j-2} + 26 c_{j-1} + 66 c_j + 26 c_{j+1} + c_{j+2}) / 120 = s_j, by Jacobi sweeps
  const auto at = [n](const std::vector<double>& v, long j) { return v[static_cast<std::size_t>((j % long(n) + long(n)) % long(n))]; };
  std::vector<double> c(n), next(n);
  for (std::size_t j = 0; j < n; ++j) c[j] = lift_m[j];
  double scale = 0;
  for (double s : lift_m) scale = std::max(scale, std::abs(s));
  bool converged = false;
  for (int sweep = 0; sweep < 2000 && !converged; ++sweep) {
    double change = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const long k = static_cast<long>(j);
      next[j] = (120 * lift_m[j] - at(c, k - 2) - 26 * at(c, k - 1) - 26 * at(c, k + 1) - at(c, k + 2)) / 66;
      change = std::max(change, std::abs(next[j] - c[j]));
    }
    c.swap(next);
    converged = change <= kSplineSolveRtol * std::max(scale, 1e-300);
  }
  ROLLWEAR_ASSERT(converged, "the periodic quintic spline's Jacobi sweeps did not converge");
  sp.c = c;

  // the check: the fit's s'' at each node against the data's central difference
  const double h = sp.h_rad;
  double max_cd = 0, worst = 0;
  std::size_t worst_i = 0;
  std::vector<double> cd(n);
  for (std::size_t i = 0; i < n; ++i) {
    const long k = static_cast<long>(i);
    cd[i] = (at(lift_m, k + 1) - 2 * lift_m[i] + at(lift_m, k - 1)) / (h * h);
    max_cd = std::max(max_cd, std::abs(cd[i]));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::abs(lift_at(law, h * static_cast<double>(i)).d2s_m_per_rad2 - cd[i]);
    if (d > worst) worst = d, worst_i = i;
  }
  law.max_abs_d2s_m_per_rad2 = max_cd;
  if (max_cd > 0 && worst > tolerance * max_cd) {
    const double angle = h * static_cast<double>(worst_i);
    throw CamError(CamErrorKind::TableFit, angle, "table_tolerance",
                   fmt::format("the lift table's spline acceleration departs from the data's central difference "
                               "by {:.4g} m/rad^2 at cam angle {:.6g} deg, {:.3g} of the largest |s''| {:.4g} "
                               "m/rad^2 > table_tolerance {:.3g}: the table is too coarse for its acceleration, "
                               "or its acceleration jumps there",
                               worst, angle * kDegPerRad, worst / max_cd, max_cd, tolerance));
  }
  return law;
}

LiftSample lift_at(const LiftLaw& law, double theta_rad) {
  const double theta = wrap(theta_rad);
  if (!law.is_table) {
    for (const Segment& g : law.segments)
      if (theta < g.start_rad + g.duration_rad) return segment_at(g, theta);
    return segment_at(law.segments.back(), theta);
  }
  const PeriodicQuinticSpline& sp = law.table;
  const long n = static_cast<long>(sp.c.size());
  const double t = theta / sp.h_rad;
  const long base = static_cast<long>(std::floor(t));
  LiftSample r;
  for (long j = base - 2; j <= base + 3; ++j) {
    double b = 0, db = 0, d2b = 0;
    bspline5(t - static_cast<double>(j), b, db, d2b);
    const double cj = sp.c[static_cast<std::size_t>((j % n + n) % n)];
    r.s_m += cj * b;
    r.ds_m_per_rad += cj * db / sp.h_rad;
    r.d2s_m_per_rad2 += cj * d2b / (sp.h_rad * sp.h_rad);
  }
  return r;
}

}  // namespace cam
