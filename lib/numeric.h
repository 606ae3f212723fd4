// What every solver shares: pi, an invariant check that stays on in every build type, and one
// bracketed root finder for a scalar function.
#pragma once

#include <spdlog/fmt/fmt.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace contact {

inline constexpr double kPi = 3.14159265358979323846;

// A broken invariant inside a solver: a defect of the program, never of the input. The command
// line reports it as a failure (exit 1) with the file and line of the check.
struct InvariantError : std::logic_error {
  using std::logic_error::logic_error;
};

[[noreturn]] inline void invariant_failed(const char* condition, const char* file, int line,
                                          const std::string& detail) {
  throw InvariantError(fmt::format("{}:{}: invariant '{}' broken{}{}", file, line, condition,
                                   detail.empty() ? "" : ": ", detail));
}

}  // namespace contact

// ROLLWEAR_ASSERT(condition, detail): on in Release too. Check per solve or per strip, never per
// cell: `detail` (a std::string expression) is built only when the check fails.
#define ROLLWEAR_ASSERT(condition, detail)                                          \
  do {                                                                              \
    if (!(condition)) ::contact::invariant_failed(#condition, __FILE__, __LINE__, (detail)); \
  } while (false)

namespace contact {

// The root of f on a bracket [lo, hi] with f(lo) f(hi) <= 0: Illinois regula falsi, with a
// bisection whenever the bracket has not halved in two steps, so that it converges at least as
// fast as bisection and superlinearly on a smooth f. Stops when the bracket is narrower than
// x_tol, when |f| <= f_tol, or after max_iterations (converged = false: the caller decides).
struct RootResult {
  double x = 0;           // the last estimate (the bracket end with the smaller |f|)
  double f = 0;           // f(x)
  double lo = 0, hi = 0;  // the final bracket
  int iterations = 0;
  bool converged = false;
};

template <class F>
RootResult find_root_bracketed(F&& f, double lo, double hi, double f_lo, double f_hi, double x_tol,
                               double f_tol = 0, int max_iterations = 200) {
  RootResult r;
  r.lo = lo;
  r.hi = hi;
  auto finish = [&](double x, double fx, bool converged) {
    r.x = x;
    r.f = fx;
    r.converged = converged;
    return r;
  };
  if (f_lo == 0) return finish(lo, f_lo, true);
  if (f_hi == 0) return finish(hi, f_hi, true);
  if ((f_lo > 0) == (f_hi > 0) || !std::isfinite(f_lo) || !std::isfinite(f_hi))
    return finish(std::abs(f_lo) < std::abs(f_hi) ? lo : hi, std::abs(f_lo) < std::abs(f_hi) ? f_lo : f_hi,
                  false);
  double w_lo = 1, w_hi = 1;  // Illinois weights: an end kept twice in a row has its f halved
  int kept = 0;               // +1: lo was kept last time, -1: hi was kept
  double width_two_ago = std::abs(hi - lo) * 4, width_one_ago = width_two_ago;
  for (; r.iterations < max_iterations; ++r.iterations) {
    const double width = std::abs(r.hi - r.lo);
    const bool small_f = std::min(std::abs(f_lo), std::abs(f_hi)) <= f_tol;
    if (width <= x_tol || small_f) {
      const bool lo_better = std::abs(f_lo) <= std::abs(f_hi);
      return finish(lo_better ? r.lo : r.hi, lo_better ? f_lo : f_hi, true);
    }
    double x = 0.5 * (r.lo + r.hi);
    if (width <= 0.5 * width_two_ago) {
      const double a = w_lo * f_lo, b = w_hi * f_hi;
      x = r.lo + (r.hi - r.lo) * a / (a - b);
      if (!(std::abs(x - r.lo) < width && std::abs(x - r.hi) < width)) x = 0.5 * (r.lo + r.hi);
    }
    width_two_ago = width_one_ago;
    width_one_ago = width;
    const double fx = f(x);
    if (fx == 0) {
      ++r.iterations;
      r.lo = r.hi = x;
      return finish(x, fx, true);
    }
    if (!std::isfinite(fx)) return finish(x, fx, false);
    if ((fx > 0) == (f_lo > 0)) {  // the root lies in [x, hi]
      r.lo = x;
      f_lo = fx;
      w_lo = 1;
      if (kept == -1) w_hi *= 0.5;
      kept = -1;
    } else {
      r.hi = x;
      f_hi = fx;
      w_hi = 1;
      if (kept == +1) w_lo *= 0.5;
      kept = +1;
    }
  }
  const bool lo_better = std::abs(f_lo) <= std::abs(f_hi);
  return finish(lo_better ? r.lo : r.hi, lo_better ? f_lo : f_hi, false);
}

}  // namespace contact
