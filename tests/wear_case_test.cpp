// The wear section of a case (wear/wear_case.h): read with the contact case in one pass; every
// error names the file, the line and column, and the key path. The texts number their lines on the right.
#include "wear/wear_case.h"
#include "wear/wear_loop.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "tests/temp_dir.h"

namespace wear {
namespace {

namespace fs = std::filesystem;

class WearCaseReader : public rollwear_test::TempDirTest {
 protected:
  std::string write(const std::string& text) const {
    const fs::path p = dir_ / "case.yaml";
    std::ofstream(p) << text;
    return p.string();
  }
  // the CaseError message of reading text, or "" if it reads
  std::string error_of(const std::string& text) const {
    const std::string path = write(text);
    try {
      read_wear_case(path);
    } catch (const contact::CaseError& e) {
      return e.what();
    }
    return "";
  }
  std::string path() const { return (dir_ / "case.yaml").string(); }
};

// a steady case with profiles: lines 1-10, then the wear section from line 11
const std::string kContact =
    "profiles:\n"                                                    // 1
    "  body1: { crowned: { Ry_m: 0.5, width_m: 0.02 } }\n"           // 2
    "  body2: { flat: { width_m: 0.03 } }\n"                         // 3
    "bodies:\n"                                                      // 4
    "  body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28 }\n"            // 5
    "  body2: { Rx_m: 0.025, E_Pa: 210.0e9, nu: 0.28 }\n"            // 6
    "load: { normal_load_N: 1500 }\n"                                // 7
    "kinematics: { speed_m_per_s: 1.0, xi: 1.0e-3 }\n"               // 8
    "friction: { mu: 0.3 }\n"                                        // 9
    "solver: { nx: 20, ny: 20 }\n";                                  // 10

TEST_F(WearCaseReader, ReadsTheShippedCase) {
  const WearCase c = read_wear_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper-wear.yaml");
  ASSERT_TRUE(c.wear.body1.has_value());
  EXPECT_FALSE(c.wear.body2.has_value());
  EXPECT_EQ(to_string(c.wear.body1->law), "archard");
  EXPECT_EQ(c.wear.body1->archard_k, 1e-4);
  EXPECT_EQ(c.wear.body1->hardness_Pa, 6e9);
  EXPECT_EQ(c.wear.revolutions, 1e10);
  EXPECT_EQ(c.wear.limits.max_depth_m, 1e-4);
  EXPECT_EQ(to_string(c.wear.stepping.method), "adaptive");
  EXPECT_EQ(c.wear.smoothing_wavelength_m, 5e-4);
  EXPECT_EQ(c.wear.snapshots_revolutions.size(), 3u);
}

TEST_F(WearCaseReader, DefaultsAndBothBodies) {
  const std::string text = kContact +
                           "wear:\n"                                                  // 11
                           "  body1: { k_E_m3_per_J: 1.0e-13 }\n"                      // 12
                           "  body2: { law: energy, k_E_m3_per_J: 2.0e-13 }\n"          // 13
                           "  revolutions: 1.0e6\n";                                   // 14
  ASSERT_EQ(error_of(text), "");
  const WearCase c = read_wear_case(path());
  EXPECT_EQ(to_string(c.wear.body1->law), "energy");
  EXPECT_EQ(c.wear.body2->k_E_m3_per_J, 2e-13);
  EXPECT_TRUE(c.wear.limits.edge);
  EXPECT_EQ(c.wear.limits.max_depth_m, 0);
  EXPECT_EQ(c.wear.stepping.rtol, 1e-3);
  EXPECT_EQ(c.wear.smoothing_wavelength_m, 5e-4);
  EXPECT_EQ(integrator_options(c.wear.stepping).method, IntegratorOptions::Method::Adaptive);
}

TEST_F(WearCaseReader, ErrorsNameFileLineAndKey) {
  const std::string file = path();
  // a law parameter out of range: at its key in the body's mapping
  EXPECT_EQ(error_of(kContact + "wear:\n  body1: { law: archard, archard_k: 2, hardness_Pa: 6.0e9 }\n  revolutions: 1\n"),
            file + ":12:37: wear.body1.archard_k: must be in (0, 1], got 2");
  // an unknown law
  EXPECT_EQ(error_of(kContact + "wear:\n  body1: { law: magic }\n  revolutions: 1\n"),
            file + ":12:17: wear.body1.law: unknown wear law 'magic' (valid: energy, archard, kth or usfd)");
  // a typo is a key left over, not a default
  EXPECT_NE(error_of(kContact + "wear:\n  body1: { k_E_m3_per_J: 1.0e-13 }\n  revolutions: 1\n  revolution: 1\n")
                .find(file + ":14:3: wear.revolution: unknown key"),
            std::string::npos);
  // nobody wears
  EXPECT_EQ(error_of(kContact + "wear:\n  revolutions: 1\n"),
            file + ":12:3: wear: no body wears: give body1: and/or body2: with a law, e.g. body1: { law: energy, "
                   "k_E_m3_per_J: 1.0e-13 }");
  // snapshots after the budget
  EXPECT_EQ(error_of(kContact + "wear:\n  body1: { k_E_m3_per_J: 1.0e-13 }\n  revolutions: 10\n"
                                "  snapshots_revolutions: [5, 20]\n"),
            file + ":14:26: wear.snapshots_revolutions, wear.revolutions: snapshot at 20 is after the end of the "
                   "life budget, 10");
  // snapshots not increasing
  EXPECT_NE(error_of(kContact + "wear:\n  body1: { k_E_m3_per_J: 1.0e-13 }\n  revolutions: 10\n"
                                "  snapshots_revolutions: [5, 5]\n")
                .find(file + ":14:30: wear.snapshots_revolutions: element 2 must be after element 1's 5"),
            std::string::npos);
  // an unknown stepping method lists the valid ones
  EXPECT_EQ(error_of(kContact + "wear:\n  body1: { k_E_m3_per_J: 1.0e-13 }\n  revolutions: 10\n"
                                "  stepping: { method: rk4 }\n"),
            file + ":14:23: wear.stepping.method: must be adaptive, fixed-depth or fixed-revolutions, got 'rk4'");
}

TEST_F(WearCaseReader, CrossKeyErrors) {
  const std::string file = path();
  // no wear section at all
  EXPECT_NE(error_of(kContact).find("wear: the run command needs a wear: section"), std::string::npos);
  // a body without rolling radius cannot count revolutions
  std::string flat_path = kContact;
  flat_path.replace(flat_path.find("Rx_m: 0.025"), 11, "Rx_m: .inf");
  EXPECT_NE(error_of(flat_path + "wear:\n  body2: { k_E_m3_per_J: 1.0e-13 }\n  revolutions: 10\n")
                .find(file + ":12:10: wear.body2: the body wears but its rolling radius Rx_m = inf gives no revolutions"),
            std::string::npos);
  // no profiles: section
  const std::string radii =
      "bodies:\n"
      "  body1: { Rx_m: 0.020, Ry_m: 0.5, E_Pa: 210.0e9, nu: 0.28 }\n"
      "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"
      "load: { normal_load_N: 1500 }\n"
      "friction: { mu: 0.3 }\n"
      "wear:\n"                                       // 6
      "  body1: { k_E_m3_per_J: 1.0e-13 }\n"
      "  revolutions: 10\n";
  EXPECT_NE(error_of(radii).find(file + ":7:3: wear, profiles: the worn body needs a lateral profile"),
            std::string::npos);
  // a transient duty cycle takes the energy-type laws only
  EXPECT_NE(error_of(kContact + "transient: { t_end_s: 1.0e-3 }\n"
                                "wear:\n  body1: { law: kth, hardness_Pa: 3.0e9 }\n  revolutions: 10\n")
                .find("wear.body1.law, transient: the kth law reads steady per-cell fields"),
            std::string::npos);
  // Hertz cannot follow a worn profile
  std::string hertz = kContact;
  hertz.replace(hertz.find("solver: { nx: 20"), 16, "solver: { normal: hertz, nx: 20");
  EXPECT_NE(error_of(hertz + "wear:\n  body1: { k_E_m3_per_J: 1.0e-13 }\n  revolutions: 10\n")
                .find(file + ":10:19: solver.normal: a wear run solves the worn profiles with auto"),
            std::string::npos);
}

// Archard's law is the energy law with k_E = K/(H mu): without friction it has no meaning. A cross-key
// error of the reader, at friction.mu's line, naming both keys (not an std::invalid_argument from the
// wear model at run time, which had no file, line or key).
TEST_F(WearCaseReader, ArchardWithoutFrictionNamesFrictionMuAndTheLaw) {
  std::string text = kContact + "wear:\n  body1: { law: archard, archard_k: 1.0e-4, hardness_Pa: 6.0e9 }\n  revolutions: 1.0e9\n";
  text.replace(text.find("mu: 0.3"), 7, "mu: 0");
  EXPECT_EQ(error_of(text).rfind(path() + ":9:17: friction.mu, wear.body1.law: the archard law needs friction", 0), 0u)
      << error_of(text);
  // the energy law wears without friction
  std::string energy = kContact + "wear:\n  body1: { law: energy, k_E_m3_per_J: 1.0e-13 }\n  revolutions: 1.0e9\n";
  energy.replace(energy.find("mu: 0.3"), 7, "mu: 0");
  EXPECT_EQ(error_of(energy), "");
}

// A wear run takes the exact theory with a steady duty cycle (one exact steady solve per wear-rate
// evaluation) and with a transient one (its rolling steps, the steady stretches skipped: exact.h,
// run_exact_transient), each read into the model with the exact theory as its scheme.
TEST_F(WearCaseReader, WearRunTakesTheExactTheorySteadyAndTransient) {
  std::string text = kContact + "wear:\n  body1: { law: energy, k_E_m3_per_J: 1.0e-13 }\n  revolutions: 1.0e9\n";
  text.replace(text.find("solver: { nx"), 12, "solver: { tangential: exact, nx");
  EXPECT_EQ(make_wear_model(read_wear_case(write(text))).scheme, contact::TangentialScheme::Exact);
  const WearModel m = make_wear_model(read_wear_case(write(text + "transient: { t_end_s: 1.0e-3 }\n")));
  EXPECT_EQ(m.scheme, contact::TangentialScheme::Exact);
  ASSERT_TRUE(m.transient.has_value());
  EXPECT_TRUE(m.transient->settings.skip_steady);
}

// wear.stepping.method's names come from one table (lib/enum_names.h): the reader's message lists them,
// and the parse refuses a name outside it instead of taking it for fixed-revolutions.
TEST_F(WearCaseReader, SteppingMethodNamesComeFromOneTable) {
  WearStepping s;
  for (const auto& [name, method] : {std::pair<const char*, IntegratorOptions::Method>{"adaptive", IntegratorOptions::Method::Adaptive},
                                     {"fixed-depth", IntegratorOptions::Method::FixedDepth},
                                     {"fixed-revolutions", IntegratorOptions::Method::FixedStep}}) {
    s.method = parse_stepping_method(name);
    EXPECT_EQ(integrator_options(s).method, method) << name;
    EXPECT_EQ(to_string(method), name);
  }
  EXPECT_THROW(parse_stepping_method("rk4"), contact::SettingError);
}


// The memory a wear run needs is estimated before its model is built and refused above solver.max_memory_bytes
// (issue 26: a 1e5-point profile file took 3.9 GB, the smoothing kernel's n^2 lc / width pairs). The estimate
// bounds the kernel make_wear_model builds (its size in bytes, counted here), and a limit below it is refused
// at the worn profile's line, naming the keys, before any kernel is built.
TEST_F(WearCaseReader, MemoryIsEstimatedAndRefusedAboveSolverMaxMemoryBytes) {
  const std::string wear_section = "wear:\n  body1: { k_E_m3_per_J: 1.0e-13 }\n  revolutions: 10\n";
  ASSERT_EQ(error_of(kContact + wear_section), "");
  const WearCase c = read_wear_case(path());
  const double estimate = estimate_memory_bytes(c);
  const WearModel m = make_wear_model(c);
  const double n = static_cast<double>(m.profiles.body1.y_m.size());
  // the kernel's values and indices, and the state, as built: the estimate is at least that
  const double built = 8.0 * static_cast<double>(m.smoothing1.s.size()) + 16 * n + 8 * n;
  EXPECT_EQ(smoothing_kernel_entries(m.profiles.body1.y_m, c.wear.smoothing_wavelength_m),
            static_cast<double>(m.smoothing1.s.size()));
  EXPECT_GE(estimate, built);
  EXPECT_LE(estimate, 100 * built);  // an estimate, not a blanket bound

  // a limit below the estimate: refused at profiles.body1 (line 2), naming the keys that drive it
  std::string small = kContact;
  small.replace(small.find("solver: { nx: 20, ny: 20 }"), 26, "solver: { nx: 20, ny: 20, max_memory_bytes: 1.0e4 }");
  ASSERT_EQ(error_of(small + wear_section), "");  // the reader takes it: the model refuses
  const WearCase limited = read_wear_case(path());
  try {
    make_wear_model(limited);
    ADD_FAILURE() << "a model above solver.max_memory_bytes was built";
  } catch (const contact::CaseError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path() + ":2:", 0), 0u) << msg;
    for (const char* word : {"profiles.body1, wear.smoothing_wavelength_m, solver.max_memory_bytes",
                             "more than solver.max_memory_bytes = 10000"})
      EXPECT_NE(msg.find(word), std::string::npos) << word << " in " << msg;
  }
  EXPECT_EQ(error_of(kContact + wear_section + "  smoothing_wavelength_m: 0\n"), "");
  EXPECT_LT(estimate_memory_bytes(read_wear_case(path())), estimate);  // no filter, no kernel
}

}  // namespace
}  // namespace wear
