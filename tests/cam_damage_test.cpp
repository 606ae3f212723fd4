// The cam track's and the roller's fatigue damage over the cam's life (cam/cam_damage.h, docs/cam-follower.md §19):
// Miner's sum under constant conditions against its closed form D = N d per cell, the failing cell located, the
// life ending by fatigue at N = 1 / max d; the command's report, maps and plot; bad keys at their file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cam/cam_case.h"
#include "cam/cam_damage.h"
#include "cam/cam_life.h"
#include "lib/errors.h"
#include "lib/numeric.h"
#include "tests/run_rollwear.h"
#include "tests/temp_dir.h"
#include "tests/test_text.h"
#include "wear/fatigue.h"

namespace {

namespace fs = std::filesystem;
using cam::AngleDissipation;
using cam::RevolutionDissipation;
using rollwear_test::read_text;

const fs::path kSource = ROLLWEAR_SOURCE_DIR;

constexpr double kL = 0.25, kTrackW = 0.012, kRollerW = 0.010, kRollerR = 0.013, kOmega = 60;
constexpr int kSteps = 72, kStrips = 12, kArcCells = 36, kLateralCells = 6;
constexpr int kPeakStep = 40, kPeakStrip = 8;  // where the T-gamma is largest

// T-gamma of angle step k, strip j: at the threshold (no damage) but near step 40, where it rises towards the
// peak (65 N at step 40, strip 8), so that one track cell collects the most damage
double tgamma_N(int k, int j) {
  const int dk = std::abs(k - kPeakStep), dj = std::abs(j - kPeakStrip);
  if (dk > 2) return 20;
  return 65 - 10.0 * dk - 4.0 * dj;
}

// a revolution at constant speed whose strips span the track (all loaded: the contact's width is the track's),
// P_l = T-gamma V / w
RevolutionDissipation revolution() {
  RevolutionDissipation rev(kSteps);
  const double dt = 2 * contact::kPi / kSteps / kOmega, V = kL / kSteps / dt;
  for (int k = 0; k < kSteps; ++k) {
    AngleDissipation& a = rev[k];
    a.theta_rad = 2 * contact::kPi * k / kSteps;
    a.duration_s = dt;
    a.cam_arc_m = kL * k / kSteps;
    a.rolling_speed_m_per_s = a.roller_surface_speed_m_per_s = V;
    a.y_m = Eigen::ArrayXd::LinSpaced(kStrips, -0.5 * kTrackW + 0.5 * kTrackW / kStrips,
                                      0.5 * kTrackW - 0.5 * kTrackW / kStrips);
    a.power_W_per_m.resize(kStrips);
    for (int j = 0; j < kStrips; ++j) a.power_W_per_m(j) = tgamma_N(k, j) * V / kTrackW;
  }
  return rev;
}

cam::CamLifeModel model() {
  cam::CamWearSpec spec;
  spec.laws.cam = wear::WearLaw{};
  spec.laws.cam->k_E_m3_per_J = 1e-20;  // wear negligible: the damage is the subject
  spec.revolutions = 1e12;
  spec.max_depth_m = 1e-3;
  spec.arc_cells = kArcCells;
  spec.lateral_cells = kLateralCells;
  spec.stepping.rtol = 1e-6;
  spec.stepping.atol_m = 1e-12;
  spec.smoothing_wavelength_m = 0;
  spec.fatigue = wear::FatigueSection{};
  contact::Profiles unworn;
  unworn.body1 = contact::crowned_profile(0.5, kRollerW);
  unworn.body2 = contact::flat_profile(kTrackW);
  return cam::make_cam_life_model("damage", spec, 0.1, unworn, kRollerR, kL, revolution(), {});
}

// the closed forms: each step's arc is half an arc cell, each strip half a lateral cell of the track, so a track
// cell's damage per revolution is the mean of its 2 x 2 (step, strip) damages per pass; the roller's cell
// collects, per revolution, every step's passes V dt / (2 pi R_r) = L / (n 2 pi R_r), the mean of its 2 strips
struct Expected {
  Eigen::ArrayXXd cam = Eigen::ArrayXXd::Zero(kArcCells, kLateralCells);
  Eigen::ArrayXd roller = Eigen::ArrayXd::Zero(kLateralCells);
};
Expected expected() {
  const wear::BurstowFunction f;
  Expected e;
  for (int k = 0; k < kSteps; ++k)
    for (int j = 0; j < kStrips; ++j) {
      const double d = wear::burstow_damage_per_pass(f, tgamma_N(k, j));
      e.cam(k / 2, j / 2) += d / 4;
      // roller: the roller is 10 mm wide, the strips 1 mm across the 12 mm track: strip j covers roller y in
      // [j - 6, j - 5) mm, the roller [-5, 5) mm, its 6 cells 5/3 mm each
      const double y0 = (j - 6) * 1e-3, y1 = y0 + 1e-3;
      for (int c = 0; c < kLateralCells; ++c) {
        const double c0 = -0.5 * kRollerW + c * kRollerW / kLateralCells, c1 = c0 + kRollerW / kLateralCells;
        const double overlap = std::max(0.0, std::min(y1, c1) - std::max(y0, c0));
        e.roller(c) += d * overlap / (kRollerW / kLateralCells) * kL / kSteps / (2 * contact::kPi * kRollerR);
      }
    }
  return e;
}

TEST(CamDamage, PerRevolutionIsTheMeanDamagePerPassOfEachCell) {
  const cam::CamLifeModel m = model();
  const cam::CamDamageRate r = cam::damage_per_revolution(revolution(), m.grid, *m.fatigue);
  const Expected e = expected();
  ASSERT_GT(e.cam.maxCoeff(), 0);
  EXPECT_LT((r.per_revolution.cam - e.cam).abs().maxCoeff(), 1e-13 * e.cam.maxCoeff());
  EXPECT_LT((r.per_revolution.roller - e.roller).abs().maxCoeff(), 1e-13 * e.cam.maxCoeff());
  EXPECT_DOUBLE_EQ(r.max_tgamma_N, 65);
  EXPECT_NEAR(r.max_tgamma_at_rad, 2 * contact::kPi * kPeakStep / kSteps, 1e-12);
  // where the strips carry nothing (no power, no pressure) the contact is narrower: T-gamma w P / V with w the
  // loaded strips' extent, half the track's here, so the damage is that of half the T-gamma
  RevolutionDissipation half = revolution();
  for (AngleDissipation& a : half) a.power_W_per_m.head(kStrips / 2) = 0;
  const cam::CamDamageRate h = cam::damage_per_revolution(half, m.grid, *m.fatigue);
  EXPECT_DOUBLE_EQ(h.max_tgamma_N, 32.5);
}

// constant conditions (the producer ignores the wear): D = N d per cell at every snapshot, the life ends by fatigue
// at N = 1 / max d, located at the worst cell (its cam angle and lateral position)
TEST(CamDamage, ConstantConditionsGiveNTimesTheDamagePerPassAndEndTheLifeAtTheWorstCell) {
  cam::CamLifeModel m = model();
  m.snapshots_revolutions = {1e4, 3e4};
  const Expected e = expected();
  Eigen::Index wi = 0, wj = 0;
  const double worst = e.cam.maxCoeff(&wi, &wj);
  ASSERT_GT(worst, e.roller.maxCoeff());  // the cam fails first on this revolution
  std::map<double, cam::CamDamage> snapshots;
  cam::CamLifeHooks hooks;
  hooks.on_damage_snapshot = [&](double N, const cam::CamDamage& d) { snapshots[N] = d; };
  std::vector<double> step_damage, step_N;
  hooks.on_step = [&](const cam::CamLifeStep& s) {
    step_N.push_back(s.N);
    step_damage.push_back(s.damage.value);
  };
  const cam::CamLifeResult life = cam::run_cam_life(m, [](const cam::CamWearState&) { return revolution(); }, hooks);
  ASSERT_EQ(life.ended_by, wear::LifeEnd::Fatigue) << life.message;
  EXPECT_NEAR(life.N, 1 / worst, 1e-9 / worst);
  EXPECT_NEAR(life.max_damage.value, 1, 1e-9);
  EXPECT_EQ(life.max_damage.body, "cam");
  EXPECT_DOUBLE_EQ(life.max_damage.arc_m, m.grid.arc_m(static_cast<int>(wi)));
  EXPECT_DOUBLE_EQ(life.max_damage.y_m, m.grid.track_y_m(static_cast<int>(wj)));
  // the worst cell holds steps 40 and 41 (cells of two steps): the contact passes its centre at step 41, 205 deg
  EXPECT_NEAR(life.max_damage.theta_rad * 180 / contact::kPi, 205, 1e-9);
  ASSERT_EQ(snapshots.size(), 4u);  // 0, the two, the end
  for (const auto& [N, d] : snapshots) {
    EXPECT_LT((d.cam - N * e.cam).abs().maxCoeff(), 1e-9 * std::max(N * worst, 1e-300)) << N;
    EXPECT_LT((d.roller - N * e.roller).abs().maxCoeff(), 1e-9 * std::max(N * worst, 1e-300)) << N;
  }
  ASSERT_FALSE(step_N.empty());
  for (std::size_t k = 0; k < step_N.size(); ++k) EXPECT_NEAR(step_damage[k], step_N[k] * worst, 1e-9) << k;
  // the report's lines
  const std::string text = cam::cam_damage_report_text(m, life);
  EXPECT_NE(text.find("fatigue_law: burstow\n"), std::string::npos) << text;
  EXPECT_NE(text.find("max_damage: 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("max_damage_body: cam\n"), std::string::npos) << text;
  EXPECT_NE(text.find("max_damage_at_deg: 205\n"), std::string::npos) << text;
  EXPECT_NE(text.find("max_tgamma_N: 65\n"), std::string::npos) << text;
}

// the roller fails first where the damaging steps cover the whole revolution: every roller point passes the contact
// L / (2 pi R_r) = 3.06 times per cam revolution, a track point once
TEST(CamDamage, TheRollerFailsFirstWhenEveryAngleDamages) {
  cam::CamLifeModel m = model();
  const auto uniform = [](const cam::CamWearState&) {
    RevolutionDissipation rev = revolution();
    for (AngleDissipation& a : rev) a.power_W_per_m = Eigen::ArrayXd::Constant(kStrips, 65 * a.rolling_speed_m_per_s / kTrackW);
    return rev;
  };
  const cam::CamLifeResult life = cam::run_cam_life(m, uniform);
  ASSERT_EQ(life.ended_by, wear::LifeEnd::Fatigue) << life.message;
  EXPECT_EQ(life.max_damage.body, "roller");
  EXPECT_TRUE(std::isnan(life.max_damage.theta_rad));
  EXPECT_NEAR(life.N, 2 * contact::kPi * kRollerR / kL / 1e-5, 1e-9 * life.N);
  EXPECT_NEAR(life.damage.cam.maxCoeff(), life.N * 1e-5, 1e-9);
}

// the damage is in the life's state, so a life stopped after a step and resumed from that step's start (a
// checkpoint's content) ends where the uninterrupted one does, to the bit, with the same damage
TEST(CamDamage, AFatigueLifeStoppedAndResumedIsTheUninterruptedOne) {
  cam::CamLifeModel m = model();
  m.stepping.method = wear::IntegratorOptions::Method::FixedDepth;  // several steps (the adaptive life takes few)
  m.stepping.max_depth_step_m = 0.1 * m.damage_scale_m;             // damage 0.1 per step
  // the rate depends on the worn state (a producer that ignores it would not show a bad restart of the damage)
  const auto producer = [](const cam::CamWearState& s) {
    RevolutionDissipation rev = revolution();
    for (AngleDissipation& a : rev) a.power_W_per_m *= 1 + 1e4 * s.cam_depth_m.maxCoeff();  // +20 % at 20 um
    return rev;
  };
  m.laws.cam->k_E_m3_per_J = 1e-13;  // about 20 um at the fatigue end, the depth limit 1 mm
  const cam::CamLifeResult whole = cam::run_cam_life(m, producer);
  ASSERT_EQ(whole.ended_by, wear::LifeEnd::Fatigue) << whole.message;
  ASSERT_GT(whole.steps, 4);
  cam::CamLifeStart at;
  cam::CamLifeHooks stop;
  stop.on_step = [&](const cam::CamLifeStep& s) { at = s.resume; };
  stop.stop_after = [](const cam::CamLifeStep& s) { return s.step == 3; };
  ASSERT_EQ(cam::run_cam_life(m, producer, stop).ended_by, wear::LifeEnd::Stopped);
  const cam::CamLifeResult resumed = cam::run_cam_life(m, producer, {}, at);
  EXPECT_EQ(resumed.ended_by, wear::LifeEnd::Fatigue);
  EXPECT_EQ(resumed.N, whole.N);
  EXPECT_EQ(resumed.steps, whole.steps);
  EXPECT_TRUE((resumed.damage.cam == whole.damage.cam).all());
  EXPECT_TRUE((resumed.damage.roller == whole.damage.roller).all());
  EXPECT_TRUE((resumed.state.cam_depth_m == whole.state.cam_depth_m).all());
  // a start without the damage (a life's state of another model) is refused
  cam::CamLifeStart short_start = at;
  short_start.x.conservativeResize(at.x.size() - m.grid.arc_cells * m.grid.track_cells - m.grid.roller_cells);
  short_start.rate.resize(0);
  EXPECT_THROW(cam::run_cam_life(m, producer, {}, short_start), std::invalid_argument);
}

// ---- the case and the command ----

class CamDamageCase : public rollwear_test::TempDirTest {
 protected:
  // the shipped cam case, coarse (72 angle steps, 72 x 28 cells), with the wear section's extra lines
  fs::path write_case(const std::string& extra) {
    std::string s = read_text(kSource / "cases" / "cam-follower.yaml");
    const std::size_t a = s.find("\n  wear:"), b = s.find("\noutput:");
    EXPECT_NE(a, std::string::npos);
    s = s.substr(0, a + 1) +
        "  wear:\n    cam: { law: archard, archard_k: 1.0e-6, hardness_Pa: 6.9e9 }\n"
        "    roller: { law: archard, archard_k: 1.0e-6, hardness_Pa: 6.9e9 }\n    revolutions: 1.0e12\n"
        "    limits: { max_depth_m: 2.0e-6 }\n    stepping: { method: fixed-depth, max_depth_step_m: 1.0e-6 }\n"
        "    arc_cells: 72\n    lateral_cells: 28\n" +
        extra + s.substr(b);
    const std::size_t at = s.find("angle_steps: 720");
    EXPECT_NE(at, std::string::npos);
    s.replace(at, 16, "angle_steps: 72");
    const fs::path p = dir_ / "case.yaml";
    std::ofstream(p) << s;
    return p;
  }
  static std::string error_of(const fs::path& path) {
    try {
      cam::read_cam_case(path.string());
    } catch (const contact::CaseError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(CamDamageCase, BadFatigueKeysNameFileLineAndKey) {
  const std::string law = error_of(write_case("    fatigue: { law: wohler }\n"));
  EXPECT_NE(law.find("case.yaml:"), std::string::npos) << law;
  EXPECT_NE(law.find("cam.wear.fatigue.law"), std::string::npos) << law;
  EXPECT_NE(law.find("burstow"), std::string::npos) << law;
  const std::string order = error_of(write_case("    fatigue: { law: burstow, threshold_N: 70 }\n"));
  EXPECT_NE(order.find("cam.wear.fatigue.peak_at_N"), std::string::npos) << order;
  const std::string typo = error_of(write_case("    fatigue: { law: burstow, peak_damage_N: 1.0e-5 }\n"));
  EXPECT_NE(typo.find("peak_damage_N"), std::string::npos) << typo;
  EXPECT_EQ(error_of(write_case("    fatigue: { law: burstow }\n")), "");
  const rollwear_test::CommandRun r =
      rollwear_test::rollwear("run '" + write_case("    fatigue: { law: burstow, peak_damage: 2 }\n").string() +
                                  "' -o '" + (dir_ / "out").string() + "' -q",
                              dir_);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("cam.wear.fatigue.peak_damage"), std::string::npos) << r.err;
}

// the shipped case's rolling roller dissipates little: its strips' T-gamma is below 1e-3 N, far under Burstow's rail
// threshold of 20 N (no damage by the published function: docs/cam-follower.md §19); with a function scaled to it
// (threshold 1e-4 N, peak 5e-4 N) the life ends by fatigue before the wear limit, on the roller, whose surface passes
// the contact about 2.8 times per cam revolution; the report, life.csv and the damage maps agree, and the plot draws
// the damage along the track
TEST_F(CamDamageCase, RunEndsByFatigueWhereTheMapsSayAndPlotDrawsTheDamage) {
  const fs::path out = dir_ / "out";
  const rollwear_test::CommandRun r = rollwear_test::rollwear(
      "run '" +
          write_case("    fatigue: { law: burstow, threshold_N: 1.0e-4, peak_at_N: 5.0e-4, zero_at_N: 1.0e-2, "
                     "peak_damage: 1.0e-9 }\n    snapshots_revolutions: [1.0e8]\n")
              .string() +
          "' -o '" + out.string() + "' -q",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string report = read_text(out / "report.txt");
  std::map<std::string, std::string> key;
  std::istringstream lines(report);
  for (std::string line; std::getline(lines, line);)
    if (const std::size_t c = line.find(": "); c != std::string::npos) key[line.substr(0, c)] = line.substr(c + 2);
  EXPECT_EQ(key["ended_by"], "fatigue") << report;
  EXPECT_EQ(key["fatigue_law"], "burstow");
  EXPECT_EQ(key["max_damage"], "1");
  EXPECT_EQ(key["max_damage_body"], "roller");
  EXPECT_LT(std::stod(key["max_depth_m"]), 2e-6);  // before the wear limit
  // the end's maps: their largest is the report's, where it says
  const double at_y = std::stod(key["max_damage_y_m"]);
  double cam_max = 0, roller_max = 0, roller_at_y = -1;
  {
    std::istringstream m(read_text(out / "snapshots" / "roller_damage_0002.csv"));
    std::string line;
    while (std::getline(m, line) && line.rfind("#", 0) == 0) {
    }
    EXPECT_EQ(line, "y_m,damage");
    while (std::getline(m, line)) {
      const double y = std::stod(line.substr(0, line.find(','))), d = std::stod(line.substr(line.find(',') + 1));
      roller_max = std::max(roller_max, d);
      if (std::abs(y - at_y) < 1e-9) roller_at_y = d;
    }
    std::istringstream t(read_text(out / "snapshots" / "damage_map_0002.csv"));
    while (std::getline(t, line) && line.rfind("#", 0) == 0) {
    }
    EXPECT_EQ(line, "cam_angle_deg,cam_arc_m,y_m,damage");
    while (std::getline(t, line)) cam_max = std::max(cam_max, std::stod(line.substr(line.rfind(',') + 1)));
  }
  EXPECT_NEAR(roller_max, 1, 1e-9);
  EXPECT_GT(cam_max, 0.1);  // the track is damaged too, less
  EXPECT_LT(cam_max, roller_max);
  EXPECT_NEAR(roller_at_y, roller_max, 1e-9);  // the report's y is a cell of the largest (two of them, mirrored)
  // life.csv's last row: the located end, damage 1
  const std::string life = read_text(out / "life.csv");
  EXPECT_NE(life.find("step,revolutions,max_depth_m,lift_loss_m,lift_loss_at_deg,energy_J,max_damage\n"),
            std::string::npos) << life;
  const std::string last = life.substr(life.rfind('\n', life.size() - 2) + 1);
  EXPECT_NEAR(std::stod(last.substr(last.rfind(',') + 1)), 1, 1e-9) << last;
  EXPECT_NEAR(std::stod(last.substr(last.find(',') + 1)), std::stod(key["revolutions"]),
              1e-5 * std::stod(key["revolutions"])) << last;
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    const rollwear_test::CommandRun p = rollwear_test::rollwear("plot '" + out.string() + "'", dir_);
    EXPECT_EQ(p.exit_code, 0) << p.err;
    EXPECT_TRUE(fs::exists(out / "plots" / "cam_damage.png"));
  }
  // without the section: no damage map, no column, no picture
  const fs::path plain = dir_ / "plain";
  ASSERT_EQ(rollwear_test::rollwear("run '" + write_case("").string() + "' -o '" + plain.string() + "' -q", dir_).exit_code, 0);
  EXPECT_FALSE(fs::exists(plain / "snapshots" / "damage_map_0000.csv"));
  EXPECT_EQ(read_text(plain / "life.csv").find("max_damage"), std::string::npos);
  EXPECT_EQ(read_text(plain / "report.txt").find("max_damage"), std::string::npos);
}

}  // namespace
