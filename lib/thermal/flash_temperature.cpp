// docs/lubrication-and-temperature.md §3
#include "lib/thermal/flash_temperature.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lib/numeric.h"

namespace contact {
namespace {

constexpr double kEulerGamma = 0.57721566490153286061;

void check_body(const ThermalBody& b) {
  for (const double v : {b.conductivity_W_per_m_K, b.density_kg_per_m3, b.specific_heat_J_per_kg_K})
    if (!(v > 0) || !std::isfinite(v))
      throw std::invalid_argument("flash temperature: conductivity, density and specific heat must be positive");
}

void check_speed(double v) {
  if (!(v > 0) || !std::isfinite(v))
    throw std::invalid_argument("flash temperature: a surface speed must be positive (a surface at rest under a "
                                "band source has no steady temperature), got " + std::to_string(v));
}

// exp(z) K0(z) for z >= 0: the Bessel function where it is representable, its asymptotic series beyond
// (four terms: relative error below 1e-9 for z >= 100)
double scaled_k0(double z) {
  if (z < 100) return std::exp(z) * std::cyl_bessel_k(0.0, z);
  const double r = 1 / (8 * z);
  return std::sqrt(kPi / (2 * z)) * (1 - r + 9 * r * r / 2 - 225 * r * r * r / 6);
}

// 16-point Gauss-Legendre nodes and weights on [-1, 1] (the positive half)
constexpr std::array<double, 8> kNodes = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                                          0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                                          0.9445750230732326, 0.9894009349916499};
constexpr std::array<double, 8> kWeights = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                            0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                            0.0622535239386479, 0.0271524594117541};

template <class F>
double gauss16(F&& f, double lo, double hi) {
  const double mid = (lo + hi) / 2, half = (hi - lo) / 2;
  double sum = 0;
  for (std::size_t k = 0; k < kNodes.size(); ++k)
    sum += kWeights[k] * (f(mid - half * kNodes[k]) + f(mid + half * kNodes[k]));
  return sum * half;
}

// adaptive bisection of gauss16 until the halves agree with the whole to kQuadratureRtol (or the depth
// runs out): the kernel varies on the scale 2 kappa / v, which may be far below a cell at high Peclet
constexpr double kQuadratureRtol = 1e-12;
template <class F>
double adaptive_gauss(F&& f, double lo, double hi, double whole, int depth) {
  const double mid = (lo + hi) / 2;
  const double left = gauss16(f, lo, mid), right = gauss16(f, mid, hi);
  if (depth == 0 || std::abs(left + right - whole) <= kQuadratureRtol * std::abs(left + right))
    return left + right;
  return adaptive_gauss(f, lo, mid, left, depth - 1) + adaptive_gauss(f, mid, hi, right, depth - 1);
}
template <class F>
double integrate(F&& f, double lo, double hi) {
  constexpr int kMaxDepth = 40;
  return adaptive_gauss(f, lo, hi, gauss16(f, lo, hi), kMaxDepth);
}

// the integral of G(d) over d in [0, L] (sign +1) or [-L, 0] (sign -1): G's logarithmic singularity at
// d = 0 removed by d = sign t^2
double integral_from_zero(double L, int sign, double speed, const ThermalBody& b) {
  return integrate([&](double t) { return 2 * t * moving_line_source_K_m_per_W(sign * t * t, speed, b); }, 0,
                   std::sqrt(L));
}

// the integral of G(d) over [d0, d1]
double cell_integral(double d0, double d1, double speed, const ThermalBody& b) {
  if (d0 < 0 && d1 > 0) return integral_from_zero(-d0, -1, speed, b) + integral_from_zero(d1, +1, speed, b);
  if (d0 == 0) return integral_from_zero(d1, +1, speed, b);
  if (d1 == 0) return integral_from_zero(-d0, -1, speed, b);
  return integrate([&](double d) { return moving_line_source_K_m_per_W(d, speed, b); }, d0, d1);
}

}  // namespace

double diffusivity_m2_per_s(const ThermalBody& b) {
  check_body(b);
  return b.conductivity_W_per_m_K / (b.density_kg_per_m3 * b.specific_heat_J_per_kg_K);
}

double jaeger_peclet(double speed_m_per_s, double half_length_m, const ThermalBody& b) {
  return speed_m_per_s * half_length_m / (2 * diffusivity_m2_per_s(b));
}

double band_max_rise_high_peclet_K(double q, double a, double speed, const ThermalBody& b) {
  return 2 * q * a / (b.conductivity_W_per_m_K * std::sqrt(kPi * jaeger_peclet(speed, a, b)));
}

double band_mean_rise_high_peclet_K(double q, double a, double speed, const ThermalBody& b) {
  return 2.0 / 3.0 * band_max_rise_high_peclet_K(q, a, speed, b);
}

double band_max_rise_low_peclet_K(double q, double a, double speed, const ThermalBody& b) {
  const double L = jaeger_peclet(speed, a, b);
  return 2 * q * a / (kPi * b.conductivity_W_per_m_K) * (1 - kEulerGamma + std::log(2 / L));
}

double moving_line_source_K_m_per_W(double d, double speed, const ThermalBody& b) {
  const double z = speed * std::abs(d) / (2 * diffusivity_m2_per_s(b));
  // behind the source (d < 0) exp(z) K0(z); ahead exp(-z) K0(z) = exp(-2z) exp(z) K0(z)
  const double e = d < 0 ? scaled_k0(z) : std::exp(-2 * z) * scaled_k0(z);
  return e / (kPi * b.conductivity_W_per_m_K);
}

Eigen::ArrayXXd surface_temperature_rise_K(const Grid& grid, const Eigen::ArrayXXd& flux, double speed,
                                           const ThermalBody& b) {
  check_body(b);
  check_speed(speed);
  if (flux.rows() != grid.nx || flux.cols() != grid.ny)
    throw std::invalid_argument("flash temperature: the heat flux must be nx x ny on the grid");
  const int nx = grid.nx;
  const double dx = grid.dx_m;
  // influence of cell k on the centre of cell i, a function of m = i - k (uniform cells): C[m + nx - 1]
  Eigen::ArrayXd C(2 * nx - 1);
  for (int m = -(nx - 1); m <= nx - 1; ++m) C(m + nx - 1) = cell_integral((m - 0.5) * dx, (m + 0.5) * dx, speed, b);
  // each strip: theta_i = sum_k C[i - k] q_k
  Eigen::ArrayXXd theta = Eigen::ArrayXXd::Zero(nx, grid.ny);
  for (int j = 0; j < grid.ny; ++j) {
    if ((flux.col(j) == 0).all()) continue;
    for (int k = 0; k < nx; ++k) {
      const double q = flux(k, j);
      if (q == 0) continue;
      for (int i = 0; i < nx; ++i) theta(i, j) += C(i - k + nx - 1) * q;
    }
  }
  return theta;
}

FlashTemperature flash_temperature(const Grid& grid, const Eigen::ArrayXXd& power, double v1, double v2,
                                   const ThermalBody& body1, const ThermalBody& body2, double half_length_m) {
  FlashTemperature f;
  f.peclet_body1 = jaeger_peclet(v1, half_length_m, body1);
  f.peclet_body2 = jaeger_peclet(v2, half_length_m, body2);
  const Eigen::ArrayXXd T1 = surface_temperature_rise_K(grid, power, v1, body1);
  const Eigen::ArrayXXd T2 = surface_temperature_rise_K(grid, power, v2, body2);
  const double M1 = T1.maxCoeff(), M2 = T2.maxCoeff();
  if (!(M1 > 0) || !(M2 > 0)) {  // no heat
    f.rise_K = Eigen::ArrayXXd::Zero(grid.nx, grid.ny);
    return f;
  }
  // Blok: beta M1 = (1 - beta) M2
  f.share_body1 = M2 / (M1 + M2);
  f.rise_K = f.share_body1 * T1;
  f.max_rise_K = M1 * M2 / (M1 + M2);
  Eigen::Index i = 0, j = 0;
  f.rise_K.maxCoeff(&i, &j);
  f.i_max = static_cast<int>(i);
  f.j_max = static_cast<int>(j);
  return f;
}

}  // namespace contact
