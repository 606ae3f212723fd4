// Lateral profiles (lib/normal/profile.h): interpolation, generators against their closed forms, the CSV
// reader's errors naming the file and the line, the shipped profiles, the parabola fit and the hash.
#include "lib/normal/profile.h"

#include <gtest/gtest.h>

#include "tests/temp_dir.h"
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace contact {
namespace {

namespace fs = std::filesystem;

// the arc of radius R at y, the closed form the generators sample
double arc(double R, double y) { return R - (R > 0 ? 1 : -1) * std::sqrt(R * R - y * y); }

TEST(ProfileInterpolation, LinearBetweenNodesExactAtNodes) {
  Profile p{(Eigen::ArrayXd(5) << 0, 1e-3, 2e-3, 4e-3, 5e-3).finished(),
            (Eigen::ArrayXd(5) << 1e-6, 0, 2e-6, 2e-6, -1e-6).finished(), "five"};
  for (int i = 0; i < 5; ++i) EXPECT_EQ(profile_z(p, p.y_m(i)), p.z_m(i));
  EXPECT_NEAR(profile_z(p, 0.5e-3), 0.5e-6, 1e-20);
  EXPECT_NEAR(profile_z(p, 1.5e-3), 1e-6, 1e-20);
  EXPECT_NEAR(profile_z(p, 4.25e-3), 1.25e-6, 1e-20);
  EXPECT_THROW(profile_z(p, -1e-9), std::out_of_range);
  EXPECT_THROW(profile_z(p, 5.1e-3), std::out_of_range);
}

// crown and concave arc: nodes on the arc, chord error below kProfileChordTol_m, spacing bounded
TEST(ProfileGenerators, ArcsSampleTheCircleWithinChordTolerance) {
  constexpr double kRounding = 1e-15;  // R - sqrt(R^2 - y^2) loses digits to cancellation
  for (double R : {0.5, 0.05, -0.2, 2.0}) {
    const double w = 0.02;
    const Profile p = R > 0 ? crowned_profile(R, w) : arc_profile(R, w);
    const Eigen::Index n = p.y_m.size();
    EXPECT_DOUBLE_EQ(p.y_m(0), -w / 2);
    EXPECT_DOUBLE_EQ(p.y_m(n - 1), w / 2);
    EXPECT_EQ(profile_z(p, 0.0), 0.0) << "y = 0 is a node and the crown's top";
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
      const double s = p.y_m(i + 1) - p.y_m(i);
      EXPECT_LE(s, w * kProfileMaxSpacingFraction * (1 + 1e-12));
      EXPECT_NEAR(p.z_m(i), arc(R, p.y_m(i)), kRounding * std::abs(R));
      const double mid = (p.y_m(i) + p.y_m(i + 1)) / 2;
      EXPECT_LE(std::abs(profile_z(p, mid) - arc(R, mid)), kProfileChordTol_m * 1.001) << "R " << R << " y " << mid;
    }
    EXPECT_EQ(R > 0, p.z_m.minCoeff() >= 0) << "convex z >= 0, concave z <= 0";
  }
}

TEST(ProfileGenerators, FlatWornCrownIsFlatOnTheBandAndTheCrownOutside) {
  const double R = 0.5, w = 0.02, c = 1.5e-3;
  const Profile p = flat_worn_crown_profile(R, w, c);
  const double depth = arc(R, c);  // worn off at the crown
  bool left_edge = false, right_edge = false;
  for (Eigen::Index i = 0; i < p.y_m.size(); ++i) {
    const double y = p.y_m(i);
    left_edge |= y == -c;
    right_edge |= y == c;
    if (std::abs(y) <= c) EXPECT_EQ(p.z_m(i), 0.0) << y;
    else EXPECT_NEAR(p.z_m(i), arc(R, y) - depth, 1e-15 * R) << y;  // cancellation in arc()
  }
  EXPECT_TRUE(left_edge && right_edge) << "the band's edges are nodes";
  // continuous: 1 um outside the band z is the slope there, c/R plus the first segment's chord
  // slope s/(2R) (s = 0.05 mm), times 1 um
  EXPECT_LT(profile_z(p, c + 1e-6), 1e-6 * (c + 0.05e-3) / R * 1.001);
  // no band: the plain crown
  const Profile crown = flat_worn_crown_profile(R, w, 0);
  EXPECT_TRUE((crown.z_m == crowned_profile(R, w).z_m).all());
}

TEST(ProfileGenerators, RejectImpossibleSizes) {
  EXPECT_THROW(crowned_profile(0.005, 0.02), std::invalid_argument);  // narrower than the body
  EXPECT_THROW(crowned_profile(-0.5, 0.02), std::invalid_argument);
  EXPECT_THROW(flat_profile(0), std::invalid_argument);
  EXPECT_THROW(flat_profile(20), std::invalid_argument);  // 20 m: millimetres as metres
  EXPECT_THROW(arc_profile(0, 0.02), std::invalid_argument);
  EXPECT_THROW(flat_worn_crown_profile(0.5, 0.02, 0.01), std::invalid_argument);  // band = whole width
  EXPECT_THROW(flat_worn_crown_profile(0.5, 0.02, -1e-3), std::invalid_argument);
}

TEST(ProfileValidation, NamesTheSourceAndTheProblem) {
  auto message = [](const Profile& p) {
    try {
      validate_profile(p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  Profile p = crowned_profile(0.5, 0.02);
  p.source = "made-up";
  EXPECT_EQ(message(p), "");
  Profile q = p;
  q.z_m(7) = std::nan("");
  EXPECT_EQ(message(q).rfind("made-up: point 7: z_m must be finite", 0), 0u) << message(q);
  q = p;
  q.y_m(9) = q.y_m(8);
  EXPECT_EQ(message(q).rfind("made-up: point 9: y_m must increase", 0), 0u) << message(q);
  q = p;
  q.z_m.conservativeResize(3);
  EXPECT_NE(message(q).find("y_m has"), std::string::npos) << message(q);
}

// a directory of its own for each test, removed at the end
class ProfileCsv : public rollwear_test::TempDirTest {
 protected:
  std::string write(const std::string& text) const {
    const fs::path p = dir_ / "x.csv";
    std::ofstream(p) << text;
    return p.string();
  }
  // the error message of reading text, with the path replaced by "x.csv"
  std::string error_of(const std::string& text) const {
    const std::string path = write(text);
    try {
      read_profile_csv(path);
    } catch (const std::invalid_argument& e) {
      std::string m = e.what();
      if (m.rfind(path, 0) == 0) m = "x.csv" + m.substr(path.size());
      return m;
    }
    return "";
  }
};

// five points around a shallow crown; line numbers on the right
const std::string kGood =
    "# a crown, metres\n"  // 1
    "y_m,z_m\n"            // 2
    "-0.002,4e-6\n"        // 3
    "\n"                   // 4
    "-0.001,1e-6\n"        // 5
    "  # comment\n"        // 6
    "0,0\n"                // 7
    "0.001,1e-6\n"         // 8
    "0.002,4e-6\n";        // 9

TEST_F(ProfileCsv, ReadsPointsSkippingCommentsAndBlankLines) {
  const Profile p = read_profile_csv(write(kGood));
  ASSERT_EQ(p.y_m.size(), 5);
  EXPECT_EQ(p.y_m(1), -0.001);
  EXPECT_EQ(p.z_m(4), 4e-6);
  EXPECT_NE(p.source.find("x.csv"), std::string::npos);
}

TEST_F(ProfileCsv, RoundTripsAtFullPrecision) {
  const Profile p = flat_worn_crown_profile(0.5, 0.02, 1.5e-3);
  const Profile q = read_profile_csv(write(profile_csv(p, "two\nlines")));
  EXPECT_TRUE((q.y_m == p.y_m).all());
  EXPECT_TRUE((q.z_m == p.z_m).all());
  EXPECT_EQ(profile_hash(q), profile_hash(p));
}

TEST_F(ProfileCsv, ErrorsNameFileLineAndValue) {
  std::string t = kGood;
  t.replace(t.find("0,0\n"), 4, "-0.0015,0\n");  // line 7 goes back
  EXPECT_EQ(error_of(t), "x.csv:7: y_m must increase, got -0.0015 after -0.001");
  t = kGood;
  t.replace(t.find("\n0.001,1e-6\n"), 12, "\n0.001,nan\n");
  EXPECT_EQ(error_of(t), "x.csv:8: z_m must be finite, got nan");
  t = kGood;
  t.replace(t.find("\n0.001,1e-6\n"), 12, "\n0.001,1e-6,3\n");
  EXPECT_EQ(error_of(t), "x.csv:8: expected 2 columns y_m,z_m, got 3: '0.001,1e-6,3'");
  t = kGood;
  t.replace(t.find("-0.001,1e-6\n"), 12, "-0.001,1e-6x\n");
  EXPECT_EQ(error_of(t), "x.csv:5: z_m is not a number, got '1e-6x'");
  EXPECT_EQ(error_of("y_mm,z_mm\n1,2\n"), "x.csv:1: expected the header 'y_m,z_m' (SI units, metres), got 'y_mm,z_mm'");
  EXPECT_EQ(error_of("y_m,z_m\n0,0\n0.001,0\n0.002,0\n"), "x.csv: 3 points, at least 5 needed");
  EXPECT_EQ(error_of("# nothing\n"), "x.csv: no header 'y_m,z_m' and no points");
  const std::string missing = (dir_ / "missing.csv").string();
  try {
    read_profile_csv(missing);
    ADD_FAILURE() << "read a missing file";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open the profile file");
  }
}

// a file of more points than kProfileMaxPoints is refused naming its count and the limit (a wear run's memory
// grows with the worn profile's nodes: issue 26); the limit itself is read
TEST_F(ProfileCsv, MorePointsThanTheLimitAreRefusedNamingTheCount) {
  const auto flat_file = [](int n) {
    std::string t = "y_m,z_m\n";
    for (int i = 0; i < n; ++i) t += std::to_string(-0.01 + 0.02 * i / (n - 1)) + ",0\n";
    return t;
  };
  // (std::to_string's 6 decimals keep 5000 points over 20 mm distinct; the refusal comes before any point is parsed)
  const std::string over = error_of(flat_file(kProfileMaxPoints + 1));
  EXPECT_EQ(over.rfind("x.csv: " + std::to_string(kProfileMaxPoints + 1) + " points, at most " +
                           std::to_string(kProfileMaxPoints) + " are read",
                       0),
            0u)
      << over;
  EXPECT_EQ(error_of(flat_file(kProfileMaxPoints / 4)), "");
}

// the same crown in millimetres, given as metres: 20 "m" wide, or deeper than wide
TEST_F(ProfileCsv, MillimetresGivenAsMetresAreRefused) {
  EXPECT_EQ(error_of("y_m,z_m\n-10,0.1\n-5,0.025\n0,0\n5,0.025\n10,0.1\n"),
            "x.csv:6: width 20 m (y_m from -10 to 10) exceeds 1 m: looks like millimetres given as metres");
  EXPECT_EQ(error_of("y_m,z_m\n-0.01,0.1\n-0.005,0.025\n0,0\n0.005,0.025\n0.01,0.1\n"),
            "x.csv:2: |z_m| = 0.1 m exceeds the profile's width 0.02 m: looks like millimetres given as metres");
}

// The files in profiles/ are what profiles/README.md says they are: each equals its generator's output.
TEST(Profile, ShippedFilesMatchTheirGenerators) {
  const std::string dir = std::string(ROLLWEAR_SOURCE_DIR) + "/profiles/";
  const struct {
    const char* file;
    Profile generated;
  } shipped[] = {
      {"crowned_R500_w20.csv", crowned_profile(0.5, 0.020)},
      {"flat_worn_R500_w20_band1p5.csv", flat_worn_crown_profile(0.5, 0.020, 0.0015)},
      {"flat_w30.csv", flat_profile(0.030)},
  };
  for (const auto& s : shipped) {
    const Profile p = read_profile_csv(dir + s.file);
    ASSERT_EQ(p.y_m.size(), s.generated.y_m.size()) << s.file;
    EXPECT_TRUE((p.y_m == s.generated.y_m).all()) << s.file;
    EXPECT_TRUE((p.z_m == s.generated.z_m).all()) << s.file;
  }
}

TEST(ProfileCurvature, ParabolaFitFindsTheCrownRadius) {
  constexpr double kArcVsParabola = 1e-3;  // the arc's y^4/(8R^3) term against the fit, 20 mm wide
  const ParabolaFit f = fit_parabola(crowned_profile(0.5, 0.02));
  EXPECT_NEAR(f.curvature_per_m * 0.5, 1, kArcVsParabola);
  EXPECT_NEAR(f.vertex_y_m, 0, 1e-12);
  EXPECT_TRUE(has_constant_curvature(crowned_profile(0.5, 0.02), 1e-3));
  EXPECT_TRUE(has_constant_curvature(arc_profile(-0.3, 0.02), 1e-3));
  EXPECT_TRUE(has_constant_curvature(flat_profile(0.03), 1e-3));  // curvature 0
  EXPECT_EQ(fit_parabola(flat_profile(0.03)).curvature_per_m, 0);
  // a worn band: the residual is a sizeable part of the depth range
  EXPECT_FALSE(has_constant_curvature(flat_worn_crown_profile(0.5, 0.02, 1.5e-3), 1e-3));
  EXPECT_THROW(has_constant_curvature(flat_profile(0.03), 0), std::invalid_argument);
}

TEST(ProfileHash, ChangesWithAnyNodeOnly) {
  const Profile p = crowned_profile(0.5, 0.02);
  Profile q = p;
  q.source = "renamed";
  EXPECT_EQ(profile_hash(q), profile_hash(p)) << "the source is not geometry";
  q.z_m(200) = std::nextafter(q.z_m(200), 1.0);
  EXPECT_NE(profile_hash(q), profile_hash(p));
  const Profile f = flat_profile(0.03);
  EXPECT_NE(profile_hash(Profiles{p, f}), profile_hash(Profiles{f, p}));
  EXPECT_EQ(profile_hash(Profiles{p, f}), profile_hash(Profiles{p, f}));
}

}  // namespace
}  // namespace contact
