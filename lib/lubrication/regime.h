// The lubrication regime of a contact from its film parameter (docs/lubrication-and-temperature.md §2):
//   lambda = h_min / sqrt(Rq1^2 + Rq2^2)
// boundary below lambda_mixed, mixed up to lambda_full_film, full film above. The thresholds 1 and 3
// are the values of Hamrock, Schmid and Jacobson (Fundamentals of Machine Elements); a case may set
// its own. The friction coefficient and the wear coefficient's factor of each regime are the user's
// (no default: they depend on the lubricant, its additives and the surfaces).
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

// the composite roughness sqrt(Rq1^2 + Rq2^2); lambda = h_min / it (infinite for smooth surfaces).
// Throws std::invalid_argument for a negative or non-finite roughness or film.
double film_parameter(double h_min_m, double Rq1_m, double Rq2_m);

// the regime of lambda: lambda < lambda_mixed boundary, lambda <= lambda_full_film mixed, else full film.
// Throws std::invalid_argument for thresholds out of order.
LubricationRegime regime_of(double lambda, const RegimeThresholds& t = {});

}  // namespace contact
