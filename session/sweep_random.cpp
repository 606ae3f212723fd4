#include "session/sweep_random.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "lib/number.h"

namespace session {

using contact::round_trip;

// ---- generator and inverse CDFs ----

namespace {
constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ull;  // SplitMix64's increment
}  // namespace

std::uint64_t splitmix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

std::uint64_t splitmix64_stream(std::uint64_t seed, std::uint64_t i) { return splitmix64(seed + (i + 1) * kGoldenGamma); }

double unit_uniform(std::uint64_t seed, std::uint64_t i, std::uint64_t input) {
  const std::uint64_t h = splitmix64_stream(splitmix64_stream(seed, i), input);
  return (static_cast<double>(h >> 11) + 0.5) / kTwoPow53;  // (k + 1/2) 2^-53: in (0, 1)
}

double normal_quantile(double p) {
  // P. J. Acklam's algorithm: rational approximations in a central region and two tails
  static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                             1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                             6.680131188771972e+01,  -1.328068155288572e+01};
  static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                             -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                             3.754408661907416e+00};
  constexpr double kLow = 0.02425;
  if (!(p > 0 && p < 1)) throw std::invalid_argument("normal_quantile: p must be in (0, 1), got " + round_trip(p));
  const auto tail = [&](double q) {
    return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
  };
  if (p < kLow) return tail(std::sqrt(-2 * std::log(p)));
  if (p > 1 - kLow) return -tail(std::sqrt(-2 * std::log1p(-p)));
  const double q = p - 0.5, r = q * q;
  return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
         (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
}

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double quantile(const RandomInput& in, double u) {
  switch (in.distribution) {
    case Distribution::Uniform: return in.min + (in.max - in.min) * u;
    case Distribution::Normal: return in.mean + in.sd * normal_quantile(u);
    case Distribution::LogNormal: return in.median * std::exp(in.sigma_ln * normal_quantile(u));
    case Distribution::TruncatedNormal: {
      const double lo = normal_cdf((in.min - in.mean) / in.sd), hi = normal_cdf((in.max - in.mean) / in.sd);
      const double p = lo + (hi - lo) * u;
      const double x = in.mean + in.sd * normal_quantile(std::clamp(p, 1e-300, 1 - 1e-16));
      return std::clamp(x, in.min, in.max);  // the approximation's last bits never leave the bounds
    }
  }
  throw std::logic_error("quantile: unknown distribution");
}

namespace {
// the order of the sample's values, ties by their index: rank r is x[order[r]]
std::vector<std::size_t> order_of(const std::vector<double>& x) {
  std::vector<std::size_t> o(x.size());
  std::iota(o.begin(), o.end(), std::size_t{0});
  std::sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b] || (x[a] == x[b] && a < b); });
  return o;
}
std::vector<double> ranks_of(const std::vector<double>& x) {
  const std::vector<std::size_t> o = order_of(x);
  std::vector<double> r(x.size());
  for (std::size_t k = 0; k < o.size(); ++k) r[o[k]] = static_cast<double>(k);
  return r;
}
double pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n, mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return sab / std::sqrt(saa * sbb);
}
}  // namespace

double spearman(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size() || a.size() < 2) throw std::invalid_argument("spearman: two samples of one length >= 2");
  return pearson(ranks_of(a), ranks_of(b));
}

void iman_conover(std::vector<std::vector<double>>& x, const std::vector<std::vector<double>>& target) {
  const std::size_t n = x.size(), k = target.size();
  if (n <= k) throw std::invalid_argument("iman_conover: needs more samples (" + std::to_string(n) + ") than inputs (" + std::to_string(k) + ")");
  Eigen::MatrixXd C(k, k), R(n, k);
  for (std::size_t a = 0; a < k; ++a)
    for (std::size_t b = 0; b < k; ++b) C(a, b) = target[a][b];
  // scores in the ranks of each column
  std::vector<double> score(n);
  for (std::size_t r = 0; r < n; ++r) score[r] = normal_quantile((r + 1.0) / (n + 1.0));
  std::vector<std::vector<double>> column(k, std::vector<double>(n));
  for (std::size_t a = 0; a < k; ++a) {
    for (std::size_t i = 0; i < n; ++i) column[a][i] = x[i][a];
    const std::vector<std::size_t> o = order_of(column[a]);
    for (std::size_t r = 0; r < n; ++r) R(static_cast<Eigen::Index>(o[r]), static_cast<Eigen::Index>(a)) = score[r];
  }
  // the scores' own correlation T, removed (L_T^-1) and the target's put in (L_C)
  Eigen::MatrixXd centred = R.rowwise() - R.colwise().mean();
  Eigen::MatrixXd T = centred.transpose() * centred;
  const Eigen::VectorXd sd = T.diagonal().cwiseSqrt();
  T = sd.cwiseInverse().asDiagonal() * T * sd.cwiseInverse().asDiagonal();
  const Eigen::LLT<Eigen::MatrixXd> lc(C), lt(T);
  if (lc.info() != Eigen::Success) throw std::invalid_argument("iman_conover: the target correlation is not positive definite");
  if (lt.info() != Eigen::Success) throw std::invalid_argument("iman_conover: the scores' correlation is singular");
  // S = L_C L_T^-1, applied to the rows of R: R S^T, S^T = L_T^-T L_C^T (a triangular solve)
  const Eigen::MatrixXd St = lt.matrixU().solve(Eigen::MatrixXd(lc.matrixU()));
  const Eigen::MatrixXd target_scores = R * St;
  // each column's values in the order of the correlated scores
  for (std::size_t a = 0; a < k; ++a) {
    std::vector<double> sorted = column[a];
    std::sort(sorted.begin(), sorted.end());
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = target_scores(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(a));
    const std::vector<std::size_t> o = order_of(t);
    for (std::size_t r = 0; r < n; ++r) x[o[r]][a] = sorted[r];
  }
}

}  // namespace session
