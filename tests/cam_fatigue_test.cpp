// The fatigue indicators per cam angle (cam/cam_lubrication.h, docs/cam-follower.md §18): at one angle they are
// lib/subsurface/shakedown.h's called by hand with that angle's p0, mu_eff = |F_t|/F_n and patch; the case without the
// shear yield keys writes what it wrote before; a bad key is an error naming file:line:key (exit 2); the life's
// first_failure names the mode whose margin is exceeded first.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cam/cam_case.h"
#include "cam/cam_lubrication.h"
#include "cam/periodic_revolution.h"
#include "cam/roller_dynamics.h"
#include "lib/errors.h"
#include "lib/numeric.h"
#include "lib/subsurface/shakedown.h"
#include "tests/run_rollwear.h"
#include "tests/temp_dir.h"
#include "tests/test_text.h"

namespace {

namespace fs = std::filesystem;
using rollwear_test::lines_of;
using rollwear_test::read_text;
using rollwear_test::CommandRun;
using rollwear_test::rollwear;
using rollwear_test::TempDirTest;

const fs::path kSource = ROLLWEAR_SOURCE_DIR;

// the shipped lubricated case on 180 angle steps and a 16 x 16 grid (the work is checked, not the resolution), with
// replacements (old -> new)
std::string coarse(std::vector<std::pair<std::string, std::string>> more = {}) {
  std::string t = read_text(kSource / "cases" / "cam-follower-lubricated.yaml");
  more.insert(more.begin(), {{"  angle_steps: 720", "  angle_steps: 180"},
                             {"  tangential: { scheme: consistent }",
                              "  tangential: { scheme: consistent, nx: 16, ny: 16, compare_full_transient: false }"}});
  for (const auto& [from, to] : more) {
    const std::size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) t.replace(at, from.size(), to);
  }
  return t;
}

fs::path write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

using CamFatigue = TempDirTest;

// At the angle of the largest mu_eff and at the revolution's worst shakedown angle: mu_eff is the motion's |F_t|/F_n,
// p0 and the semi-axes the angle's contact under the motion's F_n, and the margin and FI_surf of each body are
// shakedown.h's limit (its contact type by b/a) and Ekberg's index with them. A margin on the kinematic load, or an
// index with another traction coefficient (m.mu, or none), fail it.
TEST_F(CamFatigue, AngleMarginAndIndexAreShakedownHByHand) {
  const cam::CamCase c = cam::read_cam_case(write(dir_ / "lub.yaml", coarse()).string());
  ASSERT_GT(c.lubrication.fatigue.roller_shear_yield_Pa, 0);
  ASSERT_GT(c.lubrication.fatigue.cam_shear_yield_Pa, 0);
  const cam::CamRun run = cam::run_cam(c.model, c.solver, c.lubrication);
  const cam::RevolutionLubrication& l = run.lubrication;
  ASSERT_EQ(l.angles.size(), run.revolution.rows.size());
  const cam::CreepLawSettings law = cam::roller_dynamics_of(c.solver).law;
  for (const std::size_t k : {l.max_traction_at, l.min_shakedown_at}) {
    const cam::RevolutionRow& row = run.revolution.rows[k];
    const cam::RollerAngle& roller = run.motion.motion.angles[k];
    const cam::AngleLubrication& got = l.angles[k];
    // by hand: the angle's contact under the motion's F_n, the motion's traction coefficient
    const cam::AngleContact contact_k =
        cam::angle_contact(c.model.bodies, cam::roller_and_track_profiles(c.model.bodies),
                           c.model.geometry.roller_radius_m, row.kin, roller.normal_N, c.model.mu, law);
    const contact::ContactPatch& patch = contact_k.normal.patch;
    const double a = patch.a_m, b = patch.b_m, p0 = patch.p0_Pa, Fn = roller.normal_N;
    EXPECT_NEAR(p0, run.transient.p0_Pa[k], 1e-12 * p0);  // the revolution table's contact
    const double mu = std::abs(roller.tangential_N) / Fn;
    ASSERT_GT(mu, 1e-4) << "the roller must carry a traction for the test to see mu_eff";
    EXPECT_NEAR(got.traction_coefficient, mu, 1e-6 * mu) << "at " << row.kin.theta_rad * cam::kDegPerRad << " deg";
    EXPECT_NEAR(got.p0_Pa, p0, 1e-12 * p0);
    const contact::ShakedownContact type = contact::shakedown_contact_of(a, b);
    EXPECT_EQ(got.shakedown_contact, type);
    for (const auto& [k_Pa, margin, fi] :
         {std::tuple{c.lubrication.fatigue.roller_shear_yield_Pa, got.shakedown_margin_roller, got.fi_surf_roller},
          std::tuple{c.lubrication.fatigue.cam_shear_yield_Pa, got.shakedown_margin_cam, got.fi_surf_cam}}) {
      const double margin_hand = contact::shakedown_limit_p0_over_k(type, mu) / (p0 / k_Pa) - 1;
      const double fi_hand = mu - 2 * contact::kPi * a * b * k_Pa / (3 * Fn);
      EXPECT_NEAR(margin, margin_hand, 1e-9 * std::abs(margin_hand));
      EXPECT_NEAR(fi, fi_hand, 1e-6 * mu);  // FI_surf's traction term carries mu's tolerance
      // what a wrong traction coefficient gives (the case's mu, or none): told apart by the tolerance
      EXPECT_GT(std::abs((c.model.mu - 2 * contact::kPi * a * b * k_Pa / (3 * Fn)) - fi_hand), 1e3 * 1e-6 * mu);
      EXPECT_GT(std::abs((0 - 2 * contact::kPi * a * b * k_Pa / (3 * Fn)) - fi_hand), 1e2 * 1e-6 * mu);
    }
  }
  // the worst over the revolution is the least margin of both bodies; the lower k's (the cam's) on this case
  for (const cam::AngleLubrication& a : l.angles) {
    EXPECT_GE(a.shakedown_margin_roller, l.min_shakedown_margin);
    EXPECT_GE(a.shakedown_margin_cam, l.min_shakedown_margin);
    EXPECT_LE(a.fi_surf_cam, l.max_fi_surf);
  }
  EXPECT_EQ(l.min_shakedown_body, cam::CamBody::Cam);
}

// Without the shear yield keys the lubricated case's table and summary are what they were (no fatigue column or
// line); with them the fatigue's columns come after every other, which they leave as they were.
TEST_F(CamFatigue, WithoutTheKeysNothingChangesAndTheColumnsChangeNoOther) {
  const cam::CamCase with = cam::read_cam_case(write(dir_ / "with.yaml", coarse()).string());
  const cam::CamCase without = cam::read_cam_case(
      write(dir_ / "without.yaml", coarse({{"    shear_yield_Pa: 1.2e9", "   "}, {"    shear_yield_Pa: 0.9e9", "   "}}))
          .string());
  EXPECT_FALSE(without.lubrication.fatigue.any());
  const cam::CamRun w = cam::run_cam(with.model, with.solver, with.lubrication);
  const cam::CamRun wo = cam::run_cam(without.model, without.solver, without.lubrication);
  const std::vector<std::string> a = lines_of(cam::revolution_csv(w)), b = lines_of(cam::revolution_csv(wo));
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a[0], b[0] + ",traction_coefficient,p0_Pa,shakedown_contact,shakedown_margin_roller,fi_surf_roller,"
                         "shakedown_margin_cam,fi_surf_cam");
  for (std::size_t i = 1; i < a.size(); ++i) {
    EXPECT_EQ(a[i].substr(0, b[i].size() + 1), b[i] + ",") << i;
    if (i == 1) {
      EXPECT_NE(a[i].find(",line,"), std::string::npos) << a[i];  // b/a of 12 and more: a line contact
    }
  }
  EXPECT_EQ(cam::cam_summary(wo).find("shakedown"), std::string::npos);
  EXPECT_NE(cam::cam_summary(w).find("shakedown (Johnson, line contact at b/a "), std::string::npos)
      << cam::cam_summary(w);
}


int line_of(const std::string& file_text, const std::string& text) {
  const std::size_t at = file_text.find(text);
  return at == std::string::npos ? -1 : 1 + static_cast<int>(std::count(file_text.begin(), file_text.begin() + static_cast<long>(at), '\n'));
}

TEST_F(CamFatigue, BadShearYieldNamesFileLineAndKeyAndExits2) {
  for (const auto& [from, to, key] :
       {std::tuple{"    shear_yield_Pa: 1.2e9", "    shear_yield_Pa: -1", "cam.roller.shear_yield_Pa"},
        std::tuple{"    shear_yield_Pa: 0.9e9", "    shear_yield_Pa: 9e9", "cam.track.shear_yield_Pa"}}) {
    const std::string t = coarse({{from, to}});
    const fs::path p = write(dir_ / "bad.yaml", t);
    std::string e;
    try {
      cam::read_cam_case(p.string());
    } catch (const contact::CaseError& x) {
      e = x.what();
    }
    EXPECT_EQ(e.rfind(fmt::format("{}:{}:", p.string(), line_of(t, to)), 0), 0u) << e;
    EXPECT_NE(e.find(std::string(key) + ": must be in [1000000, 5000000000]"), std::string::npos) << e;
    const CommandRun r = rollwear("cam '" + p.string() + "' -o '" + (dir_ / "out").string() + "'", dir_);
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out" / "revolution.csv"));
  }
}

// first_failure: the mode whose margin is exceeded; scuffing before surface fatigue, both before the wear life; the
// others' margins said beside it
TEST_F(CamFatigue, FirstFailureNamesTheExceededMode) {
  cam::CamLubricationSpec spec;
  spec.fatigue.cam_shear_yield_Pa = 1e9;
  spec.thermal.emplace();
  cam::RevolutionLubrication l;
  l.angles.resize(4);
  for (std::size_t i = 0; i < 4; ++i) l.angles[i].theta_rad = static_cast<double>(i);
  l.max_flash = 1;
  l.min_shakedown_at = 2;
  l.min_shakedown_body = cam::CamBody::Cam;
  const auto first = [&](double shakedown, double scuffing, bool wear) {
    l.min_shakedown_margin = shakedown;
    l.angles[1].scuffing_margin_K = scuffing;
    const std::string t = cam::first_failure_text(spec, l, wear, "max-depth", 3e9);
    return lines_of(t).at(0);
  };
  EXPECT_EQ(first(0.5, 20, true), "first_failure: wear");
  EXPECT_EQ(first(0.5, 20, false), "first_failure: none");
  EXPECT_EQ(first(-0.1, 20, true), "first_failure: surface-fatigue");
  EXPECT_EQ(first(-0.1, -5, true), "first_failure: scuffing");
  EXPECT_EQ(first(0.5, -5, false), "first_failure: scuffing");
  // a life ended by fatigue damage 1: named after the margins exceeded from the start, in place of the wear life
  const auto by_damage = [&](double shakedown, double scuffing) {
    l.min_shakedown_margin = shakedown;
    l.angles[1].scuffing_margin_K = scuffing;
    return lines_of(cam::first_failure_text(spec, l, false, "fatigue", 2e9, true));
  };
  EXPECT_EQ(by_damage(0.5, 20).at(0), "first_failure: fatigue");
  EXPECT_EQ(by_damage(0.5, 20).at(2), "other_margins: shakedown margin 0.5 (cam at 114.6 deg); scuffing margin 20 K "
                                      "at 57.3 deg; no wear limit before fatigue at 2e+09 revolutions");
  EXPECT_EQ(by_damage(-0.1, 20).at(0), "first_failure: surface-fatigue");
  EXPECT_EQ(by_damage(0.5, -5).at(0), "first_failure: scuffing");
  EXPECT_EQ(lines_of(cam::first_failure_text(cam::CamLubricationSpec{}, l, false, "fatigue", 2e9, true)).at(0),
            "first_failure: fatigue");
  const std::string t = cam::first_failure_text(spec, l, true, "max-depth", 3e9);
  EXPECT_NE(t.find("other_margins: shakedown margin 0.5 (cam at 114.6 deg); wear life 3e+09 revolutions (max-depth)"),
            std::string::npos) << t;
  l.min_shakedown_margin = -0.1;
  l.angles[1].scuffing_margin_K = 20;
  EXPECT_NE(cam::first_failure_text(spec, l, true, "max-depth", 3e9)
                .find("ratchetting/surface fatigue expected from the first revolutions"), std::string::npos);
  // a mode not assessed is not claimed in the note
  cam::CamLubricationSpec fatigue_only;
  fatigue_only.fatigue.cam_shear_yield_Pa = 1e9;
  l.min_shakedown_margin = 0.5;
  const std::string f = cam::first_failure_text(fatigue_only, l, true, "max-depth", 3e9);
  EXPECT_EQ(lines_of(f).at(1), "first_failure_note: the wear limit (max-depth) at 3e+09 revolutions, inside shakedown "
                               "(margins of the unworn revolution)") << f;
  EXPECT_NE(f.find("scuffing not assessed (no critical_temperature_C)"), std::string::npos) << f;
  // nothing to compare: no shear yield stress, no scuffing margin
  EXPECT_EQ(cam::first_failure_text({}, l, true, "max-depth", 3e9), "");
}

}  // namespace
