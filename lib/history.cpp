#include "lib/history.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace contact {

History constant_history(double value) { return {{0.0}, {value}}; }

History ramp_history(double t0_s, double v0, double t1_s, double v1) { return {{t0_s, t1_s}, {v0, v1}}; }

void check_history(const History& h, const char* what) {
  if (h.t_s.empty() || h.t_s.size() != h.value.size())
    throw std::invalid_argument(std::string(what) + ": a history needs at least one (t, value) row");
  for (size_t k = 0; k < h.t_s.size(); ++k) {
    if (!std::isfinite(h.t_s[k]) || !std::isfinite(h.value[k]))
      throw std::invalid_argument(std::string(what) + ": row " + std::to_string(k + 1) + " is not finite");
    if (k > 0 && !(h.t_s[k] > h.t_s[k - 1]))
      throw std::invalid_argument(std::string(what) + ": times must increase, row " + std::to_string(k + 1) +
                                  " has t = " + std::to_string(h.t_s[k]) + " s after " +
                                  std::to_string(h.t_s[k - 1]) + " s");
  }
}

double value_at(const History& h, double t) {
  const auto& T = h.t_s;
  if (t <= T.front()) return h.value.front();
  if (t >= T.back()) return h.value.back();
  const size_t k = std::upper_bound(T.begin(), T.end(), t) - T.begin();  // T[k-1] <= t < T[k]
  const double w = (t - T[k - 1]) / (T[k] - T[k - 1]);
  return h.value[k - 1] + w * (h.value[k] - h.value[k - 1]);
}

double max_value(const History& h) { return *std::max_element(h.value.begin(), h.value.end()); }
double min_value(const History& h) { return *std::min_element(h.value.begin(), h.value.end()); }

bool is_constant(const History& h) { return max_value(h) == min_value(h); }

double constant_since(const History& h, double t) {
  const auto& T = h.t_s;
  const auto& v = h.value;
  // the last row at or before t, then back over rows of the same value
  size_t k = std::upper_bound(T.begin(), T.end(), t) - T.begin();  // T[k-1] <= t < T[k]
  if (k == 0) return -std::numeric_limits<double>::infinity();     // held before the first row
  if (k < T.size() && v[k] != v[k - 1] && t > T[k - 1]) return t;  // inside a ramp
  while (k > 1 && v[k - 2] == v[k - 1]) --k;
  return k == 1 ? -std::numeric_limits<double>::infinity() : T[k - 1];
}

double constant_until(const History& h, double t) {
  const auto& T = h.t_s;
  const auto& v = h.value;
  // the first row at or after t, then on over rows of the same value
  size_t k = std::lower_bound(T.begin(), T.end(), t) - T.begin();  // T[k-1] < t <= T[k]
  if (k == T.size()) return std::numeric_limits<double>::infinity();  // held after the last row
  if (k > 0 && T[k] != t && v[k] != v[k - 1]) return t;               // inside a ramp
  while (k + 1 < T.size() && v[k + 1] == v[k]) ++k;
  return k + 1 == T.size() ? std::numeric_limits<double>::infinity() : T[k];
}

namespace {
// breakpoints of the history strictly between t0 and t1, with t0 and t1 themselves
std::vector<double> pieces(const History& h, double t0, double t1) {
  std::vector<double> p{t0};
  for (double t : h.t_s)
    if (t > t0 && t < t1) p.push_back(t);
  p.push_back(t1);
  return p;
}
}  // namespace

double integral(const History& h, double t0, double t1) {
  if (!(t1 > t0)) return 0;
  if (std::isinf(t1)) return value_at(h, t0) == 0 && h.value.back() == 0 ? 0 : std::numeric_limits<double>::infinity();
  double sum = 0;
  const std::vector<double> p = pieces(h, t0, t1);
  for (size_t k = 1; k < p.size(); ++k) sum += (p[k] - p[k - 1]) * (value_at(h, p[k - 1]) + value_at(h, p[k])) / 2;
  return sum;
}

double time_to_accumulate(const History& h, double t0, double amount) {
  if (!(amount > 0)) return t0;
  double t = t0, left = amount;
  // linear pieces up to the last row, then the constant tail
  std::vector<double> breaks;
  for (double tb : h.t_s)
    if (tb > t0) breaks.push_back(tb);
  for (double tb : breaks) {
    const double v0 = value_at(h, t), v1 = value_at(h, tb);
    const double piece = (tb - t) * (v0 + v1) / 2;
    if (piece >= left) {
      // solve v0 s + (v1 - v0) s^2 / (2 (tb - t)) = left for s in [0, tb - t]
      const double slope = (v1 - v0) / (tb - t);
      double s = 0;
      if (std::abs(slope) * (tb - t) <= 1e-14 * std::abs(v0)) {
        s = left / v0;
      } else {
        const double disc = std::max(0.0, v0 * v0 + 2 * slope * left);
        s = 2 * left / (v0 + std::sqrt(disc));  // stable root of slope/2 s^2 + v0 s - left = 0
      }
      return t + std::min(s, tb - t);
    }
    left -= piece;
    t = tb;
  }
  const double v = h.value.back();
  if (!(v > 0)) return std::numeric_limits<double>::infinity();
  return t + left / v;
}

}  // namespace contact
