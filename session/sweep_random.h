// The project's own random numbers for sweeps (session/sweep.h, docs/sweeps.md): a uniform number keyed by
// (seed, case, input), inverse CDFs written here in plain arithmetic and <cmath> (no std::*_distribution,
// whose results differ between standard libraries), Iman-Conover's rank correlation and Spearman's rho.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace session {

constexpr double kTwoPow53 = 9007199254740992.0;  // the uniform's resolution; the largest seed

// SplitMix64's output function (Steele, Lea, Flood 2014; Vigna's reference code): a bijective mix
std::uint64_t splitmix64(std::uint64_t x);
// the i-th state of the SplitMix64 stream from `seed` mixed: splitmix64(seed + (i + 1) * golden gamma)
std::uint64_t splitmix64_stream(std::uint64_t seed, std::uint64_t i);
// a uniform number in (0, 1), never 0 or 1, from the 53 high bits of the key (seed, i, input) hashed
double unit_uniform(std::uint64_t seed, std::uint64_t i, std::uint64_t input);
// the standard normal quantile (Acklam's rational approximation, relative error below 1.15e-9)
double normal_quantile(double p);
// the standard normal CDF, 0.5 erfc(-x / sqrt 2)
double normal_cdf(double x);

enum class Distribution { Uniform, Normal, LogNormal, TruncatedNormal };
struct RandomInput {
  std::string key;       // the case key, e.g. friction.mu
  std::string location;  // FILE:LINE:COL of its entry in the sweep file
  Distribution distribution = Distribution::Uniform;
  double min = 0, max = 0;       // uniform; truncated-normal's bounds
  double mean = 0, sd = 0;       // normal, truncated-normal
  double median = 0, sigma_ln = 0;  // lognormal: exp(ln median + sigma_ln z)
};
// the input's value at probability u in (0, 1)
double quantile(const RandomInput& in, double u);

// Iman and Conover's (1982) rearrangement: each column of x (n samples x k inputs) permuted so that the
// columns' rank correlations approach `target` (k x k, symmetric, unit diagonal, positive definite); every
// column keeps its values, so the marginal distributions (and a Latin hypercube's strata) are unchanged.
// Scores are van der Waerden's, Phi^-1(r / (n + 1)). Throws std::invalid_argument when n <= k or a matrix
// is not positive definite.
void iman_conover(std::vector<std::vector<double>>& x, const std::vector<std::vector<double>>& target);
// Spearman's rank correlation of two equally long samples (ties ranked by their order)
double spearman(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace session
