// Putting the wear of a revolution onto the worn body's lateral profile (docs/physics.md §6): the wear
// law gives a depth per contact strip j, piecewise constant over the strip's width dy; the profile
// (lib/normal/profile.h) is a set of nodes y_i with z interpolated linearly between them.
//
// control volumes  node i stands for its dual cell, the interval between the midpoints to its
//                  neighbours (half cells at the ends), of width
//                    w_i = (y_{i+1} - y_{i-1}) / 2,  w_0 = (y_1 - y_0) / 2,  w_{n-1} = (y_{n-1} - y_{n-2}) / 2.
//                  The identity that makes them the right weights: for any nodal values d_i,
//                    sum_i w_i d_i = sum_i (y_{i+1} - y_i) (d_i + d_{i+1}) / 2,
//                  the trapezoid integral of the linearly interpolated d. So the worn area of the
//                  cross-section, A = sum_i w_i d_i (and the worn volume 2 pi R_w A), is the area
//                  of the profile the contact solver sees. Strips go to nodes by the mean of the
//                  strips' piecewise-constant depth over each dual cell: sum_i w_i d_i = sum_j dy d_j.
//
// smoothing        the Gaussian profile filter of ISO 16610-21 with cut-off wavelength lc:
//                    s(x) = exp(-pi (x / (alpha lc))^2) / (alpha lc),  alpha = sqrt(ln 2 / pi),
//                  whose transmission of a sinusoid of wavelength lambda is
//                    exp(-pi (alpha lc / lambda)^2):  50 % at lambda = lc, 99.3 % at 10 lc, 0.2 % at lc/3.
//                  Physically: wear features narrower than lc are not kept, as running-in, debris
//                  in the contact and the surface roughness would spread them; wider ones are. A
//                  typical lc for a roller with a 5 mm wide contact is about 0.5 mm. The kernel is
//                  truncated at |x| <= lc, where s has fallen to exp(-pi^2 / ln 2) = 6.5e-7 of its
//                  peak and the tail beyond holds erfc(pi / sqrt(ln 2)) = 1.3e-7 of its weight; it
//                  is lowered by s(lc) so that it reaches 0 there continuously (a node lying at
//                  |x| = lc, rounded in or out, then changes nothing). Both change the transmission
//                  by a few 1e-6.
//
// scatter form     a gathering filter (d_k = normalised sum of s(y_k - y_i) d_i over the nodes that
//                  exist) loses or gains area within lc of the profile's ends. Here each node's area
//                  m_i = w_i d_i is scattered instead, over the nodes k with weights
//                  s(y_k - y_i) w_k / Z_i, Z_i = sum_k s(y_k - y_i) w_k over the nodes that exist, so
//                  every node hands out exactly what it had and nothing leaks out of the ends:
//                    d_k = (received by k) / w_k = sum_i s(y_k - y_i) m_i / Z_i,
//                    sum_k w_k d_k = sum_i m_i  (to rounding).
//                  On uniform nodes further than 2 lc from both ends (every node that sends there
//                  has a whole kernel, so the same Z_i) it is the gathering filter and has its
//                  transmission. Within lc of an end a constant depth is not kept: the scatter form
//                  trades that for the area.
//                  A uniform depth over the whole width falls at the end node to ln 2 = 0.69 of
//                  itself (the continuum limit: d(0) = int_0^inf s(x) / (1/2 + int_0^x s) dx for a
//                  unit-weight s; 0.71 with lc = 10 node spacings) and rises a little just inside.
//                  The worn depth near a profile's ends is normally zero.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace wear {

// w_i: the control-volume width of each node of a piecewise-linear profile (m), y strictly
// increasing; half cells at the ends, sum_i w_i = y_{n-1} - y_0. Then sum_i w_i d_i is the
// trapezoid integral of the linearly interpolated d (identity at the top). Throws
// std::invalid_argument for fewer than 2 nodes, non-finite y or y not strictly increasing.
Eigen::ArrayXd node_widths_m(const Eigen::ArrayXd& node_y_m);

// A = sum_i w_i d_i: the worn area of the cross-section (m^2); times 2 pi R_w it is the worn
// volume. Throws std::invalid_argument as node_widths_m, or when the sizes differ.
double profile_area_m2(const Eigen::ArrayXd& depth_m, const Eigen::ArrayXd& node_y_m);

// the strips' depths on the profile's nodes (m). Strip j (of ny) has the constant depth
// strip_depth_m(j) over [first_edge_y_m + j dy, first_edge_y_m + (j+1) dy], in the profile's y.
// Node i gets the mean of that piecewise-constant depth over its dual cell (0 where no strip is),
// so sum_i w_i d_i = sum_j dy d_j to rounding. A part of a strip outside the profile's extent
// [y_0, y_{n-1}] is given to the nearest end node (added to its cell's area, then divided by its
// w), so the area is still conserved. A merge of the two sorted edge lists: O(n + ny). Throws
// std::invalid_argument for dy <= 0, non-finite input, or node_y_m as node_widths_m.
Eigen::ArrayXd strips_to_nodes(const Eigen::ArrayXd& strip_depth_m, double first_edge_y_m, double dy_m,
                               const Eigen::ArrayXd& node_y_m);

// the ISO 16610-21 Gaussian filter with cut-off wavelength lc, in the scatter form at the top: the
// area sum_i w_i d_i is conserved to rounding, on any node spacing. A depth symmetric about y = 0 on
// nodes symmetric about y = 0 stays symmetric (bit for bit: the sums run in a mirror-symmetric
// order), and a non-negative depth stays non-negative (all weights are >= 0). cutoff 0 returns the
// input unchanged. Cost O(n x nodes within lc), a sliding window over the sorted nodes. Throws
// std::invalid_argument for a negative or non-finite cutoff_wavelength_m, sizes that differ,
// non-finite depth, or node_y_m as node_widths_m.
Eigen::ArrayXd smooth_conserving(const Eigen::ArrayXd& depth_m, const Eigen::ArrayXd& node_y_m,
                                 double cutoff_wavelength_m);

// The filter's kernel on a set of nodes: what smooth_conserving computes from node_y_m and the cut-off
// alone (the windows, the truncated Gaussian of every pair within lc, the widths w_i), so that a run
// whose nodes never move builds it once. Throws as smooth_conserving for the nodes and the cut-off.
struct SmoothingKernel {
  double cutoff_wavelength_m = 0;
  Eigen::ArrayXd w;                     // the nodes' widths
  std::vector<int> first, count;        // row i: nodes first[i] .. first[i] + count[i] - 1, at s[offset[i]]
  std::vector<std::size_t> offset;
  std::vector<double> s;                // s(y_k - y_i) - s(lc), each row's values
};
SmoothingKernel smoothing_kernel(const Eigen::ArrayXd& node_y_m, double cutoff_wavelength_m);

// the kernel's size before it is built: the pairs of nodes within the cut-off, sum_i count[i] (= s.size(); 0 for
// cutoff 0), counted in O(n) without allocating. It grows as n^2 lc / width on uniform nodes: the memory and the
// time of a wear run's smoothing (wear/wear_loop.h estimate_memory_bytes).
double smoothing_kernel_entries(const Eigen::ArrayXd& node_y_m, double cutoff_wavelength_m);

// smooth_conserving with the kernel of its nodes: the same numbers to the bit. Throws
// std::invalid_argument for a depth of another size or non-finite.
Eigen::ArrayXd smooth_conserving(const Eigen::ArrayXd& depth_m, const SmoothingKernel& kernel);

}  // namespace wear
