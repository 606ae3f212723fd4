// The film thickness of an elastohydrodynamic (EHL) contact from published regression formulas
// (docs/lubrication-and-temperature.md §1): Hamrock and Dowson's for an elliptical point contact,
// Dowson and Higginson's (minimum) with Dowson and Toyoda's (central) for a line contact.
//
// Dimensionless groups, with R the reduced radius along the rolling direction x:
//   U = eta0 u / (E' R)      speed (u: entrainment speed, the mean surface speed (u1 + u2)/2)
//   G = alpha E'             material
//   W = w / (E' R^2)         load, point contact (w in N)
//   W = w / (E' R)           load, line contact (w in N/m)
//   H = h / R                film thickness
// with E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) = 2 E* (E* of lib/elastic.h).
// Point contact (Hamrock and Dowson 1977), k the ellipticity D_y/D_x (lateral over rolling axis):
//   H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k))
//   H_c   = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k))
// Line contact: H_min = 2.65 U^0.70 G^0.54 W^-0.13 (Dowson and Higginson),
//               H_c   = 3.06 U^0.69 G^0.56 W^-0.10 (Dowson and Toyoda).
// Isothermal, Newtonian, fully flooded, smooth surfaces; the point formulas were fitted for k in [1, 8].
#pragma once

namespace contact {

struct Lubricant {
  double viscosity_Pa_s = 0;               // eta0: dynamic viscosity at the inlet (bulk) temperature, > 0
  double pressure_viscosity_1_per_Pa = 0;  // alpha: Barus pressure-viscosity coefficient, > 0
};

// Hamrock and Dowson's fitted range of the ellipticity
constexpr double kHamrockDowsonMinEllipticity = 1.0;
constexpr double kHamrockDowsonMaxEllipticity = 8.0;

struct FilmGroups {
  double U = 0, G = 0, W = 0;  // speed, material and load groups (W per the contact's kind, above)
};

struct FilmThickness {
  FilmGroups groups;
  double ellipticity_k = 0;  // point contact: D_y/D_x; line contact: 0
  double h_min_m = 0;        // minimum film thickness
  double h_central_m = 0;    // central film thickness
};

// E' = 2 E*: the reduced modulus of the EHL literature, from E* (lib/elastic.h effective_modulus_Pa)
constexpr double ehl_reduced_modulus_Pa(double effective_modulus_Pa) { return 2 * effective_modulus_Pa; }

// Brewe and Hamrock's approximation of the ellipticity from the reduced radii, k = 1.0339 (Ry/Rx)^0.636
// (Hamrock and Dowson's 1977 paper rounds it to 1.03 (Ry/Rx)^0.64); the contact's own b/a where known
double hamrock_dowson_ellipticity(double Rx_m, double Ry_m);

// the dimensionless film thicknesses of the formulas above, from their groups
double hamrock_dowson_H_min(const FilmGroups& g, double ellipticity_k);
double hamrock_dowson_H_central(const FilmGroups& g, double ellipticity_k);
double dowson_higginson_H_min(const FilmGroups& g);
double dowson_toyoda_H_central(const FilmGroups& g);

// An elliptical point contact: Rx_m the reduced radius along rolling (1/Rx = 1/Rx1 + 1/Rx2), k its
// ellipticity (the Hertz ellipse's b/a, lateral over rolling semi-axis), load in N. Throws
// std::invalid_argument for a non-positive radius, modulus, load, speed, viscosity or alpha.
FilmThickness film_point_contact(const Lubricant& lub, double Rx_m, double ellipticity_k, double E_prime_Pa,
                                 double normal_load_N, double entrainment_m_per_s);
// A line contact: load per unit length in N/m. Same checks.
FilmThickness film_line_contact(const Lubricant& lub, double R_m, double E_prime_Pa, double load_N_per_m,
                                double entrainment_m_per_s);

}  // namespace contact
