// A quantity given as a function of time: piecewise linear through (t, value) rows, held constant
// before the first row and after the last. One row is a constant; two rows are a linear ramp.
#pragma once

#include <vector>

namespace contact {

struct History {
  std::vector<double> t_s;    // strictly increasing
  std::vector<double> value;  // same size, at least one row
};

History constant_history(double value);
History ramp_history(double t0_s, double v0, double t1_s, double v1);

// throws std::invalid_argument for empty, mismatched, non-increasing or non-finite rows
void check_history(const History& h, const char* what);

double value_at(const History& h, double t_s);
double max_value(const History& h);
double min_value(const History& h);
// integral of the history from t0 to t1 (exact for the piecewise-linear function)
double integral(const History& h, double t0_s, double t1_s);
// the time t1 >= t0 at which the integral from t0 reaches `amount` (>= 0), or +inf if never
// (the history must be >= 0 from t0 on, e.g. a speed and a rolled distance)
double time_to_accumulate(const History& h, double t0_s, double amount);
// true if the history is the same value at all times
bool is_constant(const History& h);
// The stretch of constant value around t_s: the earliest t0 <= t_s with the history constant on
// [t0, t_s] (-inf: constant since the start), and the latest t1 >= t_s with it constant on [t_s, t1]
// (+inf: constant from there on). Inside a ramp both return t_s.
double constant_since(const History& h, double t_s);
double constant_until(const History& h, double t_s);

}  // namespace contact
