// Kalker's creepage coefficients and the flexibilities of the simplified theory (docs/physics.md §3).
//
// Table: Kalker's published C11, C22, C23, C33 for nu = 0, 0.25, 0.5 and g = min(a/b, b/a) = 0.1 ... 1.
// Rows a/b <= 1 form one branch, rows b/a < 1 the other; the two meet at a/b = 1.
//   in g:   linear between neighbouring rows of the branch;
//   in nu:  quadratic Lagrange fit of 1/C through nu = 0, 0.25, 0.5, then inverted; it passes exactly
//           through the three columns. Each row is fitted in nu first, then interpolated in g.
// Two copy errors circulate in public code; the published values are C11(b/a = 0.9, nu = 0) = 3.51
// (not 3.61) and C23(a/b = 0.8, nu = 0.25) = 1.25 (not 1.15).
//
// Below g = 0.1: Kalker's asymptotic forms, with Lambda = ln(16/g^2),
//   a/b = g -> 0:  C11 = pi^2 / (4 (1-nu)),  C22 = pi^2 / 4,  C33 = pi^2 / (16 (1-nu) g),
//                  C23 = pi sqrt(g) / (3 (1-nu)) [1 + nu (Lambda/2 + ln 4 - 5)];
//   b/a = g -> 0:  C11 = 2 pi / ((Lambda - 2 nu) g) [1 + (3 - ln 4) / (Lambda - 2 nu)],
//                  C22 = 2 pi / g [1 + (1-nu)(3 - ln 4) / ((1-nu) Lambda + 2 nu)] / ((1-nu) Lambda + 2 nu),
//                  C23 = 2 pi / (3 g^(3/2) ((1-nu) Lambda - 2 + 4 nu)),
//                  C33: no asymptote; the table is extrapolated linearly from its rows b/a = 0.2, 0.1.
//
// The switch at g = 0.1 is not continuous; the jump is kept, as CONTACT keeps it. Measured at nu = 0.28
// as asymptote(g just below 0.1) / table(g = 0.1) - 1:
//   a/b branch:  C11 -0.42 %,  C22 -2.13 %,  C23 -5.25 %,  C33 -0.14 %;
//   b/a branch:  C11 -3.68 %,  C22 -2.25 %,  C23 -0.01 %,  C33  0 (extrapolated from the table).
// Over nu in [0, 0.5] the largest is C23 on the a/b branch, -6.0 % at nu = 0.5
// (Kalker.JumpAtTableEdgeIsBounded in tests/kalker_test.cpp keeps each below 10 %).
//
// Flexibilities: L1 = 8a / (3 C11 G),  L2 = 8a / (3 C22 G),  L3 = pi a sqrt(a/b) / (4 C23 G).
#include "lib/tangential/kalker.h"
#include "lib/numeric.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>

namespace contact {

namespace {

constexpr double kLn4 = 1.38629436111989061883;
constexpr double kLn16 = 2.77258872223978123767;
constexpr double kTableMinG = 0.1;  // below: the asymptotic forms

// one row of Kalker's table: C[coefficient][nu column], coefficients C11, C22, C23, C33,
// columns nu = 0, 0.25, 0.5
struct TableRow {
  double g;
  double C[4][3];
};

// as published: a/b = 0.1 ... 1.0 (index 0 ... 9), then b/a = 0.9 ... 0.1 (index 10 ... 18)
constexpr TableRow kTable[19] = {
    {0.1, {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}, {6.42, 8.28, 11.7}}},  // a/b = 0.1
    {0.2, {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}, {3.46, 4.27, 5.66}}},  // a/b = 0.2
    {0.3, {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}, {2.49, 2.96, 3.72}}},  // a/b = 0.3
    {0.4, {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}, {2.02, 2.32, 2.77}}},  // a/b = 0.4
    {0.5, {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}, {1.74, 1.93, 2.22}}},   // a/b = 0.5
    {0.6, {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}, {1.56, 1.68, 1.86}}},    // a/b = 0.6
    {0.7, {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}, {1.43, 1.50, 1.60}}},     // a/b = 0.7
    {0.8, {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}, {1.34, 1.37, 1.42}}},     // a/b = 0.8
    {0.9, {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}, {1.27, 1.27, 1.27}}},     // a/b = 0.9
    {1.0, {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}}},     // a/b = 1.0
    {0.9, {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}, {1.16, 1.11, 1.06}}},     // b/a = 0.9
    {0.8, {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}, {1.10, 1.04, 0.95}}},     // b/a = 0.8
    {0.7, {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}, {1.05, 0.97, 0.85}}},     // b/a = 0.7
    {0.6, {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}, {1.01, 0.89, 0.75}}},     // b/a = 0.6
    {0.5, {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}, {0.96, 0.82, 0.65}}},     // b/a = 0.5
    {0.4, {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}, {0.91, 0.75, 0.55}}},     // b/a = 0.4
    {0.3, {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}, {0.87, 0.67, 0.45}}},     // b/a = 0.3
    {0.2, {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}, {0.83, 0.60, 0.34}}},     // b/a = 0.2
    {0.1, {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}, {0.80, 0.53, 0.23}}},     // b/a = 0.1
};

enum class Branch { AOverB, BOverA };  // g = a/b <= 1, or g = b/a < 1

// row of the branch at g = k/10, k = 1 ... 10
const TableRow& table_row(Branch branch, int k) {
  return branch == Branch::AOverB ? kTable[k - 1] : kTable[19 - k];
}

// quadratic Lagrange fit of 1/C through the columns nu = 0, 0.25, 0.5, inverted
double fit_in_nu(const double (&C)[3], double nu) {
  const double w0 = (nu - 0.25) * (nu - 0.5) / ((0 - 0.25) * (0 - 0.5));
  const double w1 = (nu - 0) * (nu - 0.5) / ((0.25 - 0) * (0.25 - 0.5));
  const double w2 = (nu - 0) * (nu - 0.25) / ((0.5 - 0) * (0.5 - 0.25));
  return 1 / (w0 / C[0] + w1 / C[1] + w2 / C[2]);
}

// coefficient i of the branch at g, linear between the neighbouring rows (fitted in nu);
// for g < 0.1 this extrapolates from the rows g = 0.1, 0.2
double table_coefficient(Branch branch, int i, double g, double nu) {
  const int k = std::clamp(static_cast<int>(std::floor(10 * g)), 1, 9);
  const TableRow& lo = table_row(branch, k);
  const TableRow& hi = table_row(branch, k + 1);
  const double C_lo = fit_in_nu(lo.C[i], nu);
  const double C_hi = fit_in_nu(hi.C[i], nu);
  const double t = (g - lo.g) / (hi.g - lo.g);
  return C_lo + t * (C_hi - C_lo);
}

KalkerCoefficients table_coefficients(Branch branch, double g, double nu) {
  return {table_coefficient(branch, 0, g, nu), table_coefficient(branch, 1, g, nu),
          table_coefficient(branch, 2, g, nu), table_coefficient(branch, 3, g, nu)};
}

// Kalker's asymptotes for a/b = g -> 0 (contact long across the rolling direction)
KalkerCoefficients asymptote_a_over_b(double g, double nu) {
  const double Lambda = kLn16 - 2 * std::log(g);  // ln(16/g^2) without underflow of g^2
  KalkerCoefficients C;
  C.C11 = kPi * kPi / (4 * (1 - nu));
  C.C22 = kPi * kPi / 4;
  C.C23 = kPi * std::sqrt(g) / (3 * (1 - nu)) * (1 + nu * (Lambda / 2 + kLn4 - 5));
  C.C33 = kPi * kPi / (16 * (1 - nu) * g);
  return C;
}

// Kalker's asymptotes for b/a = g -> 0 (contact long along the rolling direction)
KalkerCoefficients asymptote_b_over_a(double g, double nu) {
  const double Lambda = kLn16 - 2 * std::log(g);
  const double D11 = Lambda - 2 * nu;
  const double D22 = (1 - nu) * Lambda + 2 * nu;
  KalkerCoefficients C;
  C.C11 = 2 * kPi / (D11 * g) * (1 + (3 - kLn4) / D11);
  C.C22 = 2 * kPi / g * (1 + (1 - nu) * (3 - kLn4) / D22) / D22;
  C.C23 = 2 * kPi / (3 * g * std::sqrt(g) * ((1 - nu) * Lambda - 2 + 4 * nu));
  // no asymptote for C33: extrapolate the table linearly from its rows b/a = 0.2, 0.1
  C.C33 = table_coefficient(Branch::BOverA, 3, g, nu);
  return C;
}

void check_semi_axes(const char* where, double a_m, double b_m) {
  if (!(a_m > 0) || !std::isfinite(a_m))
    throw std::invalid_argument(fmt::format("{}: semi-axis a must be positive and finite, got {} m", where, a_m));
  if (!(b_m > 0) || !std::isfinite(b_m))
    throw std::invalid_argument(fmt::format("{}: semi-axis b must be positive and finite, got {} m", where, b_m));
}

}  // namespace

KalkerCoefficients kalker_coefficients(double a_m, double b_m, double nu) {
  check_semi_axes("kalker_coefficients", a_m, b_m);
  if (!(nu >= 0 && nu <= 0.5))
    throw std::invalid_argument(fmt::format("kalker_coefficients: nu must be in [0, 0.5], got {}", nu));

  // branch and abscissa: g = a/b on the a/b rows (a <= b), g = b/a on the b/a rows
  const Branch branch = a_m <= b_m ? Branch::AOverB : Branch::BOverA;
  const double g = branch == Branch::AOverB ? a_m / b_m : b_m / a_m;
  if (!(g > 0))
    throw std::invalid_argument(fmt::format(
        "kalker_coefficients: aspect ratio of a = {} m, b = {} m underflows to zero", a_m, b_m));

  // inside the table: interpolate; below it: Kalker's asymptotes
  if (g >= kTableMinG) return table_coefficients(branch, g, nu);
  return branch == Branch::AOverB ? asymptote_a_over_b(g, nu) : asymptote_b_over_a(g, nu);
}

Flexibilities kalker_flexibilities(const KalkerCoefficients& C, double a_m, double b_m, double G_Pa) {
  check_semi_axes("kalker_flexibilities", a_m, b_m);
  if (!(G_Pa > 0) || !std::isfinite(G_Pa))
    throw std::invalid_argument(
        fmt::format("kalker_flexibilities: shear modulus G must be positive and finite, got {} Pa", G_Pa));
  for (const double Cij : {C.C11, C.C22, C.C23})
    if (!(Cij > 0) || !std::isfinite(Cij))
      throw std::invalid_argument(fmt::format(
          "kalker_flexibilities: C11, C22, C23 must be positive and finite, got {}, {}, {}", C.C11, C.C22, C.C23));

  const double a = a_m, b = b_m, G = G_Pa;
  Flexibilities L;
  L.L1_m_per_Pa = 8 * a / (3 * C.C11 * G);
  L.L2_m_per_Pa = 8 * a / (3 * C.C22 * G);
  L.L3_m_per_Pa = kPi * a * std::sqrt(a / b) / (4 * C.C23 * G);
  return L;
}

}  // namespace contact
