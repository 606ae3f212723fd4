// The EHL film thickness and the lubrication regime (lib/lubrication/film.h, regime.h) against a published
// worked problem, the formulas' exponents and the line-contact formulas at the end of the point formula's
// range (docs/lubrication-and-temperature.md §1-2).
#include "lib/lubrication/film.h"
#include "lib/lubrication/regime.h"
#include "lib/normal/hertz.h"
#include "lib/elastic.h"
#include "lib/numeric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace contact {
namespace {

// Stachowiak and Batchelor, Engineering Tribology, chapter 7 (elastohydrodynamic lubrication), problem:
// a steel ball of diameter 30 mm (E = 210 GPa, nu = 0.3, rho = 7800 kg/m^3) rolls without sliding from rest
// down a steel plate inclined at 45 degrees, under an oil of eta0 = 50 cP and alpha = 2.2e-8 1/Pa; the
// published answers are h_min = 0.059 um after 1 cm rolled and 0.281 um after 1 m.
// The book's conventions: U = eta0 u / (E' R'), W = w / (E' R'^2), h = R' H with the reduced radius
// 1/R' = 1/Rx + 1/Ry (here R' = 7.5 mm), u = (u_ball + u_plate)/2 with the plate at rest, so u = v/2;
// the load is the ball's weight normal to the plate; the ball's speed from its energy, v^2 = (10/7) g s sin(45).
TEST(FilmThickness, StachowiakRollingBallProblemReproducesPublishedMinimumFilms) {
  constexpr double kPublishedDigits = 0.5e-9;  // the answers are given to the nanometre (0.059, 0.281 um)
  const double d = 0.030, rho = 7800, g = 9.81, theta = kPi / 4;
  const double E_prime = ehl_reduced_modulus_Pa(effective_modulus_Pa({{210e9, 0.3}, {210e9, 0.3}}));
  const double weight = rho * kPi * d * d * d / 6 * g;
  const double w = weight * std::cos(theta);
  const double R_book = 1 / (1 / (d / 2) + 1 / (d / 2));  // the book's R'
  const double k = hamrock_dowson_ellipticity(d / 2, d / 2);
  const auto h_min_after = [&](double s) {
    const double v = std::sqrt(10.0 / 7.0 * g * s * std::sin(theta));
    const FilmGroups groups{0.05 * (v / 2) / (E_prime * R_book), 2.2e-8 * E_prime, w / (E_prime * R_book * R_book)};
    return R_book * hamrock_dowson_H_min(groups, k);
  };
  EXPECT_NEAR(h_min_after(0.01), 0.059e-6, kPublishedDigits);
  EXPECT_NEAR(h_min_after(1.0), 0.281e-6, kPublishedDigits);
}

// The exponents of Hamrock and Dowson's point formulas, h_min ~ U^0.68 G^0.49 W^-0.073 and
// h_c ~ U^0.67 G^0.53 W^-0.067, checked by doubling each group through the dimensional function
TEST(FilmThickness, PointContactScalesWithPublishedExponents) {
  constexpr double kRounding = 1e-12;  // ratios of powers: rounding only
  const Lubricant oil{0.01, 2e-8};
  const double Rx = 0.011, k = 4, E_prime = 2.3e11, F = 1500, u = 2;
  const FilmThickness base = film_point_contact(oil, Rx, k, E_prime, F, u);
  const FilmThickness fast = film_point_contact(oil, Rx, k, E_prime, F, 2 * u);                  // U x 2
  const FilmThickness stiff = film_point_contact({0.01, 4e-8}, Rx, k, E_prime, F, u);             // G x 2
  const FilmThickness heavy = film_point_contact(oil, Rx, k, E_prime, 2 * F, u);                  // W x 2
  EXPECT_NEAR(fast.h_min_m / base.h_min_m, std::pow(2, 0.68), kRounding);
  EXPECT_NEAR(stiff.h_min_m / base.h_min_m, std::pow(2, 0.49), kRounding);
  EXPECT_NEAR(heavy.h_min_m / base.h_min_m, std::pow(2, -0.073), kRounding);
  EXPECT_NEAR(fast.h_central_m / base.h_central_m, std::pow(2, 0.67), kRounding);
  EXPECT_NEAR(stiff.h_central_m / base.h_central_m, std::pow(2, 0.53), kRounding);
  EXPECT_NEAR(heavy.h_central_m / base.h_central_m, std::pow(2, -0.067), kRounding);
  EXPECT_NEAR(base.groups.U, 0.01 * u / (E_prime * Rx), 1e-30);
  EXPECT_NEAR(base.groups.W, F / (E_prime * Rx * Rx), 1e-18);
}

TEST(FilmThickness, LineContactScalesWithPublishedExponents) {
  constexpr double kRounding = 1e-12;
  const Lubricant oil{0.01, 2e-8};
  const double R = 0.011, E_prime = 2.3e11, w = 2e5, u = 2;
  const FilmThickness base = film_line_contact(oil, R, E_prime, w, u);
  EXPECT_NEAR(film_line_contact(oil, R, E_prime, w, 2 * u).h_min_m / base.h_min_m, std::pow(2, 0.70), kRounding);
  EXPECT_NEAR(film_line_contact({0.01, 4e-8}, R, E_prime, w, u).h_min_m / base.h_min_m, std::pow(2, 0.54), kRounding);
  EXPECT_NEAR(film_line_contact(oil, R, E_prime, 2 * w, u).h_min_m / base.h_min_m, std::pow(2, -0.13), kRounding);
  EXPECT_NEAR(film_line_contact(oil, R, E_prime, w, 2 * u).h_central_m / base.h_central_m, std::pow(2, 0.69), kRounding);
  EXPECT_NEAR(film_line_contact(oil, R, E_prime, 2 * w, u).h_central_m / base.h_central_m, std::pow(2, -0.10), kRounding);
}

// As k grows the point formula's ellipticity factor saturates (1 - exp(-0.68 k) -> 1): from k = 8 to 16
// the minimum film changes by exp(-5.44) - exp(-10.88), under half a per cent, as a line contact's does not
// depend on its length.
TEST(FilmThickness, PointFormulaSaturatesInEllipticityAsALineContact) {
  const Lubricant oil{0.01, 2e-8};
  const double h8 = film_point_contact(oil, 0.011, 8, 2.3e11, 1500, 1).h_min_m;
  const double h16 = film_point_contact(oil, 0.011, 16, 2.3e11, 1500, 1).h_min_m;
  const double e8 = std::exp(-0.68 * 8), e16 = std::exp(-0.68 * 16);
  EXPECT_NEAR(h16 / h8 - 1, (e8 - e16) / (1 - e8), 1e-12);  // the ratio of the two factors
  EXPECT_LT(h16 / h8 - 1, 0.005);
}

// At the end of Hamrock and Dowson's range (k near 8) an elongated Hertz contact's centre line carries
// the line load w' = (pi/2) p0 a = 3F/(4b); Dowson and Higginson's line formula on it and Hamrock and
// Dowson's point formula are two independent fits, and agree there to a few per cent (measured: the
// paper's rollers with Ry1 = 0.5 m, k = b/a = 11.3: ratio 1.008, docs/lubrication-and-temperature.md §1).
TEST(FilmThickness, PointFormulaNearItsRangeEndMatchesLineFormulaOnTheCentreLineLoad) {
  constexpr double kFitsAgree = 0.05;  // two regressions of different numerical solutions, each a few % off them
  const ElasticPair steel{{210e9, 0.28}, {210e9, 0.28}};
  const double E_prime = ehl_reduced_modulus_Pa(effective_modulus_Pa(steel));
  const Lubricant oil{0.01, 2e-8};
  for (const double Ry1 : {0.2, 0.5}) {
    const Bodies bodies{{0.020, Ry1}, {0.025, kFlat}};
    const HertzContact h = solve_hertz(bodies, steel, 1500);
    const double Rx = 1 / (1 / 0.020 + 1 / 0.025);
    const double k = h.b_m / h.a_m;
    const double point = film_point_contact(oil, Rx, k, E_prime, 1500, 1).h_min_m;
    const double line = film_line_contact(oil, Rx, E_prime, 3 * 1500 / (4 * h.b_m), 1).h_min_m;
    EXPECT_NEAR(point / line, 1, kFitsAgree) << "Ry1 = " << Ry1 << ", k = " << k;
  }
}

TEST(FilmThickness, RefusesNonPositiveInputs) {
  EXPECT_THROW(film_point_contact({0, 2e-8}, 0.01, 2, 2.3e11, 100, 1), std::invalid_argument);
  EXPECT_THROW(film_point_contact({0.01, 0}, 0.01, 2, 2.3e11, 100, 1), std::invalid_argument);
  EXPECT_THROW(film_point_contact({0.01, 2e-8}, 0.01, 2, 2.3e11, 100, 0), std::invalid_argument);
  EXPECT_THROW(film_line_contact({0.01, 2e-8}, -0.01, 2.3e11, 100, 1), std::invalid_argument);
}

TEST(LubricationRegime, FilmParameterAndRegimeFollowTheThresholds) {
  // lambda = h / sqrt(Rq1^2 + Rq2^2): 3-4-5 triangle
  EXPECT_DOUBLE_EQ(film_parameter(1e-6, 0.3e-6, 0.4e-6), 2.0);
  EXPECT_TRUE(std::isinf(film_parameter(1e-6, 0, 0)));
  EXPECT_EQ(regime_of(0.99), LubricationRegime::Boundary);
  EXPECT_EQ(regime_of(1.0), LubricationRegime::Mixed);
  EXPECT_EQ(regime_of(3.0), LubricationRegime::Mixed);
  EXPECT_EQ(regime_of(3.01), LubricationRegime::FullFilm);
  EXPECT_EQ(regime_of(1.5, {2, 4}), LubricationRegime::Boundary);
  EXPECT_THROW(regime_of(1, {3, 2}), std::invalid_argument);
  EXPECT_THROW(film_parameter(1e-6, -1e-7, 0), std::invalid_argument);
}

// The regime law (Johnson, Greenwood and Poon's load sharing with the cubic share across the mixed band,
// docs/lubrication-and-temperature.md §2): its limits are the case's boundary and full-film values exactly, it is
// continuous at both thresholds with a zero slope (C1), and in between the share is the cubic's (a closed form).
TEST(LubricationRegime, LoadSharingLawGivesTheBoundaryAndFullFilmValuesInTheirLimits) {
  RegimeCoefficients c;
  c.mu = {0.12, 0.07, 0.02};
  c.wear_factor = {1.0, 0.3, 0.05};
  // lambda -> 0 and up to lambda_mixed: the boundary values, to the bit
  for (const double lambda : {0.0, 1e-9, 0.5, 1.0}) {
    const RegimeFriction r = regime_friction(lambda, c);
    EXPECT_EQ(r.asperity_share, 1.0) << lambda;
    EXPECT_EQ(r.mu, 0.12) << lambda;
    EXPECT_EQ(r.wear_factor, 1.0) << lambda;
  }
  // lambda large (from lambda_full_film on, and smooth surfaces' infinite lambda): the full-film values
  for (const double lambda : {3.0, 3.5, 100.0, std::numeric_limits<double>::infinity()}) {
    const RegimeFriction r = regime_friction(lambda, c);
    EXPECT_EQ(r.asperity_share, 0.0) << lambda;
    EXPECT_EQ(r.mu, 0.02) << lambda;
    EXPECT_EQ(r.wear_factor, 0.05) << lambda;
  }
  // the middle of the mixed band: share 1/2, the mean of the two values (the cubic is symmetric)
  const RegimeFriction m = regime_friction(2.0, c);
  EXPECT_NEAR(m.asperity_share, 0.5, 1e-15);
  EXPECT_NEAR(m.mu, 0.07, 1e-15);
  EXPECT_NEAR(m.wear_factor, 0.525, 1e-15);
  // t = 1/4 of the band: 1 - 3/16 + 2/64 = 0.84375
  EXPECT_NEAR(asperity_load_share(1.5), 0.84375, 1e-15);
  EXPECT_NEAR(asperity_load_share(3.0, {2, 4}), 0.5, 1e-15);
  // C1 at both thresholds: the share's slope over 1e-6 of lambda is of order 1e-6
  for (const double at : {1.0, 3.0}) {
    EXPECT_LT(std::abs(asperity_load_share(at + 1e-6) - asperity_load_share(at - 1e-6)), 1e-11) << at;
  }
  // monotone: the asperities' share falls as the film thickens
  double previous = 1;
  for (double lambda = 0; lambda <= 4; lambda += 0.01) {
    const double f = asperity_load_share(lambda);
    EXPECT_LE(f, previous) << lambda;
    previous = f;
  }
  // the library's checks: lambda, thresholds, coefficients
  EXPECT_THROW(asperity_load_share(-0.1), std::invalid_argument);
  EXPECT_THROW(asperity_load_share(std::nan("")), std::invalid_argument);
  EXPECT_THROW(asperity_load_share(1, {3, 2}), std::invalid_argument);
  RegimeCoefficients bad = c;
  bad.mu[2] = -0.1;
  EXPECT_THROW(regime_friction(1, bad), std::invalid_argument);
  bad = c;
  bad.wear_factor[0] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(regime_friction(1, bad), std::invalid_argument);
}

}  // namespace
}  // namespace contact
