// Wear depth onto the profile's nodes and its area-conserving Gaussian smoothing; the control
// volumes, the ISO 16610-21 filter and its scatter form are at the top of wear/profile_update.h.
//
// strips_to_nodes merges the strip edges e_j = e_0 + j dy with the dual-cell edges, the midpoints
// c_i = (y_{i-1} + y_i) / 2 (node 0's cell open to the left, node n-1's to the right, so what lies
// outside the extent goes to the end nodes). Each strip is cut in its own coordinate u = y - e_j
// into pieces from 0 to dy, so its pieces add up to dy to rounding whatever the rounding of e_j.
//
// smooth_conserving finds each node's window |y_k - y_i| <= lc with two pointers and stores its
// kernel row s(y_k - y_i), each pair's value computed once for both rows: the matrix is symmetric,
// so row i serves both the normalisation Z_i = sum_k s_ik w_k and the result
// d_k = sum_i s_ki m_i / Z_i. The constant 1/(alpha lc) cancels in m_i / Z_i and is left out, and
// s(lc) is subtracted so the truncated kernel reaches 0 continuously at |x| = lc. Every sum over a
// row adds its terms in pairs from both ends inwards; on mirrored nodes the mirrored row holds the
// same terms in reverse order, so the pairs are the same and the sums bit-identical.
#include "wear/profile_update.h"
#include "lib/number.h"
#include "lib/numeric.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace wear {

using contact::kPi;

namespace {

std::string number(double v) { return contact::six_digits(v); }  // lib/number.h

// at least 2 finite, strictly increasing nodes
void check_nodes(const std::string& where, const Eigen::ArrayXd& y) {
  const Eigen::Index n = y.size();
  if (n < 2) throw std::invalid_argument(where + ": node_y_m needs at least 2 nodes, got " + std::to_string(n));
  if (!y.allFinite()) throw std::invalid_argument(where + ": node_y_m is not finite");
  for (Eigen::Index i = 1; i < n; ++i)
    if (!(y(i) > y(i - 1)))
      throw std::invalid_argument(where + ": node_y_m must be strictly increasing, got y[" + std::to_string(i - 1) +
                                  "] = " + number(y(i - 1)) + ", y[" + std::to_string(i) + "] = " + number(y(i)));
}

void check_same_size(const std::string& where, const Eigen::ArrayXd& depth, const Eigen::ArrayXd& y) {
  if (depth.size() != y.size())
    throw std::invalid_argument(where + ": depth_m has " + std::to_string(depth.size()) + " values, node_y_m " +
                                std::to_string(y.size()));
}

// w_i without the checks
Eigen::ArrayXd widths(const Eigen::ArrayXd& y) {
  const Eigen::Index n = y.size();
  Eigen::ArrayXd w(n);
  w(0) = 0.5 * (y(1) - y(0));
  for (Eigen::Index i = 1; i + 1 < n; ++i) w(i) = 0.5 * (y(i + 1) - y(i - 1));
  w(n - 1) = 0.5 * (y(n - 1) - y(n - 2));
  return w;
}

// sum_m row[m] a[first + m], added in pairs from both ends inwards (mirror-symmetric order)
double symmetric_dot(const double* row, const double* a, int count) {
  double sum = 0;
  int lo = 0, hi = count - 1;
  for (; lo < hi; ++lo, --hi) sum += row[lo] * a[lo] + row[hi] * a[hi];
  if (lo == hi) sum += row[lo] * a[lo];
  return sum;
}

}  // namespace

Eigen::ArrayXd node_widths_m(const Eigen::ArrayXd& node_y_m) {
  check_nodes("node_widths_m", node_y_m);
  return widths(node_y_m);
}

double profile_area_m2(const Eigen::ArrayXd& depth_m, const Eigen::ArrayXd& node_y_m) {
  check_nodes("profile_area_m2", node_y_m);
  check_same_size("profile_area_m2", depth_m, node_y_m);
  return (widths(node_y_m) * depth_m).sum();
}

Eigen::ArrayXd strips_to_nodes(const Eigen::ArrayXd& strip_depth_m, double first_edge_y_m, double dy_m,
                               const Eigen::ArrayXd& node_y_m) {
  check_nodes("strips_to_nodes", node_y_m);
  if (!(dy_m > 0) || !std::isfinite(dy_m))
    throw std::invalid_argument("strips_to_nodes: dy_m must be > 0 and finite, got " + number(dy_m));
  if (!std::isfinite(first_edge_y_m))
    throw std::invalid_argument("strips_to_nodes: first_edge_y_m is not finite, got " + number(first_edge_y_m));
  if (!strip_depth_m.allFinite()) throw std::invalid_argument("strips_to_nodes: strip_depth_m is not finite");

  const Eigen::Index n = node_y_m.size(), ny = strip_depth_m.size();
  const Eigen::ArrayXd& y = node_y_m;
  // the right edge of node i's dual cell (i < n-1); node n-1's is open
  auto cell_end = [&](Eigen::Index i) { return 0.5 * (y(i) + y(i + 1)); };

  // worn area per dual cell: merge the strip edges with the cell edges
  Eigen::ArrayXd area_m2 = Eigen::ArrayXd::Zero(n);
  Eigen::Index i = 0;  // the node whose cell holds the current strip's left edge
  for (Eigen::Index j = 0; j < ny; ++j) {
    const double e = first_edge_y_m + static_cast<double>(j) * dy_m, d = strip_depth_m(j);
    while (i + 1 < n && cell_end(i) <= e) ++i;
    // the strip's pieces in u = y - e, from 0 to dy: one per cell it crosses
    double u = 0;
    for (; i + 1 < n; ++i) {
      const double cut = cell_end(i) - e;
      if (cut >= dy_m) break;
      area_m2(i) += (cut - u) * d;
      u = cut;
    }
    area_m2(i) += (dy_m - u) * d;
  }

  // the mean over each cell
  return area_m2 / widths(y);
}

SmoothingKernel smoothing_kernel(const Eigen::ArrayXd& node_y_m, double cutoff_wavelength_m) {
  const double lc = cutoff_wavelength_m;
  if (!(lc >= 0) || !std::isfinite(lc))
    throw std::invalid_argument("smooth_conserving: cutoff_wavelength_m must be >= 0 and finite, got " + number(lc));
  check_nodes("smooth_conserving", node_y_m);
  SmoothingKernel k;
  k.cutoff_wavelength_m = lc;
  k.w = widths(node_y_m);
  if (lc == 0) return k;

  const int n = static_cast<int>(node_y_m.size());
  const Eigen::ArrayXd& y = node_y_m;
  const double alpha = std::sqrt(std::log(2.0) / kPi);
  const double c = kPi / (alpha * lc * alpha * lc);  // s(x) ~ exp(-c x^2)
  const double s_lc = std::exp(-c * lc * lc);         // exp(-pi^2 / ln 2) = 6.5e-7

  // kernel rows: node i reaches the nodes first[i] .. first[i] + count[i] - 1 within lc (sliding window)
  std::vector<int>&first = k.first, &count = k.count;
  std::vector<std::size_t>& offset = k.offset;
  first.resize(n);
  count.resize(n);
  offset.resize(n + 1);
  offset[0] = 0;
  for (int i = 0, lo = 0, hi = 0; i < n; ++i) {
    while (y(i) - y(lo) > lc) ++lo;
    if (hi < i) hi = i;
    while (hi + 1 < n && y(hi + 1) - y(i) <= lc) ++hi;
    first[i] = lo;
    count[i] = hi - lo + 1;
    offset[i + 1] = offset[i] + static_cast<std::size_t>(count[i]);
  }

  // s(y_k - y_i), each pair once (the window test is the same both ways): row i holds s at
  // offset[i] + k - first[i]
  std::vector<double>& s = k.s;
  s.assign(offset[n], 0.0);
  for (int i = 0; i < n; ++i) {
    s[offset[i] + i - first[i]] = 1 - s_lc;
    for (int m = i + 1; m < first[i] + count[i]; ++m) {
      const double x = y(m) - y(i);
      const double s_im = std::max(std::exp(-c * x * x) - s_lc, 0.0);
      s[offset[i] + m - first[i]] = s_im;
      s[offset[m] + i - first[m]] = s_im;
    }
  }
  return k;
}

double smoothing_kernel_entries(const Eigen::ArrayXd& node_y_m, double cutoff_wavelength_m) {
  const double lc = cutoff_wavelength_m;
  if (!(lc > 0) || !std::isfinite(lc)) return 0;
  const Eigen::ArrayXd& y = node_y_m;
  const Eigen::Index n = y.size();
  double entries = 0;
  // the window of smoothing_kernel: node i reaches lo .. hi
  for (Eigen::Index i = 0, lo = 0, hi = 0; i < n; ++i) {
    while (y(i) - y(lo) > lc) ++lo;
    if (hi < i) hi = i;
    while (hi + 1 < n && y(hi + 1) - y(i) <= lc) ++hi;
    entries += static_cast<double>(hi - lo + 1);
  }
  return entries;
}

Eigen::ArrayXd smooth_conserving(const Eigen::ArrayXd& depth_m, const SmoothingKernel& kernel) {
  if (depth_m.size() != kernel.w.size())
    throw std::invalid_argument("smooth_conserving: depth_m has " + std::to_string(depth_m.size()) +
                                " values, the kernel's nodes " + std::to_string(kernel.w.size()));
  if (!depth_m.allFinite()) throw std::invalid_argument("smooth_conserving: depth_m is not finite");
  if (kernel.cutoff_wavelength_m == 0) return depth_m;

  const int n = static_cast<int>(depth_m.size());
  const Eigen::ArrayXd& w = kernel.w;
  const std::vector<int>&first = kernel.first, &count = kernel.count;
  const std::vector<std::size_t>& offset = kernel.offset;
  const std::vector<double>& s = kernel.s;

  // what each node hands out per unit weight: m_i / Z_i, normalised over the nodes that exist
  Eigen::ArrayXd q(n);
  for (int i = 0; i < n; ++i)
    q(i) = w(i) * depth_m(i) / symmetric_dot(&s[offset[i]], &w(first[i]), count[i]);

  // what each node received, per unit width: d_k = sum_i s(y_k - y_i) m_i / Z_i
  Eigen::ArrayXd smoothed(n);
  for (int k = 0; k < n; ++k) smoothed(k) = symmetric_dot(&s[offset[k]], &q(first[k]), count[k]);
  return smoothed;
}

Eigen::ArrayXd smooth_conserving(const Eigen::ArrayXd& depth_m, const Eigen::ArrayXd& node_y_m,
                                 double cutoff_wavelength_m) {
  const SmoothingKernel kernel = smoothing_kernel(node_y_m, cutoff_wavelength_m);
  check_same_size("smooth_conserving", depth_m, node_y_m);
  return smooth_conserving(depth_m, kernel);
}

}  // namespace wear
