// The regime law fed back on a cam (cam.lubricant.friction_by_regime, cam/cam_lubrication.h, docs/cam-follower.md
// §17): a life whose film is boundary at every angle is the life with cam.mu = mu_b (to round-off); a full film
// everywhere wears at the full-film factor times the rate with cam.mu = mu_f; on a mixed film each angle's tangential
// solve uses that angle's mu (the test fails if the feedback is cut anywhere between the film and the solve).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/cam_lubrication.h"
#include "cam/periodic_revolution.h"
#include "cam/revolution_dissipation.h"
#include "lib/lubrication/regime.h"
#include "tests/temp_dir.h"
#include "tests/test_text.h"

namespace {

namespace fs = std::filesystem;
using rollwear_test::read_text;
using rollwear_test::TempDirTest;

const fs::path kSource = ROLLWEAR_SOURCE_DIR;

// the shipped lubricated case on 180 angle steps and a 16 x 16 grid, with the replacements (old -> new) given
std::string lubricated(std::initializer_list<std::pair<std::string, std::string>> replacements) {
  const std::string t = rollwear_test::replaced(
      read_text(kSource / "cases" / "cam-follower-lubricated.yaml"),
      {{"  angle_steps: 720", "  angle_steps: 180"},
       {"  tangential: { scheme: consistent }",
        "  tangential: { scheme: consistent, nx: 16, ny: 16, compare_full_transient: false }"}});
  return rollwear_test::replaced(t, replacements);
}

// the case's friction_by_regime line (the shipped case may carry it or not)
std::string with_feedback(const std::string& t, bool on) {
  std::string out = t;
  const std::size_t at = out.find("    friction_by_regime:");
  if (at != std::string::npos) out.erase(at, out.find('\n', at) + 1 - at);
  if (on) out.replace(out.find("    viscosity_Pa_s:"), 0, "    friction_by_regime: true\n");
  return out;
}

cam::CamCase read(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return cam::read_cam_case(p.string());
}

std::unique_ptr<cam::CamLifeSetup> setup_of(const cam::CamCase& c) {
  return cam::set_up_lubricated_cam_life(c.name, c.lubrication, c.model, *c.wear, cam::roller_dynamics_of(c.solver));
}

using CamRegimeFriction = TempDirTest;

// Boundary at every angle (the shipped roughness, lambda <= 0.77): the law gives mu_b = 0.1 and the factor 1 at every
// angle. With cam.mu = mu_b the life with the feedback is the life with the regime reported only, to the bit (the
// feedback's path changes no sum). With cam.mu = 0.15 (which then drives only the first pass's motion and archard's
// mu / mu_k weight) the unworn revolution is the same to the bit and its wear rate to round-off; the life is not
// compared there, since a change of one ulp in the rate moves this life's end by some 4e-6 (the worn revolution's
// skip and shared contacts decide on thresholds: seen with the roller's cells summed in another order).
TEST_F(CamRegimeFriction, BoundaryEverywhereLifeIsTheDryLifeWithTheBoundaryFriction) {
  // the life to 5 um (10 fixed depth steps; the case's 20 um takes 40)
  const std::pair<std::string, std::string> shorter = {"limits: { max_depth_m: 2.0e-5, max_lift_loss_m: 2.0e-5 }",
                                                       "limits: { max_depth_m: 5.0e-6, max_lift_loss_m: 5.0e-6 }"};
  const cam::CamCase fed = read(dir_ / "fed.yaml", with_feedback(lubricated({shorter}), true));
  const cam::CamCase dry = read(dir_ / "dry.yaml", with_feedback(lubricated({shorter}), false));
  ASSERT_TRUE(fed.lubrication.friction_by_regime);
  ASSERT_FALSE(dry.lubrication.friction_by_regime);
  ASSERT_EQ(dry.model.mu, 0.1);
  const auto a = setup_of(fed), b = setup_of(dry);
  ASSERT_EQ(a->model.mu_by_step.size(), 180u);
  for (const double mu : a->model.mu_by_step) ASSERT_EQ(mu, 0.1);  // boundary everywhere: mu_b exactly
  const cam::CamLifeResult la = cam::run_cam_life(a->life, a->producer(), {}, {}, a->memory());
  const cam::CamLifeResult lb = cam::run_cam_life(b->life, b->producer(), {}, {}, b->memory());
  ASSERT_EQ(la.ended_by, lb.ended_by);
  EXPECT_NE(lb.ended_by, wear::LifeEnd::NotRun);
  EXPECT_EQ(la.steps, lb.steps);
  EXPECT_EQ(la.N, lb.N);
  EXPECT_EQ(la.max_depth_m, lb.max_depth_m);
  EXPECT_EQ(la.energy_J, lb.energy_J);
  EXPECT_TRUE((la.state.cam_depth_m == lb.state.cam_depth_m).all());
  EXPECT_TRUE((la.state.roller_depth_m == lb.state.roller_depth_m).all());

  const cam::CamCase other = read(dir_ / "fed15.yaml", with_feedback(lubricated({{"  mu: 0.1 ", "  mu: 0.15 "}}), true));
  ASSERT_EQ(other.model.mu, 0.15);
  const auto c = setup_of(other);
  for (const double mu : c->model.mu_by_step) ASSERT_EQ(mu, 0.1);
  ASSERT_EQ(c->unworn.size(), b->unworn.size());
  for (std::size_t i = 0; i < c->unworn.size(); ++i)
    ASSERT_TRUE((c->unworn[i].power_W_per_m == b->unworn[i].power_W_per_m).all()) << i;
  const cam::CamWearRate rc = cam::wear_per_revolution(c->unworn, c->life.grid, c->life.laws);
  const cam::CamWearRate rb = cam::wear_per_revolution(b->unworn, b->life.grid, b->life.laws);
  const double peak = rb.depth_per_revolution.cam_depth_m.maxCoeff();
  ASSERT_GT(peak, 0);
  EXPECT_LT((rc.depth_per_revolution.cam_depth_m - rb.depth_per_revolution.cam_depth_m).abs().maxCoeff(), 1e-14 * peak);
  const double roller_peak = rb.depth_per_revolution.roller_depth_m.maxCoeff();
  EXPECT_LT((rc.depth_per_revolution.roller_depth_m - rb.depth_per_revolution.roller_depth_m).abs().maxCoeff(),
            1e-13 * roller_peak);
}

// Full film at every angle (surfaces of Rq 1 nm: lambda > 40): mu_f = 0.03 at every angle and the factor 0.25. The
// dissipation is the one with cam.mu = 0.03, and the wear rate a quarter of that case's, cell by cell.
TEST_F(CamRegimeFriction, FullFilmWearsLessByTheFactor) {
  const std::pair<std::string, std::string> smooth = {"    roughness_Rq_m: { body1: 0.10e-6, body2: 0.25e-6 }",
                                                      "    roughness_Rq_m: { body1: 1.0e-9, body2: 1.0e-9 }"};
  const std::pair<std::string, std::string> factor = {"full_film: 0.0 }", "full_film: 0.25 }"};
  const cam::CamCase fed = read(dir_ / "fed.yaml", with_feedback(lubricated({smooth, factor}), true));
  const cam::CamCase dry =
      read(dir_ / "dry.yaml", with_feedback(lubricated({smooth, factor, {"  mu: 0.1 ", "  mu: 0.03 "}}), false));
  const auto a = setup_of(fed), b = setup_of(dry);
  for (const double mu : a->model.mu_by_step) ASSERT_EQ(mu, 0.03);
  ASSERT_EQ(a->life.laws.wear_factor_by_step.size(), 180u);
  for (const double f : a->life.laws.wear_factor_by_step) ASSERT_EQ(f, 0.25);
  ASSERT_EQ(a->unworn.size(), b->unworn.size());
  for (std::size_t i = 0; i < a->unworn.size(); ++i)
    ASSERT_TRUE((a->unworn[i].power_W_per_m == b->unworn[i].power_W_per_m).all()) << i;
  const cam::CamWearRate ra = cam::wear_per_revolution(a->unworn, a->life.grid, a->life.laws);
  const cam::CamWearRate rb = cam::wear_per_revolution(b->unworn, b->life.grid, b->life.laws);
  const double peak = rb.depth_per_revolution.cam_depth_m.maxCoeff();
  ASSERT_GT(peak, 0);
  EXPECT_LT((ra.depth_per_revolution.cam_depth_m - 0.25 * rb.depth_per_revolution.cam_depth_m).abs().maxCoeff(),
            1e-12 * peak);
  const double roller_peak = rb.depth_per_revolution.roller_depth_m.maxCoeff();
  EXPECT_LT((ra.depth_per_revolution.roller_depth_m - 0.25 * rb.depth_per_revolution.roller_depth_m).abs().maxCoeff(),
            1e-12 * roller_peak);
  EXPECT_EQ(ra.energy_J, rb.energy_J);  // the energy reported is the dissipation's, unweighted
}

// A mixed film (surfaces of Rq 30 and 75 nm: lambda 1.2 to 2.6): mu varies from angle to angle. At the angle whose
// mu is farthest from cam.mu, the life's unworn dissipation is the tangential solve with that angle's mu on the same
// motion, and not cam.mu's; the wear law carries the angle's factor. Cut the feedback (the model's mu_by_step, mu_at
// in the dissipation, or the wear's factors) and this fails.
TEST_F(CamRegimeFriction, PerAngleFrictionReachesTheTangentialSolveAndTheWear) {
  const cam::CamCase c = read(dir_ / "mixed.yaml", with_feedback(lubricated({{"    roughness_Rq_m: { body1: 0.10e-6, "
                                                                             "body2: 0.25e-6 }",
                                                                             "    roughness_Rq_m: { body1: 0.03e-6, "
                                                                             "body2: 0.075e-6 }"}}),
                                                                 true));
  const auto s = setup_of(c);
  const std::vector<double>& mu = s->model.mu_by_step;
  ASSERT_EQ(mu.size(), 180u);
  std::size_t k = 0;
  for (std::size_t i = 0; i < mu.size(); ++i)
    if (std::abs(mu[i] - c.model.mu) > std::abs(mu[k] - c.model.mu)) k = i;
  ASSERT_GT(std::abs(mu[k] - c.model.mu), 0.02) << "the film must be mixed for the test to see the feedback";
  // the revolution's lubrication on the life's motion: the law at each angle's film, the mu used within the one
  // pass's mismatch
  const cam::RevolutionLubrication l =
      cam::revolution_lubrication(c.lubrication, s->model, s->revolution, s->motion.motion, s->dynamics.law);
  EXPECT_EQ(l.angles[k].mu_used, mu[k]);
  EXPECT_LT(l.max_mu_mismatch, 1e-3);
  EXPECT_GT(l.angles[k].law.asperity_share, 0);
  EXPECT_LT(l.angles[k].law.asperity_share, 1);
  // the angle's tangential solve: with mu[k] to the bit, not with cam.mu
  cam::CamModel uniform = s->model;
  uniform.mu_by_step.clear();
  uniform.mu = mu[k];
  const cam::RevolutionDissipation own =
      cam::revolution_dissipation(uniform, s->revolution, s->motion.motion, s->dynamics.law);
  uniform.mu = c.model.mu;
  const cam::RevolutionDissipation dry =
      cam::revolution_dissipation(uniform, s->revolution, s->motion.motion, s->dynamics.law);
  const Eigen::ArrayXd& got = s->unworn[k].power_W_per_m;
  EXPECT_TRUE((got == own[k].power_W_per_m).all());
  EXPECT_GT((got - dry[k].power_W_per_m).abs().maxCoeff(), 0.01 * got.abs().maxCoeff());
  // the wear's factor per angle is the law's at that angle's film
  const contact::RegimeFriction r = contact::regime_friction(l.angles[k].lambda, c.lubrication.lubricant->by_regime,
                                                             c.lubrication.lubricant->thresholds);
  EXPECT_NEAR(s->life.laws.wear_factor_by_step[k], r.wear_factor, 0.05);
  EXPECT_EQ(s->life.laws.mu_by_step[k], mu[k]);
}

}  // namespace
