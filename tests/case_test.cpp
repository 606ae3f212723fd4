// The case reader: every error names the file, the line and column, and the key path
// (STYLE.md, "Cases"). The YAML texts below number their lines in the comments on the right.
#include "lib/case.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace contact {
namespace {

namespace fs = std::filesystem;

// a directory of its own for each test, removed at the end
class CaseReader : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("rollwear_case_test_" + std::to_string(::getpid()) + "_" +
            testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }

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

  fs::path dir_;
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
  EXPECT_EQ(c.load.normal_load_N, 1500);
  EXPECT_EQ(c.kinematics.speed_m_per_s, 1.0);
  EXPECT_EQ(c.kinematics.xi, 0.001);
  EXPECT_EQ(c.kinematics.eta, 0);
  EXPECT_EQ(c.kinematics.phi_per_m, 0);
  EXPECT_EQ(c.friction.mu, 0.3);
  EXPECT_EQ(c.solver.tangential, "consistent");
  EXPECT_EQ(c.solver.nx, 80);
  EXPECT_EQ(c.solver.ny, 80);
  EXPECT_EQ(c.output.directory, "out/paper");
  EXPECT_TRUE(c.output.fields);
}

TEST_F(CaseReader, OptionalSectionsTakeDefaultsAndNameIsFileStem) {
  const ContactCase c = read_contact_case(write(kMinimalCase, "roller_on_path.yaml"));
  const ContactCase defaults;
  EXPECT_EQ(c.name, "roller_on_path");
  EXPECT_EQ(c.kinematics.speed_m_per_s, defaults.kinematics.speed_m_per_s);
  EXPECT_EQ(c.kinematics.xi, 0);
  EXPECT_EQ(c.solver.tangential, "consistent");
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
            path() + ":5:22: friction.muu: unknown key (valid: mu)");
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
            path() + ":6:5: bodies.body2.Rz_m: unknown key (valid: E_Pa, Rx_m, Ry_m, nu)");
  // a section that does not exist (yet)
  EXPECT_EQ(error_of(kMinimalCase + "wear: { law: archard }\n"),  // 6
            path() + ":6:1: wear: unknown key (valid: bodies, friction, kinematics, load, name, output, solver)");
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

TEST_F(CaseReader, UnknownSchemeListsValidOnes) {
  const std::string message = error_of(kMinimalCase + "solver: { tangential: fastsim }\n");  // 6
  EXPECT_EQ(message.rfind(path() + ":6:23: solver.tangential: ", 0), 0u) << message;
  EXPECT_NE(message.find("fastsim"), std::string::npos) << message;
  EXPECT_NE(message.find("consistent"), std::string::npos) << message;
  EXPECT_NE(message.find("classic"), std::string::npos) << message;
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

}  // namespace
}  // namespace contact
