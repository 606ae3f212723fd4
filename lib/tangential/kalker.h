// Kalker's creepage coefficients C11, C22, C23, C33 (linear theory) and the flexibilities of the
// simplified theory derived from them (docs/physics.md §3):
//   L1 = 8a / (3 C11 G),  L2 = 8a / (3 C22 G),  L3 = pi a sqrt(a/b) / (4 C23 G).
// Table: Kalker's published values for nu = 0, 0.25, 0.5, g = min(a/b, b/a) from 0.1 to 1,
// interpolated linearly in g and, across nu, by a quadratic fit of 1/C through the three columns.
// Below g = 0.1: Kalker's asymptotic forms (a/b -> 0 and b/a -> 0), except C33 for b/a -> 0,
// which is extrapolated linearly from the table. The switch at g = 0.1 keeps a small jump (C23
// about 5 % at nu = 0.28), as CONTACT does.
#pragma once

namespace contact {

struct KalkerCoefficients {
  double C11 = 0, C22 = 0, C23 = 0, C33 = 0;
};

// a_m along x (rolling), b_m along y; nu in [0, 0.5]; throws std::invalid_argument otherwise
KalkerCoefficients kalker_coefficients(double a_m, double b_m, double nu);

struct Flexibilities {
  double L1_m_per_Pa = 0;  // for the longitudinal creepage xi
  double L2_m_per_Pa = 0;  // for the lateral creepage eta
  double L3_m_per_Pa = 0;  // for the spin phi
};

Flexibilities kalker_flexibilities(const KalkerCoefficients& C, double a_m, double b_m, double G_Pa);

}  // namespace contact
