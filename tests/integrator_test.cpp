// wear/integrator.h: ARKODE's adaptive ERK pair and the literature's fixed Euler stepping on problems
// with closed forms, at wear-like scales (depths ~1e-4 m, lives ~1e6 revolutions).
#include "wear/integrator.h"

#include <arkode/arkode_butcher_erk.h>
#include <gtest/gtest.h>
#include <spdlog/fmt/fmt.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/log_capture.h"

namespace {

using wear::IntegratorOptions;
using wear::IntegratorResult;
using wear::IntegratorStatus;
using wear::StepInfo;
using Method = IntegratorOptions::Method;
using Kind = IntegratorStatus::Kind;

constexpr double kLife = 1e6;          // revolutions integrated in the wear-like cases
constexpr double kDepth = 1e-4;        // m, initial depth of the closed-form cases
constexpr double kTightAtol = 1e-15;   // m: far below the depths, so that rtol alone sets the steps
constexpr double kRootRtol = 1e-8;     // brief: a root located to 1e-8 relative
constexpr double kRoundoff = 1e-12;    // relative: what a few hundred additions of doubles may lose

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// -------------------------------------------------------------------------------------------
// closed forms: h' = A h

struct LinearCase {
  const char* name;
  Eigen::MatrixXd A;                           // per revolution
  std::function<Eigen::VectorXd(double)> h;    // exact h(N), h(0) = initial depth
};

std::ostream& operator<<(std::ostream& os, const LinearCase& c) { return os << c.name; }

LinearCase exponential_decay() {
  constexpr double lambda = 3e-6;  // per revolution: e^-3 over the life
  Eigen::MatrixXd A(1, 1);
  A << -lambda;
  return {"decay", A, [](double N) { return Eigen::VectorXd::Constant(1, kDepth * std::exp(-lambda * N)); }};
}

LinearCase exponential_growth() {
  constexpr double lambda = 2e-6;  // e^2 over the life
  Eigen::MatrixXd A(1, 1);
  A << lambda;
  return {"growth", A, [](double N) { return Eigen::VectorXd::Constant(1, kDepth * std::exp(lambda * N)); }};
}

// h' = [[-a, w], [-w, -a]] h: h = e^{-aN} (cos wN, -sin wN) h0_x for h0 = (h0_x, 0)
LinearCase damped_rotation() {
  constexpr double a = 1e-6, w = 1e-5;  // 1.6 turns over the life
  Eigen::MatrixXd A(2, 2);
  A << -a, w, -w, -a;
  return {"rotation", A, [](double N) {
            Eigen::VectorXd h(2);
            h << std::cos(w * N), -std::sin(w * N);
            return Eigen::VectorXd(kDepth * std::exp(-a * N) * h);
          }};
}

wear::Rhs linear_rate(const Eigen::MatrixXd& A) {
  return [A](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) { dhdN = A * h; };
}

class IntegratorClosedForm : public testing::TestWithParam<LinearCase> {};

TEST_P(IntegratorClosedForm, GlobalErrorFallsAsRtolTightens) {
  // the global error of a tolerance-controlled run is of the order of rtol, not bounded by it: the
  // relative local errors add up (decay at rtol 1e-2: 7 steps, global error 9.9 rtol)
  constexpr double kGlobalErrorPerRtol = 20;
  const LinearCase& c = GetParam();
  const Eigen::VectorXd h0 = c.h(0);
  const Eigen::VectorXd exact = c.h(kLife);

  std::printf("  %-8s %8s %6s %8s %9s %11s %9s\n", c.name, "rtol", "steps", "rhs", "rejected", "rel. error",
              "err/rtol");
  std::vector<double> errors;
  for (const double rtol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
    IntegratorOptions o;
    o.rtol = rtol;
    o.atol = kTightAtol;
    double worst_estimate = 0;
    const IntegratorResult r = wear::integrate(linear_rate(c.A), {}, 0, 0, h0, kLife, o,
                                               [&](const StepInfo& s, const Eigen::VectorXd&) {
                                                 worst_estimate = std::max(worst_estimate, s.error_estimate);
                                                 return true;
                                               });
    ASSERT_EQ(r.status.kind, Kind::ReachedEnd) << r.status.message;
    EXPECT_EQ(r.N, kLife);  // the stop time is hit, not passed
    EXPECT_LE(worst_estimate, 1.0) << "an accepted step must have passed ARKODE's error test";
    const double error = (r.h_m - exact).norm() / exact.norm();
    std::printf("  %-8s %8.0e %6ld %8ld %9ld %11.3e %9.3f\n", "", rtol, r.steps, r.rhs_evals, r.rejected, error,
                error / rtol);
    EXPECT_LE(error, kGlobalErrorPerRtol * rtol) << "rtol " << rtol;
    errors.push_back(error);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) EXPECT_LT(errors[i], errors[i - 1]) << "step " << i;
}

INSTANTIATE_TEST_SUITE_P(Integrator, IntegratorClosedForm,
                         testing::Values(exponential_decay(), exponential_growth(), damped_rotation()),
                         [](const testing::TestParamInfo<LinearCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

// -------------------------------------------------------------------------------------------
// roots: the depth h = N^2 (h' = 2N) reaches its limit 4 at N = 2

const wear::Rhs kQuadraticWear = [](double N, const Eigen::VectorXd&, Eigen::VectorXd& dhdN) {
  dhdN.setConstant(2 * N);
};

TEST(Integrator, AdaptiveLocatesTheDepthLimitOfQuadraticWear) {
  // three limits: depth 9 (later), depth 4 (first), and a revolution count never reached
  const wear::Roots limits = [](double N, const Eigen::VectorXd& h, Eigen::VectorXd& g) {
    g << 9 - h[0], 4 - h[0], 100 - N;
  };
  IntegratorOptions o;
  o.atol = 1e-12;
  const IntegratorResult r = wear::integrate(kQuadraticWear, limits, 3, 0, Eigen::VectorXd::Zero(1), 10, o);
  ASSERT_EQ(r.status.kind, Kind::RootFound) << r.status.message;
  EXPECT_EQ(r.status.roots, std::vector<int>{1});
  EXPECT_NEAR(r.N, 2.0, kRootRtol * 2.0);
  EXPECT_NEAR(r.h_m[0], 4.0, kRootRtol * 4.0);
  EXPECT_GE(r.h_m[0], 4.0);  // the state returned is on the far side of the limit
  EXPECT_TRUE(has(r.status.message, "root 1 at N 2")) << r.status.message;
}

// the Euler solution's crossing of h = limit, from its closed form: the discrete solution is the
// polyline through (N_k, h_k); on the segment that crosses, N = N_k + (limit - h_k) / f_k
double euler_crossing(const std::vector<double>& N, const std::vector<double>& h, double limit) {
  for (std::size_t k = 0; k + 1 < N.size(); ++k)
    if (h[k] < limit && h[k + 1] >= limit) return N[k] + (limit - h[k]) / (2 * N[k]);
  return NAN;
}

TEST(Integrator, FixedStepLocatesTheDepthLimitOnTheEulerLine) {
  // Euler with dN on h' = 2N, h(0) = 0: h_k = N_k (N_k - dN), so the first-order error in N is ~dN/2
  constexpr double kStep = 0.01;
  std::vector<double> N{0}, h{0};
  for (int k = 1; k <= 300; ++k) {
    N.push_back(k * kStep);
    h.push_back(N.back() * (N.back() - kStep));
  }
  const double expected = euler_crossing(N, h, 4);  // 2.005

  IntegratorOptions o;
  o.method = Method::FixedStep;
  o.fixed_step = kStep;
  const wear::Roots limit = [](double, const Eigen::VectorXd& d, Eigen::VectorXd& g) { g[0] = 4 - d[0]; };
  long steps_seen = 0;
  const IntegratorResult r =
      wear::integrate(kQuadraticWear, limit, 1, 0, Eigen::VectorXd::Zero(1), 10, o,
                      [&](const StepInfo& s, const Eigen::VectorXd& d) {
                        ++steps_seen;
                        EXPECT_NEAR(s.step, kStep, kRoundoff * kStep);
                        EXPECT_NEAR(d[0], s.N * (s.N - kStep), kRoundoff * (1 + d[0]));  // Euler's closed form
                        return true;
                      });
  ASSERT_EQ(r.status.kind, Kind::RootFound) << r.status.message;
  EXPECT_EQ(r.status.roots, std::vector<int>{0});
  EXPECT_NEAR(r.N, expected, kRoundoff * expected);
  EXPECT_NEAR(r.h_m[0], 4.0, kRoundoff * 4.0);
  EXPECT_GE(r.h_m[0], 4.0);      // the state returned is on the far side of the limit
  EXPECT_NEAR(r.N, 2.0, kStep);  // and within Euler's error of the true limit
  EXPECT_EQ(steps_seen, 200);    // the step that crosses is not reported: it ends past the limit,
  EXPECT_EQ(r.steps, 201);       // but it counts
}

TEST(Integrator, FixedStepLocatesANonlinearLimitOnTheEulerLine) {
  // g = 16 - h^2 is curved along the Euler line: regula falsi needs iterations, not one secant
  constexpr double kStep = 0.01;
  constexpr int kMaxLimitChecks = 20;  // superlinear (Illinois) convergence from a bracket of one step
  std::vector<double> N{0}, h{0};
  for (int k = 1; k <= 300; ++k) {
    N.push_back(k * kStep);
    h.push_back(N.back() * (N.back() - kStep));
  }
  const double expected = euler_crossing(N, h, 4);

  IntegratorOptions o;
  o.method = Method::FixedStep;
  o.fixed_step = kStep;
  int checks_in_last_step = 0;
  const wear::Roots limit = [&](double N_now, const Eigen::VectorXd& d, Eigen::VectorXd& g) {
    if (N_now > 2.0) ++checks_in_last_step;
    g[0] = 16 - d[0] * d[0];
  };
  const IntegratorResult r = wear::integrate(kQuadraticWear, limit, 1, 0, Eigen::VectorXd::Zero(1), 10, o);
  ASSERT_EQ(r.status.kind, Kind::RootFound) << r.status.message;
  EXPECT_NEAR(r.N, expected, kRoundoff * expected);
  EXPECT_GE(r.h_m[0], 4.0);
  EXPECT_LE(checks_in_last_step, kMaxLimitChecks);
  std::printf("  limit located with %d checks of g inside the crossing step\n", checks_in_last_step);
}

TEST(Integrator, FixedDepthLocatesTheDepthLimitOnTheEulerLine) {
  // from h(1) = 1: each Euler step wears exactly kDepthStep, dN_k = kDepthStep / (2 N_k)
  constexpr double kDepthStep = 0.007;  // 3 / 0.007 is not whole: the limit falls inside a step
  std::vector<double> N{1}, h{1};
  while (h.back() < 5) {
    N.push_back(N.back() + kDepthStep / (2 * N.back()));
    h.push_back(h.back() + kDepthStep);
  }
  const double expected = euler_crossing(N, h, 4);

  IntegratorOptions o;
  o.method = Method::FixedDepth;
  o.max_depth_step = kDepthStep;
  const wear::Roots limit = [](double, const Eigen::VectorXd& d, Eigen::VectorXd& g) { g[0] = 4 - d[0]; };
  const IntegratorResult r = wear::integrate(kQuadraticWear, limit, 1, 1, Eigen::VectorXd::Ones(1), 10, o);
  ASSERT_EQ(r.status.kind, Kind::RootFound) << r.status.message;
  EXPECT_NEAR(r.N, expected, kRoundoff * expected);
  EXPECT_NEAR(r.h_m[0], 4.0, kRoundoff * 4.0);
  EXPECT_GE(r.h_m[0], 4.0);
  EXPECT_NEAR(r.N, 2.0, 2 * kDepthStep);  // Euler's error
}

TEST(Integrator, FixedDepthWearsExactlyTheDepthLimitPerStep) {
  // three nodes wearing at different, depth-dependent rates; the fastest sets each step
  const wear::Rhs rate = [](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) {
    dhdN << 1e-10 * (1 + h[0] / 2e-5), 3e-10 * (1 - h[1] / 4e-4), 2e-10;
  };
  IntegratorOptions o;
  o.method = Method::FixedDepth;
  o.max_depth_step = 1e-5;  // 0.01 mm per update
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(3);
  int full_steps = 0;
  const IntegratorResult r =
      wear::integrate(rate, {}, 0, 0, previous, kLife, o, [&](const StepInfo& s, const Eigen::VectorXd& h) {
        const double dh = (h - previous).cwiseAbs().maxCoeff();
        previous = h;
        if (s.N < kLife) {
          EXPECT_NEAR(dh, o.max_depth_step, kRoundoff * o.max_depth_step) << "step " << s.steps;
          ++full_steps;
        } else {
          EXPECT_LE(dh, o.max_depth_step * (1 + kRoundoff)) << "the last step is cut at N_end";
        }
        return true;
      });
  ASSERT_EQ(r.status.kind, Kind::ReachedEnd) << r.status.message;
  EXPECT_EQ(r.N, kLife);
  EXPECT_GT(full_steps, 10);
  EXPECT_EQ(r.steps, full_steps + 1);
  EXPECT_EQ(r.rhs_evals, r.steps + 1);  // one evaluation per update, plus the start
}

TEST(Integrator, FixedStepIsExplicitEuler) {
  // h' = -lambda h: Euler gives h_k = h0 (1 - lambda dN)^k exactly
  constexpr double kLambda = 3e-6, kStep = 2e4;
  const wear::Rhs decay = [](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) { dhdN = -kLambda * h; };
  IntegratorOptions o;
  o.method = Method::FixedStep;
  o.fixed_step = kStep;
  const IntegratorResult r = wear::integrate(decay, {}, 0, 0, Eigen::VectorXd::Constant(1, kDepth), kLife, o,
                                             [&](const StepInfo& s, const Eigen::VectorXd& h) {
                                               const double k = s.N / kStep;
                                               EXPECT_NEAR(h[0], kDepth * std::pow(1 - kLambda * kStep, k),
                                                           kRoundoff * kDepth);
                                               return true;
                                             });
  ASSERT_EQ(r.status.kind, Kind::ReachedEnd) << r.status.message;
  EXPECT_EQ(r.steps, 50);
  EXPECT_EQ(r.N, kLife);
  EXPECT_EQ(r.rejected, 0);  // lambda dN = 0.06: the stability control leaves the step alone
}

// Stability control: a fixed step far too large is refused by the step control, not taken into an oscillating
// profile. h' = -lambda h with lambda dN = 10: plain Euler multiplies h by -9 per step. The control
// halves each step until its rate changes by at most the rate's size, i.e. lambda dN <= 1 for this
// linear decay (Euler's factor in [0, 1]): h decays monotonically and stays >= 0, and the run still
// reaches N_end. The same for a step that makes f throw (an absurd profile): halved until it does not.
TEST(Integrator, FixedStepTooLargeIsHalvedNotOscillating) {
  constexpr double kLambda = 1e-5, kStep = 1e6;  // lambda dN = 10
  const wear::Rhs decay = [](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) {
    if (h[0] < -1e-3 * kDepth) throw std::runtime_error("the profile is absurd");
    dhdN = -kLambda * h;
  };
  IntegratorOptions o;
  o.method = Method::FixedStep;
  o.fixed_step = kStep;
  double previous = kDepth;
  const IntegratorResult r = wear::integrate(decay, {}, 0, 0, Eigen::VectorXd::Constant(1, kDepth), 1e7, o,
                                             [&](const StepInfo& s, const Eigen::VectorXd& h) {
                                               EXPECT_LE(kLambda * s.step, 1 + kRoundoff) << "N " << s.N;
                                               EXPECT_LE(h[0], previous) << "N " << s.N;
                                               EXPECT_GE(h[0], 0) << "N " << s.N;
                                               previous = h[0];
                                               return true;
                                             });
  ASSERT_EQ(r.status.kind, Kind::ReachedEnd) << r.status.message;
  EXPECT_EQ(r.N, 1e7);
  EXPECT_GT(r.rejected, 0);
  EXPECT_LT(r.h_m[0], 1e-6 * kDepth);  // exp(-100) in truth; decayed, not blown up
}

// -------------------------------------------------------------------------------------------
// failures inside the wear rate

struct ContactSolveFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class IntegratorMethods : public testing::TestWithParam<Method> {};

IntegratorOptions options_for(Method m) {
  IntegratorOptions o;
  o.method = m;
  o.fixed_step = 1e4;
  o.max_depth_step = 1e-6;
  return o;
}

TEST_P(IntegratorMethods, ThrowingWearRateSurfacesWithTheRevolution) {
  constexpr double kFailsAfter = 3e5;
  double thrown_at = NAN;
  const wear::Rhs rate = [&](double N, const Eigen::VectorXd&, Eigen::VectorXd& dhdN) {
    if (N > kFailsAfter) {
      thrown_at = N;
      throw ContactSolveFailed("contact solve did not converge");
    }
    dhdN.setConstant(1e-10);
  };
  try {
    wear::integrate(rate, {}, 0, 0, Eigen::VectorXd::Zero(2), kLife, options_for(GetParam()));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_TRUE(has(what, fmt::format("at N {:.10g} revolutions", thrown_at))) << what;
    EXPECT_TRUE(has(what, "contact solve did not converge")) << what;
    EXPECT_THROW(std::rethrow_if_nested(e), ContactSolveFailed);  // the original, nested
  }
}

TEST_P(IntegratorMethods, NonFiniteWearRateIsReportedWithTheRevolution) {
  constexpr double kBadAfter = 4e5;
  double bad_at = NAN;
  const wear::Rhs rate = [&](double N, const Eigen::VectorXd&, Eigen::VectorXd& dhdN) {
    dhdN.setConstant(1e-10);
    if (N > kBadAfter) {
      bad_at = N;
      dhdN[1] = std::nan("");
    }
  };
  try {
    wear::integrate(rate, {}, 0, 0, Eigen::VectorXd::Zero(2), kLife, options_for(GetParam()));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(has(e.what(), fmt::format("dh/dN is not finite at N {:.10g} revolutions: component 1", bad_at)))
        << e.what();
  }

  // a component the rate forgot to set arrives as NaN
  const wear::Rhs forgetful = [](double, const Eigen::VectorXd&, Eigen::VectorXd& dhdN) { dhdN[0] = 1e-10; };
  try {
    wear::integrate(forgetful, {}, 0, 0, Eigen::VectorXd::Zero(2), kLife, options_for(GetParam()));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(has(e.what(), "dh/dN is not finite at N 0 revolutions: component 1")) << e.what();
  }
}

TEST_P(IntegratorMethods, ThrowingLimitCheckSurfacesWithTheRevolution) {
  const wear::Rhs rate = [](double, const Eigen::VectorXd&, Eigen::VectorXd& dhdN) { dhdN.setConstant(1e-10); };
  const wear::Roots limits = [](double N, const Eigen::VectorXd&, Eigen::VectorXd& g) {
    if (N > 5e5) throw ContactSolveFailed("peak pressure unavailable");
    g[0] = 1;
  };
  try {
    wear::integrate(rate, limits, 1, 0, Eigen::VectorXd::Zero(2), kLife, options_for(GetParam()));
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(has(e.what(), "the root functions threw at N ")) << e.what();
    EXPECT_TRUE(has(e.what(), "peak pressure unavailable")) << e.what();
    EXPECT_THROW(std::rethrow_if_nested(e), ContactSolveFailed);
  }
}

// -------------------------------------------------------------------------------------------
// checkpoint and resume

TEST_P(IntegratorMethods, StopAndResumeReachesTheUninterruptedEnd) {
  // a resumed adaptive run restarts ARKODE's step controller: its steps differ, within the tolerance
  constexpr double kResumeRtol = 10 * 1e-3;  // 10 x the default rtol, as the global error above
  constexpr long kStopAfter = 7;             // steps before the "kill"
  const LinearCase c = damped_rotation();
  const wear::Rhs rate = linear_rate(c.A);
  const Eigen::VectorXd h0 = c.h(0);
  const IntegratorOptions o = options_for(GetParam());
  const IntegratorResult full = wear::integrate(rate, {}, 0, 0, h0, kLife, o);
  ASSERT_EQ(full.status.kind, Kind::ReachedEnd) << full.status.message;

  // checkpoint after kStopAfter steps: (N, h, last step)
  const IntegratorResult first = wear::integrate(
      rate, {}, 0, 0, h0, kLife, o, [](const StepInfo& s, const Eigen::VectorXd&) { return s.steps < kStopAfter; });
  ASSERT_EQ(first.status.kind, Kind::Stopped) << first.status.message;
  EXPECT_EQ(first.steps, kStopAfter);
  EXPECT_LT(first.N, kLife);
  EXPECT_GT(first.last_step, 0);

  // resume
  IntegratorOptions resume = o;
  resume.initial_step = first.last_step;
  double first_step = 0;
  const IntegratorResult second =
      wear::integrate(rate, {}, 0, first.N, first.h_m, kLife, resume, [&](const StepInfo& s, const Eigen::VectorXd&) {
        if (s.steps == 1) first_step = s.step;
        return true;
      });
  ASSERT_EQ(second.status.kind, Kind::ReachedEnd) << second.status.message;
  EXPECT_EQ(second.N, kLife);
  const double difference = (second.h_m - full.h_m).norm() / full.h_m.norm();
  std::printf("  resumed at N %.6g after %ld of %ld steps: first step %.6g (checkpoint's %.6g), "
              "%ld + %ld steps, end differs by %.2e (relative)\n",
              first.N, first.steps, full.steps, first_step, first.last_step, first.steps, second.steps, difference);
  if (GetParam() == Method::Adaptive) {
    EXPECT_LE(difference, kResumeRtol);
    if (second.rejected == 0) {
      EXPECT_EQ(first_step, first.last_step);  // it starts with the checkpoint's step
    }
  } else {
    EXPECT_LE(difference, kRoundoff);  // Euler's steps do not depend on the history
  }
}

INSTANTIATE_TEST_SUITE_P(Integrator, IntegratorMethods,
                         testing::Values(Method::Adaptive, Method::FixedDepth, Method::FixedStep),
                         [](const testing::TestParamInfo<Method>& param_info) {
                           switch (param_info.param) {
                             case Method::Adaptive: return std::string("Adaptive");
                             case Method::FixedDepth: return std::string("FixedDepth");
                             case Method::FixedStep: return std::string("FixedStep");
                           }
                           return std::string("Unknown");
                         });

// -------------------------------------------------------------------------------------------
// piecewise-smooth wear: a kink and a jump in dh/dN

// node 0: h' = r max(0, 1 - h/H) + r0, a kink where h reaches H (a strip leaves the contact);
// node 1: h' = r1 while h0 < J, then r2 (a strip enters: a jump in the rate)
constexpr double kR = 1e-10, kH = 5e-5, kR0 = 2e-11, kJ = 3e-5, kR1 = 1e-10, kR2 = 3e-10;

const wear::Rhs kPiecewiseWear = [](double, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) {
  dhdN << kR * std::max(0.0, 1 - h[0] / kH) + kR0, h[0] < kJ ? kR1 : kR2;
};

// closed form: before the kink h0' = (r + r0) - (r/H) h0, so h0 = c (1 - e^{-kN}), c = (r + r0)/k, k = r/H
Eigen::VectorXd piecewise_exact(double N) {
  const double k = kR / kH, c = (kR + kR0) / k;
  const double N_kink = -std::log(1 - kH / c) / k;
  const double N_jump = -std::log(1 - kJ / c) / k;
  Eigen::VectorXd h(2);
  h[0] = N < N_kink ? c * (1 - std::exp(-k * N)) : kH + kR0 * (N - N_kink);
  h[1] = N < N_jump ? kR1 * N : kR1 * N_jump + kR2 * (N - N_jump);
  return h;
}

TEST(Integrator, PiecewiseSmoothWearIntegratesWithoutStalls) {
  constexpr long kMaxSteps = 1000;      // brief: no stall at the kink or the jump over 1e6 revolutions
  constexpr double kPiecewiseTol = 10;  // global error / rtol, as for the smooth cases
  const Eigen::VectorXd exact = piecewise_exact(kLife);
  std::printf("  %8s %6s %8s %9s %11s\n", "rtol", "steps", "rhs", "rejected", "rel. error");
  for (const double rtol : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}) {
    IntegratorOptions o;
    o.rtol = rtol;
    o.atol = 1e-12;  // m: 1 pm
    const IntegratorResult r = wear::integrate(kPiecewiseWear, {}, 0, 0, Eigen::VectorXd::Zero(2), kLife, o);
    ASSERT_EQ(r.status.kind, Kind::ReachedEnd) << r.status.message;
    const double error = ((r.h_m - exact).array() / exact.array()).abs().maxCoeff();
    std::printf("  %8.0e %6ld %8ld %9ld %11.3e\n", rtol, r.steps, r.rhs_evals, r.rejected, error);
    EXPECT_LT(r.steps, kMaxSteps) << "rtol " << rtol;
    EXPECT_LE(error, kPiecewiseTol * rtol) << "rtol " << rtol;
  }
}

// the embedded tables this ARKODE integrates correctly: the cost of each on smooth wear (growth,
// as a depth that speeds its own wear) and on the piecewise case
class IntegratorTables : public testing::TestWithParam<int> {};

TEST_P(IntegratorTables, EmbeddedTableMeetsTheToleranceOnSmoothAndPiecewiseWear) {
  constexpr double kGlobalErrorPerRtol = 20;  // as GlobalErrorFallsAsRtolTightens
  const LinearCase smooth = exponential_growth();
  struct Case {
    const char* name;
    wear::Rhs rate;
    Eigen::VectorXd h0, exact;
  };
  const Case cases[] = {{"smooth", linear_rate(smooth.A), smooth.h(0), smooth.h(kLife)},
                        {"piecewise", kPiecewiseWear, Eigen::VectorXd::Zero(2), piecewise_exact(kLife)}};
  for (const Case& c : cases) {
    std::string row;
    for (const double rtol : {1e-2, 1e-3, 1e-4}) {
      IntegratorOptions o;
      o.rtol = rtol;
      o.atol = 1e-12;
      o.table = GetParam();
      const IntegratorResult r = wear::integrate(c.rate, {}, 0, 0, c.h0, kLife, o);
      ASSERT_EQ(r.status.kind, Kind::ReachedEnd) << r.status.message;
      const double error = ((r.h_m - c.exact).array() / c.exact.array()).abs().maxCoeff();
      row += fmt::format(" | {:4d} {:3d} {:8.1e}", r.rhs_evals, r.rejected, error);
      EXPECT_LE(error, kGlobalErrorPerRtol * rtol) << c.name << ", rtol " << rtol;
    }
    std::printf("  table %2d %-9s (rhs evals, rejected, error at rtol 1e-2 | 1e-3 | 1e-4)%s\n", GetParam(), c.name,
                row.c_str());
  }
}

INSTANTIATE_TEST_SUITE_P(Integrator, IntegratorTables,
                         testing::Values(ARKODE_BOGACKI_SHAMPINE_4_2_3, ARKODE_ZONNEVELD_5_3_4, ARKODE_CASH_KARP_6_4_5,
                                         ARKODE_FEHLBERG_6_4_5, ARKODE_DORMAND_PRINCE_7_4_5),
                         [](const testing::TestParamInfo<int>& param_info) {
                           switch (param_info.param) {
                             case ARKODE_BOGACKI_SHAMPINE_4_2_3: return std::string("BogackiShampine32");
                             case ARKODE_ZONNEVELD_5_3_4: return std::string("Zonneveld43");
                             case ARKODE_CASH_KARP_6_4_5: return std::string("CashKarp54");
                             case ARKODE_FEHLBERG_6_4_5: return std::string("Fehlberg54");
                             case ARKODE_DORMAND_PRINCE_7_4_5: return std::string("DormandPrince54");
                             default: return std::to_string(param_info.param);
                           }
                         });

// -------------------------------------------------------------------------------------------
// statuses and errors

TEST(Integrator, MaxStepsIsAStatusWithAWarning) {
  IntegratorOptions o;
  o.max_steps = 5;
  const rollwear_test::ExpectWarnings warnings;
  const IntegratorResult r = wear::integrate(kPiecewiseWear, {}, 0, 0, Eigen::VectorXd::Zero(2), kLife, o);
  EXPECT_EQ(r.status.kind, Kind::MaxSteps);
  EXPECT_EQ(r.steps, 5);
  EXPECT_LT(r.N, kLife);
  ASSERT_EQ(warnings.count(), 1);
  EXPECT_TRUE(has(warnings.messages()[0], "max_steps 5 reached at N ")) << warnings.messages()[0];
}

TEST(Integrator, EmptySpanReturnsTheStart) {
  const IntegratorResult r =
      wear::integrate(kPiecewiseWear, {}, 0, 7, Eigen::VectorXd::Constant(2, 1e-6), 7, IntegratorOptions{});
  EXPECT_EQ(r.status.kind, Kind::ReachedEnd);
  EXPECT_EQ(r.N, 7);
  EXPECT_EQ(r.steps, 0);
  EXPECT_EQ(r.h_m, Eigen::VectorXd::Constant(2, 1e-6));
}

TEST(Integrator, BadOptionsThrowNamingTheOption) {
  const Eigen::VectorXd h0 = Eigen::VectorXd::Zero(2);
  auto message = [&](IntegratorOptions o, double N_end = kLife, int n_roots = 0) {
    try {
      wear::integrate(kPiecewiseWear, {}, n_roots, 0, h0, N_end, o);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  IntegratorOptions o;
  o.rtol = 0;
  EXPECT_TRUE(has(message(o), "rtol must be in (0, 1), got 0")) << message(o);
  o = {};
  o.atol = 0;
  EXPECT_TRUE(has(message(o), "atol must be > 0")) << message(o);
  o = {};
  EXPECT_TRUE(has(message(o, -1), "N_end -1 < N0 0")) << message(o, -1);
  EXPECT_TRUE(has(message(o, kLife, 2), "n_roots is 2 but no root functions")) << message(o, kLife, 2);
  o.method = Method::FixedStep;
  EXPECT_TRUE(has(message(o), "fixed_step must be > 0")) << message(o);
  o = {};
  o.method = Method::FixedDepth;
  o.max_depth_step = -1e-4;
  EXPECT_TRUE(has(message(o), "max_depth_step must be > 0")) << message(o);
  o = {};
  o.table = 99;
  EXPECT_TRUE(has(message(o), "unknown ERK table id 99")) << message(o);
  EXPECT_TRUE(has(message(o), "usable ids: 1, 3, 6, 7, 8")) << message(o);
  o.table = ARKODE_HEUN_EULER_2_1_2;  // c_s = 1, not FSAL: ERKStep 6.4.1 reuses a stale stage
  EXPECT_TRUE(has(message(o), "wrongly reuses its last stage")) << message(o);
  o.table = ARKODE_KNOTH_WOLKE_3_3;
  EXPECT_TRUE(has(message(o), "has no embedded method")) << message(o);
}

TEST(Integrator, ArkodeErrorThrowsNamingTheCallAndFlag) {
  // a span below ARKODE's time roundoff (one ulp of N): ARKODE refuses to start
  constexpr double kN0 = 1e6;
  try {
    wear::integrate(kPiecewiseWear, {}, 0, kN0, Eigen::VectorXd::Zero(2), std::nextafter(kN0, 2 * kN0),
                    IntegratorOptions{});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(has(e.what(), "ERKStepEvolve failed with flag -27 (ARK_TOO_CLOSE)")) << e.what();
    EXPECT_TRUE(has(e.what(), "too close")) << e.what();  // ARKODE's own message
  }
}

}  // namespace
