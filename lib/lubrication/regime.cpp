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

}  // namespace contact
