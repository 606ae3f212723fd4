// The contact command's film, regime and flash temperature (lib/io/case_run.h lubrication_of, thermal_of):
// the case's lubricant: and thermal: sections read and checked with file:line:key errors, the steady run's
// film and temperature equal to the library's functions on the solved patch, a dry case unchanged
// (docs/lubrication-and-temperature.md §4).
#include "lib/io/case.h"
#include "lib/io/case_run.h"
#include "lib/io/csv.h"
#include "lib/elastic.h"
#include "wear/wear_case.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace contact {
namespace {

const std::string kCase = std::string(ROLLWEAR_SOURCE_DIR) + "/tests/data/lubrication/paper-lubricated.yaml";

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

ContactCase read_text(const std::string& text) { return read_contact_case_text(text, "case.yaml", "."); }

// the CaseError's message of a text, or "" when it reads
std::string error_of(const std::string& text) {
  try {
    validate_steady(read_text(text));
  } catch (const CaseError& e) {
    return e.what();
  }
  return "";
}

TEST(ContactLubrication, FilmAndRegimeAreTheLibrarysOnTheSolvedPatch) {
  const ContactCase c = read_contact_case(kCase);
  const ContactRun r = solve_contact_case(c, false);
  ASSERT_TRUE(r.lubrication.has_value());
  const ContactPatch& p = r.normal.patch;
  const double Rx = 1 / (1 / 0.020 + 1 / 0.025);
  const double E_prime = 2 * effective_modulus_Pa({{210e9, 0.28}, {210e9, 0.28}});
  const FilmThickness f = film_point_contact({0.01, 2e-8}, Rx, p.b_m / p.a_m, E_prime, 1500, 1.0);
  EXPECT_DOUBLE_EQ(r.lubrication->film.h_min_m, f.h_min_m);
  EXPECT_DOUBLE_EQ(r.lubrication->film.h_central_m, f.h_central_m);
  EXPECT_DOUBLE_EQ(r.lubrication->lambda, f.h_min_m / std::hypot(0.05e-6, 0.1e-6));
  // the paper's ellipse, k = 11.3, is beyond Hamrock and Dowson's fitted range
  EXPECT_FALSE(r.lubrication->within_fit_range);
  EXPECT_EQ(r.lubrication->regime, regime_of(r.lubrication->lambda));
  EXPECT_EQ(r.lubrication->regime, LubricationRegime::Boundary);  // lambda = 0.81
  EXPECT_EQ(r.lubrication->mu, 0.12);
  EXPECT_EQ(r.lubrication->wear_factor, 1.0);
}

TEST(ContactLubrication, FlashTemperatureIsBloksOnTheDissipatedPower) {
  const ContactCase c = read_contact_case(kCase);
  const ContactRun r = solve_contact_case(c, false);
  ASSERT_TRUE(r.thermal.has_value());
  const ThermalBody steel{46, 7800, 460};
  const FlashTemperature f = flash_temperature(r.normal.patch.grid, r.solution.power_W_per_m2, 1 - 0.0005,
                                               1 + 0.0005, steel, steel, r.normal.patch.a_m);
  EXPECT_DOUBLE_EQ(r.thermal->flash.max_rise_K, f.max_rise_K);
  EXPECT_GT(f.max_rise_K, 0);
  EXPECT_DOUBLE_EQ(*r.thermal->contact_temperature_C, 80 + f.max_rise_K);
  EXPECT_DOUBLE_EQ(*r.thermal->scuffing_margin_K, 150 - 80 - f.max_rise_K);
  // the summary's extra columns
  const std::string csv = contact_summary_csv(c.name, r);
  EXPECT_NE(csv.find(",h_min_m,"), std::string::npos);
  EXPECT_NE(csv.find(",boundary,"), std::string::npos);
  EXPECT_NE(csv.find(",scuffing_margin_K\n"), std::string::npos);
}

TEST(ContactLubrication, DryCaseSummaryIsUnchanged) {
  const ContactCase c = read_contact_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper.yaml");
  const ContactRun r = solve_contact_case(c, false);
  EXPECT_FALSE(r.lubrication || r.thermal);
  EXPECT_EQ(contact_summary_csv(c.name, r), summary_csv(c.name, r.normal.patch, r.problem, r.solution, r.scheme));
}

TEST(ContactLubrication, BadSectionsNameFileLineAndKey) {
  const std::string good = text_of(kCase);
  EXPECT_EQ(error_of(good), "");
  // a regime's friction left out: at the mapping that lacks it
  const std::string no_mixed = std::regex_replace(good, std::regex("mixed: 0.08, "), "");
  EXPECT_EQ(error_of(no_mixed).rfind("case.yaml:", 0), 0u) << error_of(no_mixed);
  EXPECT_NE(error_of(no_mixed).find("lubricant.friction.mixed: required key is missing"), std::string::npos)
      << error_of(no_mixed);
  // thresholds out of order
  const std::string order = std::regex_replace(good, std::regex("  friction: \\{ boundary"),
                                               "  lambda_mixed: 4\n  friction: { boundary");
  EXPECT_NE(error_of(order).find("lubricant.lambda_full_film, lubricant.lambda_mixed"), std::string::npos)
      << error_of(order);
  // a non-positive viscosity, at its line (14) and column
  const std::string viscosity = std::regex_replace(good, std::regex("viscosity_Pa_s: 0.01"), "viscosity_Pa_s: 0");
  EXPECT_NE(error_of(viscosity).find("case.yaml:14:19: "), std::string::npos) << error_of(viscosity);
  EXPECT_NE(error_of(viscosity).find("lubricant.viscosity_Pa_s: must be > 0"), std::string::npos)
      << error_of(viscosity);
  // Blok's criterion without the bulk temperature
  const std::string bulk = std::regex_replace(good, std::regex("  bulk_temperature_C: 80\n"), "");
  EXPECT_NE(error_of(bulk).find("thermal.critical_temperature_C, thermal.bulk_temperature_C"), std::string::npos)
      << error_of(bulk);
  // a surface at rest has no steady flash temperature: at kinematics.xi (line 10)
  const std::string at_rest = std::regex_replace(good, std::regex("xi: 0.001"), "xi: 2");
  EXPECT_NE(error_of(at_rest).find("case.yaml:10:39: kinematics.speed_m_per_s, kinematics.xi, thermal: "),
            std::string::npos) << error_of(at_rest);
  // a thermal body's property missing
  const std::string no_k = std::regex_replace(good, std::regex("  body2: \\{ conductivity_W_per_m_K: 46, "), "  body2: { ");
  EXPECT_NE(error_of(no_k).find("thermal.body2.conductivity_W_per_m_K: required key is missing"), std::string::npos)
      << error_of(no_k);
}

TEST(ContactLubrication, TransientRefusesTheSectionsItDoesNotUse) {
  const std::string text = text_of(kCase) + "transient: { scheme: shift, t_end_s: 1.0e-4 }\n";
  try {
    transient_case_of(read_text(text));
    ADD_FAILURE() << "no error";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("lubricant: the 'transient' command does not use this section"),
              std::string::npos) << e.what();
  }
}

TEST(ContactLubrication, WearRunRefusesTheLubricantWithATransientDutyCycle) {
  // the lubricated case with the wear section of cases/paper-wear.yaml (profiles left out: radii only) and a
  // transient duty cycle: the film needs one entrainment speed (a steady duty cycle takes the lubricant,
  // tests/wear_lubrication_test.cpp)
  const std::string text = text_of(kCase) +
                           "transient: { scheme: shift, t_end_s: 1.0e-4 }\n"
                           "wear:\n"
                           "  body1: { law: archard, archard_k: 1.0e-4, hardness_Pa: 6.0e9 }\n"
                           "  revolutions: 1.0e10\n";
  try {
    wear::read_wear_case_text(text, "case.yaml", ".");
    ADD_FAILURE() << "no error";
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("lubricant, transient: a wear run takes the film of a steady duty cycle"),
              std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace contact
