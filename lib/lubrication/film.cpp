// docs/lubrication-and-temperature.md §1
#include "lib/lubrication/film.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace contact {
namespace {

void check_positive(double v, const char* what) {
  if (!(v > 0) || !std::isfinite(v))
    throw std::invalid_argument(std::string("film thickness: ") + what + " must be positive and finite, got " +
                                std::to_string(v));
}

void check_inputs(const Lubricant& lub, double R_m, double E_prime_Pa, double load, double u) {
  check_positive(lub.viscosity_Pa_s, "viscosity_Pa_s");
  check_positive(lub.pressure_viscosity_1_per_Pa, "pressure_viscosity_1_per_Pa");  // piezoviscous formulas
  check_positive(R_m, "the reduced radius");
  check_positive(E_prime_Pa, "the reduced modulus");
  check_positive(load, "the load");
  check_positive(u, "the entrainment speed");
}

}  // namespace

double hamrock_dowson_ellipticity(double Rx_m, double Ry_m) { return 1.0339 * std::pow(Ry_m / Rx_m, 0.636); }

double hamrock_dowson_H_min(const FilmGroups& g, double k) {
  return 3.63 * std::pow(g.U, 0.68) * std::pow(g.G, 0.49) * std::pow(g.W, -0.073) * (1 - std::exp(-0.68 * k));
}

double hamrock_dowson_H_central(const FilmGroups& g, double k) {
  return 2.69 * std::pow(g.U, 0.67) * std::pow(g.G, 0.53) * std::pow(g.W, -0.067) *
         (1 - 0.61 * std::exp(-0.73 * k));
}

double dowson_higginson_H_min(const FilmGroups& g) {
  return 2.65 * std::pow(g.U, 0.70) * std::pow(g.G, 0.54) * std::pow(g.W, -0.13);
}

double dowson_toyoda_H_central(const FilmGroups& g) {
  return 3.06 * std::pow(g.U, 0.69) * std::pow(g.G, 0.56) * std::pow(g.W, -0.10);
}

FilmThickness film_point_contact(const Lubricant& lub, double Rx_m, double k, double E_prime_Pa, double load_N,
                                 double u_m_per_s) {
  check_inputs(lub, Rx_m, E_prime_Pa, load_N, u_m_per_s);
  check_positive(k, "the ellipticity k");
  FilmThickness f;
  f.groups = {lub.viscosity_Pa_s * u_m_per_s / (E_prime_Pa * Rx_m), lub.pressure_viscosity_1_per_Pa * E_prime_Pa,
              load_N / (E_prime_Pa * Rx_m * Rx_m)};
  f.ellipticity_k = k;
  f.h_min_m = Rx_m * hamrock_dowson_H_min(f.groups, k);
  f.h_central_m = Rx_m * hamrock_dowson_H_central(f.groups, k);
  return f;
}

FilmThickness film_line_contact(const Lubricant& lub, double R_m, double E_prime_Pa, double load_N_per_m,
                                double u_m_per_s) {
  check_inputs(lub, R_m, E_prime_Pa, load_N_per_m, u_m_per_s);
  FilmThickness f;
  f.groups = {lub.viscosity_Pa_s * u_m_per_s / (E_prime_Pa * R_m), lub.pressure_viscosity_1_per_Pa * E_prime_Pa,
              load_N_per_m / (E_prime_Pa * R_m)};
  f.h_min_m = R_m * dowson_higginson_H_min(f.groups);
  f.h_central_m = R_m * dowson_toyoda_H_central(f.groups);
  return f;
}

}  // namespace contact
