// The case reader: every error names the file, the line and column, and the key path
// (README.md, "The case file"). The YAML texts below number their lines in the comments on the right.
#include "lib/io/case.h"

#include <gtest/gtest.h>

#include <regex>

#include "lib/numeric.h"
#include "tests/temp_dir.h"
#include <spdlog/fmt/fmt.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lib/grid.h"
#include "lib/normal/hertz.h"
#include "lib/history.h"
#include "lib/normal/profile.h"
#include "lib/tangential/satran.h"

namespace contact {
namespace {

namespace fs = std::filesystem;

// a directory of its own for each test, removed at the end
class CaseReader : public rollwear_test::TempDirTest {
 protected:

  // writes text to DIR/name and returns the path
  std::string write(const std::string& text, const std::string& name = "case.yaml") const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

  // the CaseError message of reading text, or "" if it reads
  std::string error_of(const std::string& text) const {
    const std::string path = write(text);
    try {
      read_contact_case(path);
    } catch (const CaseError& e) {
      return e.what();
    }
    return "";
  }

  std::string path() const { return (dir_ / "case.yaml").string(); }

};

// the smallest valid case: required sections only
const std::string kMinimalCase =
    "bodies:\n"                                                        // 1
    "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
    "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
    "load: { normal_load_N: 1500 }\n"                                  // 4
    "friction: { mu: 0.3 }\n";                                         // 5

TEST_F(CaseReader, ReadsPaperCase) {
  const ContactCase c = read_contact_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper.yaml");
  EXPECT_EQ(c.name, "paper");
  EXPECT_EQ(c.bodies.body1.Rx_m, 0.020);
  EXPECT_EQ(c.bodies.body1.Ry_m, 0.500);
  EXPECT_EQ(c.bodies.body2.Rx_m, 0.025);
  EXPECT_TRUE(std::isinf(c.bodies.body2.Ry_m) && c.bodies.body2.Ry_m > 0);
  EXPECT_EQ(c.bodies.body1.E_Pa, 210.0e9);
  EXPECT_EQ(c.bodies.body2.E_Pa, 210.0e9);
  EXPECT_EQ(c.bodies.body1.nu, 0.28);
  EXPECT_EQ(c.bodies.body2.nu, 0.28);
  EXPECT_EQ(normal_load_of(c), 1500);
  EXPECT_EQ(speed_of(c), 1.0);
  EXPECT_EQ(c.kinematics.xi.value, std::vector<double>{0.001});
  EXPECT_EQ(c.kinematics.eta.value, std::vector<double>{0});
  EXPECT_EQ(c.kinematics.phi_per_m.value, std::vector<double>{0});
  EXPECT_EQ(c.friction.mu, 0.3);
  EXPECT_EQ(to_string(c.solver.tangential), "relaxed");  // the default (no solver.tangential in the shipped case)
  EXPECT_EQ(c.solver.nx, 80);
  EXPECT_EQ(c.solver.ny, 80);
  EXPECT_EQ(c.output.directory, "out/paper");
  EXPECT_TRUE(c.output.fields);
}

TEST_F(CaseReader, OptionalSectionsTakeDefaultsAndNameIsFileStem) {
  const ContactCase c = read_contact_case(write(kMinimalCase, "roller_on_path.yaml"));
  const ContactCase defaults;
  EXPECT_EQ(c.name, "roller_on_path");
  EXPECT_EQ(speed_of(c), speed_of(defaults));
  EXPECT_EQ(creepages_of(c).xi, 0);
  EXPECT_FALSE(c.transient);
  EXPECT_FALSE(c.inertia);
  // the default scheme: the relaxed model, matched to the exact theory (lib/tangential/tangential.h)
  EXPECT_EQ(to_string(c.solver.tangential), "relaxed");
  EXPECT_EQ(c.solver.tangential, kDefaultTangentialScheme);
  EXPECT_EQ(kDefaultTangentialScheme, TangentialScheme::Relaxed);
  EXPECT_EQ(c.solver.nx, defaults.solver.nx);
  EXPECT_EQ(c.solver.ny, defaults.solver.ny);
  EXPECT_EQ(c.output.directory, "");
  EXPECT_TRUE(c.output.fields);
}

TEST_F(CaseReader, RecordsWhereEachValueWasRead) {
  const ContactCase c = read_contact_case(write(kMinimalCase));
  EXPECT_EQ(c.locations.at("friction.mu"), path() + ":5:17");
  EXPECT_EQ(c.locations.at("bodies.body2.Ry_m"), path() + ":3:31");
}

TEST_F(CaseReader, ConversionsCarryTheValues) {
  const ContactCase c = read_contact_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper.yaml");
  const Bodies b = bodies_of(c);
  EXPECT_EQ(b.body1.Rx_m, 0.020);
  EXPECT_EQ(b.body1.Ry_m, 0.500);
  EXPECT_EQ(b.body2.Rx_m, 0.025);
  EXPECT_EQ(b.body2.Ry_m, kFlat);
  const ElasticPair m = materials_of(c);
  EXPECT_EQ(m.body1.E_Pa, 210.0e9);
  EXPECT_EQ(m.body2.nu, 0.28);
  const Creepages k = creepages_of(c);
  EXPECT_EQ(k.xi, 0.001);
  EXPECT_EQ(k.eta, 0);
  EXPECT_EQ(k.phi_per_m, 0);
  const GridSpec g = grid_of(c);
  EXPECT_EQ(g.nx, 80);
  EXPECT_EQ(g.ny, 80);
}

TEST_F(CaseReader, UnknownKeyReportsKeyAndLine) {
  // a typo next to the key it was meant to be
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3, muu: 0.4 }\n"),                              // 5
            path() + ":5:22: friction.muu: unknown key, did you mean 'mu'? (valid: mu)");
  // one level deeper, in a block mapping
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2:\n"                                                       // 3
                     "    Rx_m: 0.025\n"                                                // 4
                     "    Ry_m: .inf\n"                                                 // 5
                     "    Rz_m: 0.1\n"                                                  // 6
                     "    E_Pa: 210.0e9\n"                                              // 7
                     "    nu: 0.28\n"                                                   // 8
                     "load: { normal_load_N: 1500 }\n"                                  // 9
                     "friction: { mu: 0.3 }\n"),                                        // 10
            path() + ":6:5: bodies.body2.Rz_m: unknown key, did you mean 'Rx_m'? (valid: E_Pa, Rx_m, Ry_m, dang_van, nu, shear_yield_Pa)");
  // a section that does not exist (yet)
  EXPECT_EQ(error_of(kMinimalCase + "wear: { law: archard }\n"),  // 6
            path() + ":6:1: wear: unknown key (valid: bodies, friction, inertia, kinematics, load, lubricant, "
                      "name, output, profiles, solver, thermal, transient)");
}

// The place of an error is data too (CaseError::location), for callers that must not read the message (the
// Python bindings' InputError): the same file, line, column and key path the message names.
TEST_F(CaseReader, ErrorCarriesItsPlaceAsData) {
  const auto expect = [&](const std::string& text, int line, int column, const std::string& key) {
    try {
      read_contact_case(write(text));
      ADD_FAILURE() << "no error for " << text;
    } catch (const CaseError& e) {
      const InputLocation& l = e.location;
      EXPECT_EQ(l.file, path());
      EXPECT_EQ(l.line, line) << e.what();
      EXPECT_EQ(l.column, column) << e.what();
      EXPECT_EQ(l.key, key) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind(fmt::format("{}:{}:{}: ", l.file, l.line, l.column), 0), 0u) << e.what();
    }
  };
  expect(kMinimalCase + "frction: { mu: 0.3 }\n", 6, 1, "frction");  // an unknown key, at the key
  std::string bad_value = kMinimalCase;
  bad_value.replace(bad_value.find("mu: 0.3"), 7, "mu: -1");
  expect(bad_value, 5, 17, "friction.mu");  // a value refused, at the value
  std::string missing = kMinimalCase;
  missing.erase(missing.rfind(", nu: 0.28"), 10);
  expect(missing, 3, 10, "bodies.body2.nu");  // a key missing, at its mapping
  expect(kMinimalCase.substr(0, kMinimalCase.find("load:")) + "friction: { mu: 0.3 }\n", 1, 1, "load");  // a section
}

// A check across keys (after every value was read) carries its first key's place as data too
TEST_F(CaseReader, CrossKeyErrorCarriesItsPlaceAsData) {
  std::string flat = kMinimalCase;
  flat.replace(flat.find("Ry_m: 0.500"), 11, "Ry_m: .inf");  // no relative curvature across: a line contact
  try {
    read_contact_case(write(flat));
    ADD_FAILURE() << "no error for two cylinders with parallel axes";
  } catch (const CaseError& e) {
    const InputLocation& l = e.location;
    EXPECT_EQ(l.file, path());
    EXPECT_EQ(l.line, 2) << e.what();
    EXPECT_GT(l.column, 0) << e.what();
    EXPECT_EQ(l.key, "bodies.body1.Ry_m") << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(fmt::format("{}:{}:{}: ", l.file, l.line, l.column), 0), 0u) << e.what();
  }
}

// A document's text reads as the file with that text does; profile files are relative to the folder given
TEST_F(CaseReader, TextReadsAsTheFile) {
  const std::string text = std::regex_replace(kMinimalCase, std::regex("  body1: .*\n  body2: .*\n"),
                                              "  body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28 }\n"
                                              "  body2: { Rx_m: 0.025, E_Pa: 210.0e9, nu: 0.28 }\n") +
                           "profiles: { body1: { file: flat_worn_R500_w20_band1p5.csv }, body2: { flat: { width_m: 0.03 } } }\n";
  const fs::path profiles = fs::path(ROLLWEAR_SOURCE_DIR) / "profiles";
  const ContactCase t = read_contact_case_text(text, "<text>", profiles);
  EXPECT_EQ(t.path, "<text>");
  const ContactCase f = read_contact_case(write(std::regex_replace(text, std::regex("file: "), "file: " + profiles.string() + "/")));
  EXPECT_TRUE((t.profiles->profiles.body1.z_m == f.profiles->profiles.body1.z_m).all());
  EXPECT_EQ(t.friction.mu, f.friction.mu);
  try {
    read_contact_case_text(text + "frction: 1\n", "<text>", profiles);
    ADD_FAILURE() << "no error";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.location.file, "<text>");
    EXPECT_EQ(e.location.line, 7);
    EXPECT_EQ(e.location.key, "frction");
  }
}

TEST_F(CaseReader, MissingKeyReportsKey) {
  // at the mapping that lacks it
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9 }\n"             // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":3:10: bodies.body2.nu: required key is missing");
  // a required section, at the document
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "friction: { mu: 0.3 }\n"),                                        // 4
            path() + ":1:1: load: required section is missing");
}

TEST_F(CaseReader, WrongTypeReportsKey) {
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: abc, nu: 0.28 }\n"      // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":2:44: bodies.body1.E_Pa: expected a number, got 'abc'");
  // a count is an integer: 80.5 is a type error, not a rounding
  EXPECT_EQ(error_of(kMinimalCase + "solver: { nx: 80.5 }\n"),  // 6
            path() + ":6:15: solver.nx: expected an integer, got '80.5'");
  // a quoted number is a string
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: \"0.001\" }\n"),  // 6
            path() + ":6:19: kinematics.xi: expected a number, got the quoted string '0.001'");
  EXPECT_EQ(error_of(kMinimalCase + "output: { fields: 3 }\n"),  // 6
            path() + ":6:19: output.fields: expected true or false, got '3'");
  // a section that is a value
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: 1500\n"                                                     // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":4:7: load: expected a mapping, got '1500'");
}

TEST_F(CaseReader, OutOfRangeReportsValue) {
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: -1 }\n"),                                         // 5
            path() + ":5:17: friction.mu: must be in [0, 10], got -1");
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.5 }\n"   // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":2:57: bodies.body1.nu: must be in [0, 0.5), got 0.5");
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"       // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":3:18: bodies.body2.Rx_m: must be nonzero (.inf for flat, negative for concave), got 0");
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: .inf, nu: 0.28 }\n"      // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":3:43: bodies.body2.E_Pa: must be > 0 and finite, got .inf");
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 0 }\n"                                     // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":4:24: load.normal_load_N: must be > 0 and finite, got 0");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { speed_m_per_s: -1 }\n"),  // 6
            path() + ":6:30: kinematics.speed_m_per_s: must be >= 0 and finite, got -1");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: .nan }\n"),  // 6
            path() + ":6:19: kinematics.xi: must be finite, got .nan");
  EXPECT_EQ(error_of(kMinimalCase + "solver: { nx: 80, ny: 4097 }\n"),  // 6
            path() + ":6:23: solver.ny: must be in [1, 4096], got 4097");
  EXPECT_EQ(error_of(kMinimalCase + "solver: { nx: 0 }\n"),  // 6
            path() + ":6:15: solver.nx: must be in [1, 4096], got 0");
}

// Plausibility bounds on the moduli, radii and a generated profile's width refuse a unit slip at its key,
// naming the slip (the bounds: README "The case file"); the shipped values sit well inside them
TEST_F(CaseReader, ImplausibleValuesNameTheirKeyAndTheLikelySlip) {
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210, nu: 0.28 }\n"      // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":2:44: bodies.body1.E_Pa: is not plausible: must be in [1e+06, 1e+13] Pa (GPa or MPa written as "
                     "Pa (steel: 2.1e11 Pa)?), got 210");
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 20, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"     // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            "");  // 20 m: a plausible radius (a large wheel), not refused
  EXPECT_NE(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: -5.0e4, E_Pa: 210.0e9, nu: 0.28 }\n" // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n")                                         // 5
                .find(":2:31: bodies.body1.Ry_m: is not plausible: must be in [0.0001, 10000] m (millimetres written as metres?), got -5.0e4"),
            std::string::npos);
  const std::string profiles = "profiles:\n  body1: { crowned: { Ry_m: 0.5, width_m: 2.0e-12 } }\n";  // 6, 7
  const std::string bodies = "bodies:\n  body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28 }\n"
                             "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"
                             "load: { normal_load_N: 1500 }\nfriction: { mu: 0.3 }\n";
  EXPECT_NE(error_of(bodies + profiles).find("profiles.body1.crowned.width_m: is not plausible: must be in [1e-05, 10] m"),
            std::string::npos)
      << error_of(bodies + profiles);
}

TEST_F(CaseReader, UnknownSchemeListsValidOnes) {
  const std::string message = error_of(kMinimalCase + "solver: { tangential: fastsim }\n");  // 6
  EXPECT_EQ(message.rfind(path() + ":6:23: solver.tangential: ", 0), 0u) << message;
  EXPECT_NE(message.find("fastsim"), std::string::npos) << message;
  EXPECT_NE(message.find("consistent"), std::string::npos) << message;
  EXPECT_NE(message.find("classic"), std::string::npos) << message;
  EXPECT_NE(message.find("exact"), std::string::npos) << message;
}

TEST_F(CaseReader, SyntaxErrorReportsLine) {
  // a flow mapping closed by a bracket
  const std::string message = error_of("bodies:\n"                                // 1
                                       "  body1: { Rx_m: 0.020 }\n"               // 2
                                       "load: { normal_load_N: 1500 ]\n"          // 3
                                       "friction: { mu: 0.3 }\n");                // 4
  EXPECT_EQ(message.rfind(path() + ":3:29: YAML syntax error: ", 0), 0u) << message;
}

TEST_F(CaseReader, DuplicateKeyReportsBothLines) {
  EXPECT_EQ(error_of(kMinimalCase + "friction: { mu: 0.4 }\n"),  // 6
            path() + ":6:1: friction: duplicate key (first at line 5)");
}

TEST_F(CaseReader, NotAMappingReportsLine) {
  EXPECT_EQ(error_of("- bodies\n- load\n"), path() + ":1:1: expected a mapping of sections, got a sequence");
  EXPECT_EQ(error_of(""), path() + ":1:1: expected a mapping of sections, got nothing (null)");
}

TEST_F(CaseReader, UnreadableFileNamesFile) {
  const std::string missing = (dir_ / "no_such_case.yaml").string();
  try {
    read_contact_case(missing);
    FAIL() << "read a file that does not exist";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot read: No such file or directory");
  }
  try {
    read_contact_case(dir_.string());
    FAIL() << "read a directory";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()), dir_.string() + ": cannot read: Is a directory");
  }
}

TEST_F(CaseReader, ConformingContactNamesBothKeys) {
  // a roller of 20 mm in a groove of 15 mm: A = (1/0.020 - 1/0.015)/2 < 0
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: -0.015, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"  // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() +
                ":2:18: bodies.body1.Rx_m, bodies.body2.Rx_m: conforming contact (relative curvature "
                "A = -8.33333 1/m <= 0): Hertz cannot treat it");
  // two flat profiles across: a line contact
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: 1500 }\n"                                  // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() +
                ":2:31: bodies.body1.Ry_m, bodies.body2.Ry_m: no relative curvature (B = 0 1/m): Hertz "
                "cannot treat a line contact");
}

TEST_F(CaseReader, ValidateNamesKeysOfACaseBuiltInCode) {
  ContactCase c;
  c.bodies.body1 = {0.020, 0.500, 210e9, 0.28};
  c.bodies.body2 = {0.025, -0.400, 210e9, 0.28};  // B = (2 - 2.5)/2 < 0
  try {
    validate(c);
    FAIL() << "validated a conforming contact";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bodies.body1.Ry_m, bodies.body2.Ry_m: conforming contact (relative curvature B = -0.25 1/m "
              "<= 0): Hertz cannot treat it");
  }
}

// ---- time histories, the transient and inertia sections ----

TEST_F(CaseReader, HistoryFormsReadAsConstantRampAndTable) {
  const ContactCase c = read_contact_case(write(kMinimalCase +
                                                "kinematics:\n"                                                 // 6
                                                "  speed_m_per_s: { ramp: [0, 0, 1.0e-4, 1.8] }\n"              // 7
                                                "  xi: { table: [[0, 0.001], [2.0e-4, 0.002], [3.0e-4, 0]] }\n"  // 8
                                                "  eta: -0.0004\n"));                                           // 9
  const History& V = c.kinematics.speed_m_per_s;
  EXPECT_EQ(V.t_s, (std::vector<double>{0, 1.0e-4}));
  EXPECT_EQ(V.value, (std::vector<double>{0, 1.8}));
  EXPECT_DOUBLE_EQ(value_at(V, 0.5e-4), 0.9);  // linear inside
  EXPECT_EQ(value_at(V, 1.0), 1.8);            // held outside
  EXPECT_EQ(c.kinematics.xi.t_s, (std::vector<double>{0, 2.0e-4, 3.0e-4}));
  EXPECT_EQ(c.kinematics.xi.value, (std::vector<double>{0.001, 0.002, 0}));
  EXPECT_TRUE(is_constant(c.kinematics.eta));
  EXPECT_EQ(value_at(c.kinematics.eta, 1.0), -0.0004);
  EXPECT_TRUE(is_constant(c.kinematics.phi_per_m));  // the default
  EXPECT_EQ(c.locations.at("kinematics.speed_m_per_s"), path() + ":7:18");
  // the load as a history: >= 0 everywhere, positive somewhere
  const ContactCase ramped = read_contact_case(write(
      "bodies:\n"                                                                   // 1
      "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"             // 2
      "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"              // 3
      "load: { normal_load_N: { table: [[0, 0], [1.0e-4, 1500], [2.0e-4, 0]] } }\n"  // 4
      "friction: { mu: 0.3 }\n"));                                                  // 5
  EXPECT_EQ(ramped.load.normal_load_N.value, (std::vector<double>{0, 1500, 0}));
}

TEST_F(CaseReader, HistoryErrorsReportFileLineAndKey) {
  // a ramp is four numbers, times increasing, values in the key's range
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { speed_m_per_s: { ramp: [0, 0, 1.0e-4] } }\n"),  // 6
            path() + ":6:38: kinematics.speed_m_per_s.ramp: expected [t0_s, v0, t1_s, v1], got 3 elements");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { speed_m_per_s: { ramp: [1.0e-4, 0, 1.0e-4, 1.8] } }\n"),  // 6
            path() + ":6:50: kinematics.speed_m_per_s.ramp: t1_s must be after t0_s = 0.0001, got 1.0e-4");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { speed_m_per_s: { ramp: [0, 0, 1.0e-4, -1] } }\n"),  // 6
            path() + ":6:53: kinematics.speed_m_per_s.ramp: v1 must be >= 0 and finite, got -1");
  // a table: rows of [t_s, value], times strictly increasing, at least one row
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: { table: [[0, 0.001], [2.0e-4, 0.002], [1.0e-4, 0]] } }\n"),
            path() + ":6:59: kinematics.xi.table: row 3: t_s must be after row 2's 0.0002 (times strictly "
                     "increasing), got 1.0e-4");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: { table: [[0, 0.001], [2.0e-4]] } }\n"),  // 6
            path() + ":6:41: kinematics.xi.table: row 2: expected [t_s, value], got 1 element");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: { table: [] } }\n"),  // 6
            path() + ":6:28: kinematics.xi.table: expected at least one [t_s, value] row, got none");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: { table: [[0, .nan]] } }\n"),  // 6
            path() + ":6:33: kinematics.xi.table: row 1: value must be finite, got .nan");
  // the forms themselves
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: { tabel: [[0, 1]] } }\n"),  // 6
            path() + ":6:21: kinematics.xi.tabel: unknown key, did you mean 'table'? (valid: ramp, table)");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: { ramp: [0, 0, 1, 1], table: [[0, 1]] } }\n"),  // 6
            path() + ":6:19: kinematics.xi: give one of 'ramp' and 'table', not both");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: [0, 0.001] }\n"),  // 6
            path() + ":6:19: kinematics.xi: expected a number, { ramp: [t0_s, v0, t1_s, v1] } or "
                     "{ table: [[t_s, value], ...] }, got a sequence");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: {} }\n"),  // 6
            path() + ":6:19: kinematics.xi: expected a number, { ramp: [t0_s, v0, t1_s, v1] } or "
                     "{ table: [[t_s, value], ...] }, got an empty mapping");
  // a load history that never loads
  EXPECT_EQ(error_of("bodies:\n"                                                        // 1
                     "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                     "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                     "load: { normal_load_N: { ramp: [0, 0, 1.0e-4, 0] } }\n"           // 4
                     "friction: { mu: 0.3 }\n"),                                        // 5
            path() + ":4:24: load.normal_load_N: must be positive at some time, got 0 throughout");
}

TEST_F(CaseReader, TransientAndInertiaSectionsConvertToTheRun) {
  const ContactCase c = read_contact_case(write(
      kMinimalCase +
      "kinematics: { speed_m_per_s: { ramp: [0, 0, 1.0e-4, 1.8] }, xi: 0.001 }\n"                      // 6
      "solver: { nx: 20, ny: 30 }\n"                                                                    // 7
      "transient: { scheme: upwind, t_end_s: 4.0e-4, dt_s: 2.0e-6, substep: true,\n"                     // 8
      "             snapshots_s: [1.0e-4, 4.0e-4] }\n"));                                               // 9
  ASSERT_TRUE(c.transient);
  EXPECT_EQ(to_string(c.transient->scheme), "upwind");
  EXPECT_EQ(c.transient->snapshots_s, (std::vector<double>{1.0e-4, 4.0e-4}));
  const TransientCase t = transient_case_of(c);
  EXPECT_EQ(t.settings.scheme, TransientScheme::Upwind);
  EXPECT_EQ(t.settings.t_end_s, 4.0e-4);
  EXPECT_EQ(t.settings.dt_s, 2.0e-6);
  EXPECT_TRUE(t.settings.substep);
  EXPECT_EQ(t.settings.grid.nx, 20);
  EXPECT_EQ(t.settings.grid.ny, 30);
  EXPECT_EQ(t.settings.snapshot_times_s, (std::vector<double>{1.0e-4, 4.0e-4}));
  EXPECT_EQ(t.mu, 0.3);
  EXPECT_EQ(t.bodies.body2.Ry_m, kFlat);
  EXPECT_EQ(t.materials.body1.E_Pa, 210.0e9);
  EXPECT_EQ(t.inputs.speed_m_per_s.value, (std::vector<double>{0, 1.8}));
  EXPECT_EQ(t.inputs.xi.value, std::vector<double>{0.001});
  EXPECT_EQ(t.inputs.normal_load_N.value, std::vector<double>{1500});
  EXPECT_FALSE(t.inertia);

  // defaults: shift without a step limit, no substeps, no snapshots; with the roller's inertia
  const ContactCase spin = read_contact_case(write(
      kMinimalCase +
      "transient: { t_end_s: 1.0e-3, dt_s: 2.0e-6 }\n"                                                  // 6
      "inertia: { R1_m: 0.020, J1_kg_m2: 3.9458e-5, omega1_0_rad_per_s: 10,\n"                          // 7
      "           path_speed_m_per_s: { ramp: [0, 0, 1.0e-4, 1.0] } }\n"));                             // 8
  const TransientCase ts = transient_case_of(spin);
  EXPECT_EQ(ts.settings.scheme, TransientScheme::Shift);
  EXPECT_FALSE(ts.settings.substep);
  EXPECT_TRUE(ts.settings.snapshot_times_s.empty());
  ASSERT_TRUE(ts.inertia);
  EXPECT_EQ(ts.inertia->R1_m, 0.020);
  EXPECT_EQ(ts.inertia->J1_kg_m2, 3.9458e-5);
  EXPECT_EQ(ts.inertia->T_res_N_m, 0);
  EXPECT_EQ(ts.inertia->omega1_0_rad_per_s, 10);
  EXPECT_EQ(ts.inertia->path_speed_m_per_s.value, (std::vector<double>{0, 1.0}));
}

TEST_F(CaseReader, TransientSectionErrorsReportKeyAndLine) {
  EXPECT_EQ(error_of(kMinimalCase + "transient: { scheme: shift }\n"),  // 6
            path() + ":6:12: transient.t_end_s: required key is missing");
  EXPECT_EQ(error_of(kMinimalCase + "transient: { t_end_s: 1.0e-3, snapshots_s: [2.0e-4, 1.0e-4] }\n"),  // 6
            path() + ":6:53: transient.snapshots_s: element 2 must be after element 1's 0.0002 (times strictly "
                     "increasing), got 1.0e-4");
  EXPECT_EQ(error_of(kMinimalCase + "transient: { t_end_s: 1.0e-3, snapshots_s: [-1] }\n"),  // 6
            path() + ":6:45: transient.snapshots_s: element 1 must be >= 0 and finite, got -1");
  EXPECT_EQ(error_of(kMinimalCase + "transient: { t_end_s: 1.0e-3, snapshots_s: 1.0e-4 }\n"),  // 6
            path() + ":6:44: transient.snapshots_s: expected a list of times, e.g. [1.0e-4, 2.0e-4], got '1.0e-4'");
  // cross-key: a snapshot after the end; a fixed-step scheme without its step
  EXPECT_EQ(error_of(kMinimalCase + "transient: { t_end_s: 1.0e-3, snapshots_s: [1.0e-4, 2.0e-3] }\n"),  // 6
            path() + ":6:44: transient.snapshots_s, transient.t_end_s: snapshot at 0.002 s is after the end of "
                     "the run, t_end_s = 0.001 s");
  EXPECT_EQ(error_of(kMinimalCase + "transient: { scheme: upwind, t_end_s: 1.0e-3 }\n"),  // 6
            path() + ":6:12: transient.dt_s, transient.scheme: the upwind scheme needs a time step dt_s > 0");
}

TEST_F(CaseReader, UnknownTransientSchemeListsValidOnes) {
  const std::string message = error_of(kMinimalCase + "transient: { scheme: crank-nicolson, t_end_s: 1 }\n");  // 6
  EXPECT_EQ(message.rfind(path() + ":6:22: transient.scheme: ", 0), 0u) << message;
  for (const char* word : {"crank-nicolson", "shift", "upwind", "lax-friedrichs"})
    EXPECT_NE(message.find(word), std::string::npos) << word << " missing from: " << message;
}

TEST_F(CaseReader, InertiaForbidsSpeedAndXiNamingThem) {
  const std::string inertia =
      "inertia: { R1_m: 0.020, J1_kg_m2: 3.9458e-5, path_speed_m_per_s: 1.0 }\n"  // 7
      "transient: { t_end_s: 1.0e-3, dt_s: 2.0e-6 }\n";                          // 8
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { speed_m_per_s: 1.0, xi: 0.001 }\n" + inertia),  // 6
            path() + ":6:30: kinematics.speed_m_per_s, kinematics.xi, inertia: with inertia the rolling speed "
                     "and xi follow from the roller's spin (V = (omega1 R1 + V2)/2, xi = (V2 - omega1 R1)/V); "
                     "remove them and give inertia.path_speed_m_per_s");
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { xi: 0.001 }\n" + inertia),  // 6
            path() + ":6:19: kinematics.xi, inertia: with inertia the rolling speed and xi follow from the "
                     "roller's spin (V = (omega1 R1 + V2)/2, xi = (V2 - omega1 R1)/V); remove it and give "
                     "inertia.path_speed_m_per_s");
  // the inertia run carries longitudinal creep only: a lateral creepage would be ignored
  EXPECT_EQ(error_of(kMinimalCase + "kinematics: { eta: 0.001 }\n" + inertia),  // 6
            path() + ":6:20: kinematics.eta, inertia: an inertia run models longitudinal creep only; lateral "
                     "and spin creepage must be 0");
  // its own keys; a shift run with a longest step
  EXPECT_EQ(error_of(kMinimalCase + "\ninertia: { R1_m: 0.020, J1_kg_m2: 3.9458e-5 }\n"),  // 7
            path() + ":7:10: inertia.path_speed_m_per_s: required key is missing");
  EXPECT_EQ(error_of(kMinimalCase +
                     "transient: { scheme: upwind, t_end_s: 1.0e-3, dt_s: 2.0e-6 }\n"               // 6
                     "inertia: { R1_m: 0.020, J1_kg_m2: 3.9458e-5, path_speed_m_per_s: 1.0 }\n"),  // 7
            path() + ":6:22: transient.scheme, inertia: an inertia run uses the shift scheme, got 'upwind'");
  EXPECT_EQ(error_of(kMinimalCase +
                     "transient: { t_end_s: 1.0e-3 }\n"                                            // 6
                     "inertia: { R1_m: 0.020, J1_kg_m2: 3.9458e-5, path_speed_m_per_s: 1.0 }\n"),  // 7
            path() + ":6:12: transient.dt_s, inertia: an inertia run needs the longest step dt_s > 0 (the "
                     "spin-up is stiff; e.g. 2.0e-6 s)");
}

TEST_F(CaseReader, SteadyCommandRefusesAHistory) {
  const ContactCase c = read_contact_case(write(kMinimalCase +
                                                "kinematics:\n"                                     // 6
                                                "  speed_m_per_s: { ramp: [0, 0, 1.0e-4, 1.8] }\n"  // 7
                                                "transient: { t_end_s: 1.0e-3 }\n"));               // 8
  const std::string expected = path() +
                               ":7:18: kinematics.speed_m_per_s: the steady 'contact' command needs a constant; "
                               "histories are for 'transient'";
  try {
    validate_steady(c);
    FAIL() << "the steady command took a ramp";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
  EXPECT_THROW(speed_of(c), CaseError);  // the conversion guards itself too
  EXPECT_NO_THROW(transient_case_of(c));

  // a table that holds one value is a constant
  const ContactCase flat = read_contact_case(write(kMinimalCase + "kinematics: { xi: { table: [[0, 0.002], [1, 0.002]] } }\n"));
  EXPECT_NO_THROW(validate_steady(flat));
  EXPECT_EQ(creepages_of(flat).xi, 0.002);

  // and the roller's inertia is for the transient command only
  const ContactCase spin = read_contact_case(write(
      kMinimalCase + "inertia: { R1_m: 0.020, J1_kg_m2: 3.9458e-5, path_speed_m_per_s: 1.0 }\n"));  // 6
  try {
    validate_steady(spin);
    FAIL() << "the steady command took the roller's inertia";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()), path() + ":6:10: inertia: the steady 'contact' command has no roller "
                                              "inertia; inertia is for 'transient'");
  }
}

TEST_F(CaseReader, TransientCommandNeedsItsSection) {
  const std::string paper = std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper.yaml";
  const ContactCase c = read_contact_case(paper);
  try {
    transient_case_of(c);
    FAIL() << "converted a case without a transient: section";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()), paper + ": transient: the 'transient' command needs a transient: section, "
                                             "e.g. transient: { scheme: shift, t_end_s: 4.0e-4 }");
  }
}

TEST_F(CaseReader, CflBreachNamesDtAndLargestAllowedStep) {
  const ContactCase c = read_contact_case(write(kMinimalCase +
                                                "kinematics: { speed_m_per_s: 1.8, xi: 0.001 }\n"                // 6
                                                "solver: { nx: 20, ny: 20 }\n"                                   // 7
                                                "transient: { scheme: upwind, t_end_s: 2.0e-4, dt_s: 5.0e-5 }\n"));  // 8
  const TransientCase t = transient_case_of(c);
  try {
    run_transient(t);
    FAIL() << "ran at a CFL number above 1";
  } catch (const SettingError& e) {  // the setting's key as data
    const std::string message = transient_error(c, e).what();
    EXPECT_EQ(message.rfind(path() + ":8:53: transient.dt_s: 5e-05 s breaks the CFL condition of the upwind "
                                     "scheme",
                            0),
              0u)
        << message;
    // the largest allowed step: dx / V on the grid of the run (Hertz a = 0.230 mm: dx = 2a/20)
    const HertzContact h = solve_hertz(t.bodies, t.materials, 1500);
    const double dt_max = make_grid(h.a_m, h.b_m, {20, 20}).dx_m / 1.8;
    const std::string key = "the largest allowed dt_s is ";
    const std::size_t at = message.find(key);
    ASSERT_NE(at, std::string::npos) << message;
    const double named = std::strtod(message.c_str() + at + key.size(), nullptr);
    EXPECT_LE(named, dt_max);  // it runs
    EXPECT_NEAR(named / dt_max, 1, 1e-5) << message;
  }
}

TEST_F(CaseReader, ShippedTransientCasesRead) {
  const ContactCase startup = read_contact_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper-startup.yaml");
  const TransientCase s = transient_case_of(startup);
  EXPECT_EQ(s.settings.scheme, TransientScheme::Shift);
  EXPECT_EQ(s.settings.t_end_s, 4.0e-4);
  EXPECT_EQ(s.settings.grid.nx, 80);
  EXPECT_EQ(s.settings.grid.ny, 80);
  EXPECT_EQ(s.settings.snapshot_times_s, (std::vector<double>{5.0e-5, 1.0e-4, 2.0e-4, 4.0e-4}));
  EXPECT_EQ(value_at(s.inputs.speed_m_per_s, 0), 0);
  EXPECT_EQ(value_at(s.inputs.speed_m_per_s, 1.0e-4), 1.8);
  EXPECT_EQ(value_at(s.inputs.xi, 0), 0.001);
  EXPECT_THROW(validate_steady(startup), CaseError);

  const ContactCase spinup = read_contact_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/roller-spinup.yaml");
  const TransientCase r = transient_case_of(spinup);
  ASSERT_TRUE(r.inertia);
  // a steel disc 40 mm x 20 mm: J1 = pi R^4 w rho / 2
  const double R = 0.020, w = 0.020, rho = 7850;
  EXPECT_NEAR(r.inertia->J1_kg_m2 / (kPi * R * R * R * R * w * rho / 2), 1, 1e-4);
  EXPECT_EQ(r.inertia->R1_m, R);
  EXPECT_EQ(value_at(r.inertia->path_speed_m_per_s, 0), 1.0);
  EXPECT_EQ(r.settings.dt_s, 2.0e-6);
  EXPECT_EQ(r.settings.t_end_s, 1.0e-3);
  EXPECT_EQ(r.settings.grid.nx, 40);
}

// ---- profiles ---------------------------------------------------------------------------------------

// kMinimalCase with profiles: the bodies without Ry_m; body1's profile as given
std::string profiles_case(const std::string& body1, const std::string& solver = "") {
  return "profiles:\n"                                                    // 1
         "  body1: " + body1 + "\n"                                      // 2
         "  body2: { flat: { width_m: 0.030 } }\n"                        // 3
         "bodies:\n"                                                      // 4
         "  body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28 }\n"            // 5
         "  body2: { Rx_m: 0.025, E_Pa: 210.0e9, nu: 0.28 }\n"            // 6
         "load: { normal_load_N: 1500 }\n"                                // 7
         "friction: { mu: 0.3 }\n" +                                      // 8
         (solver.empty() ? "" : "solver: { normal: " + solver + " }\n");  // 9
}

TEST_F(CaseReader, EachProfileFormReads) {
  const std::pair<std::string, Profile> forms[] = {
      {"{ crowned: { Ry_m: 0.5, width_m: 0.020 } }", crowned_profile(0.5, 0.020)},
      {"{ flat: { width_m: 0.020 } }", flat_profile(0.020)},
      {"{ arc: { R_m: 0.4, width_m: 0.020 } }", arc_profile(0.4, 0.020)},
      {"{ flat_worn_crown: { Ry_m: 0.5, width_m: 0.020, band_half_width_m: 0.0015 } }",
       flat_worn_crown_profile(0.5, 0.020, 0.0015)},
      {"{ file: " + std::string(ROLLWEAR_SOURCE_DIR) + "/profiles/crowned_R500_w20.csv }",
       read_profile_csv(std::string(ROLLWEAR_SOURCE_DIR) + "/profiles/crowned_R500_w20.csv")},
  };
  for (const auto& [text, expected] : forms) {
    const ContactCase c = read_contact_case(write(profiles_case(text)));
    ASSERT_TRUE(c.profiles) << text;
    EXPECT_TRUE(c.profiles->heathcote_slip);
    EXPECT_EQ(std::string(to_string(c.solver.normal)), "auto");
    EXPECT_TRUE((c.profiles->profiles.body1.y_m == expected.y_m).all()) << text;
    EXPECT_TRUE((c.profiles->profiles.body1.z_m == expected.z_m).all()) << text;
    EXPECT_EQ(c.profiles->profiles.body2.y_m.size(), flat_profile(0.030).y_m.size());
  }
}

TEST_F(CaseReader, ProfileFileIsRelativeToTheCaseFile) {
  fs::create_directories(dir_ / "profiles");
  const Profile p = flat_worn_crown_profile(0.5, 0.020, 0.0015);
  write(profile_csv(p), "profiles/worn.csv");
  const ContactCase c = read_contact_case(write(profiles_case("{ file: profiles/worn.csv }")));
  ASSERT_TRUE(c.profiles);
  EXPECT_EQ(c.profiles->profiles.body1.y_m.size(), p.y_m.size());
  EXPECT_TRUE((c.profiles->profiles.body1.z_m == p.z_m).all());
}

TEST_F(CaseReader, BadProfileCsvReportsCaseKeyAndCsvLine) {
  const std::string csv = write("y_m,z_m\n-0.01,0\n-0.005,0\n0,oops\n0.005,0\n0.01,0\n", "bad.csv");
  const std::string e = error_of(profiles_case("{ file: bad.csv }"));
  EXPECT_NE(e.find(path() + ":2:18: profiles.body1.file: "), std::string::npos) << e;
  EXPECT_NE(e.find(csv + ":4: z_m is not a number, got 'oops'"), std::string::npos) << e;
}

TEST_F(CaseReader, RyWithProfilesIsAnErrorNamingBothKeys) {
  std::string text = profiles_case("{ flat: { width_m: 0.020 } }");
  text.replace(text.find("Rx_m: 0.020,"), 12, "Rx_m: 0.020, Ry_m: 0.5,");
  const std::string e = error_of(text);
  EXPECT_NE(e.find(path() + ":5:"), std::string::npos) << e;
  EXPECT_NE(e.find("bodies.body1.Ry_m, profiles:"), std::string::npos) << e;
}

TEST_F(CaseReader, ProfileWithTwoFormsOrNoneIsAnError) {
  EXPECT_NE(error_of(profiles_case("{ flat: { width_m: 0.02 }, arc: { R_m: 1, width_m: 0.02 } }"))
                .find(":2:10: profiles.body1: give one of"),
            std::string::npos);
  EXPECT_NE(error_of(profiles_case("{ crowned: { Ry_m: 0.005, width_m: 0.020 } }")).find(":2:21: profiles.body1.crowned"),
            std::string::npos);
}

TEST_F(CaseReader, UnknownNormalSolverListsValidOnes) {
  const std::string e = error_of(profiles_case("{ flat: { width_m: 0.020 } }", "exact"));
  EXPECT_NE(e.find(path() + ":9:19: solver.normal: unknown normal solver 'exact' (valid: auto, hertz, "
                   "semi-hertz or halfspace)"),
            std::string::npos)
      << e;
}

TEST_F(CaseReader, HertzNeedsProfilesOfConstantCurvature) {
  const std::string e = error_of(
      profiles_case("{ flat_worn_crown: { Ry_m: 0.5, width_m: 0.020, band_half_width_m: 0.0015 } }", "hertz"));
  EXPECT_NE(e.find(path() + ":9:19: solver.normal, profiles.body1: Hertz needs"), std::string::npos) << e;
  EXPECT_NO_THROW(read_contact_case(write(profiles_case("{ crowned: { Ry_m: 0.5, width_m: 0.020 } }", "hertz"))));
  EXPECT_NE(error_of(kMinimalCase + "solver: { normal: semi-hertz }\n").find("solver.normal, profiles:"),
            std::string::npos);
}

TEST_F(CaseReader, ShippedWornCrownCaseReads) {
  const ContactCase c = read_contact_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/worn-crown.yaml");
  ASSERT_TRUE(c.profiles);
  EXPECT_FALSE(has_constant_curvature(c.profiles->profiles.body1, kCaseCurvatureRtol));
  EXPECT_EQ(c.friction.mu, 0.3);
  EXPECT_EQ(creepages_of(c).xi, 1e-3);
  EXPECT_EQ(c.solver.nx, 80);
  EXPECT_EQ(c.solver.ny, 80);
}

// A typo in a required section's key is the typo's error, at its line, with the closest valid key; not
// "friction: required section is missing".
TEST_F(CaseReader, TypoInARequiredKeyNamesItAndTheClosestKey) {
  const std::string typo = "bodies:\n"                                                        // 1
                           "  body1: { Rx_m: 0.020, Ry_m: 0.500, E_Pa: 210.0e9, nu: 0.28 }\n"  // 2
                           "  body2: { Rx_m: 0.025, Ry_m: .inf, E_Pa: 210.0e9, nu: 0.28 }\n"   // 3
                           "load: { normal_load_N: 1500 }\n"                                  // 4
                           "frction: { mu: 0.3 }\n";                                          // 5
  EXPECT_EQ(error_of(typo), path() + ":5:1: frction: unknown key, did you mean 'friction'? (friction: required "
                                     "section is missing)");
  // inside a section: an optional key misspelt is named with the closest one
  EXPECT_EQ(error_of(kMinimalCase + "solver: { nx: 20, nyy: 20 }\n"),
            path() + ":6:19: solver.nyy: unknown key, did you mean 'ny'? (valid: correction_grid, correction_tolerance, error_estimate, fidelity, grid_extrapolation, max_memory_bytes, normal, nx, ny, tangential)");
  // a key like none: no suggestion
  EXPECT_EQ(error_of(kMinimalCase + "solver: { grid_size: 20 }\n"),
            path() + ":6:11: solver.grid_size: unknown key (valid: correction_grid, correction_tolerance, error_estimate, fidelity, grid_extrapolation, max_memory_bytes, normal, nx, ny, tangential)");
}

// solver.grid_extrapolation (lib/tangential/grid_extrapolation.h): of the exact theory's steady solves, on
// even grids; refused with another tangential model, an odd grid or a transient run, at the key's line
TEST_F(CaseReader, GridExtrapolationNeedsTheExactTheoryOnAnEvenGrid) {
  const std::string exact = kMinimalCase + "solver: { tangential: exact, grid_extrapolation: true, nx: 20, ny: 20 }\n";
  EXPECT_TRUE(read_contact_case(write(exact)).solver.grid_extrapolation);
  EXPECT_FALSE(read_contact_case(write(kMinimalCase)).solver.grid_extrapolation);
  const std::string relaxed = error_of(kMinimalCase + "solver: { grid_extrapolation: true }\n");
  EXPECT_EQ(relaxed.rfind(path() + ":6:31: solver.grid_extrapolation, solver.tangential: ", 0), 0u) << relaxed;
  EXPECT_NE(relaxed.find("not relaxed"), std::string::npos) << relaxed;
  const std::string odd_line = "solver: { tangential: exact, grid_extrapolation: true, nx: 21, ny: 20 }\n";
  const std::string odd = error_of(kMinimalCase + odd_line);
  EXPECT_EQ(odd.rfind(path() + ":6:" + std::to_string(odd_line.find("21") + 1) + ": solver.nx, solver.grid_extrapolation: ", 0), 0u) << odd;
  const std::string transient = error_of(kMinimalCase + "solver: { tangential: exact, grid_extrapolation: true }\n" +
                                         "transient: { t_end_s: 1.0e-3 }\n");
  EXPECT_NE(transient.find("solver.grid_extrapolation, transient: "), std::string::npos) << transient;
}

// A message never echoes a huge value whole: its first 80 characters and its size.
TEST_F(CaseReader, HugeValuesAreCutInMessages) {
  constexpr std::size_t kHuge = 20'000'000;  // a 20 MB line, as pasted by mistake
  constexpr std::size_t kMessageMax = 400;    // the message's own words, the file path and the 80 characters
  const std::string mu = "friction: { mu: " + std::string(kHuge, '7') + "x }\n";
  const std::string m = error_of(kMinimalCase.substr(0, kMinimalCase.find("friction")) + mu);
  EXPECT_LT(m.size(), kMessageMax) << m.substr(0, 1000);
  EXPECT_NE(m.find("… (20000001 bytes)"), std::string::npos) << m.substr(0, 1000);
  // a profile file with a 20 MB line
  std::ofstream(dir_ / "big.csv") << "y_m,z_m\n" << std::string(kHuge, '1') << ",0,0\n";
  const std::string p = error_of(std::string("profiles:\n  body1: { file: big.csv }\n  body2: { flat: { width_m: 0.03 } }\n") +
                                 "bodies:\n  body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28 }\n"
                                 "  body2: { Rx_m: 0.025, E_Pa: 210.0e9, nu: 0.28 }\n"
                                 "load: { normal_load_N: 1500 }\nfriction: { mu: 0.3 }\n");
  EXPECT_LT(p.size(), kMessageMax) << p.substr(0, 1000);
  EXPECT_NE(p.find("big.csv:2: expected 2 columns y_m,z_m, got 3"), std::string::npos) << p.substr(0, 1000);
  // a cut never splits a UTF-8 character
  EXPECT_EQ(clipped(std::string(79, 'a') + "é" + std::string(100, 'b')), std::string(79, 'a') + "… (181 bytes)");
  EXPECT_EQ(clipped("short"), "short");
}

}  // namespace
}  // namespace contact
