// The cam case file (cam/cam_case.h) and the `rollwear cam` command: the shipped case reads and runs to a
// complete revolution; unknown keys, bad values and refused designs are errors naming file:line and the key
// (exit 2); above the jump speed the command stops with status jump (exit 1) and writes no table.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "cam/cam_case.h"
#include "cam/lift_law.h"
#include "cam/revolution.h"
#include "lib/errors.h"
#include "lib/numeric.h"
#include "tests/run_rollwear.h"
#include "tests/temp_dir.h"

namespace {

namespace fs = std::filesystem;
using rollwear_test::CommandRun;
using rollwear_test::rollwear;
using rollwear_test::TempDirTest;

const fs::path kSource = ROLLWEAR_SOURCE_DIR;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// the shipped case with one line replaced (old must occur once)
std::string shipped_with(const std::string& old_text, const std::string& new_text) {
  std::string t = read_text(kSource / "cases" / "cam-follower.yaml");
  const std::size_t at = t.find(old_text);
  EXPECT_NE(at, std::string::npos) << old_text;
  if (at != std::string::npos) t.replace(at, old_text.size(), new_text);
  return t;
}

// the line (1-based) of the first occurrence of text
int line_of(const std::string& file_text, const std::string& text) {
  const std::size_t at = file_text.find(text);
  return at == std::string::npos ? -1 : 1 + static_cast<int>(std::count(file_text.begin(), file_text.begin() + static_cast<long>(at), '\n'));
}

using CamCaseTest = TempDirTest;

TEST_F(CamCaseTest, ShippedCaseReadsAndRunsACompleteRevolution) {
  const cam::CamCase c = cam::read_cam_case((kSource / "cases" / "cam-follower.yaml").string());
  EXPECT_EQ(c.name, "cam-follower");
  EXPECT_EQ(c.model.angle_steps, 720);
  EXPECT_DOUBLE_EQ(c.model.geometry.roller_radius_m, 0.013);
  const cam::Revolution r = cam::run_revolution(c.model);
  ASSERT_EQ(r.status, cam::RevolutionStatus::Complete);
  EXPECT_EQ(r.rows.size(), 720u);
  const std::string csv = cam::revolution_csv(r);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 721);
}

void expect_case_error(const fs::path& file, const std::string& text, const std::string& key, int line,
                       const std::string& also = "") {
  { std::ofstream(file) << text; }
  try {
    cam::read_cam_case(file.string());
    FAIL() << "accepted: " << key;
  } catch (const contact::CaseError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(file.string() + ":" + std::to_string(line) + ":", 0), 0u) << what;
    EXPECT_NE(what.find(key), std::string::npos) << what;
    if (!also.empty()) {
      EXPECT_NE(what.find(also), std::string::npos) << what;
    }
  }
}

TEST_F(CamCaseTest, UnknownKeysAndBadValuesNameFileLineAndKey) {
  const fs::path f = dir_ / "cam.yaml";
  std::string t = shipped_with("    radius_m: 0.013", "    radus_m: 0.013");
  expect_case_error(f, t, "cam.roller.radus_m: unknown key", line_of(t, "radus_m"), "did you mean 'radius_m'");
  t = shipped_with("  mu: 0.1", "  mu: -0.1");
  expect_case_error(f, t, "cam.mu", line_of(t, "  mu: -0.1"), "must be in [0, 2]");
  t = shipped_with("    rise_law: cycloidal", "    rise_law: parabolic");
  expect_case_error(f, t, "cam.lift.rise_law", line_of(t, "parabolic"), "must be cycloidal, polynomial-345 or harmonic");
}

// a segment law the lift does not know is named once, with the laws a rise or a return can take: not dwell,
// which it refuses there
TEST_F(CamCaseTest, UnknownRiseLawListsTheLawsARiseTakesOnce) {
  const fs::path f = dir_ / "cam.yaml";
  for (const std::string law : {"cycloid", "dwell"}) {
    const std::string t = shipped_with("    rise_law: cycloidal", "    rise_law: " + law);
    expect_case_error(f, t, "cam.lift.rise_law: must be cycloidal, polynomial-345 or harmonic, got '" + law + "'",
                      line_of(t, "rise_law: " + law));
    try {
      cam::read_cam_case(f.string());
    } catch (const contact::CaseError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.find("got"), what.rfind("got")) << what;
    }
  }
}

// Plausibility bounds on the lengths, forces and moduli refuse a unit slip at its key, naming the slip: a 40 m
// base circle (millimetres written as metres) stalled the roller (exit 1); a roller 2 pm wide was solved
// (p0 = 3.5e17 Pa). The shipped values sit well inside every bound.
TEST_F(CamCaseTest, ImplausibleValuesNameTheirKeyAndTheLikelySlip) {
  const fs::path f = dir_ / "cam.yaml";
  struct Slip {
    std::string from, to, key, slip;
  };
  for (const Slip& k : std::vector<Slip>{
           {"  base_radius_m: 0.040", "  base_radius_m: 40", "cam.base_radius_m", "millimetres written as metres?"},
           {"    width_m: 0.011", "    width_m: 2.0e-12", "cam.roller.width_m", "a slip in the exponent"},
           {"    width_m: 0.014", "    width_m: 14", "cam.track.width_m", "millimetres written as metres?"},
           {"    radius_m: 0.013", "    radius_m: 13", "cam.roller.radius_m", "millimetres written as metres?"},
           {"    E_Pa: 2.1e11\n    nu: 0.3\n    inertia", "    E_Pa: 210\n    nu: 0.3\n    inertia",
            "cam.roller.E_Pa", "GPa or MPa written as Pa"},
           {"    lift_m: 0.010", "    lift_m: 1.0e-8", "cam.lift.lift_m", "millimetres converted to metres twice?"},
           {"    preload_N: 150", "    preload_N: 1.5e9", "cam.follower.preload_N", "a slip in the exponent"},
           {"    moving_mass_kg: 0.4", "    moving_mass_kg: 400000", "cam.follower.moving_mass_kg",
            "grams written as kilograms?"}}) {
    const std::string t = shipped_with(k.from, k.to);
    const std::string to_line = k.to.substr(0, k.to.find('\n'));
    expect_case_error(f, t, k.key + ": is not plausible: must be in [", line_of(t, to_line), k.slip);
  }
}

// cam.tangential.scheme chooses the tangential model as a wear case's solver.tangential does: relaxed by default,
// consistent or exact on request (the shipped case asks for consistent: docs/cam-follower.md §9); classic and a
// misspelling refused at the key's line
TEST_F(CamCaseTest, TangentialSchemeIsRelaxedByDefaultConsistentOnRequestOthersRefused) {
  const fs::path f = dir_ / "cam.yaml";
  const cam::CamCase shipped = cam::read_cam_case((kSource / "cases" / "cam-follower.yaml").string());
  EXPECT_EQ(shipped.solver.scheme, contact::TangentialScheme::Consistent);
  const std::string key = "  tangential: { scheme: consistent }";
  std::string t = shipped_with(key, "  tangential: { nx: 40 }");
  { std::ofstream(f) << t; }
  EXPECT_EQ(cam::read_cam_case(f.string()).solver.scheme, contact::TangentialScheme::Relaxed);
  t = shipped_with(key, "  tangential: { scheme: relaxed }");
  { std::ofstream(f) << t; }
  EXPECT_EQ(cam::read_cam_case(f.string()).solver.scheme, contact::TangentialScheme::Relaxed);
  t = shipped_with(key, "  tangential: { scheme: exact }");
  { std::ofstream(f) << t; }
  EXPECT_EQ(cam::read_cam_case(f.string()).solver.scheme, contact::TangentialScheme::Exact);
  for (const char* bad : {"classic", "relaxd"}) {
    t = shipped_with(key, std::string("  tangential: { scheme: ") + bad + " }");
    expect_case_error(f, t, "cam.tangential.scheme", line_of(t, "scheme: " + std::string(bad)), "must be relaxed");
  }
}

// The keys are SI: a key of the former spelling is refused at its line, naming its SI key with the value
// converted (600 rpm = 62.83 rad/s, 100 deg = 1.745 rad)
TEST_F(CamCaseTest, FormerDegreeAndRpmKeysAreRefusedWithTheirSIKey) {
  const fs::path f = dir_ / "cam.yaml";
  std::string t = shipped_with("  speed_rad_per_s: 62.83185307179586", "  speed_rpm: 600");
  expect_case_error(f, t, "cam.speed_rpm", line_of(t, "speed_rpm"), "write speed_rad_per_s: 62.83185307179");
  t = shipped_with("    rise_rad: 1.7453292519943295", "    rise_deg: 100");
  expect_case_error(f, t, "cam.lift.rise_deg", line_of(t, "rise_deg"), "write rise_rad: 1.74532925199");
  t = shipped_with("  max_pressure_angle_rad: 0.5235987755982988", "  max_pressure_angle_deg: 30");
  expect_case_error(f, t, "cam.max_pressure_angle_deg", line_of(t, "max_pressure_angle_deg"),
                    "write max_pressure_angle_rad: 0.52359877559");
  // the shipped case's angles are its degrees in radians, to the last digit
  const cam::CamCase c = cam::read_cam_case((kSource / "cases" / "cam-follower.yaml").string());
  EXPECT_EQ(c.model.law.segments.size(), 4u);
  EXPECT_DOUBLE_EQ(c.model.law.segments[1].start_rad, 100 / cam::kDegPerRad);
  EXPECT_DOUBLE_EQ(c.model.max_pressure_angle_rad, 30 / cam::kDegPerRad);
  EXPECT_DOUBLE_EQ(c.model.omega_rad_per_s, 600 * 2 * contact::kPi / 60);
}

TEST_F(CamCaseTest, RefusedDesignsAreErrorsAtTheirKeyNamingTheAngle) {
  const fs::path f = dir_ / "cam.yaml";
  // a harmonic rise between dwells: its acceleration jumps where it meets the high dwell, at 100 deg
  std::string t = shipped_with("    rise_law: cycloidal", "    rise_law: harmonic");
  expect_case_error(f, t, "cam.lift.rise_law", line_of(t, "rise_law: harmonic"), "cam angle 100 deg");
  // a harmonic return: blamed on return_law, at its start (140 deg)
  t = shipped_with("    return_law: polynomial-345", "    return_law: harmonic");
  expect_case_error(f, t, "cam.lift.return_law", line_of(t, "return_law: harmonic"), "cam angle 140 deg");
  // min_radius_m of 35 mm: the base circle (40 mm) passes, the top of the lift does not; the error is at
  // min_radius_m's line
  t = shipped_with("  min_radius_m: 0.003", "  min_radius_m: 0.035");
  { std::ofstream(f) << t; }
  const cam::CamCase c = cam::read_cam_case(f.string());
  try {
    cam::run_revolution(c.model);
    FAIL();
  } catch (const cam::CamError& e) {
    const std::string what = cam::case_error_of(c, e).what();
    EXPECT_EQ(what.rfind(f.string() + ":" + std::to_string(line_of(t, "  min_radius_m")) + ":", 0), 0u) << what;
    EXPECT_NE(what.find("cam angle"), std::string::npos) << what;
  }
}

// the shipped case's lift given as a table at 1 deg: read, fitted and run; its revolution agrees with
// the law's (the spline's error, 6.3e-10 m in s, 1.1e-3 of the peak in s'', tests/cam_lift_law_test.cpp)
TEST_F(CamCaseTest, LiftTableIsReadFittedAndRunLikeTheLaw) {
  const cam::CamCase law_case = cam::read_cam_case((kSource / "cases" / "cam-follower.yaml").string());
  std::string rows;
  for (int i = 0; i < 360; ++i)
    rows += fmt::format("{}[{:.17g}, {:.17g}]", i ? ", " : "", 2 * contact::kPi * i / 360,
                        cam::lift_at(law_case.model.law, 2 * contact::kPi * i / 360).s_m);
  std::string text = read_text(kSource / "cases" / "cam-follower.yaml");
  const std::size_t from = text.find("  lift:\n"), to = text.find("output:");
  ASSERT_NE(from, std::string::npos);
  text.replace(from, to - from, "  lift:\n    table: [" + rows + "]\n");
  const fs::path f = dir_ / "table.yaml";
  { std::ofstream(f) << text; }
  const cam::CamCase c = cam::read_cam_case(f.string());
  ASSERT_TRUE(c.model.law.is_table);
  const cam::Revolution a = cam::run_revolution(law_case.model), b = cam::run_revolution(c.model);
  ASSERT_EQ(a.rows.size(), b.rows.size());
  constexpr double kLoadRtol = 2e-3;  // the mass term is a few % of F_n, and s'' within 1.1e-3 of its peak
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    EXPECT_NEAR(b.rows[i].kin.lift.s_m, a.rows[i].kin.lift.s_m, 2e-9) << i;
    EXPECT_NEAR(b.rows[i].loads.normal_N, a.rows[i].loads.normal_N, kLoadRtol * a.rows[i].loads.normal_N) << i;
  }
  // a row off the equal steps: an error at the table naming the row
  const std::string row8 = fmt::format("[{:.17g}, ", 2 * contact::kPi * 7 / 360);
  const std::size_t at = text.find(row8);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, row8.size(), "[0.1225, ");
  { std::ofstream(f) << text; }
  try {
    cam::read_cam_case(f.string());
    FAIL();
  } catch (const contact::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("cam.lift.table: row 8: angle_rad must be 0.1221730476"), std::string::npos) << e.what();
  }
}


// (the shipped case on 180 angle steps and a 16 x 16 grid: the command's work, not its resolution, is checked)
TEST_F(CamCaseTest, CommandWritesTheRevolutionTableAndStopsAboveTheJumpSpeed) {
  const fs::path out = dir_ / "out", coarse = dir_ / "coarse.yaml";
  {
    std::string t = shipped_with("  angle_steps: 720", "  angle_steps: 180");
    const std::string key = "  tangential: { scheme: consistent }";
    t.replace(t.find(key), key.size(), "  tangential: { scheme: consistent, nx: 16, ny: 16 }");
    std::ofstream(coarse) << t;
  }
  CommandRun r = rollwear("cam '" + coarse.string() + "' -o '" + out.string() + "' --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("jump speed: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("status: complete"), std::string::npos) << r.out;
  for (const char* line : {"roller dynamics: periodic after", "transient: grid 16 x 16", "quasi-steady skip against",
                           "energy per revolution: shaft", "contact: dissipated"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  const std::string csv = read_text(out / "revolution.csv");
  EXPECT_EQ(csv.rfind("cam_angle_deg,lift_m,", 0), 0u);
  for (const char* column : {"pressure_angle_deg", "cam_radius_m", "normal_load_N", "tangential_load_N", "a_m", "b_m",
                             "p0_Pa", ",xi,", "roller_omega_rad_per_s", "contact_arc_m", "rolling_speed_m_per_s",
                             "slip_speed_m_per_s", "dissipated_power_W", "quasi_steady"})
    EXPECT_NE(csv.find(column), std::string::npos) << column;
  // no temporary file left
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();

  // 2500 rpm (261.8 rad/s) is above the shipped case's jump speed
  const fs::path fast = dir_ / "fast.yaml", out2 = dir_ / "out2";
  {
    std::string t = read_text(coarse);
    t.replace(t.find("62.83185307179586"), 17, "261.8");
    std::ofstream(fast) << t;
  }
  r = rollwear("cam '" + fast.string() + "' -o '" + out2.string() + "' --log-level warn", dir_);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("status: jump"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out2 / "revolution.csv"));

  // an unknown key: exit 2 naming the file
  { std::ofstream(fast) << shipped_with("  offset_m: 0.0", "  ofset_m: 0.0"); }
  r = rollwear("cam '" + fast.string() + "' -o '" + out2.string() + "'", dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(fast.string() + ":"), std::string::npos) << r.err;
}

}  // namespace
