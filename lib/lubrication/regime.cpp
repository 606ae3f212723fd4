// docs/lubrication-and-temperature.md §2
#include "lib/lubrication/regime.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace contact {

const char* to_string(LubricationRegime r) {
  switch (r) {
    case LubricationRegime::Boundary: return "boundary";
    case LubricationRegime::Mixed: return "mixed";
    case LubricationRegime::FullFilm: return "full-film";
  }
  return "?";
}

double film_parameter(double h_min_m, double Rq1_m, double Rq2_m) {
  for (const double v : {h_min_m, Rq1_m, Rq2_m})
    if (!(v >= 0) || !std::isfinite(v))
      throw std::invalid_argument("film parameter: the film and the roughnesses must be >= 0 and finite");
  const double composite_m = std::hypot(Rq1_m, Rq2_m);
  return composite_m > 0 ? h_min_m / composite_m : std::numeric_limits<double>::infinity();
}

LubricationRegime regime_of(double lambda, const RegimeThresholds& t) {
  if (!(t.lambda_mixed > 0) || !(t.lambda_full_film > t.lambda_mixed) || !std::isfinite(t.lambda_full_film))
    throw std::invalid_argument("lubrication regime: need 0 < lambda_mixed < lambda_full_film");
  if (lambda < t.lambda_mixed) return LubricationRegime::Boundary;
  if (lambda <= t.lambda_full_film) return LubricationRegime::Mixed;
  return LubricationRegime::FullFilm;
}

double asperity_load_share(double lambda, const RegimeThresholds& t) {
  regime_of(1.0, t);  // the thresholds' check
  if (!(lambda >= 0)) throw std::invalid_argument("asperity load share: lambda must be >= 0");
  if (lambda <= t.lambda_mixed) return 1;
  if (lambda >= t.lambda_full_film) return 0;
  const double s = (lambda - t.lambda_mixed) / (t.lambda_full_film - t.lambda_mixed);
  return 1 - s * s * (3 - 2 * s);
}

RegimeFriction regime_friction(double lambda, const RegimeCoefficients& c, const RegimeThresholds& t) {
  constexpr int b = static_cast<int>(LubricationRegime::Boundary), f = static_cast<int>(LubricationRegime::FullFilm);
  for (const int i : {b, f}) {
    if (!(c.mu[i] >= 0 && c.mu[i] <= 10))
      throw std::invalid_argument("regime friction: the boundary and full-film mu must be in [0, 10]");
    if (!(c.wear_factor[i] >= 0) || !std::isfinite(c.wear_factor[i]))
      throw std::invalid_argument("regime friction: the boundary and full-film wear factors must be >= 0 and finite");
  }
  RegimeFriction r;
  r.asperity_share = asperity_load_share(lambda, t);
  r.mu = r.asperity_share * c.mu[b] + (1 - r.asperity_share) * c.mu[f];
  r.wear_factor = r.asperity_share * c.wear_factor[b] + (1 - r.asperity_share) * c.wear_factor[f];
  return r;
}

}  // namespace contact
