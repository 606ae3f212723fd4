// The relaxed model's per-strip power distribution (its strip weights, lib/tangential/relaxed_shape.h) against
// Kalker's exact theory in-house: the exact per-strip power on the paper's contact (cases/paper.yaml, a/b = 0.088)
// extrapolated from 80², 160², 320² cells (tests/data/fast_model/exact_strips.csv, with the command that made it:
// scripts/strip-power-reference), the model on 80².
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "lib/io/case_run.h"
#include "lib/history.h"
#include "lib/io/case.h"
#include "lib/csv_reader.h"

namespace contact {
namespace {

const std::string kSource = std::string(ROLLWEAR_SOURCE_DIR);

// the target, not loosened: the distribution over the strips (normalised to unit total) within 10 %
// (relative L1) of the exact theory's, extrapolated; that distribution is the shape of the worn profile
constexpr double kStripTarget = 0.10;

std::map<std::string, std::vector<double>> exact_strips() {
  std::map<std::string, std::vector<double>> m;
  for (const auto& r : read_csv_table(kSource + "/tests/data/fast_model/exact_strips.csv").rows)
    m[r.at(0)].push_back(std::stod(r.at(5)));
  return m;
}

// relative L1 distance of the two distributions, each normalised to unit total
double relative_l1(const Eigen::ArrayXd& model, const std::vector<double>& exact) {
  double se = 0;
  for (const double v : exact) se += v;
  const double sm = model.sum();
  double d = 0;
  for (std::size_t j = 0; j < exact.size(); ++j) d += std::abs(model(Eigen::Index(j)) / sm - exact[j] / se);
  return d;
}

void expect_within_target(const std::string& name, double xi, double eta, double phi) {
  const auto exact = exact_strips();
  ASSERT_EQ(exact.count(name), 1u) << name;
  ContactCase c = read_contact_case(kSource + "/cases/paper.yaml");
  c.solver.tangential = TangentialScheme::Relaxed;
  c.kinematics.xi = constant_history(xi);
  c.kinematics.eta = constant_history(eta);
  c.kinematics.phi_per_m = constant_history(phi);
  const ContactRun r = solve_contact_case(c, false);
  ASSERT_EQ(r.solution.strip_power_W_per_m.size(), Eigen::Index(exact.at(name).size()));
  const double l1 = relative_l1(r.solution.strip_power_W_per_m, exact.at(name));
  std::cout << "[ strips  ] " << name << ": relative L1 against the exact (extrapolated) " << 100 * l1 << " %\n";
  EXPECT_LE(l1, kStripTarget) << name;
}

// pure xi = 1e-3 (|Fx| = 0.34 mu N): the weights' thin-contact gain kept (1.7 % with p = p0 alone)
TEST(StripPower, PureXiLowLevel) { expect_within_target("xi_low", 1e-3, 0, 0); }

// xi = 4e-3 (|Fx| = 0.92 mu N): near full slip the exact and the springs' strip powers tend to the same
// mu integral of p |s| dx (11.2 % with p = p0 whatever the level)
TEST(StripPower, PureXiNearSaturation) { expect_within_target("xi_90", 4e-3, 0, 0); }

// xi, eta and spin together (spin's share of the creep work 0.96): spin's power grows towards the outer strips
// (20.5 % with p = p0 whatever the spin)
TEST(StripPower, ThreeCreepageMix) { expect_within_target("mix", 5e-4, 5e-4, 4.0); }

}  // namespace
}  // namespace contact
