// Tests of lib/tangential/kalker.h against Kalker's published table of creepage coefficients and his asymptotic
// forms below the table (docs/physics.md §3). Expected values are written here again from the published
// table and the formulas, never taken from the implementation.
#include "lib/tangential/kalker.h"
#include "lib/numeric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace contact {
namespace {

constexpr double kTableTol = 1e-12;    // the 1/C fit passes through the table points, up to rounding
constexpr double kFormulaTol = 1e-12;  // the same closed form, evaluated in another order
constexpr double kNuColumns[3] = {0, 0.25, 0.5};

enum class Branch { AOverB, BOverA };  // g = a/b <= 1 (a along rolling x), or g = b/a < 1

// Kalker's table as published: C[coefficient][nu column], coefficients C11, C22, C23, C33
struct TableRow {
  Branch branch;
  double g;
  double C[4][3];
};

const TableRow kPublished[] = {
    {Branch::AOverB, 0.1, {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}, {6.42, 8.28, 11.7}}},
    {Branch::AOverB, 0.2, {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}, {3.46, 4.27, 5.66}}},
    {Branch::AOverB, 0.3, {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}, {2.49, 2.96, 3.72}}},
    {Branch::AOverB, 0.4, {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}, {2.02, 2.32, 2.77}}},
    {Branch::AOverB, 0.5, {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}, {1.74, 1.93, 2.22}}},
    {Branch::AOverB, 0.6, {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}, {1.56, 1.68, 1.86}}},
    {Branch::AOverB, 0.7, {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}, {1.43, 1.50, 1.60}}},
    {Branch::AOverB, 0.8, {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}, {1.34, 1.37, 1.42}}},
    {Branch::AOverB, 0.9, {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}, {1.27, 1.27, 1.27}}},
    {Branch::AOverB, 1.0, {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}}},
    {Branch::BOverA, 0.9, {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}, {1.16, 1.11, 1.06}}},
    {Branch::BOverA, 0.8, {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}, {1.10, 1.04, 0.95}}},
    {Branch::BOverA, 0.7, {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}, {1.05, 0.97, 0.85}}},
    {Branch::BOverA, 0.6, {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}, {1.01, 0.89, 0.75}}},
    {Branch::BOverA, 0.5, {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}, {0.96, 0.82, 0.65}}},
    {Branch::BOverA, 0.4, {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}, {0.91, 0.75, 0.55}}},
    {Branch::BOverA, 0.3, {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}, {0.87, 0.67, 0.45}}},
    {Branch::BOverA, 0.2, {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}, {0.83, 0.60, 0.34}}},
    {Branch::BOverA, 0.1, {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}, {0.80, 0.53, 0.23}}},
};

const TableRow& published_row(Branch branch, double g) {
  for (const TableRow& row : kPublished)
    if (row.branch == branch && row.g == g) return row;
  throw std::logic_error("no such row in the published table");
}

double get(const KalkerCoefficients& C, int i) {
  const double values[4] = {C.C11, C.C22, C.C23, C.C33};
  return values[i];
}

const char* const kNames[4] = {"C11", "C22", "C23", "C33"};

// the coefficients for a contact of aspect g on the branch; a = g, b = 1 (or a = 1, b = g) keeps the
// ratio exactly g, so g = 0.1 stays on the table
KalkerCoefficients at(Branch branch, double g, double nu) {
  return branch == Branch::AOverB ? kalker_coefficients(g, 1, nu) : kalker_coefficients(1, g, nu);
}

// quadratic Lagrange fit of 1/C through the published columns nu = 0, 0.25, 0.5
double fit_inverse_in_nu(const double (&C)[3], double nu) {
  double inverse = 0;
  for (int k = 0; k < 3; ++k) {
    double w = 1;
    for (int m = 0; m < 3; ++m)
      if (m != k) w *= (nu - kNuColumns[m]) / (kNuColumns[k] - kNuColumns[m]);
    inverse += w / C[k];
  }
  return 1 / inverse;
}

double relative_error(double value, double expected) { return std::abs(value / expected - 1); }

// ---------------------------------------------------------------------------------------------------
// the published table

class KalkerTable : public testing::TestWithParam<TableRow> {};

TEST_P(KalkerTable, PointsReproducedAtNuColumns) {
  const TableRow& row = GetParam();
  for (int n = 0; n < 3; ++n) {
    const KalkerCoefficients C = at(row.branch, row.g, kNuColumns[n]);
    for (int i = 0; i < 4; ++i)
      EXPECT_LT(relative_error(get(C, i), row.C[i][n]), kTableTol)
          << kNames[i] << " at nu = " << kNuColumns[n] << ": " << get(C, i) << " vs " << row.C[i][n];
  }
}

std::string row_name(const testing::TestParamInfo<TableRow>& info) {
  const int tenths = static_cast<int>(std::lround(10 * info.param.g));
  return std::string(info.param.branch == Branch::AOverB ? "a_over_b_" : "b_over_a_") +
         (tenths == 10 ? std::string("1p0") : "0p" + std::to_string(tenths));
}

INSTANTIATE_TEST_SUITE_P(Kalker, KalkerTable, testing::ValuesIn(kPublished), row_name);

TEST(Kalker, CopyErrorsCirculatingInPublicCodeAreNotReproduced) {
  // published: C11(b/a = 0.9, nu = 0) = 3.51 (copies have 3.61), C23(a/b = 0.8, nu = 0.25) = 1.25 (1.15)
  EXPECT_NEAR(kalker_coefficients(1, 0.9, 0).C11, 3.51, 3.51 * kTableTol);
  EXPECT_NEAR(kalker_coefficients(0.8, 1, 0.25).C23, 1.25, 1.25 * kTableTol);
}

// ---------------------------------------------------------------------------------------------------
// interpolation between the table points

TEST(Kalker, NuFitBetweenColumnsLiesBetweenTheirValues) {
  // every coefficient of the table varies monotonically from nu = 0.25 to 0.5
  constexpr double kSlack = 1e-12;  // the row b/a = 0.9 has C33 equal in all three columns
  for (const TableRow& row : kPublished) {
    const KalkerCoefficients C = at(row.branch, row.g, 0.28);
    for (int i = 0; i < 4; ++i) {
      const double lo = std::min(row.C[i][1], row.C[i][2]), hi = std::max(row.C[i][1], row.C[i][2]);
      EXPECT_GE(get(C, i), lo * (1 - kSlack)) << kNames[i] << " at g = " << row.g;
      EXPECT_LE(get(C, i), hi * (1 + kSlack)) << kNames[i] << " at g = " << row.g;
    }
  }
}

TEST(Kalker, NuFitIsLagrangeOnInverseCoefficient) {
  // C23 at a/b = 0.5, nu = 0.28, by hand: Lagrange weights at nu = 0.28 through 0, 0.25, 0.5 are
  // (0.03)(-0.22)/0.125 = -0.0528, (0.28)(-0.22)/(-0.0625) = 0.9856, (0.28)(0.03)/0.125 = 0.0672
  const double expected = 1 / (-0.0528 / 0.827 + 0.9856 / 0.929 + 0.0672 / 1.07);
  EXPECT_NEAR(expected, 0.943499, 1e-6);  // the hand computation itself
  EXPECT_LT(relative_error(kalker_coefficients(0.5, 1, 0.28).C23, expected), kTableTol);

  // the same fit for every coefficient of every row, at a few nu between and on the columns
  for (const TableRow& row : kPublished)
    for (const double nu : {0.05, 0.1, 0.28, 0.4, 0.45})
      for (int i = 0; i < 4; ++i)
        EXPECT_LT(relative_error(get(at(row.branch, row.g, nu), i), fit_inverse_in_nu(row.C[i], nu)),
                  kTableTol)
            << kNames[i] << " at g = " << row.g << ", nu = " << nu;
}

TEST(Kalker, LinearInAspectRatioBetweenRows) {
  // midpoints: a/b = 0.45 between the rows 0.4 and 0.5, b/a = 0.15 between 0.1 and 0.2, b/a = 0.95
  // between 0.9 and 1, on a nu column (the table values themselves) and off it (the nu fit of each row)
  struct Midpoint {
    Branch branch;
    double g, g_lo, g_hi;
  };
  for (const Midpoint& m : {Midpoint{Branch::AOverB, 0.45, 0.4, 0.5}, Midpoint{Branch::BOverA, 0.15, 0.1, 0.2},
                            Midpoint{Branch::BOverA, 0.95, 0.9, 1.0}}) {
    // the row g = 1 (a/b = 1) is shared by both branches
    const TableRow& lo = published_row(m.branch, m.g_lo);
    const TableRow& hi = m.g_hi == 1.0 ? published_row(Branch::AOverB, 1.0) : published_row(m.branch, m.g_hi);
    for (const double nu : {0.25, 0.28}) {
      const KalkerCoefficients C = at(m.branch, m.g, nu);
      for (int i = 0; i < 4; ++i) {
        const double expected = (fit_inverse_in_nu(lo.C[i], nu) + fit_inverse_in_nu(hi.C[i], nu)) / 2;
        EXPECT_LT(relative_error(get(C, i), expected), kTableTol)
            << kNames[i] << " at g = " << m.g << ", nu = " << nu;
      }
    }
  }
  // on a column the midpoint is the mean of the published values: C11(a/b = 0.45, nu = 0.25)
  EXPECT_NEAR(kalker_coefficients(0.45, 1, 0.25).C11, (3.53 + 3.62) / 2, 3.575 * kTableTol);
}

TEST(Kalker, SquareContactIsTheSameFromEitherBranch) {
  // a/b = 1 closes both branches; approaching it from a < b and from a > b gives one value
  constexpr double kStep = 1e-9;
  constexpr double kContinuityTol = 1e-8;  // step 1e-9 in g times slopes of order 1 per unit g
  for (const double nu : {0.0, 0.1, 0.28, 0.5}) {
    const KalkerCoefficients square = kalker_coefficients(2e-3, 2e-3, nu);
    const KalkerCoefficients from_a_over_b = at(Branch::AOverB, 1 - kStep, nu);
    const KalkerCoefficients from_b_over_a = at(Branch::BOverA, 1 - kStep, nu);
    for (int i = 0; i < 4; ++i) {
      EXPECT_LT(relative_error(get(from_a_over_b, i), get(square, i)), kContinuityTol) << kNames[i];
      EXPECT_LT(relative_error(get(from_b_over_a, i), get(square, i)), kContinuityTol) << kNames[i];
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// below the table: Kalker's asymptotic forms, Lambda = ln(16/g^2)

struct AsymptoteCase {
  double g, nu;
};

class KalkerAsymptote : public testing::TestWithParam<AsymptoteCase> {};

TEST_P(KalkerAsymptote, AOverBToZeroMatchesKalkerForms) {
  const double g = GetParam().g, nu = GetParam().nu;
  const double Lambda = std::log(16 / (g * g));
  const double C11 = kPi * kPi / (4 * (1 - nu));
  const double C22 = kPi * kPi / 4;
  const double C23 = kPi * std::sqrt(g) / (3 * (1 - nu)) * (1 + nu * (Lambda / 2 + std::log(4.0) - 5));
  const double C33 = kPi * kPi / (16 * (1 - nu) * g);

  const KalkerCoefficients C = kalker_coefficients(g * 4e-3, 4e-3, nu);
  EXPECT_LT(relative_error(C.C11, C11), kFormulaTol);
  EXPECT_LT(relative_error(C.C22, C22), kFormulaTol);
  EXPECT_LT(relative_error(C.C23, C23), kFormulaTol);
  EXPECT_LT(relative_error(C.C33, C33), kFormulaTol);
}

TEST_P(KalkerAsymptote, BOverAToZeroMatchesKalkerForms) {
  const double g = GetParam().g, nu = GetParam().nu;
  const double Lambda = std::log(16 / (g * g));
  const double ln4 = std::log(4.0);
  const double C11 = 2 * kPi / ((Lambda - 2 * nu) * g) * (1 + (3 - ln4) / (Lambda - 2 * nu));
  const double C22 = 2 * kPi / g * (1 + (1 - nu) * (3 - ln4) / ((1 - nu) * Lambda + 2 * nu)) /
                     ((1 - nu) * Lambda + 2 * nu);
  const double C23 = 2 * kPi / (3 * std::pow(g, 1.5) * ((1 - nu) * Lambda - 2 + 4 * nu));
  // no asymptote for C33: the line through the rows b/a = 0.1 and 0.2, each fitted in nu
  const double C33_01 = fit_inverse_in_nu(published_row(Branch::BOverA, 0.1).C[3], nu);
  const double C33_02 = fit_inverse_in_nu(published_row(Branch::BOverA, 0.2).C[3], nu);
  const double C33 = C33_01 + (g - 0.1) / (0.2 - 0.1) * (C33_02 - C33_01);

  const KalkerCoefficients C = kalker_coefficients(4e-3, g * 4e-3, nu);
  EXPECT_LT(relative_error(C.C11, C11), kFormulaTol);
  EXPECT_LT(relative_error(C.C22, C22), kFormulaTol);
  EXPECT_LT(relative_error(C.C23, C23), kFormulaTol);
  EXPECT_LT(relative_error(C.C33, C33), kFormulaTol);
}

INSTANTIATE_TEST_SUITE_P(Kalker, KalkerAsymptote,
                         testing::Values(AsymptoteCase{0.05, 0}, AsymptoteCase{0.05, 0.25},
                                         AsymptoteCase{0.05, 0.28}, AsymptoteCase{0.05, 0.5},
                                         AsymptoteCase{0.01, 0}, AsymptoteCase{0.01, 0.25},
                                         AsymptoteCase{0.01, 0.28}, AsymptoteCase{0.01, 0.5}));

TEST(Kalker, PaperCaseC11IsThinStripLimit) {
  // a/b = 0.088, nu = 0.28 (the paper's case, just below the table): C11 = pi^2 / (4 * 0.72) = 3.4269,
  // the value docs/physics.md §4 uses
  constexpr double kQuotedTol = 5e-5;  // docs/physics.md quotes four decimals
  EXPECT_NEAR(kalker_coefficients(0.088, 1, 0.28).C11, 3.4269, kQuotedTol);
  // and C11 -> pi^2 / (4 (1 - nu)) as a/b -> 0, for every nu
  for (const double nu : {0.0, 0.1, 0.25, 0.3, 0.5})
    for (const double g : {0.09, 1e-3, 1e-6})
      EXPECT_LT(relative_error(kalker_coefficients(g, 1, nu).C11, kPi * kPi / (4 * (1 - nu))), kFormulaTol)
          << "g = " << g << ", nu = " << nu;
}

TEST(Kalker, JumpAtTableEdgeIsBounded) {
  // the switch to the asymptotes at g = 0.1 is kept discontinuous, as in CONTACT; bound it on both
  // branches, for every coefficient, over nu
  constexpr double kMaxJump = 0.10;
  const double below = std::nextafter(0.1, 0.0);
  for (const Branch branch : {Branch::AOverB, Branch::BOverA})
    for (const double nu : {0.0, 0.1, 0.25, 0.28, 0.4, 0.5}) {
      const KalkerCoefficients table = at(branch, 0.1, nu), asymptote = at(branch, below, nu);
      for (int i = 0; i < 4; ++i)
        EXPECT_LT(relative_error(get(asymptote, i), get(table, i)), kMaxJump)
            << kNames[i] << (branch == Branch::AOverB ? " a/b" : " b/a") << ", nu = " << nu;
    }
  // C33 on the b/a branch is extrapolated from the table: no jump at all
  EXPECT_NEAR(at(Branch::BOverA, below, 0.28).C33, at(Branch::BOverA, 0.1, 0.28).C33, 1e-12);
}

TEST(Kalker, JumpAtTableEdgeMatchesDocumentedSize) {
  // lib/tangential/kalker.cpp quotes asymptote(g just below 0.1) / table(0.1) - 1 at nu = 0.28
  constexpr double kQuotedTol = 5e-5;  // quoted to 0.01 %
  const double below = std::nextafter(0.1, 0.0);
  const double a_over_b[4] = {-0.0042, -0.0213, -0.0525, -0.0014};
  const double b_over_a[4] = {-0.0368, -0.0225, -0.0001, 0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(get(at(Branch::AOverB, below, 0.28), i) / get(at(Branch::AOverB, 0.1, 0.28), i) - 1,
                a_over_b[i], kQuotedTol)
        << kNames[i] << " a/b";
    EXPECT_NEAR(get(at(Branch::BOverA, below, 0.28), i) / get(at(Branch::BOverA, 0.1, 0.28), i) - 1,
                b_over_a[i], kQuotedTol)
        << kNames[i] << " b/a";
  }
}

TEST(Kalker, CoefficientsPositiveAndFiniteOverAllShapes) {
  for (const Branch branch : {Branch::AOverB, Branch::BOverA})
    for (double g = 1e-8; g <= 1; g *= 1.1)
      for (const double nu : {0.0, 0.05, 0.15, 0.25, 0.28, 0.35, 0.45, 0.5}) {
        const KalkerCoefficients C = at(branch, g, nu);
        for (int i = 0; i < 4; ++i)
          EXPECT_TRUE(get(C, i) > 0 && std::isfinite(get(C, i))) << kNames[i] << " at g = " << g << ", nu = " << nu;
      }
}

// ---------------------------------------------------------------------------------------------------
// flexibilities of the simplified theory

TEST(Kalker, FlexibilitiesFollowFromCoefficients) {
  // L1 = 8a / (3 C11 G), L2 = 8a / (3 C22 G), L3 = pi a sqrt(a/b) / (4 C23 G)
  constexpr double kFlexTol = 1e-14;  // one closed form, a few roundings
  const double a = 0.35e-3, b = 3.98e-3, G = 8.0e10;
  const KalkerCoefficients C = kalker_coefficients(a, b, 0.28);
  const Flexibilities L = kalker_flexibilities(C, a, b, G);
  EXPECT_LT(relative_error(L.L1_m_per_Pa, 8 * a / (3 * C.C11 * G)), kFlexTol);
  EXPECT_LT(relative_error(L.L2_m_per_Pa, 8 * a / (3 * C.C22 * G)), kFlexTol);
  EXPECT_LT(relative_error(L.L3_m_per_Pa, kPi * a * std::sqrt(a / b) / (4 * C.C23 * G)), kFlexTol);

  // with the paper's C11: L1 G / a = 8 / (3 * 3.4269)
  const Flexibilities paper = kalker_flexibilities({3.4269, 1, 1, 1}, 1e-3, 1e-2, 1);
  EXPECT_NEAR(paper.L1_m_per_Pa / 1e-3, 8 / (3 * 3.4269), 1e-15);
}

// ---------------------------------------------------------------------------------------------------
// invalid input

// the call throws std::invalid_argument whose message names `what`
template <class F>
void expect_invalid(F call, const std::string& what) {
  try {
    call();
    ADD_FAILURE() << "no exception; expected one naming " << what;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(Kalker, InvalidInputThrowsNamingTheQuantity) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (const double bad : {0.0, -1e-3, kNaN, kInf}) {
    expect_invalid([&] { kalker_coefficients(bad, 1e-3, 0.28); }, "semi-axis a");
    expect_invalid([&] { kalker_coefficients(1e-3, bad, 0.28); }, "semi-axis b");
    expect_invalid([&] { kalker_flexibilities({3, 3, 1, 1}, bad, 1e-3, 8e10); }, "semi-axis a");
    expect_invalid([&] { kalker_flexibilities({3, 3, 1, 1}, 1e-3, bad, 8e10); }, "semi-axis b");
    expect_invalid([&] { kalker_flexibilities({3, 3, 1, 1}, 1e-3, 1e-3, bad); }, "shear modulus G");
    expect_invalid([&] { kalker_flexibilities({bad, 3, 1, 1}, 1e-3, 1e-3, 8e10); }, "C11, C22, C23");
  }
  for (const double bad : {-1e-9, 0.5 + 1e-9, -1.0, kNaN, kInf})
    expect_invalid([&] { kalker_coefficients(1e-3, 1e-3, bad); }, "nu must be in [0, 0.5]");
  // an aspect ratio that underflows cannot be placed in the table
  expect_invalid([&] { kalker_coefficients(1e-300, 1e300, 0.28); }, "underflows");

  // the ends of the nu range are valid
  EXPECT_NO_THROW(kalker_coefficients(1e-3, 1e-3, 0));
  EXPECT_NO_THROW(kalker_coefficients(1e-3, 1e-3, 0.5));
}

}  // namespace
}  // namespace contact
