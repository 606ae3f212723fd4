// The film and the flash temperature per cam angle (cam/cam_lubrication.h, docs/cam-follower.md §17): at one angle
// they are the contact-level functions' (lib/lubrication/film.h, lib/thermal/flash_temperature.h) called by hand
// with that angle's load, radii and the two surfaces' speeds; the dry case's outputs are unchanged, and the lubricated
// case's columns are appended to them without changing any; bad keys are errors naming file:line:key (exit 2).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "cam/cam_case.h"
#include "cam/cam_lubrication.h"
#include "cam/periodic_revolution.h"
#include "cam/revolution_dissipation.h"
#include "lib/elastic.h"
#include "lib/errors.h"
#include "lib/lubrication/film.h"
#include "lib/thermal/flash_temperature.h"
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

// a shipped case on 180 angle steps and a 16 x 16 grid without the full transient's comparison (the work is
// checked, not the resolution), with one more replacement (old -> new) if given
std::string coarse(const std::string& case_name, const std::string& old_text = "", const std::string& new_text = "") {
  const std::string t = rollwear_test::replaced(
      read_text(kSource / "cases" / case_name),
      {{"  angle_steps: 720", "  angle_steps: 180"},
       {"  tangential: { scheme: consistent }",
        "  tangential: { scheme: consistent, nx: 16, ny: 16, compare_full_transient: false }"}});
  return old_text.empty() ? t : rollwear_test::replaced(t, {{old_text, new_text}});
}

fs::path write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// each line of csv cut before its `columns`-th comma (its first `columns` cells)
std::string first_columns(const std::string& csv, std::size_t columns) {
  std::string out;
  for (const std::string& line : lines_of(csv)) {
    std::size_t at = 0, commas = 0;
    while (at < line.size() && !(line[at] == ',' && ++commas == columns)) ++at;
    out += line.substr(0, at) + "\n";
  }
  return out;
}

std::size_t cells_in(const std::string& line) { return 1 + static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')); }

using CamLubrication = TempDirTest;

// The dry case: no column, no line added. The lubricated case with its sections removed is that dry revolution; with
// them its table is the dry one's, each row the same to the byte, with the film's and temperature's columns after.
TEST_F(CamLubrication, DryOutputsUnchangedAndTheLubricatedColumnsChangeNoOther) {
  const cam::CamCase dry = cam::read_cam_case(write(dir_ / "dry.yaml", coarse("cam-follower.yaml")).string());
  EXPECT_FALSE(dry.lubrication.any());
  const cam::CamRun d = cam::run_cam(dry.model, dry.solver, dry.lubrication);
  const std::string dry_csv = cam::revolution_csv(d);
  EXPECT_EQ(lines_of(dry_csv).at(0).substr(lines_of(dry_csv).at(0).rfind(',') + 1), "unsteadiness");
  EXPECT_TRUE(d.lubrication.angles.empty());
  EXPECT_EQ(cam::cam_summary(d).find("film"), std::string::npos);
  EXPECT_EQ(cam::cam_summary(d).find("flash"), std::string::npos);
  // the same solve with no spec at all (the call every other caller makes): the same bytes
  EXPECT_EQ(cam::revolution_csv(cam::run_cam(dry.model, dry.solver)), dry_csv);

  // the shipped lubricated case feeds the regime law back (friction_by_regime): boundary at every angle, mu_b = cam.mu,
  // so its columns are still the dry run's to the byte
  const std::string lubricated_text = coarse("cam-follower-lubricated.yaml");
  const cam::CamCase lub = cam::read_cam_case(write(dir_ / "lub.yaml", lubricated_text).string());
  ASSERT_TRUE(lub.lubrication.lubricant && lub.lubrication.thermal && lub.lubrication.friction_by_regime);
  const cam::CamRun l = cam::run_cam(lub.model, lub.solver, lub.lubrication);
  const cam::CamRun l_dry = cam::run_cam(lub.model, lub.solver);
  const std::string with = cam::revolution_csv(l), without = cam::revolution_csv(l_dry);
  const std::size_t base_columns = cells_in(lines_of(without).at(0));
  EXPECT_EQ(first_columns(with, base_columns), without);
  EXPECT_EQ(lines_of(with).at(0).substr(lines_of(without).at(0).size()),
            ",cam_surface_speed_m_per_s,roller_surface_speed_m_per_s,entrainment_m_per_s,Rx_m,ellipticity_k,h_min_m,"
            "h_central_m,lambda,lubrication_regime,regime_mu,regime_wear_factor,asperity_share,law_mu,mu_used,"
            "wear_factor_used,heat_W,flash_max_K,heat_share_roller,"
            "peclet_roller,peclet_cam,transit_s,contact_temperature_C,scuffing_margin_K,traction_coefficient,p0_Pa,"
            "shakedown_contact,shakedown_margin_roller,fi_surf_roller,shakedown_margin_cam,fi_surf_cam");
  for (const std::string& line : lines_of(with)) EXPECT_EQ(cells_in(line), base_columns + 30) << line;
  // the summary's lines come after the dry summary's, which they leave as it was
  const std::regex cpu("[0-9.e+-]+ s CPU");
  const std::string summary = std::regex_replace(cam::cam_summary(l), cpu, "s CPU"),
                    dry_summary = std::regex_replace(cam::cam_summary(l_dry), cpu, "s CPU");
  EXPECT_EQ(summary.substr(0, dry_summary.size()), dry_summary);
  for (const char* line : {"film (Hamrock-Dowson): h_min ", "lambda: min ", "flash temperature (Blok, quasi-steady): max ",
                           "scuffing margin (Blok's critical temperature 200 C): ", "quasi-steady temperature: Peclet number >= "})
    EXPECT_NE(summary.find(line), std::string::npos) << line << "\n" << summary;
}

// At the angle where the roller slips most against the cam (off the base circle), the film is Hamrock and Dowson's on
// 1/Rx = 1/R_r + 1/rho_cam with the mean of the two surface speeds, and the flash temperature Blok's on the steady
// solution's power with the roller at V_cam - w and the cam at V_cam: a radius of the roller or the cam alone, or the
// cam's speed for the entrainment (|w|/V > 1e-5 there: a relative change of the film above 3e-6), fail it.
TEST_F(CamLubrication, AngleFilmAndFlashAreTheContactFunctionsOfThatAngle) {
  const cam::CamCase c = cam::read_cam_case(write(dir_ / "lub.yaml", coarse("cam-follower-lubricated.yaml")).string());
  const cam::CamRun run = cam::run_cam(c.model, c.solver, c.lubrication);
  const std::vector<cam::RevolutionRow>& rows = run.revolution.rows;
  ASSERT_EQ(run.lubrication.angles.size(), rows.size());
  const double base_curvature = 1 / c.model.geometry.base_radius_m;
  std::size_t k = 0;
  double most = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const cam::RollerAngle& a = run.motion.motion.angles[i];
    const double ratio = std::abs(a.slip_speed_m_per_s) / rows[i].kin.rolling_speed_m_per_s;
    if (std::abs(rows[i].kin.cam_curvature_per_m - base_curvature) > 0.05 * base_curvature && ratio > most)
      most = ratio, k = i;
  }
  ASSERT_GT(most, 1e-5) << "the roller must slip for the test to see the entrainment speed";
  const cam::RevolutionRow& row = rows[k];
  const cam::RollerAngle& roller = run.motion.motion.angles[k];
  const cam::AngleLubrication& got = run.lubrication.angles[k];

  // by hand: the radii, the speeds, the load, the Hertz ellipse of the revolution's table (its a_m, b_m)
  const double R_roller = c.model.geometry.roller_radius_m, rho_cam = 1 / row.kin.cam_curvature_per_m;
  const double Rx = R_roller * rho_cam / (R_roller + rho_cam);
  const double v_cam = row.kin.rolling_speed_m_per_s, v_roller = v_cam - roller.slip_speed_m_per_s;
  const double u = 0.5 * (v_cam + v_roller);
  const double k_ellipse = run.transient.b_m[k] / run.transient.a_m[k];
  const double E_prime = 2 * contact::effective_modulus_Pa(c.model.bodies.pair);
  const contact::FilmThickness film =
      contact::film_point_contact(c.lubrication.lubricant->lubricant, Rx, k_ellipse, E_prime, roller.normal_N, u);
  EXPECT_NEAR(got.Rx_m, Rx, 1e-14 * Rx);
  EXPECT_NEAR(got.entrainment_m_per_s, u, 1e-14 * u);
  EXPECT_NEAR(got.film.h_min_m, film.h_min_m, 1e-9 * film.h_min_m);
  EXPECT_NEAR(got.film.h_central_m, film.h_central_m, 1e-9 * film.h_central_m);
  const contact::FilmThickness at_cam_speed =  // what a wrong entrainment would give: told apart by the tolerance
      contact::film_point_contact(c.lubrication.lubricant->lubricant, Rx, k_ellipse, E_prime, roller.normal_N, v_cam);
  EXPECT_GT(std::abs(at_cam_speed.h_min_m - film.h_min_m), 1e3 * 1e-9 * film.h_min_m);
  const contact::LubricantSection& lub = *c.lubrication.lubricant;
  EXPECT_DOUBLE_EQ(got.lambda, film.h_min_m / std::hypot(lub.Rq1_m, lub.Rq2_m));

  // the flash temperature: the angle's contact and steady solution at the roller's creepage, Blok on both speeds
  const cam::CreepLawSettings law = cam::roller_dynamics_of(c.solver).law;
  cam::AngleContact contact_k = cam::angle_contact(c.model.bodies, cam::roller_and_track_profiles(c.model.bodies),
                                                   R_roller, row.kin, roller.normal_N, c.model.mu, law);
  EXPECT_NEAR(contact_k.normal.patch.b_m / contact_k.normal.patch.a_m, k_ellipse, 1e-12 * k_ellipse);
  if (contact_k.normal.patch.pressure_Pa.size() == 0) contact::fill_strip_pressures(contact_k.normal.patch);
  const contact::TangentialSolution heat = cam::steady_creep(contact_k, roller.xi, roller.speed_m_per_s, true);
  const contact::ThermalSection& th = *c.lubrication.thermal;
  const contact::FlashTemperature flash = contact::flash_temperature(
      contact_k.normal.patch.grid, heat.power_W_per_m2, v_roller, v_cam, th.body1, th.body2, contact_k.normal.patch.a_m);
  ASSERT_GT(flash.max_rise_K, 0);
  EXPECT_NEAR(got.flash_max_K, flash.max_rise_K, 1e-12 * flash.max_rise_K);
  EXPECT_NEAR(got.heat_share_roller, flash.share_body1, 1e-12);
  EXPECT_DOUBLE_EQ(got.scuffing_margin_K, *th.critical_temperature_C - (*th.bulk_temperature_C + flash.max_rise_K));
  // the heat: the power density's integral is the steady solution's strip powers' sum
  const double strips_W = heat.strip_power_W_per_m.sum() * contact_k.normal.patch.grid.dy_m;
  EXPECT_NEAR(got.power_W, strips_W, 1e-9 * strips_W);
}

// The quasi-steady flash temperature holds where a surface point passes through the contact in a time short against
// the changes of the source: on the shipped lubricated case the Peclet numbers are large and the flash temperature
// changes by a few per cent of its maximum during one passage (the number the command prints)
TEST_F(CamLubrication, ShippedLubricatedCaseIsQuasiSteadyInTemperature) {
  const cam::CamCase c = cam::read_cam_case((kSource / "cases" / "cam-follower-lubricated.yaml").string());
  cam::CamSolverSettings s = c.solver;
  s.compare_full_transient = false;
  const cam::CamRun run = cam::run_cam(c.model, s, c.lubrication);
  const cam::RevolutionLubrication& l = run.lubrication;
  ASSERT_EQ(l.angles.size(), 720u);
  EXPECT_GT(l.min_peclet, 5);
  EXPECT_LT(l.thermal_unsteadiness, 0.1);
  // the worst film at the nose's flank, boundary there
  EXPECT_LT(l.angles[l.min_lambda].lambda, 1);
  for (const cam::AngleLubrication& a : l.angles) EXPECT_GE(a.lambda, l.angles[l.min_lambda].lambda);
}


std::string error_of(const fs::path& p) {
  try {
    cam::read_cam_case(p.string());
  } catch (const contact::CaseError& e) {
    return e.what();
  }
  return "";
}

// the line (1-based) of the first occurrence of text
int line_of(const std::string& file_text, const std::string& text) {
  const std::size_t at = file_text.find(text);
  return at == std::string::npos ? -1 : 1 + static_cast<int>(std::count(file_text.begin(), file_text.begin() + static_cast<long>(at), '\n'));
}

TEST_F(CamLubrication, BadKeysNameFileLineAndKey) {
  const fs::path p = dir_ / "case.yaml";
  // an unknown key in the lubricant: at its line, with the closest valid key; the command exits 2
  std::string t = coarse("cam-follower-lubricated.yaml", "    viscosity_Pa_s: 0.009", "    viscosity: 0.009");
  write(p, t);
  std::string e = error_of(p);
  EXPECT_EQ(e.rfind(fmt::format("{}:{}:", p.string(), line_of(t, "    viscosity: 0.009")), 0), 0u) << e;
  EXPECT_NE(e.find("cam.lubricant.viscosity"), std::string::npos) << e;
  const CommandRun r = rollwear("cam '" + p.string() + "' -o '" + (dir_ / "out").string() + "'", dir_);
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("cam.lubricant.viscosity"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "revolution.csv"));
  // a bad value at its line
  t = coarse("cam-follower-lubricated.yaml", "pressure_viscosity_1_per_Pa: 1.6e-8", "pressure_viscosity_1_per_Pa: -1");
  write(p, t);
  e = error_of(p);
  EXPECT_EQ(e.rfind(fmt::format("{}:{}:", p.string(), line_of(t, "pressure_viscosity_1_per_Pa: -1")), 0), 0u) << e;
  EXPECT_NE(e.find("cam.lubricant.pressure_viscosity_1_per_Pa: must be > 0"), std::string::npos) << e;
  // the regime thresholds out of order: at lambda_full_film
  t = coarse("cam-follower-lubricated.yaml", "    viscosity_Pa_s: 0.009",
             "    lambda_mixed: 2\n    lambda_full_film: 1.5\n    viscosity_Pa_s: 0.009");
  write(p, t);
  e = error_of(p);
  EXPECT_EQ(e.rfind(fmt::format("{}:{}:", p.string(), line_of(t, "lambda_full_film: 1.5")), 0), 0u) << e;
  EXPECT_NE(e.find("cam.lubricant.lambda_full_film: need lambda_mixed < lambda_full_film"), std::string::npos) << e;
  // Blok's criterion without the bulk temperature
  t = coarse("cam-follower-lubricated.yaml", "    bulk_temperature_C: 100", "");
  write(p, t);
  e = error_of(p);
  EXPECT_NE(e.find("cam.thermal.critical_temperature_C: Blok's criterion is on bulk + flash"), std::string::npos) << e;
  // the regime's friction fed back: not a bool at its line; a full-film mu of 0 (the solves' mu and archard's
  // K/(H mu) need mu > 0) at the friction's line
  t = coarse("cam-follower-lubricated.yaml", "    friction_by_regime: true ", "    friction_by_regime: yes please ");
  write(p, t);
  e = error_of(p);
  EXPECT_EQ(e.rfind(fmt::format("{}:{}:", p.string(), line_of(t, "friction_by_regime: yes please")), 0), 0u) << e;
  EXPECT_NE(e.find("cam.lubricant.friction_by_regime: expected true or false"), std::string::npos) << e;
  t = coarse("cam-follower-lubricated.yaml", "full_film: 0.03 }", "full_film: 0 }");
  write(p, t);
  e = error_of(p);
  EXPECT_EQ(e.rfind(fmt::format("{}:{}:", p.string(), line_of(t, "    friction: ")), 0), 0u) << e;
  EXPECT_NE(e.find("cam.lubricant.friction: full_film: with friction_by_regime the solves use it as cam.mu: must be in "
                   "(0, 2], got 0"), std::string::npos) << e;
  // a thermal body's property missing: at the body's mapping
  t = coarse("cam-follower-lubricated.yaml", "    body2: { conductivity_W_per_m_K: 46, ", "    body2: { ");
  write(p, t);
  e = error_of(p);
  EXPECT_NE(e.find("cam.thermal.body2.conductivity_W_per_m_K: required key is missing"), std::string::npos) << e;
}

// the command on the lubricated case: its lines and its columns; the life's report (coarse, short) its margins
TEST_F(CamLubrication, CommandsPrintTheFilmAndTemperatureAndTheLifeReportsTheMargins) {
  const fs::path p = write(dir_ / "lub.yaml", coarse("cam-follower-lubricated.yaml", "    revolutions: 1.0e13",
                                                     "    revolutions: 1.0e8"));
  CommandRun r = rollwear("cam '" + p.string() + "' -o '" + (dir_ / "rev").string() + "' --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("lambda: min "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("scuffing margin"), std::string::npos) << r.out;
  EXPECT_NE(read_text(dir_ / "rev" / "revolution.csv").find(",h_min_m,"), std::string::npos);
  r = rollwear("run '" + p.string() + "' -o '" + (dir_ / "life").string() + "' -q --log-level warn", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = read_text(dir_ / "life" / "report.txt");
  for (const char* key : {"\nended_by: revolutions\n", "\nmin_lambda: ", "\nregime_at_min_lambda: boundary\n",
                          "\nmax_flash_K: ", "\nscuffing_margin_K: ", "\nshakedown_margin: ", "\nshakedown_worst_deg: ",
                          "\nfi_surf_max: ", "\nfirst_failure: none\n", "\nother_margins: shakedown margin "})
    EXPECT_NE(report.find(key), std::string::npos) << key << "\n" << report;
  EXPECT_NE(read_text(dir_ / "life" / "dissipation.csv").find(",flash_max_K,"), std::string::npos);
}

}  // namespace
