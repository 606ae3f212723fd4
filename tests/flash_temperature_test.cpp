// The flash temperature (lib/thermal/flash_temperature.h): the per-strip numerical solution of a uniform
// band source against Jaeger's closed forms in the high- and low-Peclet limits, on three grids with the
// observed order, and Blok's partition (docs/lubrication-and-temperature.md §3).
#include "lib/thermal/flash_temperature.h"
#include "lib/grid.h"
#include "lib/numeric.h"
#include "lib/patch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <stdexcept>

namespace contact {
namespace {

const ThermalBody kSteelLike{46, 7800, 460};  // numbers for the test only: kappa = 1.28e-5 m^2/s

// a strip covering exactly the band |x| < a, nx cells, uniform flux q
struct Band {
  Grid grid;
  Eigen::ArrayXXd flux;
};
Band uniform_band(double a, int nx, double q) {
  Band b{make_grid(a, a, {nx, 1}), Eigen::ArrayXXd::Constant(nx, 1, q)};
  return b;
}

// speed giving Jaeger's Peclet number L on half-length a
double speed_for_peclet(double L, double a, const ThermalBody& b) { return 2 * L * diffusivity_m2_per_s(b) / a; }

// High Peclet (L = 1e6, where the 2D solution's departure from 1D conduction, O(1/L), is below 1e-6): the
// maximum is 2 q a / (K sqrt(pi L)) at the trailing edge. The cell centres miss the edge by dx/2, and
// theta ~ sqrt(a - x) there, so the largest centre value is low by dx/(8a) to first order: order 1.
// The mean over the band, 2/3 of the maximum, converges at the midpoint rule's order on sqrt(a - x), 1.5.
TEST(FlashTemperature, UniformBandHighPecletConvergesToJaegerOnThreeGrids) {
  const double a = 1e-3, q = 1e8, L = 1e6;
  const double V = speed_for_peclet(L, a, kSteelLike);
  const double theta_max = band_max_rise_high_peclet_K(q, a, V, kSteelLike);
  EXPECT_NEAR(theta_max, 2 * q * a / (46 * std::sqrt(kPi * L)), 1e-9 * theta_max);
  const std::array<int, 3> grids{20, 40, 80};
  std::array<double, 3> err_max{}, err_mean{};
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const Band band = uniform_band(a, grids[g], q);
    const Eigen::ArrayXXd theta = surface_temperature_rise_K(band.grid, band.flux, V, kSteelLike);
    err_max[g] = std::abs(theta.maxCoeff() / theta_max - 1);
    err_mean[g] = std::abs(theta.mean() / (2.0 / 3.0 * theta_max) - 1);
    // first-order model of the sampling error of the maximum
    EXPECT_NEAR(err_max[g], band.grid.dx_m / (8 * a), 0.1 * band.grid.dx_m / (8 * a)) << "nx " << grids[g];
    EXPECT_EQ(theta(0, 0), theta.maxCoeff());  // at the trailing edge (x = -a, cell 0)
  }
  for (std::size_t g = 0; g + 1 < grids.size(); ++g) {
    const double order_max = std::log2(err_max[g] / err_max[g + 1]);
    const double order_mean = std::log2(err_mean[g] / err_mean[g + 1]);
    EXPECT_NEAR(order_max, 1.0, 0.1) << "grids " << grids[g] << ", " << grids[g + 1];
    EXPECT_NEAR(order_mean, 1.5, 0.1) << "grids " << grids[g] << ", " << grids[g + 1];
  }
  EXPECT_LT(err_max[2], 0.004);
  for (std::size_t g = 0; g < grids.size(); ++g) std::printf("nx %d: max err %.4e, mean err %.4e\n", grids[g], err_max[g], err_mean[g]);
}

// Low Peclet (L = 1e-6): the maximum is (2 q a / (pi K)) (1 - gamma + ln(2/L)) at x = 0. With an even nx the
// nearest centres are at +-dx/2, where theta is lower by (q / (pi K a)) (dx/2)^2 (theta'' = -2q/(pi K a) at
// the centre): order 2. The limit's own error there is O(L (dx/a) ln L), odd in x (the convection's first
// order): at L = 1e-4 it was already 15 % of the sampling error on 80 cells, at L = 1e-6 it is below 1 %.
TEST(FlashTemperature, UniformBandLowPecletConvergesToJaegerOnThreeGrids) {
  const double a = 1e-3, q = 1e8, L = 1e-6;
  const double V = speed_for_peclet(L, a, kSteelLike);
  const double theta_max = band_max_rise_low_peclet_K(q, a, V, kSteelLike);
  const std::array<int, 3> grids{20, 40, 80};
  std::array<double, 3> err{};
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const Band band = uniform_band(a, grids[g], q);
    const Eigen::ArrayXXd theta = surface_temperature_rise_K(band.grid, band.flux, V, kSteelLike);
    err[g] = std::abs(theta.maxCoeff() / theta_max - 1);
    const double dx = band.grid.dx_m;
    const double model = q / (kPi * 46 * a) * (dx / 2) * (dx / 2) / theta_max;
    EXPECT_NEAR(err[g], model, 0.1 * model) << "nx " << grids[g];
  }
  for (std::size_t g = 0; g + 1 < grids.size(); ++g)
    EXPECT_NEAR(std::log2(err[g] / err[g + 1]), 2.0, 0.15) << "grids " << grids[g] << ", " << grids[g + 1];
  EXPECT_LT(err[2], 6e-6);
  for (std::size_t g = 0; g < grids.size(); ++g) std::printf("nx %d: max err %.4e\n", grids[g], err[g]);
}

// A given distribution: the Hertzian semi-ellipse q0 sqrt(1 - x^2/a^2) (a constant mu times the pressure
// at a constant slip speed) at high Peclet (L = 1e6), against the 1D conduction solution
// theta(x) = (1/K) sqrt(kappa / (pi v)) * 2 * integral_0^sqrt(a - x) q(x + t^2) dt at the same centres, that
// integral by 4000 panels of 16-point Gauss-Legendre (its endpoint singularity, sqrt(a - s), leaves an error
// below 1e-8). The cells carry the semi-ellipse's exact cell means (lib/patch.h semi_ellipse_integral);
// the error is that of a piecewise-constant flux. It is largest at the trailing cell: there q rises as
// sqrt(x + a) across the cell, by O(sqrt(dx/a)) of q0, while the kernel weighs the cell's near half by
// 1/sqrt(d); the error is O(dx), order 1 (measured, sup over the centres relative to the maximum:
// 1.141e-2, 5.670e-3, 2.820e-3 on 20, 40, 80 cells).
TEST(FlashTemperature, SemiEllipticBandHighPecletConvergesToOneDimensionalSolution) {
  const double a = 1e-3, q0 = 1e8, L = 1e6;
  const double V = speed_for_peclet(L, a, kSteelLike), kappa = diffusivity_m2_per_s(kSteelLike);
  const auto reference = [&](double x) {
    const double T = std::sqrt(a - x);
    constexpr int kPanels = 4000;
    // 16-point Gauss-Legendre on each panel (nodes and weights of lib/thermal, repeated here as data)
    static const double n[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                                0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
    static const double w[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                                0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
    const auto q = [&](double t) {
      const double u = (x + t * t) / a;
      return q0 * std::sqrt(std::max(0.0, 1 - u * u));
    };
    double sum = 0;
    for (int p = 0; p < kPanels; ++p) {
      const double lo = T * p / kPanels, hi = T * (p + 1) / kPanels, mid = (lo + hi) / 2, half = (hi - lo) / 2;
      for (int k = 0; k < 8; ++k) sum += w[k] * half * (q(mid - half * n[k]) + q(mid + half * n[k]));
    }
    return 2 * sum * std::sqrt(kappa / (kPi * V)) / 46;
  };
  const std::array<int, 3> grids{20, 40, 80};
  std::array<double, 3> err{};
  for (std::size_t g = 0; g < grids.size(); ++g) {
    const Grid grid = make_grid(a, a, {grids[g], 1});
    Eigen::ArrayXXd flux(grids[g], 1);
    for (int i = 0; i < grids[g]; ++i) {
      const double u0 = grid.x_edge(i) / a, u1 = grid.x_edge(i + 1) / a;
      flux(i, 0) = q0 * (semi_ellipse_integral(u1) - semi_ellipse_integral(u0)) / (u1 - u0);
    }
    const Eigen::ArrayXXd theta = surface_temperature_rise_K(grid, flux, V, kSteelLike);
    double worst = 0, peak = 0;
    int at = -1;
    for (int i = 0; i < grids[g]; ++i) {
      const double r = reference(grid.x_m(i));
      if (std::abs(theta(i, 0) - r) > worst) worst = std::abs(theta(i, 0) - r), at = i;
      peak = std::max(peak, r);
    }
    err[g] = worst / peak;
    EXPECT_EQ(at, 0) << "nx " << grids[g];  // the largest error at the trailing cell
  }
  for (std::size_t g = 0; g < grids.size(); ++g) std::printf("nx %d: sup err %.4e\n", grids[g], err[g]);
  for (std::size_t g = 0; g + 1 < grids.size(); ++g)
    EXPECT_NEAR(std::log2(err[g] / err[g + 1]), 1.0, 0.1) << "grids " << grids[g] << ", " << grids[g + 1];
}

// The kernel far behind the source tends to 1D conduction: G(d) -> sqrt(kappa / (pi v |d|)) / K
TEST(FlashTemperature, MovingLineSourceTendsToOneDimensionalConductionBehind) {
  const double V = 10, kappa = diffusivity_m2_per_s(kSteelLike);
  for (const double d : {-1e-3, -1e-2}) {  // z = V |d| / (2 kappa) = 390 and 3900: asymptotic branch
    const double one_d = std::sqrt(kappa / (kPi * V * -d)) / 46;
    const double z = V * -d / (2 * kappa);
    EXPECT_NEAR(moving_line_source_K_m_per_W(d, V, kSteelLike) / one_d, 1 - 1 / (8 * z), 1e-5);
  }
  // ahead of the source the material is cold
  EXPECT_LT(moving_line_source_K_m_per_W(1e-3, V, kSteelLike), 1e-100);
  // the Bessel branch and the series branch meet at z = 100 (continuity to the series' accuracy)
  const double d100 = -100 * 2 * kappa / V;
  EXPECT_NEAR(moving_line_source_K_m_per_W(d100 * (1 - 1e-12), V, kSteelLike) /
                  moving_line_source_K_m_per_W(d100 * (1 + 1e-12), V, kSteelLike), 1, 1e-8);
}

// Blok: the maxima of the two bodies' temperatures are equal; for identical bodies at equal speeds each
// takes half of the heat
TEST(FlashTemperature, BlokPartitionEqualisesTheMaxima) {
  const double a = 1e-3, q = 1e8;
  const Band band = uniform_band(a, 40, q);
  const ThermalBody other{20, 4000, 700};
  const double v1 = 3, v2 = 5;
  const FlashTemperature same = flash_temperature(band.grid, band.flux, v1, v1, kSteelLike, kSteelLike, a);
  const double alone = surface_temperature_rise_K(band.grid, band.flux, v1, kSteelLike).maxCoeff();
  EXPECT_DOUBLE_EQ(same.share_body1, 0.5);
  EXPECT_NEAR(same.max_rise_K, alone / 2, 1e-12 * alone);
  const FlashTemperature f = flash_temperature(band.grid, band.flux, v1, v2, kSteelLike, other, a);
  const double M1 = surface_temperature_rise_K(band.grid, band.flux, v1, kSteelLike).maxCoeff();
  const double M2 = surface_temperature_rise_K(band.grid, band.flux, v2, other).maxCoeff();
  EXPECT_NEAR(f.share_body1 * M1, (1 - f.share_body1) * M2, 1e-12 * M1);
  EXPECT_NEAR(f.max_rise_K, f.rise_K.maxCoeff(), 1e-12 * M1);
  EXPECT_NEAR(f.peclet_body1, v1 * a / (2 * diffusivity_m2_per_s(kSteelLike)), 1e-12);
  EXPECT_THROW(flash_temperature(band.grid, band.flux, 0, v2, kSteelLike, other, a), std::invalid_argument);
  EXPECT_DOUBLE_EQ(blok_scuffing_margin_K(80, 70, 200), 50);
}

}  // namespace
}  // namespace contact
