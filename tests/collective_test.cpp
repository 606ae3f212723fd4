// A load collective in one life (wear/collective.h, docs/wear-loop.md "Load collectives"): one condition
// is the case's own life to the bit; two conditions under the energy law with uniform wear follow the
// closed form 1/L = sum_k w_k/L_k; the thread count does not change a bit; bad weights and conditions are
// refused naming the file, line and key.
#include "wear/collective.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "lib/errors.h"
#include "tests/log_capture.h"
#include "tests/temp_dir.h"
#include "session/sweep.h"
#include "wear/wear_loop.h"

namespace wear {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = ROLLWEAR_SOURCE_DIR;

class Collective : public rollwear_test::TempDirTest {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

LifeResult life_of(const WearCase& c, int threads = 1, LifeCounters* counters = nullptr) {
  WearModel m = make_wear_model(c);
  m.collective_threads = threads;
  WearCache cache;
  const LifeResult r = run_life(m, c, LifeStart{}, LifeHooks{}, cache);
  if (counters) *counters = r.counters;
  return r;
}

void expect_same_life(const LifeResult& a, const LifeResult& b) {
  EXPECT_EQ(a.ended_by, b.ended_by);
  EXPECT_EQ(a.N, b.N);  // to the bit
  ASSERT_EQ(a.state.size(), b.state.size());
  for (Eigen::Index i = 0; i < a.state.size(); ++i) ASSERT_EQ(a.state(i), b.state(i)) << "node " << i;
  EXPECT_EQ(a.counters.steps, b.counters.steps);
  EXPECT_EQ(a.counters.rhs_evals, b.counters.rhs_evals);
  EXPECT_EQ(a.counters.normal_solves, b.counters.normal_solves);
  EXPECT_EQ(a.counters.tangential_solves, b.counters.tangential_solves);
}

// the shipped paper-wear case on a 40 x 40 grid, its wear: section followed by `collective`
std::string paper_wear_with(const std::string& collective) {
  std::string text = read_text(kSource / "cases" / "paper-wear.yaml");
  const std::string anchor = "  snapshots_revolutions: [1.0e7, 3.0e7, 1.0e8]\n";
  const std::size_t at = text.find(anchor);
  EXPECT_NE(at, std::string::npos);
  text.insert(at + anchor.size(), collective);
  const std::string grid = "nx: 80, ny: 80";
  text.replace(text.find(grid), grid.size(), "nx: 40, ny: 40");
  return text;
}

// A collective of one condition of weight 1 is the case's own life: the same revolutions, worn state
// and counts, to the bit (the rate is 1 x f, the limits the one condition's).
TEST_F(Collective, OneConditionIsTheCasesOwnLifeToTheBit) {
  const WearCase plain = read_wear_case(write("plain.yaml", paper_wear_with("")).string());
  const WearCase one = read_wear_case(write("one.yaml", paper_wear_with("  collective: [{ weight: 1 }]\n")).string());
  ASSERT_EQ(one.wear.collective.size(), 1u);
  const LifeResult a = life_of(plain), b = life_of(one);
  EXPECT_EQ(a.ended_by, LifeEnd::Edge);  // on this grid the contact spreads to the crown's edge first
  expect_same_life(a, b);
}

// Two running conditions under the energy law with uniform wear. A flat roller 10 mm wide on a flat path
// 30 mm wide (no crown, no Heathcote slip, no smoothing, the edge limit off) is a line contact over the
// roller's whole width: every strip carries the same load and dissipates the same energy, so the wear is
// uniform, the worn profile is the unworn one shifted, and the contact (hence each condition's rate r_k)
// never changes. The life to the depth D is then D / r_k alone and, for the collective, D / sum_k w_k r_k:
//   1/L = sum_k w_k / L_k   exactly (docs/physics.md §6: the energy law's depth rate is k_E E_l / (2 pi R)).
// The tolerance: the uniform depth is uniform to about 1e-13 relative (the strips' rounding), which is
// what the located root inherits.
constexpr double kHarmonicTolerance = 1e-10;
TEST_F(Collective, TwoConditionsWithUniformWearFollowTheHarmonicCombination) {
  const std::string head = R"(name: flat-line
profiles:
  body1: { flat: { width_m: 0.010 } }
  body2: { flat: { width_m: 0.030 } }
  heathcote_slip: false
bodies:
  body1: { Rx_m: 0.020, E_Pa: 210.0e9, nu: 0.28 }
  body2: { Rx_m: 0.025, E_Pa: 210.0e9, nu: 0.28 }
solver: { normal: semi-hertz, tangential: consistent, nx: 20, ny: 20 }
wear:
  body1: { law: energy, k_E_m3_per_J: 1.0e-13 }
  revolutions: 1.0e12
  limits: { max_depth_m: 1.0e-5, edge: false }
  smoothing_wavelength_m: 0
)";
  const std::string a = "load: { normal_load_N: 1500 }\nkinematics: { speed_m_per_s: 1.0, xi: 1.0e-3 }\nfriction: { mu: 0.3 }\n";
  const std::string b = "load: { normal_load_N: 1000 }\nkinematics: { speed_m_per_s: 2.0, xi: 3.0e-3 }\nfriction: { mu: 0.4 }\n";
  const std::string collective =
      "  collective:\n    - { weight: 0.75 }\n"
      "    - { weight: 0.25, load: { normal_load_N: 1000 }, kinematics: { speed_m_per_s: 2.0, xi: 3.0e-3 }, friction: { mu: 0.4 } }\n";
  const rollwear_test::ExpectWarnings warnings;  // "the contact reaches the end of the profiles' overlap": meant
  const double LA = life_of(read_wear_case(write("a.yaml", head + a).string())).N;
  const double LB = life_of(read_wear_case(write("b.yaml", head + b).string())).N;
  const LifeResult c = life_of(read_wear_case(write("c.yaml", head + collective + a).string()));
  EXPECT_EQ(c.ended_by, LifeEnd::MaxDepth);
  const double expected = 1 / (0.75 / LA + 0.25 / LB);
  EXPECT_NEAR(c.N / expected, 1, kHarmonicTolerance) << "LA " << LA << " LB " << LB << " collective " << c.N;
  EXPECT_GT(LA / LB, 1.5);  // the conditions differ: the test sees the weights
}

// A collective case in a sweep (run_case: its conditions on the case's one thread) ends where the life of
// the same case ends on 2 threads, to the bit.
TEST_F(Collective, SweepCaseIsTheSameLife) {
  const std::string collective =
      "  collective:\n    - { weight: 0.8 }\n    - { weight: 0.2, load: { normal_load_N: 2200 }, kinematics: { xi: 2.0e-3 } }\n";
  std::string text = paper_wear_with(collective);
  text.replace(text.find("max_depth_m: 1.0e-4"), 19, "max_depth_m: 2.0e-5");
  const fs::path path = write("c.yaml", text);
  const session::CaseOutcome row = session::run_case(text, 0, {}, dir_ / "case_0000");
  ASSERT_EQ(row.status, session::CaseStatus::Ok) << row.message;
  const LifeResult life = life_of(read_wear_case(path.string()), 2);
  EXPECT_EQ(row.ended_by, life.ended_by);
  EXPECT_EQ(row.life_revolutions, life.N);  // to the bit
  EXPECT_EQ(row.max_depth_m, max_depth_m(make_wear_model(read_wear_case(path.string())), life.state));
}

// The conditions' rates evaluated on 1 or 2 threads give the same life to the bit (each condition has its
// own model and cache; the weighted sum runs in the conditions' order after every evaluation has ended).
TEST_F(Collective, ThreadsGiveTheSameLifeToTheBit) {
  const std::string collective =
      "  collective:\n    - { weight: 0.6 }\n    - { weight: 0.3, load: { normal_load_N: 2200 }, kinematics: { xi: 2.0e-3 } }\n"
      "    - { weight: 0.1, kinematics: { xi: -1.5e-3 }, friction: { mu: 0.2 } }\n";
  WearCase c = read_wear_case(write("c.yaml", paper_wear_with(collective)).string());
  c.wear.limits.max_depth_m = 3e-5;  // a shorter life: the same steps, fewer of them
  const LifeResult one = life_of(c, 1), two = life_of(c, 2);
  EXPECT_EQ(one.ended_by, LifeEnd::MaxDepth);
  expect_same_life(one, two);
  // and the collective is not any one condition: its life lies between the shortest and the longest
  const LifeResult first = life_of(condition_case(c, 0)), second = life_of(condition_case(c, 1));
  EXPECT_LT(one.N, first.N);
  EXPECT_GT(one.N, second.N);
}

std::string refusal(const fs::path& p) {
  try {
    (void)read_wear_case(p.string());
  } catch (const contact::CaseError& e) {
    return e.what();
  }
  return "(accepted)";
}

// Bad weights and conditions: the file, the line and the key.
TEST_F(Collective, BadWeightsAndConditionsNameFileLineAndKey) {
  const auto with = [&](const std::string& name, const std::string& collective) {
    return refusal(write(name, paper_wear_with(collective)));
  };
  // paper-wear.yaml's wear: snapshots_revolutions is line 29 of the file: the collective starts at 30
  const std::string negative = with("neg.yaml", "  collective:\n    - { weight: 0.5 }\n    - { weight: -0.5 }\n");
  EXPECT_NE(negative.find("neg.yaml:32:17: wear.collective[2].weight: must be > 0 and finite"), std::string::npos) << negative;
  const std::string nan = with("nan.yaml", "  collective:\n    - { weight: .nan }\n");
  EXPECT_NE(nan.find("nan.yaml:31:17: wear.collective[1].weight: must be > 0"), std::string::npos) << nan;
  const std::string missing = with("missing.yaml", "  collective:\n    - { load: { normal_load_N: 2000 } }\n");
  EXPECT_NE(missing.find("missing.yaml:31:7: wear.collective[1].weight: required key is missing"), std::string::npos) << missing;
  const std::string sum = with("sum.yaml", "  collective:\n    - { weight: 0.7 }\n    - { weight: 0.2 }\n");
  EXPECT_NE(sum.find("sum.yaml:31:5: wear.collective: the weights sum to 0.8999999999999999, not 1"), std::string::npos) << sum;
  const std::string empty = with("empty.yaml", "  collective: []\n");
  EXPECT_NE(empty.find("empty.yaml:30:15: wear.collective: needs at least one running condition"), std::string::npos) << empty;
  const std::string typo = with("typo.yaml", "  collective:\n    - { weight: 1, lod: { normal_load_N: 2000 } }\n");
  EXPECT_NE(typo.find("typo.yaml:31:20: wear.collective[1].lod: unknown key, did you mean 'load'?"), std::string::npos) << typo;
  const std::string load = with("load.yaml", "  collective:\n    - { weight: 1, load: { normal_load_N: -2 } }\n");
  EXPECT_NE(load.find("load.yaml:31:43: wear.collective[1].load.normal_load_N: must be > 0"), std::string::npos) << load;
  // a cross-key check of the condition's case: at the condition's key, the condition named
  const std::string speed = with("speed.yaml", "  collective:\n    - { weight: 1, kinematics: { speed_m_per_s: 0 } }\n");
  EXPECT_NE(speed.find("speed.yaml:31:49: kinematics.speed_m_per_s: steady running needs a rolling speed > 0"),
            std::string::npos) << speed;
  EXPECT_NE(speed.find("(in wear.collective[1], the running condition at "), std::string::npos) << speed;
  // a speed history without a transient: section: the condition's duty cycle lacks it (no 'contact' command here)
  const std::string history = with("history.yaml", "  collective:\n    - weight: 1\n      kinematics: { speed_m_per_s: "
                                                   "{ table: [[0, 0], [1.0e-3, 1.8]] } }\n");
  EXPECT_NE(history.find("history.yaml:32:36: kinematics.speed_m_per_s: a history runs as a duty cycle, which needs "
                         "a transient: section"),
            std::string::npos) << history;
  EXPECT_EQ(history.find("'contact'"), std::string::npos) << history;
}

// The shipped collective reads, and its conditions are the ones its comments describe.
TEST(CollectiveCase, ShippedCaseReadsWithItsConditions) {
  const WearCase c = read_wear_case((kSource / "cases" / "collective-duty-mix.yaml").string());
  ASSERT_EQ(c.wear.collective.size(), 3u);
  double sum = 0;
  for (const WearCondition& k : c.wear.collective) sum += k.weight;
  EXPECT_NEAR(sum, 1, kCollectiveWeightSumTolerance);
  const WearModel m = make_wear_model(c);
  ASSERT_EQ(m.conditions.size(), 3u);
  EXPECT_FALSE(m.conditions[0].transient.has_value());
  EXPECT_TRUE(m.conditions[2].transient.has_value());  // the start-stop condition
}

}  // namespace
}  // namespace wear
