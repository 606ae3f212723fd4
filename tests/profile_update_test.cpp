// Wear depth onto the profile's nodes (wear/profile_update.h): the control-volume widths against an
// independent trapezoid sum and by hand, strips to nodes against hand-computed overlaps and the
// area identity sum_i w_i d_i = sum_j dy d_j, and the conserving Gaussian filter against its area,
// its symmetry, the closed-form transmission of ISO 16610-21 and the errors.
#include "wear/profile_update.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <ostream>
#include <random>
#include <stdexcept>
#include <string>
#include "lib/numeric.h"
#include "tests/test_text.h"

namespace wear {
namespace {
using contact::kPi;
using rollwear_test::message_of;

constexpr double kRounding = 1e-14;  // relative: sums of a few thousand non-negative terms in double

// n nodes over [y0, y0 + width], spacings drawn from [0.2, 1.8] x mean (fixed seed)
Eigen::ArrayXd random_nodes(int n, double y0, double width, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.2, 1.8);
  Eigen::ArrayXd h(n - 1);
  for (int i = 0; i < n - 1; ++i) h(i) = u(rng);
  h *= width / h.sum();
  Eigen::ArrayXd y(n);
  y(0) = y0;
  for (int i = 1; i < n; ++i) y(i) = y(i - 1) + h(i - 1);
  return y;
}

// n values drawn from [lo, hi] (fixed seed)
Eigen::ArrayXd random_values(int n, double lo, double hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  Eigen::ArrayXd v(n);
  for (int i = 0; i < n; ++i) v(i) = u(rng);
  return v;
}

// ---- control volumes ----

TEST(ProfileUpdate, NodeWidthsByHand) {
  // y = 0, 1, 3, 6: dual cells [0, 0.5], [0.5, 2], [2, 4.5], [4.5, 6]
  const Eigen::ArrayXd w = node_widths_m((Eigen::ArrayXd(4) << 0, 1, 3, 6).finished());
  ASSERT_EQ(w.size(), 4);
  EXPECT_EQ(w(0), 0.5);
  EXPECT_EQ(w(1), 1.5);
  EXPECT_EQ(w(2), 2.5);
  EXPECT_EQ(w(3), 1.5);
  // two nodes: two half cells
  const Eigen::ArrayXd w2 = node_widths_m((Eigen::ArrayXd(2) << -1, 3).finished());
  EXPECT_EQ(w2(0), 2);
  EXPECT_EQ(w2(1), 2);
}

TEST(ProfileUpdate, NodeWidthsGiveTheTrapezoidIntegral) {
  // identity: sum_i w_i d_i = sum_i (y_{i+1} - y_i) (d_i + d_{i+1}) / 2, against an independent
  // trapezoid sum on random non-uniform nodes and random (signed) values
  const Eigen::ArrayXd y = random_nodes(401, -0.01, 0.02, 1);
  const Eigen::ArrayXd d = random_values(401, -1e-6, 3e-6, 2);
  double trapezoid = 0, trapezoid_abs = 0;
  for (int i = 0; i + 1 < 401; ++i) {
    trapezoid += (y(i + 1) - y(i)) * (d(i) + d(i + 1)) / 2;
    trapezoid_abs += (y(i + 1) - y(i)) * (std::abs(d(i)) + std::abs(d(i + 1))) / 2;
  }
  const Eigen::ArrayXd w = node_widths_m(y);
  EXPECT_NEAR((w * d).sum(), trapezoid, kRounding * trapezoid_abs);
  EXPECT_NEAR(profile_area_m2(d, y), trapezoid, kRounding * trapezoid_abs);
  // the cells tile the extent
  EXPECT_NEAR(w.sum(), y(400) - y(0), kRounding * (y(400) - y(0)));
  EXPECT_TRUE((w > 0).all());
}

TEST(ProfileUpdate, AreaOfALinearDepthIsItsIntegral) {
  // closed form: the trapezoid rule is exact for d = a + b y; over [-0.01, 0.012] with a = 2e-6,
  // b = 1e-4: A = a L + b (y1^2 - y0^2) / 2 = 4.4e-8 + 1e-4 * 2.2e-5 = 4.62e-8 m^2
  const Eigen::ArrayXd y = random_nodes(57, -0.01, 0.022, 3);
  const Eigen::ArrayXd d = 2e-6 + 1e-4 * y;
  EXPECT_NEAR(profile_area_m2(d, y) / 4.62e-8, 1, kRounding);
}

// ---- strips to nodes ----

TEST(ProfileUpdateStrips, OneStripSplitsByOverlapByHand) {
  // nodes 0, 1, 3, 6 (cells [0, 0.5], [0.5, 2], [2, 4.5], [4.5, 6], widths 0.5, 1.5, 2.5, 1.5);
  // one strip of depth 2 over [0.25, 2.25]: areas 0.5, 3, 0.5, 0 -> means 1, 2, 0.2, 0
  const Eigen::ArrayXd y = (Eigen::ArrayXd(4) << 0, 1, 3, 6).finished();
  const Eigen::ArrayXd d = strips_to_nodes(Eigen::ArrayXd::Constant(1, 2.0), 0.25, 2.0, y);
  ASSERT_EQ(d.size(), 4);
  EXPECT_NEAR(d(0), 1.0, 1e-15);
  EXPECT_NEAR(d(1), 2.0, 1e-15);
  EXPECT_NEAR(d(2), 0.2, 1e-15);
  EXPECT_EQ(d(3), 0);
}

TEST(ProfileUpdateStrips, PartsOutsideTheExtentGoToTheEndNodes) {
  // nodes 0, 1, 3, 6; strips of width 1 over [-2, -1] (depth 3), [-1, 0] (depth 5), then [0, 1] ...
  // Left: the two strips outside give 3 + 5 = 8 to node 0, plus its own cell [0, 0.5] of strip 2
  // (depth 7): area 8 + 3.5 = 11.5, mean 11.5 / 0.5 = 23. A strip over [5.5, 7.5] (depth 4) gives
  // node 3 (cell [4.5, 6], width 1.5) 0.5 * 4 inside and 1.5 * 4 outside: 8 / 1.5.
  const Eigen::ArrayXd y = (Eigen::ArrayXd(4) << 0, 1, 3, 6).finished();
  const Eigen::ArrayXd left = strips_to_nodes((Eigen::ArrayXd(3) << 3, 5, 7).finished(), -2.0, 1.0, y);
  EXPECT_NEAR(left(0), 23.0, 1e-14);
  EXPECT_NEAR(left(1), 7.0 * 0.5 / 1.5, 1e-14);  // [0.5, 1] of strip 2
  EXPECT_EQ(left(2), 0);
  EXPECT_EQ(left(3), 0);
  const Eigen::ArrayXd right = strips_to_nodes(Eigen::ArrayXd::Constant(1, 4.0), 5.5, 2.0, y);
  EXPECT_EQ(right(0), 0);
  EXPECT_EQ(right(1), 0);
  EXPECT_EQ(right(2), 0);
  EXPECT_NEAR(right(3), 8.0 / 1.5, 1e-14);
  // wholly outside, both ends at once: one long strip over [-10, 20] of depth 1 puts 10 + 0.5 on
  // node 0 and 14 + 1.5 on node 3
  const Eigen::ArrayXd all = strips_to_nodes(Eigen::ArrayXd::Ones(1), -10.0, 30.0, y);
  EXPECT_NEAR(all(0), 10.5 / 0.5, 1e-13);
  EXPECT_NEAR(all(1), 1.0, 1e-15);
  EXPECT_NEAR(all(2), 1.0, 1e-15);
  EXPECT_NEAR(all(3), 15.5 / 1.5, 1e-13);
}

TEST(ProfileUpdateStrips, AreaIsConservedOnNonUniformNodes) {
  // identity: sum_i w_i d_i = sum_j dy d_j. 80 strips on 401 random nodes over 20 mm (the strips
  // straddle nodes, each node's cell is cut by up to ~2 strips), and 200 narrow strips sticking out
  // of both ends, and 7 strips each wider than many cells
  const Eigen::ArrayXd y = random_nodes(401, -0.01, 0.02, 4);
  struct Layout {
    int ny;
    double first_edge_m, dy_m;
  };
  for (const Layout& l : {Layout{80, -0.004, 1e-4}, Layout{200, -0.0103, 0.000103}, Layout{7, -0.0071, 0.0021}}) {
    const Eigen::ArrayXd strips = random_values(l.ny, 0, 1e-6, 5);
    const double strip_area = (strips * l.dy_m).sum();
    const Eigen::ArrayXd d = strips_to_nodes(strips, l.first_edge_m, l.dy_m, y);
    ASSERT_EQ(d.size(), 401);
    EXPECT_TRUE((d >= 0).all());
    EXPECT_NEAR(profile_area_m2(d, y) / strip_area, 1, kRounding) << l.ny << " strips";
  }
}

TEST(ProfileUpdateStrips, ConstantDepthIsKeptOnCoveredNodes) {
  // closed form: a constant c over strips that cover a node's whole dual cell has mean c there;
  // nodes whose cell the strips do not reach get 0. 50 strips over [-3, 4.5] mm on random nodes
  constexpr double kEdgeRounding = 1e-12;  // strip edges e_0 + j dy rounded at |e| ~ 1e2 cell widths
  const Eigen::ArrayXd y = random_nodes(401, -0.01, 0.02, 6);
  const double c = 2.5e-7, lo = -0.003, dy = 1.5e-4, hi = lo + 50 * dy;
  const Eigen::ArrayXd d = strips_to_nodes(Eigen::ArrayXd::Constant(50, c), lo, dy, y);
  int covered = 0, outside = 0;
  for (int i = 1; i + 1 < 401; ++i) {
    const double a = 0.5 * (y(i - 1) + y(i)), b = 0.5 * (y(i) + y(i + 1));  // dual cell
    if (a >= lo && b <= hi) {
      EXPECT_NEAR(d(i) / c, 1, kEdgeRounding) << "node " << i;
      ++covered;
    } else if (b <= lo || a >= hi) {
      EXPECT_EQ(d(i), 0) << "node " << i;
      ++outside;
    } else {
      EXPECT_GT(d(i), 0) << "node " << i;  // partly covered: between 0 and c
      EXPECT_LT(d(i), c) << "node " << i;
    }
  }
  EXPECT_GT(covered, 100);
  EXPECT_GT(outside, 200);
}

TEST(ProfileUpdateStrips, BadInputThrowsNamingTheArgument) {
  const Eigen::ArrayXd y = (Eigen::ArrayXd(4) << 0, 1, 3, 6).finished(), strips = Eigen::ArrayXd::Ones(3);
  EXPECT_EQ(message_of([&] { strips_to_nodes(strips, 0, 0, y); }), "strips_to_nodes: dy_m must be > 0 and finite, got 0");
  EXPECT_EQ(message_of([&] { strips_to_nodes(strips, 0, -1e-4, y); }),
            "strips_to_nodes: dy_m must be > 0 and finite, got -0.0001");
  EXPECT_EQ(message_of([&] { strips_to_nodes(strips, 0, NAN, y); }), "strips_to_nodes: dy_m must be > 0 and finite, got nan");
  EXPECT_EQ(message_of([&] { strips_to_nodes(strips, INFINITY, 1, y); }),
            "strips_to_nodes: first_edge_y_m is not finite, got inf");
  Eigen::ArrayXd bad = strips;
  bad(1) = NAN;
  EXPECT_EQ(message_of([&] { strips_to_nodes(bad, 0, 1, y); }), "strips_to_nodes: strip_depth_m is not finite");
  EXPECT_EQ(message_of([&] { strips_to_nodes(strips, 0, 1, Eigen::ArrayXd::Zero(1)); }),
            "strips_to_nodes: node_y_m needs at least 2 nodes, got 1");
  EXPECT_EQ(message_of([&] { strips_to_nodes(strips, 0, 1, (Eigen::ArrayXd(3) << 0, 2, 2).finished()); }),
            "strips_to_nodes: node_y_m must be strictly increasing, got y[1] = 2, y[2] = 2");
  EXPECT_EQ(message_of([&] { strips_to_nodes(strips, 0, 1, (Eigen::ArrayXd(3) << 0, NAN, 2).finished()); }),
            "strips_to_nodes: node_y_m is not finite");
  EXPECT_EQ(message_of([&] { profile_area_m2(strips, y); }), "profile_area_m2: depth_m has 3 values, node_y_m 4");
  EXPECT_EQ(message_of([&] { node_widths_m(Eigen::ArrayXd()); }), "node_widths_m: node_y_m needs at least 2 nodes, got 0");
}

// ---- conserving Gaussian filter ----

constexpr double kLc = 0.5e-3;  // cut-off wavelength of a roller with a 5 mm wide contact

TEST(ProfileUpdateSmooth, AreaIsConservedOnNonUniformNodes) {
  // identity of the scatter form: sum_k w_k d_k = sum_i w_i d_i, on random nodes, for random depths
  // and for wear concentrated at an end (where a gathering filter would lose area)
  const Eigen::ArrayXd y = random_nodes(401, -0.01, 0.02, 7);
  Eigen::ArrayXd end_wear = Eigen::ArrayXd::Zero(401);
  end_wear.head(8) = 1e-6;
  for (const Eigen::ArrayXd& d : {random_values(401, 0, 1e-6, 8), end_wear}) {
    for (double lc : {kLc, 4 * kLc, 40 * kLc}) {
      const Eigen::ArrayXd s = smooth_conserving(d, y, lc);
      ASSERT_EQ(s.size(), 401);
      EXPECT_GT((s - d).abs().maxCoeff(), 1e-3 * d.maxCoeff()) << "lc " << lc;  // it did smooth
      EXPECT_NEAR(profile_area_m2(s, y) / profile_area_m2(d, y), 1, kRounding) << "lc " << lc;
    }
  }
}

TEST(ProfileUpdateSmooth, KernelBuiltOnceGivesTheSameNumbers) {
  // the wear loop builds the kernel once per run (the nodes never move) and applies it to every depth:
  // the result is smooth_conserving's on the nodes, bit for bit, for every depth in turn
  const Eigen::ArrayXd y = random_nodes(301, -0.01, 0.02, 13);
  const SmoothingKernel kernel = smoothing_kernel(y, kLc);
  for (unsigned seed : {14u, 15u, 16u}) {
    const Eigen::ArrayXd d = random_values(301, 0, 1e-6, seed);
    EXPECT_TRUE((smooth_conserving(d, kernel) == smooth_conserving(d, y, kLc)).all()) << "seed " << seed;
  }
  EXPECT_THROW(smooth_conserving(Eigen::ArrayXd::Zero(300), kernel), std::invalid_argument);
}

TEST(ProfileUpdateSmooth, ZeroCutoffIsTheIdentity) {
  // by definition: lc = 0 returns the input, bit for bit
  const Eigen::ArrayXd y = random_nodes(101, -0.01, 0.02, 9);
  const Eigen::ArrayXd d = random_values(101, -1e-6, 1e-6, 10);
  EXPECT_TRUE((smooth_conserving(d, y, 0) == d).all());
}

TEST(ProfileUpdateSmooth, SymmetricDepthStaysSymmetric) {
  // symmetry: nodes mirrored about y = 0 (random spacing), a depth even in y; the result is even in
  // y to below 1e-15 of its maximum (the sums run in mirror order: it is exact)
  const Eigen::ArrayXd half = random_nodes(201, 0, 0.01, 11);
  Eigen::ArrayXd y(401);
  for (int i = 0; i < 201; ++i) {
    y(200 + i) = half(i);
    y(200 - i) = -half(i);
  }
  Eigen::ArrayXd d(401);
  const Eigen::ArrayXd r = random_values(201, 0, 1e-6, 12);
  for (int i = 0; i < 201; ++i) d(200 + i) = d(200 - i) = r(i);
  for (double lc : {kLc, 3 * kLc}) {
    const Eigen::ArrayXd s = smooth_conserving(d, y, lc);
    const double asymmetry = (s - s.reverse()).abs().maxCoeff();
    EXPECT_LT(asymmetry, 1e-15 * s.abs().maxCoeff()) << "lc " << lc;
    EXPECT_GT((s - d).abs().maxCoeff(), 1e-3 * d.maxCoeff()) << "lc " << lc;  // it did smooth
  }
}

// the ISO 16610-21 Gaussian filter transmits a sinusoid of wavelength lambda with amplitude
// exp(-pi (alpha lc / lambda)^2), alpha = sqrt(ln 2 / pi): 1/2 at lambda = lc
struct Transmission {
  double wavelength_over_lc;
  double lo, hi;  // the bounds the filter must meet
};

std::ostream& operator<<(std::ostream& os, const Transmission& t) { return os << "lambda/lc " << t.wavelength_over_lc; }

class ProfileUpdateSmoothTransmission : public ::testing::TestWithParam<Transmission> {};

TEST_P(ProfileUpdateSmoothTransmission, SinusoidAmplitudeMatchesGaussianClosedForm) {
  // 1 + sin(2 pi y / lambda) on 2001 uniform nodes over 20 mm (lc / 50 spacing); away from the ends
  // (further than 2 lc: every node that sends there has a full kernel, so the scatter form is the
  // gathering filter) the result is 1 + T sin(2 pi y / lambda). T by least squares on those nodes.
  // measured 1.3e-6 off the closed form: the kernel's truncation and shift at lc (header); the sum
  // over nodes lc/50 apart matches the integral of the smooth Gaussian far closer than that
  constexpr double kDiscreteTol = 1e-5;
  const Transmission t = GetParam();
  const double lambda = t.wavelength_over_lc * kLc;
  const Eigen::ArrayXd y = Eigen::ArrayXd::LinSpaced(2001, -0.01, 0.01);
  const Eigen::ArrayXd wave = (2 * kPi * y / lambda).sin();
  const Eigen::ArrayXd s = smooth_conserving(1 + wave, y, kLc);
  double num = 0, den = 0;
  for (int i = 0; i < 2001; ++i) {
    if (y(i) - y(0) > 2 * kLc && y(2000) - y(i) > 2 * kLc) {
      num += (s(i) - 1) * wave(i);
      den += wave(i) * wave(i);
    }
  }
  const double T = num / den;
  const double alpha = std::sqrt(std::log(2.0) / kPi);
  const double closed_form = std::exp(-kPi * std::pow(alpha * kLc / lambda, 2));
  RecordProperty("transmission", std::to_string(T));
  std::printf("lambda = %.4g lc: transmission %.7f, closed form %.7f\n", t.wavelength_over_lc, T, closed_form);
  EXPECT_GE(T, t.lo);
  EXPECT_LE(T, t.hi);
  EXPECT_NEAR(T, closed_form, kDiscreteTol);
  // and it is that sinusoid, node by node
  for (int i = 0; i < 2001; ++i) {
    if (y(i) - y(0) > 2 * kLc && y(2000) - y(i) > 2 * kLc) {
      ASSERT_NEAR(s(i), 1 + T * wave(i), kDiscreteTol) << "y " << y(i);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ProfileUpdateIso16610, ProfileUpdateSmoothTransmission,
                         ::testing::Values(Transmission{1.0, 0.49, 0.51},        // 50 % at lc
                                           Transmission{10.0, 0.97, 1.0},       // exp(-ln 2 / 100) = 0.9931
                                           Transmission{1.0 / 3, 0.0, 0.01}));  // 2^-9 = 0.0020

TEST(ProfileUpdateSmooth, ConstantIsKeptAwayFromTheEndsAndFallsToLn2AtThem) {
  // closed form: further than 2 lc from both ends of uniform nodes every node that sends to a node
  // has the same Z, so a constant stays that constant; within lc of an end the scatter form keeps
  // the area, not the constant, and the end node falls to ln 2 of it in the continuum limit (header),
  // approached at second order in spacing / lc (measured 0.7112 at lc / 10, 0.69388 at lc / 50)
  double end_error[2];
  for (int k = 0; k < 2; ++k) {
    const int n = k == 0 ? 401 : 2001;  // lc = 10 and 50 node spacings
    const Eigen::ArrayXd y = Eigen::ArrayXd::LinSpaced(n, -0.01, 0.01);
    const Eigen::ArrayXd s = smooth_conserving(Eigen::ArrayXd::Constant(n, 1e-6), y, kLc);
    for (int i = 0; i < n; ++i) {
      if (y(i) - y(0) > 2 * kLc && y(n - 1) - y(i) > 2 * kLc) {
        EXPECT_NEAR(s(i) / 1e-6, 1, kRounding) << n << " nodes, node " << i;
      }
    }
    EXPECT_EQ(s(0), s(n - 1));
    EXPECT_NEAR(profile_area_m2(s, y) / 2e-8, 1, kRounding);
    end_error[k] = s(0) / 1e-6 - std::log(2.0);
  }
  RecordProperty("end_error_lc_over_10", std::to_string(end_error[0]));
  RecordProperty("end_error_lc_over_50", std::to_string(end_error[1]));
  EXPECT_NEAR(end_error[0], 0, 0.02);
  EXPECT_NEAR(end_error[1], 0, 1e-3);
  EXPECT_NEAR(end_error[0] / end_error[1], 25, 3);  // (50 / 10)^2: second order
}

TEST(ProfileUpdateSmooth, NonNegativeDepthStaysNonNegative) {
  // every weight is >= 0: isolated spikes between zeros (where a filter with negative lobes would
  // undershoot) stay >= 0, on random nodes
  const Eigen::ArrayXd y = random_nodes(401, -0.01, 0.02, 13);
  Eigen::ArrayXd d = Eigen::ArrayXd::Zero(401);
  for (int i = 3; i < 401; i += 37) d(i) = 1e-6;
  d(0) = d(400) = 2e-6;
  for (double lc : {0.2 * kLc, kLc, 5 * kLc}) {
    const Eigen::ArrayXd s = smooth_conserving(d, y, lc);
    EXPECT_GE(s.minCoeff(), 0) << "lc " << lc;
    EXPECT_GT(s(4), 0) << "lc " << lc;  // a spike spread to its neighbour
  }
}

TEST(ProfileUpdateSmooth, BadInputThrowsNamingTheArgument) {
  const Eigen::ArrayXd y = Eigen::ArrayXd::LinSpaced(5, 0, 0.004), d = Eigen::ArrayXd::Ones(5);
  EXPECT_EQ(message_of([&] { smooth_conserving(d, y, -1e-4); }),
            "smooth_conserving: cutoff_wavelength_m must be >= 0 and finite, got -0.0001");
  EXPECT_EQ(message_of([&] { smooth_conserving(d, y, NAN); }),
            "smooth_conserving: cutoff_wavelength_m must be >= 0 and finite, got nan");
  EXPECT_EQ(message_of([&] { smooth_conserving(d, y, INFINITY); }),
            "smooth_conserving: cutoff_wavelength_m must be >= 0 and finite, got inf");
  EXPECT_EQ(message_of([&] { smooth_conserving(Eigen::ArrayXd::Ones(4), y, kLc); }),
            "smooth_conserving: depth_m has 4 values, node_y_m 5");
  // sizes are checked at lc = 0 too
  EXPECT_EQ(message_of([&] { smooth_conserving(Eigen::ArrayXd::Ones(4), y, 0); }),
            "smooth_conserving: depth_m has 4 values, node_y_m 5");
  Eigen::ArrayXd bad = d;
  bad(2) = INFINITY;
  EXPECT_EQ(message_of([&] { smooth_conserving(bad, y, kLc); }), "smooth_conserving: depth_m is not finite");
  EXPECT_EQ(message_of([&] { smooth_conserving(d, y.reverse(), kLc); }),
            "smooth_conserving: node_y_m must be strictly increasing, got y[0] = 0.004, y[1] = 0.003");
}

}  // namespace
}  // namespace wear
