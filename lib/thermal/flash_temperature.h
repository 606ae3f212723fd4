// The flash temperature of a rolling-sliding contact: the surface temperature rise from the frictional
// power density, each body a half-space whose surface moves through a steady heat source
// (docs/lubrication-and-temperature.md §3).
//
// Per strip (a grid row along the rolling direction x) the lateral conduction is neglected: the strip is
// Jaeger's band source. A line source of unit strength (1 W/m) at x = s on the surface of an insulated
// half-space whose material passes at speed v in the -x direction (the contact's frame, docs/physics.md §1)
// raises the surface temperature at x by
//   G(d) = exp(-v d / (2 kappa)) K0(v |d| / (2 kappa)) / (pi K),   d = x - s,
// K the conductivity, kappa = K / (rho c) the diffusivity, K0 the modified Bessel function (Rosenthal's
// moving line source). The heat flux is constant over each cell (the cell's mean), so a strip's
// temperature is the convolution of the flux with G integrated over the cells, exact for a piecewise
// constant flux; it is evaluated at the cell centres.
// Closed forms for the uniform band of intensity q over |x| < a, Jaeger's Peclet number L = v a / (2 kappa):
//   high L (1D conduction into depth):  theta_max = 2 q a / (K sqrt(pi L))  at the trailing edge x = -a,
//                                       theta_mean = 2/3 theta_max
//   low L (K0(z) ~ -ln(z/2) - gamma):   theta_max = (2 q a / (pi K)) (1 - gamma + ln(2 / L))  at x = 0
// Partition between the bodies: Blok's rule, the fraction of the heat into each body chosen so that the
// maxima of their surface temperatures are equal.
#pragma once

#include <Eigen/Core>

#include "lib/grid.h"

namespace contact {

struct ThermalBody {
  double conductivity_W_per_m_K = 0;   // K, > 0
  double density_kg_per_m3 = 0;        // rho, > 0
  double specific_heat_J_per_kg_K = 0;  // c, > 0
};

// kappa = K / (rho c); throws std::invalid_argument for a non-positive or non-finite property
double diffusivity_m2_per_s(const ThermalBody& b);

// Jaeger's Peclet number L = v a / (2 kappa) of a band of half-length a
double jaeger_peclet(double speed_m_per_s, double half_length_m, const ThermalBody& b);

// the closed forms above (uniform band, heat all into this body)
double band_max_rise_high_peclet_K(double flux_W_per_m2, double half_length_m, double speed_m_per_s,
                                   const ThermalBody& b);
double band_mean_rise_high_peclet_K(double flux_W_per_m2, double half_length_m, double speed_m_per_s,
                                    const ThermalBody& b);
double band_max_rise_low_peclet_K(double flux_W_per_m2, double half_length_m, double speed_m_per_s,
                                  const ThermalBody& b);

// G(d) above, in K per W/m; speed > 0, d != 0
double moving_line_source_K_m_per_W(double d_m, double speed_m_per_s, const ThermalBody& b);

// The surface temperature rise (nx x ny, column j = strip j, at the cell centres) of one body taking all of
// the heat flux (nx x ny, W/m^2, mean over each cell), its surface passing at speed > 0. Throws
// std::invalid_argument for a flux of another shape than the grid's, a speed <= 0 or a bad property.
Eigen::ArrayXXd surface_temperature_rise_K(const Grid& grid, const Eigen::ArrayXXd& flux_W_per_m2,
                                           double speed_m_per_s, const ThermalBody& b);

struct FlashTemperature {
  Eigen::ArrayXXd rise_K;       // (nx x ny) the surface temperature rise of body 1 under its share of the heat
  double max_rise_K = 0;        // the maximum, equal for both bodies by Blok's rule
  int i_max = -1, j_max = -1;   // the cell of body 1's maximum (-1: no heat)
  double share_body1 = 0.5;     // the fraction of the heat into body 1
  double peclet_body1 = 0, peclet_body2 = 0;  // Jaeger's L of each body on the half-length a_m given
};

// Blok's partition of the frictional power density between body 1 (surface speed v1 > 0) and body 2
// (v2 > 0): each body's rise under all of the heat, T_k, with maxima M_k; body 1 takes M2 / (M1 + M2)
// of it, so that both maxima are M1 M2 / (M1 + M2). half_length_m (the contact's a) only labels the
// Peclet numbers. Without heat (zero flux) the rise is zero and the share 1/2.
FlashTemperature flash_temperature(const Grid& grid, const Eigen::ArrayXXd& power_W_per_m2, double v1_m_per_s,
                                   double v2_m_per_s, const ThermalBody& body1, const ThermalBody& body2,
                                   double half_length_m);

// Blok's criterion: scuffing when the contact temperature (bulk + flash) reaches the critical temperature;
// the margin is critical - (bulk + flash), in K (negative: past the criterion)
constexpr double blok_scuffing_margin_K(double bulk_temperature_C, double flash_rise_K,
                                        double critical_temperature_C) {
  return critical_temperature_C - (bulk_temperature_C + flash_rise_K);
}

}  // namespace contact
