// wear/life.h: the one life driver on a constant wear rate, whose life has a closed form: the depth
// x(N) = c N reaches the limit H at N = H / c, on Euler's line exactly (a constant rate makes every
// scheme exact), so the driver's segments, snapshots, counters, stops and failures are checked against it.
#include "wear/life.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace {

using wear::LifeEnd;
using wear::LifeFailure;

constexpr double kRate_m = 1e-9;   // wear per revolution
constexpr double kLimit_m = 1e-5;  // the depth limit: the life is kLimit_m / kRate_m = 1e4 revolutions
constexpr double kRootTol = 1e-12;  // relative: the root is located to 100 eps (|N| + |dN|) on the step's line

// dx/dN = c, the limit g = x - H; the fixed depth steps of step_m wear step_m each
wear::LifeProblem constant_rate(double step_m, long* evaluations = nullptr) {
  wear::LifeProblem p;
  p.rate = [evaluations](double, const Eigen::VectorXd& x, Eigen::VectorXd& dxdN) {
    if (evaluations) ++*evaluations;
    dxdN = Eigen::VectorXd::Constant(x.size(), kRate_m);
  };
  p.limits = {LifeEnd::MaxDepth};
  p.limit_values = [](double, const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    g = Eigen::VectorXd::Constant(1, x.maxCoeff() - kLimit_m);
  };
  p.options.method = wear::IntegratorOptions::Method::FixedDepth;
  p.options.max_depth_step = step_m;
  p.revolutions = 1e6;
  p.budget_key = "revolutions";
  return p;
}

wear::LifeStart unworn() {
  wear::LifeStart s;
  s.state = Eigen::VectorXd::Zero(2);
  return s;
}

TEST(LifeDriver, ConstantRateEndsAtTheDepthLimitAtHOverRate) {
  const wear::LifeOutcome life = wear::integrate_life(constant_rate(3e-6), unworn());
  ASSERT_EQ(life.ended_by, LifeEnd::MaxDepth) << life.message;
  EXPECT_NEAR(life.N, kLimit_m / kRate_m, kRootTol * kLimit_m / kRate_m);
  EXPECT_EQ(life.counters.steps, 4);  // 3 whole steps of 3 um, the fourth cut short by the limit
  EXPECT_EQ(life.failure, LifeFailure::None);
}

TEST(LifeDriver, TheBudgetEndsALifeWhoseLimitLiesBeyondIt) {
  wear::LifeProblem p = constant_rate(3e-6);
  p.revolutions = 5e3;
  const wear::LifeOutcome life = wear::integrate_life(p, unworn());
  EXPECT_EQ(life.ended_by, LifeEnd::Revolutions) << life.message;
  EXPECT_EQ(life.N, 5e3);
  EXPECT_NE(life.message.find("revolutions = 5000"), std::string::npos) << life.message;
}

// Each snapshot revolution ends a segment: the life stops there, the hook sees the state x = c N, and the
// next segment's first evaluation (at the step end already evaluated) is not counted again.
TEST(LifeDriver, SnapshotsStopTheLifeAtEachSnapshotRevolution) {
  long evaluations = 0;
  wear::LifeProblem p = constant_rate(1e-6, &evaluations);
  p.snapshots_revolutions = {2.5e3, 5e3, 2e4};  // the last beyond the life
  std::vector<double> at;
  wear::LifeDriverHooks hooks;
  hooks.on_snapshot = [&](double N, const Eigen::VectorXd& x) {
    at.push_back(N);
    EXPECT_NEAR(x.maxCoeff(), kRate_m * N, kRootTol * kLimit_m);
  };
  const wear::LifeOutcome life = wear::integrate_life(p, unworn(), hooks);
  ASSERT_EQ(life.ended_by, LifeEnd::MaxDepth) << life.message;
  EXPECT_NEAR(life.N, kLimit_m / kRate_m, kRootTol * kLimit_m / kRate_m);
  ASSERT_EQ(at.size(), 2u);
  EXPECT_EQ(at[0], 2.5e3);
  EXPECT_EQ(at[1], 5e3);
  EXPECT_EQ(life.counters.rhs_evals, evaluations - 2);  // three segments: two continuations
}

// A life stopped after k steps and continued from that step's end (a checkpoint's content) ends as the
// uninterrupted one: the same revolutions, state and counters, to the bit.
TEST(LifeDriver, AStoppedLifeResumedIsTheUninterruptedOne) {
  const wear::LifeOutcome whole = wear::integrate_life(constant_rate(1e-6), unworn());
  wear::LifeStart saved;
  wear::LifeDriverHooks stop;
  stop.on_step = [&](const wear::LifeStepEnd& e) {
    saved = {e.N, *e.state, e.next_step, e.counters()};
    return e.info.steps < 3;
  };
  const wear::LifeOutcome first = wear::integrate_life(constant_rate(1e-6), unworn(), stop);
  ASSERT_EQ(first.ended_by, LifeEnd::Stopped) << first.message;
  EXPECT_EQ(first.counters.steps, 3);
  const wear::LifeOutcome resumed = wear::integrate_life(constant_rate(1e-6), saved);
  ASSERT_EQ(resumed.ended_by, LifeEnd::MaxDepth) << resumed.message;
  EXPECT_EQ(resumed.N, whole.N);
  EXPECT_TRUE(resumed.state == whole.state);
  EXPECT_EQ(resumed.counters.steps, whole.counters.steps);
  EXPECT_EQ(resumed.counters.rejected, whole.counters.rejected);
  EXPECT_EQ(resumed.counters.rhs_evals, whole.counters.rhs_evals);
}

// A rate that throws ends the life Failed at its last accepted step when failure_of names the cause, and
// propagates otherwise.
TEST(LifeDriver, ARateFailureEndsTheLifeAtItsLastAcceptedStepOrPropagates) {
  wear::LifeProblem p = constant_rate(1e-6);
  p.rate = [](double, const Eigen::VectorXd& x, Eigen::VectorXd& dxdN) {
    if (x.maxCoeff() > 4.5e-6) throw std::runtime_error("the contact could not be solved");
    dxdN = Eigen::VectorXd::Constant(x.size(), kRate_m);
  };
  EXPECT_THROW(wear::integrate_life(p, unworn()), std::runtime_error);
  p.failure_of = [](const std::exception&, double) { return LifeFailure::Rate; };
  const wear::LifeOutcome life = wear::integrate_life(p, unworn());
  ASSERT_EQ(life.ended_by, LifeEnd::Failed);
  EXPECT_EQ(life.failure, LifeFailure::Rate);
  EXPECT_NE(life.message.find("could not be solved"), std::string::npos) << life.message;
  EXPECT_LE(life.state.maxCoeff(), 4.5e-6);
  EXPECT_GT(life.N, 0);
}

// A limit reached where the life starts ends it there, without a step.
TEST(LifeDriver, ALimitReachedAtTheStartEndsTheLifeThere) {
  wear::LifeStart start = unworn();
  start.state.setConstant(kLimit_m);
  const wear::LifeOutcome life = wear::integrate_life(constant_rate(1e-6), start);
  EXPECT_EQ(life.ended_by, LifeEnd::MaxDepth) << life.message;
  EXPECT_EQ(life.counters.steps, 0);
}

// LifeEnd's words serve both lives: the cam's lift_loss reads back as the roller's limits do.
TEST(LifeDriver, EveryLifeEndReadsBackFromItsWord) {
  for (LifeEnd e : {LifeEnd::NotRun, LifeEnd::MaxDepth, LifeEnd::MaxPressure, LifeEnd::Edge, LifeEnd::LiftLoss,
                    LifeEnd::Revolutions, LifeEnd::MaxSteps, LifeEnd::Stopped, LifeEnd::Failed})
    EXPECT_EQ(wear::parse_life_end(wear::to_string(e)), e) << wear::to_string(e);
  EXPECT_EQ(wear::to_string(LifeEnd::LiftLoss), "lift_loss");
}

}  // namespace
