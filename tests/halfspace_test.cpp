// The exact half-space normal solver (halfspace.h) against Boussinesq's point load, a direct
// summation of the influence coefficients, and Hertz's closed forms (docs/physics.md §2).
#include "lib/normal/halfspace.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/normal/hertz.h"
#include "lib/numeric.h"
#include "tests/log_capture.h"

namespace contact {
namespace {

constexpr double kBox = 1.25;  // grid half-sizes, in Hertz semi-axes: room for the discrete edge

ElasticPair steel() { return {{210e9, 0.28}, {210e9, 0.28}}; }

struct HertzCase {
  std::string name;
  Bodies bodies;
  double normal_load_N;
};

// two equal spheres; the paper's roller on its path (docs/physics.md §2: a = 0.230290 mm, b = 2.610098 mm,
// p0 = 1191.517 MPa, delta = 9.1991 um); the same turned by 90 degrees (the long axis along x)
std::vector<HertzCase> hertz_cases() {
  return {{"two_spheres", {{0.010, 0.010}, {0.010, 0.010}}, 100},
          {"paper_roller", {{0.020, 0.500}, {0.025, kFlat}}, 1500},
          {"paper_roller_turned", {{0.500, 0.020}, {kFlat, 0.025}}, 1500}};
}

// grid over the Hertz ellipse's box, and the undeformed gap A x^2 + B y^2 at the cell centres
Grid hertz_grid(const HertzContact& h, int n) { return make_grid(kBox * h.a_m, kBox * h.b_m, {n, n}); }

Eigen::ArrayXXd hertz_gap(const HertzContact& h, const Grid& g) {
  Eigen::ArrayXXd gap(g.nx, g.ny);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) gap(i, j) = h.A_per_m * g.x_m(i) * g.x_m(i) + h.B_per_m * g.y_m(j) * g.y_m(j);
  return gap;
}

HalfspaceSolution solve_hertz_gap(const HertzContact& h, const Grid& g) {
  return solve_halfspace(g, hertz_gap(h, g), h.Estar_Pa, h.normal_load_N);
}

double rel(double value, double expected) { return std::abs(value / expected - 1); }

// ---------------------------------------------------------------------------------------------
// influence coefficients

// Far from the cell, unit pressure on dx x dy acts as the point load dx dy: u -> dx dy / (pi E* r).
// The next term of the expansion is the cell's second moment: relative error
//   e(x, y) = [dx^2 (3 x^2/r^2 - 1) + dy^2 (3 y^2/r^2 - 1)] / (24 r^2),
// so the error falls as r^-2.
TEST(HalfspaceInfluence, FarFieldTendsToPointLoadBoussinesq) {
  constexpr double kEstar = 113.9e9;
  constexpr double kNextOrder = 0.05;  // the r^-4 term, relative to e, at 8 cells and beyond
  const double dx = 1e-5, dy = 3e-5;
  double previous_error = 1;
  for (double cells : {8.0, 16.0, 32.0, 64.0}) {
    const double x = 0.6 * cells * dy, y = 0.8 * cells * dy, r = std::hypot(x, y);
    const double point = dx * dy / (kPi * kEstar * r);
    const double u = rectangle_influence_m_per_Pa(x, y, dx, dy, kEstar);
    const double e = (dx * dx * (3 * x * x / (r * r) - 1) + dy * dy * (3 * y * y / (r * r) - 1)) / (24 * r * r);
    EXPECT_NEAR(u / point - 1, e, kNextOrder * std::abs(e)) << cells << " cells";
    EXPECT_LT(std::abs(u / point - 1), previous_error / 3.5) << "error falls as r^-2";
    previous_error = std::abs(u / point - 1);
  }
  EXPECT_LT(previous_error, 1e-4);  // 64 cells away
}

// Love's displacement at the centre of a uniformly loaded c x d half-width rectangle (logarithmic
// form), and at neighbouring points against a midpoint quadrature of dA / r (smooth there).
TEST(HalfspaceInfluence, NearFieldMatchesLoveCentreFormulaAndQuadrature) {
  constexpr double kEstar = 113.9e9;
  constexpr double kQuadratureTol = 1e-6;  // 600 x 600 midpoint panels, integrand smooth off the cell
  const double dx = 2e-5, dy = 2.2e-4;     // the paper's cell shape on a square grid: dy/dx = 11
  const double c = dx / 2, d = dy / 2, diag = std::hypot(c, d);
  const double centre = 4 * (c * std::log((diag + d) / c) + d * std::log((diag + c) / d)) / (kPi * kEstar);
  EXPECT_NEAR(rectangle_influence_m_per_Pa(0, 0, dx, dy, kEstar) / centre, 1, 1e-14);

  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{dx, 0}, {0, dy}, {1.5 * dx, 0.7 * dy}, {-3 * dx, 2 * dy}}) {
    const int n = 600;
    double sum = 0;
    for (int q = 0; q < n; ++q)
      for (int k = 0; k < n; ++k) {
        const double xs = -c + (k + 0.5) * dx / n, ys = -d + (q + 0.5) * dy / n;
        sum += 1 / std::hypot(x - xs, y - ys);
      }
    const double quadrature = sum * (dx / n) * (dy / n) / (kPi * kEstar);
    EXPECT_NEAR(rectangle_influence_m_per_Pa(x, y, dx, dy, kEstar) / quadrature, 1, kQuadratureTol)
        << "at (" << x / dx << " dx, " << y / dy << " dy)";
  }
}

// ---------------------------------------------------------------------------------------------
// Hertz

class HalfspaceHertz : public testing::TestWithParam<HertzCase> {};

TEST_P(HalfspaceHertz, PeakPressureSemiAxesAndApproachMatchHertz) {
  constexpr double kFineGridTol = 0.01;  // issue goal; 64 x 64 over 1.25 a x 1.25 b gives <= 0.15 %
  const HertzContact h = solve_hertz(GetParam().bodies, steel(), GetParam().normal_load_N);
  const Grid g = hertz_grid(h, 64);
  const HalfspaceSolution s = solve_hertz_gap(h, g);
  ASSERT_TRUE(s.status.converged()) << s.status.message;
  // semi-axes of the pressure field: its strips' refined extents (halfspace_patch)
  const ContactPatch patch = halfspace_patch(s, g, h.normal_load_N);
  EXPECT_NEAR(rel(s.pressure_Pa.maxCoeff(), h.p0_Pa), 0, kFineGridTol);
  EXPECT_NEAR(rel(patch.a_m, h.a_m), 0, kFineGridTol);
  EXPECT_NEAR(rel(patch.b_m, h.b_m), 0, kFineGridTol);
  EXPECT_NEAR(rel(s.approach_m, h.approach_m), 0, kFineGridTol);
  EXPECT_NEAR(rel(s.contact_area_m2, kPi * h.a_m * h.b_m), 0, 2 * kFineGridTol);  // whole cells: 1.6 % at 64
}

TEST_P(HalfspaceHertz, PressureCarriesTheLoadExactly) {
  constexpr double kRounding = 1e-12;
  const HertzContact h = solve_hertz(GetParam().bodies, steel(), GetParam().normal_load_N);
  for (int n : {16, 48}) {
    const Grid g = hertz_grid(h, n);
    const HalfspaceSolution s = solve_hertz_gap(h, g);
    EXPECT_NEAR(s.pressure_Pa.sum() * g.dx_m * g.dy_m / h.normal_load_N, 1, kRounding) << n << " x " << n;
    EXPECT_TRUE((s.pressure_Pa >= 0).all());
  }
}

// The errors against Hertz shrink as the grid is refined (about second order for the peak).
TEST_P(HalfspaceHertz, ErrorsShrinkAsTheGridIsRefined) {
  const HertzContact h = solve_hertz(GetParam().bodies, steel(), GetParam().normal_load_N);
  std::vector<double> p0_error, approach_error;
  for (int n : {16, 32, 64}) {
    const HalfspaceSolution s = solve_hertz_gap(h, hertz_grid(h, n));
    p0_error.push_back(rel(s.pressure_Pa.maxCoeff(), h.p0_Pa));
    approach_error.push_back(rel(s.approach_m, h.approach_m));
  }
  for (std::size_t k = 1; k < p0_error.size(); ++k) {
    EXPECT_LT(p0_error[k], p0_error[k - 1] / 2) << "peak pressure, refinement " << k;
    EXPECT_LT(approach_error[k], approach_error[k - 1]) << "approach, refinement " << k;
  }
  EXPECT_LT(approach_error.back(), approach_error.front() / 5);
}

// Strips: each carries its row's load, so together they carry the normal load; the equivalent
// ellipse is Hertz's.
TEST_P(HalfspaceHertz, PatchStripsIntegrateToTheLoad) {
  constexpr double kRounding = 1e-12;
  constexpr double kFineGridTol = 0.01;   // as above
  constexpr double kStripEdgeTol = 0.02;  // 48 cells along x: the edge within about a third of a cell
  const HertzContact h = solve_hertz(GetParam().bodies, steel(), GetParam().normal_load_N);
  const Grid g = hertz_grid(h, 48);
  const HalfspaceSolution s = solve_hertz_gap(h, g);
  const ContactPatch patch = halfspace_patch(s, g, h.normal_load_N);
  double strips_N = 0;
  for (int j = 0; j < g.ny; ++j) {
    const double row_N = s.pressure_Pa.col(j).sum() * g.dx_m * g.dy_m;
    const double strip_N = kPi / 2 * patch.strip_peak_Pa(j) * patch.half_length_m(j) * g.dy_m;
    EXPECT_NEAR(strip_N, row_N, kRounding * h.normal_load_N) << "strip " << j;
    EXPECT_LE(patch.half_length_m(j), g.half_x_m);
    const double s2 = std::pow(g.y_m(j) / h.b_m, 2);
    if (s2 < 0.75) {  // Hertz strips a sqrt(1 - y^2/b^2), away from the lateral ends
      EXPECT_NEAR(rel(patch.half_length_m(j), h.a_m * std::sqrt(1 - s2)), 0, kStripEdgeTol) << "strip " << j;
    }
    strips_N += strip_N;
  }
  EXPECT_NEAR(strips_N / h.normal_load_N, 1, kRounding);
  EXPECT_NEAR(patch.pressure_Pa.sum() * g.dx_m * g.dy_m / h.normal_load_N, 1, kRounding);
  EXPECT_NEAR(rel(patch.p0_Pa, h.p0_Pa), 0, kFineGridTol);
  EXPECT_NEAR(rel(patch.a_m, h.a_m), 0, kFineGridTol);
  EXPECT_NEAR(rel(patch.b_m, h.b_m), 0, kFineGridTol);
  EXPECT_EQ(patch.approach_m, s.approach_m);
  EXPECT_EQ(patch.normal_load_N, h.normal_load_N);
}

INSTANTIATE_TEST_SUITE_P(HalfspaceHertzCases, HalfspaceHertz, testing::ValuesIn(hertz_cases()),
                         [](const testing::TestParamInfo<HertzCase>& param_info) { return param_info.param.name; });

// ---------------------------------------------------------------------------------------------
// contact conditions

void separation_vanishes_under_load_and_is_open_elsewhere(GridSpec n) {
  constexpr double kGapTol = 1e-8;  // of delta: residual tol 1e-9 plus rounding of the two sums
  const HertzContact h = solve_hertz({{0.020, 0.500}, {0.025, kFlat}}, steel(), 1500);
  const Grid g = make_grid(kBox * h.a_m, kBox * h.b_m, n);
  const Eigen::ArrayXXd gap = hertz_gap(h, g);
  const HalfspaceSolution s = solve_halfspace(g, gap, h.Estar_Pa, 1500);
  ASSERT_TRUE(s.status.converged()) << s.status.message;
  int loaded = 0, open = 0;
  for (int l = 0; l < g.ny; ++l)
    for (int k = 0; k < g.nx; ++k) {
      double u = 0;
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
          u += rectangle_influence_m_per_Pa(g.x_m(k) - g.x_m(i), g.y_m(l) - g.y_m(j), g.dx_m, g.dy_m, h.Estar_Pa) *
               s.pressure_Pa(i, j);
      const double separation = gap(k, l) + u - s.approach_m;
      if (s.pressure_Pa(k, l) > 0) {
        EXPECT_NEAR(separation / s.approach_m, 0, kGapTol) << "loaded cell " << k << ", " << l;
        ++loaded;
      } else {
        EXPECT_GE(separation / s.approach_m, -kGapTol) << "unloaded cell " << k << ", " << l;
        ++open;
      }
    }
  EXPECT_GT(loaded, 100);
  EXPECT_GT(open, 100);
}

// The converged pressure against a direct O(N^2) summation of the influence coefficients (not the
// FFT): the separation h + K p - delta vanishes on the loaded cells and is non-negative elsewhere.
// On 24 x 24 (padded to 48 x 48) and on 25 x 14, whose padded lengths are 49 = 2 x 25 - 1 and
// 27 = 2 x 14 - 1 (fft_size): the kernel's offsets -(n-1)..(n-1) fill the padded grid without a gap.
TEST(HalfspaceComplementarity, SeparationVanishesUnderLoadAndIsOpenElsewhere) {
  for (const GridSpec n : {GridSpec{24, 24}, GridSpec{25, 14}}) {
    SCOPED_TRACE(std::to_string(n.nx) + " x " + std::to_string(n.ny));
    separation_vanishes_under_load_and_is_open_elsewhere(n);
  }
}

// Outside the Hertz ellipse the gap opens: no pressure beyond the cells the edge cuts.
TEST(HalfspaceComplementarity, NoPressureOutsideTheHertzEllipse) {
  const HertzContact h = solve_hertz({{0.010, 0.010}, {0.010, 0.010}}, steel(), 100);
  const Grid g = hertz_grid(h, 64);
  const HalfspaceSolution s = solve_hertz_gap(h, g);
  const double margin = 1 + 1.5 * g.dx_m / h.a_m;  // the discrete edge may reach one cell out
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double rho = std::hypot(g.x_m(i) / h.a_m, g.y_m(j) / h.b_m);
      if (rho > margin) {
        EXPECT_EQ(s.pressure_Pa(i, j), 0.0) << i << ", " << j;
      }
      if (rho < 0.95) {
        EXPECT_GT(s.pressure_Pa(i, j), 0.0) << i << ", " << j;
      }
    }
}

// A groove deeper than the approach across the contact stays open: exactly zero pressure in it, and
// the load moves to either side.
TEST(HalfspaceComplementarity, OpenGrooveCarriesNoPressure) {
  const HertzContact h = solve_hertz({{0.010, 0.010}, {0.010, 0.010}}, steel(), 100);
  const Grid g = hertz_grid(h, 48);
  Eigen::ArrayXXd gap = hertz_gap(h, g);
  std::vector<int> groove;
  for (int i = 0; i < g.nx; ++i)
    if (std::abs(g.x_m(i)) < 0.2 * h.a_m) groove.push_back(i);
  ASSERT_GE(groove.size(), 3u);
  for (int i : groove) gap.row(i) += 10 * h.approach_m;
  const HalfspaceSolution s = solve_halfspace(g, gap, h.Estar_Pa, 100);
  ASSERT_TRUE(s.status.converged()) << s.status.message;
  for (int i : groove) EXPECT_TRUE((s.pressure_Pa.row(i) == 0).all()) << "groove row " << i;
  EXPECT_NEAR(s.pressure_Pa.sum() * g.dx_m * g.dy_m / 100, 1, 1e-12);
  EXPECT_GT(s.approach_m, h.approach_m);  // less contact, more approach for the same load
}

// ---------------------------------------------------------------------------------------------
// status, logging, input

TEST(HalfspaceStatus, ConvergedMessageCarriesResidualToleranceAndIterations) {
  const HertzContact h = solve_hertz({{0.010, 0.010}, {0.010, 0.010}}, steel(), 100);
  const Grid g = hertz_grid(h, 32);
  const HalfspaceSolution s = solve_hertz_gap(h, g);
  ASSERT_TRUE(s.status.converged());
  EXPECT_FALSE(s.reaches_border);  // hertz_grid holds the contact
  EXPECT_LE(s.status.residual, 1e-9);
  EXPECT_GT(s.status.iterations, 0);
  EXPECT_NE(s.status.message.find("<= tol 1e-09 after " + std::to_string(s.status.iterations) + " iterations"),
            std::string::npos)
      << s.status.message;
}

TEST(HalfspaceStatus, IterationLimitWarnsAndStillCarriesTheLoad) {
  const HertzContact h = solve_hertz({{0.020, 0.500}, {0.025, kFlat}}, steel(), 1500);
  const Grid g = hertz_grid(h, 32);
  const rollwear_test::ExpectWarnings warnings;
  const HalfspaceSolution s = solve_halfspace(g, hertz_gap(h, g), h.Estar_Pa, 1500, {1e-9, 3});
  EXPECT_EQ(s.status.kind, SolveStatus::Kind::MaxIterations);
  EXPECT_EQ(s.status.iterations, 3);
  EXPECT_GT(s.status.residual, 1e-9);
  EXPECT_NE(s.status.message.find("> tol 1e-09 after 3 iterations"), std::string::npos) << s.status.message;
  ASSERT_EQ(warnings.count(), 1);
  EXPECT_NE(warnings.messages()[0].find("not converged"), std::string::npos);
  EXPECT_NEAR(s.pressure_Pa.sum() * g.dx_m * g.dy_m / 1500, 1, 1e-12);
}

TEST(HalfspaceStatus, ContactCutByTheGridBorderWarns) {
  const HertzContact h = solve_hertz({{0.010, 0.010}, {0.010, 0.010}}, steel(), 100);
  const Grid g = make_grid(0.8 * h.a_m, 0.8 * h.b_m, {16, 16});
  const rollwear_test::ExpectWarnings warnings;
  const HalfspaceSolution s = solve_hertz_gap(h, g);
  EXPECT_TRUE(s.status.converged()) << s.status.message;
  EXPECT_TRUE(s.reaches_border);  // the cut is data; the warning tells the user
  ASSERT_EQ(warnings.count(), 1);
  EXPECT_NE(warnings.messages()[0].find("border"), std::string::npos) << warnings.messages()[0];
}

TEST(Halfspace, RejectsBadInput) {
  const HertzContact h = solve_hertz({{0.010, 0.010}, {0.010, 0.010}}, steel(), 100);
  const Grid g = hertz_grid(h, 16);
  const Eigen::ArrayXXd gap = hertz_gap(h, g);
  EXPECT_THROW(solve_halfspace(g, Eigen::ArrayXXd::Zero(16, 15), h.Estar_Pa, 100), std::invalid_argument);
  EXPECT_THROW(solve_halfspace(g, gap, h.Estar_Pa, 0), std::invalid_argument);
  EXPECT_THROW(solve_halfspace(g, gap, h.Estar_Pa, -1), std::invalid_argument);
  EXPECT_THROW(solve_halfspace(g, gap, h.Estar_Pa, std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(solve_halfspace(g, gap, 0, 100), std::invalid_argument);
  EXPECT_THROW(solve_halfspace(g, gap, -h.Estar_Pa, 100), std::invalid_argument);
  Eigen::ArrayXXd nan_gap = gap;
  nan_gap(3, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solve_halfspace(g, nan_gap, h.Estar_Pa, 100), std::invalid_argument);
  EXPECT_THROW(solve_halfspace(g, gap, h.Estar_Pa, 100, {0, 10}), std::invalid_argument);
  EXPECT_THROW(solve_halfspace(g, gap, h.Estar_Pa, 100, {1e-9, 0}), std::invalid_argument);

  const HalfspaceSolution s = solve_halfspace(g, gap, h.Estar_Pa, 100);
  EXPECT_THROW(halfspace_patch(s, hertz_grid(h, 17), 100), std::invalid_argument);  // other grid
  EXPECT_THROW(halfspace_patch(s, g, 101), std::invalid_argument);                  // other load
  EXPECT_THROW(halfspace_patch(s, g, 0), std::invalid_argument);
}

}  // namespace
}  // namespace contact
