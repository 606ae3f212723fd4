// The cam's life in cam revolutions (cam/cam_life.h): the depth and lift-loss limits located against
// closed forms, the worn state fed back into the producer, failures and snapshots
// (docs/cam-follower.md §8).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "cam/cam_life.h"
#include "lib/numeric.h"

namespace {

using cam::AngleDissipation;
using cam::CamLifeModel;
using cam::RevolutionDissipation;

constexpr double kL = 0.25, kTrackW = 0.012, kRollerW = 0.010, kRollerR = 0.013, kOmega = 60, kE = 2e-14;
constexpr int kSteps = 72;

// a uniform revolution: constant speed, P_l = c V on strips covering the track, so the track wears
// k_E c per revolution everywhere
RevolutionDissipation uniform_revolution(double c) {
  RevolutionDissipation rev(kSteps);
  const double dt = 2 * contact::kPi / kSteps / kOmega, V = kL / kSteps / dt;
  for (int k = 0; k < kSteps; ++k) {
    AngleDissipation& a = rev[k];
    a.theta_rad = 2 * contact::kPi * k / kSteps;
    a.duration_s = dt;
    a.cam_arc_m = kL * k / kSteps;
    a.rolling_speed_m_per_s = a.roller_surface_speed_m_per_s = V;
    a.y_m = Eigen::ArrayXd::LinSpaced(12, -0.5 * kTrackW + kTrackW / 24, 0.5 * kTrackW - kTrackW / 24);
    a.power_W_per_m = Eigen::ArrayXd::Constant(12, c * V);
  }
  return rev;
}

CamLifeModel model(bool roller_wears) {
  cam::CamWearSpec spec;
  spec.laws.cam = wear::WearLaw{};
  spec.laws.cam->k_E_m3_per_J = kE;
  if (roller_wears) spec.laws.roller = spec.laws.cam;
  spec.revolutions = 1e12;
  spec.arc_cells = 36;
  spec.lateral_cells = 6;
  spec.stepping.rtol = 1e-6;
  spec.stepping.atol_m = 1e-12;
  contact::Profiles unworn;
  unworn.body1 = contact::crowned_profile(0.5, kRollerW);
  unworn.body2 = contact::flat_profile(kTrackW);
  std::vector<cam::LiftLossSample> samples;
  for (int k = 0; k < kSteps; ++k) {
    const double th = 2 * contact::kPi * k / kSteps;
    samples.push_back({th, kL * k / kSteps, 0.3 * std::sin(th)});  // |phi| <= 0.3 rad, reached at 90 deg
  }
  return cam::make_cam_life_model("test", spec, 0.1, unworn, kRollerR, kL, uniform_revolution(1), samples);
}

// the root is located on the integrator's dense output to ARKODE's root tolerance; the depth is linear in
// N here, so the located N is exact to that tolerance
constexpr double kRootRtol = 1e-9;

// A rate that does not change with wear: the deepest wear, the roller's (k_E c L / (2 pi R_r) per
// revolution against the track's k_E c), reaches the limit at N = H / rate.
TEST(CamLife, ConstantRateEndsAtTheDepthLimit) {
  CamLifeModel m = model(true);
  m.max_depth_m = 2e-5;
  const double c = 3;
  const cam::CamLifeResult life = cam::run_cam_life(m, [&](const cam::CamWearState&) { return uniform_revolution(c); });
  ASSERT_EQ(life.ended_by, cam::CamLifeEnd::MaxDepth) << life.message;
  const double roller_rate = kE * c * kL / (2 * contact::kPi * kRollerR);
  EXPECT_NEAR(life.N, m.max_depth_m / roller_rate, kRootRtol * life.N);
  EXPECT_NEAR(life.state.cam_depth_m.maxCoeff(), kE * c * life.N, kRootRtol * 2e-5);
  // worn volumes and the energy: track volume = k_E E to the integrator's tolerance on a linear solution
  EXPECT_NEAR(life.cam_volume_m3, kE * life.energy_J, 1e-9 * kE * life.energy_J);
}

// Only the track wears, evenly; the lift loss h / cos phi is largest where |phi| is, 0.3 rad:
// N = limit cos(0.3) / (k_E c).
TEST(CamLife, LiftLossEndsTheLifeWhereThePressureAngleIsLargest) {
  CamLifeModel m = model(false);
  m.max_lift_loss_m = 1e-5;
  m.max_depth_m = 1e-3;  // far
  const double c = 3;
  const cam::CamLifeResult life = cam::run_cam_life(m, [&](const cam::CamWearState&) { return uniform_revolution(c); });
  ASSERT_EQ(life.ended_by, cam::CamLifeEnd::LiftLoss) << life.message;
  EXPECT_NEAR(life.N, m.max_lift_loss_m * std::cos(0.3) / (kE * c), kRootRtol * life.N);
  EXPECT_NEAR(life.lift_loss.at_theta_rad, contact::kPi / 2, 1e-12);
  EXPECT_NEAR(life.lift_loss.max_m, 1e-5, kRootRtol * 1e-5);
}

// The worn state reaches the producer: a power falling as exp(-h / h0) with the depth h it is given gives
// dh/dN = a exp(-h / h0), h = h0 ln(1 + a N / h0), and the depth limit H at N = h0 (exp(H / h0) - 1) / a.
TEST(CamLife, TheWornStateFeedsTheRate) {
  CamLifeModel m = model(false);
  m.max_depth_m = 2e-5;
  const double c = 3, h0 = 1e-5, a = kE * c;
  long calls = 0;
  const cam::CamLifeResult life = cam::run_cam_life(m, [&](const cam::CamWearState& s) {
    ++calls;
    return uniform_revolution(c * std::exp(-s.cam_depth_m.maxCoeff() / h0));
  });
  ASSERT_EQ(life.ended_by, cam::CamLifeEnd::MaxDepth) << life.message;
  const double want = h0 * (std::exp(2.0) - 1) / a;
  // rtol 1e-6 on the depth: the located life within a few times that
  EXPECT_NEAR(life.N, want, 1e-5 * want);
  EXPECT_EQ(life.revolutions_solved, calls);
  EXPECT_GT(life.steps, 3);
}

TEST(CamLife, AProducerFailureEndsTheLifeFailedAtTheLastAcceptedStep) {
  CamLifeModel m = model(false);
  m.max_depth_m = 2e-5;
  const cam::CamLifeResult life = cam::run_cam_life(m, [&](const cam::CamWearState& s) {
    if (s.cam_depth_m.maxCoeff() > 5e-6) throw std::runtime_error("the normal problem did not converge");
    return uniform_revolution(3);
  });
  ASSERT_EQ(life.ended_by, cam::CamLifeEnd::Failed);
  EXPECT_NE(life.message.find("did not converge"), std::string::npos) << life.message;
  EXPECT_LE(life.max_depth_m, 5e-6 * (1 + 1e-12));
  EXPECT_GT(life.N, 0);
}

TEST(CamLife, SnapshotsAtTheStartEachSnapshotAndTheEnd) {
  CamLifeModel m = model(false);
  m.max_depth_m = 2e-5;
  m.snapshots_revolutions = {1e7, 5e7, 1e13};  // the last beyond the life
  std::vector<double> at;
  cam::CamLifeHooks hooks;
  hooks.on_snapshot = [&](double N, const cam::CamWearState& s) {
    at.push_back(N);
    EXPECT_NEAR(s.cam_depth_m.maxCoeff(), kE * 3 * N, 1e-9 * 2e-5);
  };
  const cam::CamLifeResult life = cam::run_cam_life(m, [&](const cam::CamWearState&) { return uniform_revolution(3); },
                                                    hooks);
  ASSERT_EQ(at.size(), 4u);
  EXPECT_EQ(at[0], 0);
  EXPECT_NEAR(at[1], 1e7, 1e-6);
  EXPECT_NEAR(at[2], 5e7, 1e-6);
  EXPECT_EQ(at[3], life.N);
}

}  // namespace
