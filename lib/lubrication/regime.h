// The lubrication regime of a contact from its film parameter (docs/lubrication-and-temperature.md §2):
//   lambda = h_min / sqrt(Rq1^2 + Rq2^2)
// boundary below lambda_mixed, mixed up to lambda_full_film, full film above. The thresholds 1 and 3
// are the values of Hamrock, Schmid and Jacobson (Fundamentals of Machine Elements); a case may set
// its own. The friction coefficient and the wear coefficient's factor of each regime are the user's
// (no default: they depend on the lubricant, its additives and the surfaces).
//
// The regime law (docs/lubrication-and-temperature.md §2a): Johnson, Greenwood and Poon's load sharing (A simple
// theory of asperity contact in elastohydrodynamic lubrication, Wear 19, 1972): the load is carried partly by the
// asperities, a share f_a, and partly by the film; the asperities' share has the boundary friction mu_b, the
// film's the full-film traction mu_f, and only the asperities' share wears (Archard's law on the asperity load):
//   mu(lambda)          = f_a mu_b + (1 - f_a) mu_f
//   wear_factor(lambda) = f_a w_b + (1 - f_a) w_f
// with mu_b, w_b the case's boundary values and mu_f, w_f its full-film ones. The share f_a is 1 up to
// lambda_mixed (boundary: the asperities carry the load), 0 from lambda_full_film on (full film) and between them
// the C1 cubic 1 - 3t^2 + 2t^3, t = (lambda - lambda_mixed)/(lambda_full_film - lambda_mixed): a Stribeck-type
// transition across Hamrock, Schmid and Jacobson's mixed band, its shape an ASSUMPTION (a Greenwood-Tripp asperity
// pressure would need the asperities' density and radius, which a case does not give). Continuous in lambda, so a
// life's wear rate stays continuous as the film changes.
#pragma once

#include <array>
#include <string>

namespace contact {

enum class LubricationRegime { Boundary = 0, Mixed = 1, FullFilm = 2 };

// "boundary", "mixed", "full-film"
const char* to_string(LubricationRegime r);

constexpr double kLambdaMixed = 1.0;     // boundary below (Hamrock, Schmid and Jacobson)
constexpr double kLambdaFullFilm = 3.0;  // full film above (same source)

struct RegimeThresholds {
  double lambda_mixed = kLambdaMixed;         // > 0
  double lambda_full_film = kLambdaFullFilm;  // > lambda_mixed
};

// Per regime, indexed by LubricationRegime
struct RegimeCoefficients {
  std::array<double, 3> mu{};           // friction coefficient in the regime
  std::array<double, 3> wear_factor{};  // factor on the wear law's coefficient in the regime
};

// Johnson, Greenwood and Poon's asperity load share f_a(lambda) of the law above: 1 for lambda <= lambda_mixed,
// 0 for lambda >= lambda_full_film (and infinite lambda), the cubic between. Throws std::invalid_argument for a
// negative or NaN lambda or thresholds out of order.
double asperity_load_share(double lambda, const RegimeThresholds& t = {});

// what the law gives at one lambda
struct RegimeFriction {
  double asperity_share = 1;  // f_a
  double mu = 0;              // f_a mu_b + (1 - f_a) mu_f
  double wear_factor = 1;     // f_a w_b + (1 - f_a) w_f
};
// the law at lambda with c's boundary and full-film entries (the mixed ones are the regime's reported values, not
// the law's). Throws std::invalid_argument as asperity_load_share, and for a mu outside [0, 10] or a wear factor
// negative or not finite.
RegimeFriction regime_friction(double lambda, const RegimeCoefficients& c, const RegimeThresholds& t = {});

// the composite roughness sqrt(Rq1^2 + Rq2^2); lambda = h_min / it (infinite for smooth surfaces).
// Throws std::invalid_argument for a negative or non-finite roughness or film.
double film_parameter(double h_min_m, double Rq1_m, double Rq2_m);

// the regime of lambda: lambda < lambda_mixed boundary, lambda <= lambda_full_film mixed, else full film.
// Throws std::invalid_argument for thresholds out of order.
LubricationRegime regime_of(double lambda, const RegimeThresholds& t = {});

}  // namespace contact
