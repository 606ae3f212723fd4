// rollwear sweep (session/sweep.h, docs/sweeps.md): the generator and inverse CDFs against reference values
// and closed forms, the sweep file's grid and sampling, the validation of every case before any runs,
// and the command: threads, shards merged and a resumed run all give the whole sweep's table to the bit.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lib/errors.h"
#include "temp_dir.h"
#include "session/sweep.h"
#include "session/sweep_summary.h"

namespace {

namespace fs = std::filesystem;
using rollwear_test::TempDirTest;
using namespace wear;
using namespace session;

const fs::path kSource = ROLLWEAR_SOURCE_DIR;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream t;
  t << in.rdbuf();
  return t.str();
}
void write_text(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

// ---- generator and inverse CDFs ----

TEST(SweepRandom, SplitMix64MatchesTheReferenceStream) {
  // Vigna's splitmix64.c seeded with 1234567: its first five outputs
  const std::uint64_t expected[] = {6457827717110365317ull, 3203168211198807973ull, 9817491932198370423ull,
                                    4593380528125082431ull, 16408922859458223821ull};
  for (std::uint64_t i = 0; i < 5; ++i) EXPECT_EQ(splitmix64_stream(1234567, i), expected[i]) << "output " << i;
}

TEST(SweepRandom, UniformIsInsideTheOpenIntervalAndFlat) {
  // 10^5 draws: every decile holds 1/10 of them within 5 binomial standard deviations (sqrt(n p (1-p)) = 95)
  constexpr int kDraws = 100000;
  constexpr double kSigmas = 5;
  std::vector<int> deciles(10, 0);
  for (int i = 0; i < kDraws; ++i) {
    const double u = unit_uniform(7, static_cast<std::uint64_t>(i), 0);
    ASSERT_GT(u, 0.0);
    ASSERT_LT(u, 1.0);
    ++deciles[static_cast<std::size_t>(u * 10)];
  }
  const double sd = std::sqrt(kDraws * 0.1 * 0.9);
  for (int d = 0; d < 10; ++d) EXPECT_NEAR(deciles[static_cast<std::size_t>(d)], kDraws / 10.0, kSigmas * sd) << "decile " << d;
}

TEST(SweepRandom, NormalQuantileMatchesTabulatedValues) {
  // Acklam's approximation: relative error below 1.15e-9 over (0, 1); reference quantiles to 16 digits
  constexpr double kRelative = 1.2e-9;
  const std::pair<double, double> table[] = {
      {0.5, 0.0},
      {0.975, 1.959963984540054},
      {0.8413447460685429, 1.0},  // Phi(1)
      {0.001, -3.090232306167814},
      {1e-10, -6.361340902404056},
      {0.999, 3.090232306167814},
  };
  for (const auto& [p, x] : table) EXPECT_NEAR(normal_quantile(p), x, kRelative * std::abs(x) + 1e-15) << "p = " << p;
  EXPECT_THROW(normal_quantile(0.0), std::invalid_argument);
  EXPECT_THROW(normal_quantile(1.0), std::invalid_argument);
}

TEST(SweepRandom, DistributionsHaveTheirMomentsAndBounds) {
  // 4 x 10^4 Monte Carlo draws per input: sample statistics within 5 standard errors of the closed forms
  constexpr int kDraws = 40000;
  constexpr double kSigmas = 5;
  RandomInput normal{"a", "", Distribution::Normal};
  normal.mean = 5;
  normal.sd = 2;
  RandomInput lognormal{"b", "", Distribution::LogNormal};
  lognormal.median = 1e-4;
  lognormal.sigma_ln = 0.5;
  RandomInput truncated{"c", "", Distribution::TruncatedNormal};
  truncated.mean = 0.3;
  truncated.sd = 0.05;
  truncated.min = 0.25;
  truncated.max = 0.45;
  double sum = 0, sum2 = 0;
  int below_median = 0, below_mean = 0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = quantile(normal, unit_uniform(11, static_cast<std::uint64_t>(i), 0));
    sum += x;
    sum2 += x * x;
    if (quantile(lognormal, unit_uniform(11, static_cast<std::uint64_t>(i), 1)) < 1e-4) ++below_median;
    const double t = quantile(truncated, unit_uniform(11, static_cast<std::uint64_t>(i), 2));
    ASSERT_GE(t, 0.25);
    ASSERT_LE(t, 0.45);
    if (t < 0.3) ++below_mean;
  }
  const double mean = sum / kDraws, sd = std::sqrt(sum2 / kDraws - mean * mean);
  EXPECT_NEAR(mean, 5.0, kSigmas * 2 / std::sqrt(kDraws));
  EXPECT_NEAR(sd, 2.0, kSigmas * 2 / std::sqrt(2.0 * kDraws));
  const double binomial_sd = std::sqrt(0.25 / kDraws);
  EXPECT_NEAR(below_median / double(kDraws), 0.5, kSigmas * binomial_sd);
  // truncated to [mean - sd, mean + 3 sd]: P(x < mean) = (Phi(0) - Phi(-1)) / (Phi(3) - Phi(-1))
  const double p = (0.5 - normal_cdf(-1)) / (normal_cdf(3) - normal_cdf(-1));
  EXPECT_NEAR(below_mean / double(kDraws), p, kSigmas * std::sqrt(p * (1 - p) / kDraws));
}

// ---- the sweep file ----

class SweepFile : public TempDirTest {
 protected:
  // the base case: the paper's worn roller on a coarse grid, to a 20 um depth (about 20 ms a life)
  void SetUp() override {
    TempDirTest::SetUp();
    std::string base = read_text(kSource / "cases" / "paper-wear.yaml");
    base = std::regex_replace(base, std::regex("nx: 80, ny: 80"), "nx: 16, ny: 16");
    base = std::regex_replace(base, std::regex("max_depth_m: 1.0e-4"), "max_depth_m: 2.0e-5");
    base = std::regex_replace(base, std::regex("snapshots_revolutions:.*\n"), "");
    base = std::regex_replace(base, std::regex("output:.*\n"), "");
    write_text(dir_ / "base.yaml", base);
  }
  fs::path sweep_file(const std::string& body, const std::string& name = "sweep.yaml") {
    write_text(dir_ / name, "base: base.yaml\n" + body);
    return dir_ / name;
  }
};

TEST_F(SweepFile, ProductGridVariesTheLastAxisFastestWithRangesEndingAsWritten) {
  const Sweep s = read_sweep(sweep_file(
      "axes:\n"
      "  - { key: friction.mu, values: [0.2, 0.3] }\n"
      "  - { key: load.normal_load_N, linear: { from: 1000, to: 2000, count: 3 } }\n"
      "  - { key: wear.body1.archard_k, log: { from: 1.0e-6, to: 1.0e-4, count: 3 } }\n").string());
  ASSERT_EQ(case_count(s), 18);
  EXPECT_EQ(varied_keys(s), (std::vector<std::string>{"friction.mu", "load.normal_load_N", "wear.body1.archard_k"}));
  EXPECT_EQ(case_inputs(s, 0), (std::vector<double>{0.2, 1000, 1e-6}));
  EXPECT_EQ(case_inputs(s, 17), (std::vector<double>{0.3, 2000, 1e-4}));
  EXPECT_EQ(case_inputs(s, 4)[1], 1500.0);
  // the log range's middle is the geometric mean, to rounding of exp(log(.)) (a few ulp)
  EXPECT_NEAR(case_inputs(s, 1)[2], 1e-5, 1e-5 * 1e-14);
  EXPECT_THROW(case_inputs(s, 18), std::out_of_range);
}

TEST_F(SweepFile, ZipPairsTheAxesAndNeedsOneLength) {
  const Sweep s = read_sweep(sweep_file(
      "combine: zip\naxes:\n  - { key: friction.mu, values: [0.2, 0.3] }\n  - { key: load.normal_load_N, values: [1000, 1200] }\n")
                                 .string());
  ASSERT_EQ(case_count(s), 2);
  EXPECT_EQ(case_inputs(s, 1), (std::vector<double>{0.3, 1200}));
  try {
    read_sweep(sweep_file("combine: zip\naxes:\n  - { key: friction.mu, values: [0.2, 0.3] }\n"
                          "  - { key: load.normal_load_N, values: [1000] }\n").string());
    FAIL() << "no error";
  } catch (const contact::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("sweep.yaml:5:5: axes: load.normal_load_N"), std::string::npos) << e.what();
  }
}

TEST_F(SweepFile, RandomCaseDependsOnSeedAndIndexAlone) {
  const auto random = [&](int count, int seed, const std::string& method) {
    return read_sweep(sweep_file("random:\n  method: " + method + "\n  count: " + std::to_string(count) + "\n  seed: " +
                                 std::to_string(seed) +
                                 "\n  inputs:\n    - { key: friction.mu, distribution: uniform, min: 0, max: 1 }\n"
                                 "    - { key: load.normal_load_N, distribution: normal, mean: 1500, sd: 100 }\n")
                          .string());
  };
  const Sweep few = random(10, 5, "monte-carlo"), many = random(1000, 5, "monte-carlo"), other = random(10, 6, "monte-carlo");
  for (long i = 0; i < 10; ++i) {
    EXPECT_EQ(case_inputs(few, i), case_inputs(many, i)) << "case " << i;
    EXPECT_NE(case_inputs(few, i), case_inputs(other, i)) << "case " << i;
  }
  // a Latin hypercube: every one of the n strata of each input holds exactly one case
  constexpr long kCount = 50;
  const Sweep lhs = random(kCount, 5, "latin-hypercube");
  std::set<long> strata;
  for (long i = 0; i < kCount; ++i) strata.insert(static_cast<long>(case_inputs(lhs, i)[0] * kCount));
  EXPECT_EQ(strata.size(), static_cast<std::size_t>(kCount));
  EXPECT_EQ(*strata.begin(), 0);
  EXPECT_EQ(*strata.rbegin(), kCount - 1);
}

TEST_F(SweepFile, RankCorrelationReachesItsTargetAndKeepsTheMarginals) {
  // Iman-Conover on a 400-case Latin hypercube: Spearman's rho within 0.05 of the target (the method's
  // error is O(1/sqrt(n)), 0.05 = 1/sqrt(400)), each input's values (and so its strata) unchanged
  constexpr long kCount = 400;
  constexpr double kRhoTolerance = 0.05;
  const std::string inputs =
      "random:\n  method: latin-hypercube\n  count: 400\n  seed: 9\n  inputs:\n"
      "    - { key: friction.mu, distribution: uniform, min: 0, max: 1 }\n"
      "    - { key: load.normal_load_N, distribution: normal, mean: 1500, sd: 100 }\n"
      "    - { key: wear.body1.archard_k, distribution: lognormal, median: 1.0e-4, sigma_ln: 0.5 }\n";
  const Sweep plain = read_sweep(sweep_file(inputs).string());
  const Sweep s = read_sweep(
      sweep_file(inputs + "  correlation: [[1, 0.7, 0], [0.7, 1, -0.4], [0, -0.4, 1]]\n", "correlated.yaml").string());
  std::vector<std::vector<double>> column(3), plain_column(3);
  for (long i = 0; i < kCount; ++i)
    for (std::size_t a = 0; a < 3; ++a) {
      column[a].push_back(case_inputs(s, i)[a]);
      plain_column[a].push_back(case_inputs(plain, i)[a]);
    }
  EXPECT_NEAR(spearman(column[0], column[1]), 0.7, kRhoTolerance);
  EXPECT_NEAR(spearman(column[1], column[2]), -0.4, kRhoTolerance);
  EXPECT_NEAR(spearman(column[0], column[2]), 0.0, kRhoTolerance);
  EXPECT_GT(std::abs(spearman(plain_column[0], plain_column[1]) - 0.7), 0.5) << "uncorrelated draws already correlated";
  for (std::size_t a = 0; a < 3; ++a) {
    std::sort(column[a].begin(), column[a].end());
    std::sort(plain_column[a].begin(), plain_column[a].end());
    EXPECT_EQ(column[a], plain_column[a]) << "input " << a;
  }
  // a matrix no correlation can have: refused at its line
  try {
    read_sweep(sweep_file(inputs + "  correlation: [[1, 0.9, -0.9], [0.9, 1, 0.9], [-0.9, 0.9, 1]]\n", "bad.yaml").string());
    FAIL() << "no error";
  } catch (const contact::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml:10:16: random.correlation: must be positive definite"), std::string::npos) << e.what();
  }
}

TEST(SweepRandom, SpearmanOfMonotoneAndReversedSamples) {
  const std::vector<double> x = {0.3, 1.0, -2.0, 5.0, 4.0};
  std::vector<double> cube, reversed;
  for (const double v : x) cube.push_back(v * v * v), reversed.push_back(-std::exp(v));
  EXPECT_DOUBLE_EQ(spearman(x, cube), 1.0);
  EXPECT_DOUBLE_EQ(spearman(x, reversed), -1.0);
}

TEST_F(SweepFile, ShippedSweepsReadAndEveryCaseIsValid) {
  for (const char* name : {"sweep-grid.yaml", "sweep-monte-carlo.yaml", "sweep-contact.yaml"}) {
    const Sweep s = read_sweep((kSource / "cases" / name).string());
    std::vector<long> all(static_cast<std::size_t>(case_count(s)));
    for (long i = 0; i < case_count(s); ++i) all[static_cast<std::size_t>(i)] = i;
    EXPECT_NO_THROW(validate_cases(s, all)) << name;
    EXPECT_FALSE(fs::exists(dir_ / "scratch.yaml"));
  }
}

// the error of validate_cases, "" if none
std::string validation_error(const Sweep& s) {
  std::vector<long> all;
  for (long i = 0; i < case_count(s); ++i) all.push_back(i);
  try {
    validate_cases(s, all);
  } catch (const contact::CaseError& e) {
    return e.what();
  }
  return "";
}

TEST_F(SweepFile, BadValueNamesTheSweepFileLineKeyAndCase) {
  const Sweep s = read_sweep(sweep_file("axes:\n  - { key: load.normal_load_N, values: [1000, 1500] }\n"
                                        "  - { key: friction.mu, values: [0.3, -0.1] }\n").string());
  const std::string e = validation_error(s);
  EXPECT_NE(e.find((dir_ / "sweep.yaml").string() + ":4:5: friction.mu: case 1's value -0.1 is refused: "), std::string::npos) << e;
  EXPECT_NE(e.find("case_0001/case.yaml:"), std::string::npos) << e;  // the reader's own message, its line
}

TEST_F(SweepFile, KeyTheBaseCaseLacksIsAnError) {
  // a misspelt leaf: the case reader's unknown key, blamed on the axis; a missing parent: the sweep's own
  const std::string leaf = validation_error(
      read_sweep(sweep_file("axes:\n  - { key: friction.muu, values: [0.3] }\n").string()));
  EXPECT_NE(leaf.find("sweep.yaml:3:5: friction.muu:"), std::string::npos) << leaf;
  EXPECT_NE(leaf.find("unknown key"), std::string::npos) << leaf;
  const std::string parent = validation_error(
      read_sweep(sweep_file("axes:\n  - { key: frction.mu, values: [0.3] }\n").string()));
  EXPECT_NE(parent.find("sweep.yaml:3:5: frction.mu: the base case"), std::string::npos) << parent;
}

TEST_F(SweepFile, FailedCaseIsARowNotAnException) {
  CaseOutcome o;
  ASSERT_NO_THROW(o = run_case("name: broken\nfriction: { mu: 0.3 }\n", 3, {0.3}, dir_ / "case_0003"));
  EXPECT_EQ(o.status, CaseStatus::BadInput);
  EXPECT_FALSE(o.message.empty());
  EXPECT_EQ(read_text(dir_ / "case_0003" / "row.csv"), results_row(o));
  EXPECT_EQ(row_status(results_row(o), 1), CaseStatus::BadInput);
  EXPECT_EQ(row_index(results_row(o)), 3);
}

// ---- the command ----

struct Process {
  int exit_code = -1;
  std::string out, err;
};
Process rollwear(const std::string& args, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = "'" + std::string(ROLLWEAR_EXE) + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  Process r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}
std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

TEST_F(SweepFile, ThreadsShardsAndResumeGiveTheWholeSweepsTable) {
  const fs::path sweep = sweep_file(
      "axes:\n  - { key: load.normal_load_N, values: [1000, 2000] }\n"
      "  - { key: wear.body1.archard_k, log: { from: 1.0e-5, to: 1.0e-4, count: 3 } }\n");
  const std::string quiet = " -q --log-level warn";
  const Process whole = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "whole") + " -j 2" + quiet, dir_);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const std::string table = read_text(dir_ / "whole" / "results.csv");
  ASSERT_EQ(std::count(table.begin(), table.end(), '\n'), 7) << table;
  EXPECT_EQ(table.find(",failed,"), std::string::npos) << table;
  EXPECT_TRUE(fs::exists(dir_ / "whole" / "case_0005" / "summary.csv"));
  EXPECT_TRUE(fs::exists(dir_ / "whole" / "case_0005" / "report.txt"));

  const Process one = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "one") + " -j 1" + quiet, dir_);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(read_text(dir_ / "one" / "results.csv"), table);

  std::string shards;
  for (int k = 1; k <= 3; ++k) {
    const fs::path d = dir_ / ("shard" + std::to_string(k));
    const Process p = rollwear("sweep " + q(sweep) + " --shard " + std::to_string(k) + "/3 -o " + q(d) + quiet, dir_);
    ASSERT_EQ(p.exit_code, 0) << p.err;
    shards += " " + q(d);
  }
  const Process merged = rollwear("sweep --merge" + shards + " -o " + q(dir_ / "merged") + quiet, dir_);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(read_text(dir_ / "merged" / "results.csv"), table);
  // a shard left out: an error naming the missing cases, not a short table
  const Process partial = rollwear("sweep --merge " + q(dir_ / "shard1") + " -o " + q(dir_ / "partial") + quiet, dir_);
  EXPECT_EQ(partial.exit_code, 2);
  EXPECT_NE(partial.err.find("4 of 6 cases missing"), std::string::npos) << partial.err;

  // killed after four cases (two rows removed): the same command runs only those two again
  fs::remove(dir_ / "whole" / "case_0001" / "row.csv");
  fs::remove(dir_ / "whole" / "case_0004" / "row.csv");
  fs::remove(dir_ / "whole" / "results.csv");
  // a killed process's temporaries: its own names removed, any other file kept (pid 999999999: above pid_max)
  write_text(dir_ / "whole" / "case_0001" / "summary.csv.tmp.999999999", "torn");
  write_text(dir_ / "whole" / "case_0001" / "notes.txt.tmp.999999999", "the user's");
  const fs::path untouched = dir_ / "whole" / "case_0002" / "report.txt";
  const auto before = fs::last_write_time(untouched);
  const Process resumed = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "whole") + quiet, dir_);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("2 run now, 4 finished before"), std::string::npos) << resumed.out;
  EXPECT_EQ(fs::last_write_time(untouched), before);
  EXPECT_FALSE(fs::exists(dir_ / "whole" / "case_0001" / "summary.csv.tmp.999999999"));
  EXPECT_TRUE(fs::exists(dir_ / "whole" / "case_0001" / "notes.txt.tmp.999999999"));
  EXPECT_EQ(read_text(dir_ / "whole" / "results.csv"), table);
}

// SweepRunOptions::cancelled (the Python bindings' Ctrl-C): asked true, no new case starts, the running one
// finishes and is kept, no table is written, and the sweep resumes from there.
TEST_F(SweepFile, CancelledSweepStopsAfterTheRunningCaseAndResumes) {
  const Sweep s = read_sweep(sweep_file("axes:\n  - { key: load.normal_load_N, linear: { from: 1000, to: 2400, count: 8 } }\n").string());
  SweepRunOptions o;
  o.output_directory = dir_ / "out";
  o.threads = 1;
  int asked = 0;
  o.cancelled = [&] { return ++asked > 0; };
  EXPECT_THROW(run_sweep(s, o), SweepCancelled);
  EXPECT_GE(asked, 1);
  EXPECT_FALSE(fs::exists(o.output_directory / "results.csv"));
  long finished = 0;
  for (long i = 0; i < 8; ++i) finished += fs::exists(o.output_directory / case_folder_name(i) / "row.csv") ? 1 : 0;
  EXPECT_GE(finished, 1);
  EXPECT_LT(finished, 8);  // asked when the first case ends: the thread has started the second at most
  o.cancelled = {};
  const SweepRunSummary r = run_sweep(s, o);
  EXPECT_EQ(r.resumed, finished);
  EXPECT_EQ(r.failed, 0);
  EXPECT_TRUE(fs::exists(o.output_directory / "results.csv"));
}

TEST_F(SweepFile, BadAxisIsExitTwoBeforeAnyCaseRuns) {
  const fs::path sweep = sweep_file("axes:\n  - { key: friction.mu, values: [0.3, 20] }\n");
  const Process p = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "out") + " -q", dir_);
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("sweep.yaml:3:5: friction.mu: case 1's value 20 is refused"), std::string::npos) << p.err;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "a case ran, or a folder stayed, before the sweep was validated";
}

TEST_F(SweepFile, SlurmArrayScriptShardsMergeToTheWholeTable) {
  // scripts/sweep-slurm.sh as Slurm runs it: each task of an array 1-3 with its array variables, then
  // --merge of the shard folders
  const fs::path sweep = sweep_file("axes:\n  - { key: load.normal_load_N, linear: { from: 1000, to: 2400, count: 8 } }\n");
  const Process whole = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "whole") + " -q --log-level warn", dir_);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  // task K of an array MIN-MAX (COUNT tasks), as Slurm sets its variables
  const auto task = [&](int k, int min, int max) {
    const std::string command = "SLURM_ARRAY_TASK_ID=" + std::to_string(k) + " SLURM_ARRAY_TASK_MIN=" + std::to_string(min) +
                                " SLURM_ARRAY_TASK_MAX=" + std::to_string(max) + " SLURM_ARRAY_TASK_COUNT=" +
                                std::to_string(max - min + 1) + " SLURM_CPUS_PER_TASK=2 ROLLWEAR='" + std::string(ROLLWEAR_EXE) +
                                "' " + q(kSource / "scripts" / "sweep-slurm.sh") + " " + q(sweep) + " " + q(dir_ / "array") +
                                " 3 >>" + q(dir_ / "tasks.log") + " 2>&1";
    return std::system(command.c_str());
  };
  for (int k = 1; k <= 3; ++k) ASSERT_EQ(task(k, 1, 3), 0) << read_text(dir_ / "tasks.log");
  EXPECT_TRUE(fs::exists(dir_ / "array" / "shard_3" / "results.csv"));
  const std::string merge = "sweep --merge " + q(dir_ / "array" / "shard_1") + " " + q(dir_ / "array" / "shard_2") + " " +
                            q(dir_ / "array" / "shard_3") + " -o " + q(dir_ / "array");
  const Process merged = rollwear(merge, dir_);
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(read_text(dir_ / "array" / "results.csv"), read_text(dir_ / "whole" / "results.csv"));

  // task 2 killed after its first case (its table and a row gone), then submitted again as the docs say,
  // `sbatch --array=2 ...`: an array of one task, 2-2. It continues shard 2/3 in shard_2.
  fs::remove(dir_ / "array" / "shard_2" / "results.csv");
  fs::remove(dir_ / "array" / "shard_2" / "sweep.txt");
  fs::remove(dir_ / "array" / "shard_2" / "case_0004" / "row.csv");
  fs::remove(dir_ / "array" / "results.csv");
  ASSERT_EQ(task(2, 2, 2), 0) << read_text(dir_ / "tasks.log");
  EXPECT_NE(read_text(dir_ / "tasks.log").find("3 cases in this shard, 1 run now, 2 finished before"), std::string::npos)
      << read_text(dir_ / "tasks.log");
  EXPECT_FALSE(fs::exists(dir_ / "array" / "shard_1" / "case_0004")) << "the resubmitted task ran into shard_1";
  const Process again = rollwear(merge, dir_);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(read_text(dir_ / "array" / "results.csv"), read_text(dir_ / "whole" / "results.csv"));

  // array indices are the shard numbers 1..N: an array 0-2, or a task above N, is refused before anything runs
  EXPECT_NE(task(0, 0, 2), 0);
  EXPECT_NE(task(4, 1, 4), 0);
  EXPECT_FALSE(fs::exists(dir_ / "array" / "shard_0"));
  EXPECT_FALSE(fs::exists(dir_ / "array" / "shard_4"));
}

TEST_F(SweepFile, AShardsFolderRefusesAnotherShard) {
  // shard_1 holds shard 1/4 of the sweep (its case 0 finished, case 4 not): running shard 1/1 or 2/4 into it
  // would reuse case 0 as a case of another shard; refused (exit 2) before any case runs, naming the folder,
  // what it holds and what was asked
  const fs::path sweep = sweep_file("axes:\n  - { key: load.normal_load_N, linear: { from: 1000, to: 2400, count: 8 } }\n");
  const fs::path shard = dir_ / "shard_1";
  const Process first = rollwear("sweep " + q(sweep) + " --shard 1/4 -o " + q(shard) + " -q --log-level warn", dir_);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  ASSERT_TRUE(fs::exists(shard / "case_0004" / "row.csv"));
  fs::remove(shard / "case_0004" / "row.csv");  // killed before its second case finished
  fs::remove(shard / "results.csv");
  fs::remove(shard / "sweep.txt");
  for (const std::string asked : {"1/1", "2/4", "1/2"}) {
    const Process p = rollwear("sweep " + q(sweep) + " --shard " + asked + " -o " + q(shard) + " -q --log-level warn", dir_);
    EXPECT_EQ(p.exit_code, 2) << asked << ": " << p.out << p.err;
    EXPECT_NE(p.err.find(shard.string()), std::string::npos) << p.err;
    EXPECT_NE(p.err.find("holds shard 1/4"), std::string::npos) << p.err;
    EXPECT_NE(p.err.find("asked for shard " + asked), std::string::npos) << p.err;
    EXPECT_FALSE(fs::exists(shard / "case_0001")) << asked << ": a case of another shard ran";
    EXPECT_FALSE(fs::exists(shard / "case_0004" / "row.csv")) << asked;
  }
  // the same shard continues (1 run now, 1 finished before)
  const Process resumed = rollwear("sweep " + q(sweep) + " --shard 1/4 -o " + q(shard) + " -q --log-level warn", dir_);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("1 run now, 1 finished before"), std::string::npos) << resumed.out;
  // a finished whole sweep's folder (sweep.txt: shard 1/1) refuses a shard too
  const Process whole = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "whole") + " -q --log-level warn", dir_);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const Process part = rollwear("sweep " + q(sweep) + " --shard 2/4 -o " + q(dir_ / "whole") + " -q --log-level warn", dir_);
  EXPECT_EQ(part.exit_code, 2) << part.out << part.err;
  EXPECT_NE(part.err.find("holds shard 1/1"), std::string::npos) << part.err;
}

// a results table of given lives (ended_by revolutions: censored) for sweep_summary
std::string table_of(const std::vector<std::pair<double, LifeEnd>>& lives) {
  std::string t = results_header({"friction.mu"});
  long i = 0;
  for (const auto& [life, ended_by] : lives) {
    CaseOutcome o;
    o.index = i++;
    o.inputs = {0.1 * static_cast<double>(i)};
    o.life_revolutions = life;
    o.ended_by = ended_by;
    o.status = CaseStatus::Ok;
    t += results_row(o);
  }
  return t;
}

std::string summary_line(const std::string& summary, const std::string& start) {
  const std::size_t at = summary.find(start);
  return at == std::string::npos ? "" : summary.substr(at, summary.find('\n', at) - at);
}

TEST(SweepSummary, KaplanMeierQuantilesOfCensoredLives) {
  const std::string info = "cases 5\nsampling monte-carlo\nseed 1\n";
  // uncensored: the empirical quantiles, B10 = the 1st of 10 lives, B50 = the 5th
  std::vector<std::pair<double, LifeEnd>> ten;
  for (int k = 1; k <= 10; ++k) ten.emplace_back(k * 1e6, LifeEnd::MaxDepth);
  const std::string plain = sweep_summary(table_of(ten), info);
  EXPECT_EQ(summary_line(plain, "B10 life: ").substr(0, 19), "B10 life: 1e+06 rev") << plain;
  EXPECT_EQ(summary_line(plain, "B50 life: ").substr(0, 19), "B50 life: 5e+06 rev") << plain;
  // 1, 2, 3 (censored), 4, 5: Kaplan-Meier's F = 0.2, 0.4, then 1 - 0.6 x 1/2 = 0.7 at 4, so B50 = 4
  // (counting the censored life as a failure would give 3)
  const std::string censored = sweep_summary(
      table_of({{1e6, LifeEnd::MaxDepth}, {2e6, LifeEnd::Edge}, {3e6, LifeEnd::Revolutions}, {4e6, LifeEnd::MaxDepth},
                {5e6, LifeEnd::MaxDepth}}), info);
  EXPECT_EQ(summary_line(censored, "B50 life: ").substr(0, 19), "B50 life: 4e+06 rev") << censored;
  EXPECT_NE(censored.find("max_steps; Kaplan-Meier): 1"), std::string::npos) << censored;
  // every life censored: B50 is beyond the budget
  const std::string all = sweep_summary(table_of({{1e6, LifeEnd::Revolutions}, {1e6, LifeEnd::Revolutions}}), info);
  EXPECT_NE(summary_line(all, "B50 life: ").find("beyond the budget"), std::string::npos) << all;
}

TEST_F(SweepFile, GridElasticityOfArchardsCoefficientIsMinusOne) {
  // the wear rate is proportional to K (Archard, k_E = K/(H mu)): the life to a depth limit scales as 1/K
  // (docs/physics.md §6), so d ln(life)/d ln(K) = -1; to within the adaptive stepping's tolerance (rtol 1e-3)
  constexpr double kTolerance = 2e-3;
  const fs::path sweep = sweep_file("axes:\n  - { key: wear.body1.archard_k, log: { from: 5.0e-5, to: 2.0e-4, count: 3 } }\n");
  const Process p = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "out") + " -q --log-level warn", dir_);
  ASSERT_EQ(p.exit_code, 0) << p.err;
  const std::string summary = read_text(dir_ / "out" / "summary.txt");
  const std::string line = summary_line(summary, "  wear.body1.archard_k: ");
  ASSERT_FALSE(line.empty()) << summary;
  EXPECT_NEAR(std::stod(line.substr(std::string("  wear.body1.archard_k: ").size())), -1.0, kTolerance) << summary;
  EXPECT_NE(line.find("central"), std::string::npos) << summary;
  // a base case without wear.fatigue, a shakedown or scuffing limit or thermal: (docs/fatigue.md): no margin
  // columns in the table, no damage column in the snapshots
  std::istringstream table(read_text(dir_ / "out" / "results.csv"));
  std::string header, row;
  std::getline(table, header);
  EXPECT_EQ(header, "index,wear.body1.archard_k,life_revolutions,ended_by,max_depth_m,worn_volume_m3,fidelity,exact_solves,error_power_rel,error_power_l1,status,message");
  while (std::getline(table, row)) {  // the status right after the estimate (the message may hold commas)
    const std::string before_status = row.substr(0, row.find(",ok,"));
    EXPECT_EQ(std::count(before_status.begin(), before_status.end(), ','), 9) << row;
    // the fast fidelity, its one exact solve and its estimate (report.txt's numbers)
    EXPECT_NE(before_status.find(",fast,1,"), std::string::npos) << row;
    EXPECT_EQ(before_status.find("nan"), std::string::npos) << row;
  }
  const std::string snapshot = read_text(dir_ / "out" / "case_0000" / "snapshots" / "snapshot_0000_body1.csv");
  EXPECT_NE(snapshot.find("\ny_m,z_original_m,z_m,depth_m\n"), std::string::npos) << snapshot.substr(0, 200);
}

// Which base cases give the table the margin columns: those whose report.txt has the failure margins
// (wear::failure_margins: wear.fatigue, wear.limits.shakedown or scuffing true, a thermal: section); read, not run
TEST_F(SweepFile, MarginColumnsFollowTheSectionsThatGiveTheReportItsMargins) {
  const std::string plain = read_text(dir_ / "base.yaml");
  int variants = 0;
  const auto margins_of = [&](const std::string& base) {
    const std::string name = "variant" + std::to_string(variants++);
    write_text(dir_ / (name + ".yaml"), base);
    write_text(dir_ / (name + "_sweep.yaml"), "base: " + name + ".yaml\naxes:\n  - { key: friction.mu, values: [0.2] }\n");
    return read_sweep((dir_ / (name + "_sweep.yaml")).string()).margins;
  };
  const auto with_wear_key = [&](const std::string& line) {
    return std::regex_replace(plain, std::regex("\nwear:\n"), "\nwear:\n" + line + "\n");
  };
  ASSERT_NE(with_wear_key("  x: 1"), plain) << "the base case has no 'wear:' line to add keys under";
  EXPECT_FALSE(margins_of(plain));
  EXPECT_TRUE(margins_of(with_wear_key("  fatigue: { law: burstow }")));
  EXPECT_TRUE(margins_of(plain + "\nthermal: { bulk_temperature_C: 80 }\n"));  // top level (plain ends indented)
  const auto with_limit = [&](const std::string& entry) {
    return std::regex_replace(plain, std::regex("edge: true \\}"), "edge: true, " + entry + " }");
  };
  ASSERT_NE(with_limit("shakedown: true"), plain) << "the base case has no limits to add one to";
  EXPECT_TRUE(margins_of(with_limit("shakedown: true")));
  EXPECT_TRUE(margins_of(with_limit("scuffing: true")));
  EXPECT_FALSE(margins_of(with_limit("shakedown: false")));
  EXPECT_EQ(results_header({"friction.mu"}),
            "index,friction.mu,life_revolutions,ended_by,max_depth_m,worn_volume_m3,fidelity,exact_solves,error_power_rel,error_power_l1,status,message\n");
  EXPECT_EQ(results_header({"friction.mu"}, SweepKind::Wear, true),
            "index,friction.mu,life_revolutions,ended_by,max_depth_m,worn_volume_m3,max_damage,depth_fraction,"
            "shakedown_margin,scuffing_margin_K,fidelity,exact_solves,error_power_rel,error_power_l1,status,message\n");
  // a row without margins is as it was; with them, a case refused as bad input has NaN in each
  CaseOutcome o;
  o.index = 3;
  o.inputs = {0.2};
  o.status = CaseStatus::BadInput;
  o.message = "bad";
  EXPECT_EQ(results_row(o), "3,0.2,nan,not_run,nan,nan,,0,nan,nan,bad_input,bad\n");
  o.margins = true;
  EXPECT_EQ(results_row(o), "3,0.2,nan,not_run,nan,nan,nan,nan,nan,nan,,0,nan,nan,bad_input,bad\n");
  EXPECT_EQ(row_status(results_row(o), 1, SweepKind::Wear, true), CaseStatus::BadInput);
}

// A sweep of a fatigue case (docs/fatigue.md): results.csv carries max_damage after worn_volume_m3; at 10 % slip the
// life ends by fatigue (damage 1), at 5 % by wear with the damage short of 1; the summary and the plot read the table
TEST_F(SweepFile, FatigueSweepCarriesTheDamageColumn) {
  std::string base = read_text(kSource / "cases" / "paper-wear-fatigue.yaml");
  base = std::regex_replace(base, std::regex("nx: 80, ny: 80"), "nx: 24, ny: 24");
  base = std::regex_replace(base, std::regex("snapshots_revolutions:.*\n"), "");
  base = std::regex_replace(base, std::regex("output:.*\n"), "");
  write_text(dir_ / "fatigue.yaml", base);
  write_text(dir_ / "sweep.yaml", "base: fatigue.yaml\naxes:\n  - { key: kinematics.xi, values: [0.05, 0.1] }\n");
  const Process p = rollwear("sweep " + q(dir_ / "sweep.yaml") + " -o " + q(dir_ / "out") + " -q --log-level warn", dir_);
  ASSERT_EQ(p.exit_code, 0) << p.err;
  std::istringstream table(read_text(dir_ / "out" / "results.csv"));
  std::string header, slow, fast;
  std::getline(table, header);
  std::getline(table, slow);
  std::getline(table, fast);
  EXPECT_EQ(header, "index,kinematics.xi,life_revolutions,ended_by,max_depth_m,worn_volume_m3,max_damage,depth_fraction,"
                    "shakedown_margin,scuffing_margin_K,fidelity,exact_solves,error_power_rel,error_power_l1,status,message");
  const auto field = [](const std::string& row, int k) {
    std::istringstream in(row);
    std::string f;
    for (int i = 0; i <= k; ++i) std::getline(in, f, ',');
    return f;
  };
  EXPECT_EQ(field(slow, 3), "edge") << slow;
  EXPECT_GT(std::stod(field(slow, 6)), 0.1) << slow;
  EXPECT_LT(std::stod(field(slow, 6)), 1.0) << slow;
  EXPECT_EQ(field(fast, 3), "fatigue") << fast;
  EXPECT_NEAR(std::stod(field(fast, 6)), 1.0, 1e-9) << fast;
  EXPECT_EQ(field(fast, 10), "fast") << fast;  // the fidelity and its error estimate (docs/fidelity.md)
  EXPECT_EQ(field(fast, 11), "1") << fast;
  EXPECT_EQ(field(fast, 14), "ok") << fast;
  // the margins are each case's report.txt's, to the digit; the case has no k and no thermal: NaN there
  for (const auto& [row, folder] : {std::pair{slow, "case_0000"}, std::pair{fast, "case_0001"}}) {
    const std::string report = read_text(dir_ / "out" / folder / "report.txt");
    for (const auto& [column, key] : {std::pair{6, "max_damage"}, std::pair{7, "depth_fraction"}})
      EXPECT_NE(report.find(std::string("\n") + key + ": " + field(row, column) + "\n"), std::string::npos)
          << key << " " << row << "\n" << report;
    EXPECT_EQ(field(row, 8), "nan") << row;
    EXPECT_EQ(field(row, 9), "nan") << row;
    // the damage along the track: the last snapshot's damage column, whose largest is the row's max_damage
    std::istringstream snapshot(read_text(dir_ / "out" / folder / "snapshots" / "snapshot_0001_body1.csv"));
    std::string line;
    while (std::getline(snapshot, line) && line.rfind("#", 0) == 0) {
    }
    EXPECT_EQ(line, "y_m,z_original_m,z_m,depth_m,damage");
    double largest = 0;
    int nodes = 0;
    while (std::getline(snapshot, line)) {
      largest = std::max(largest, std::stod(field(line, 4)));
      ++nodes;
    }
    EXPECT_GT(nodes, 10);
    EXPECT_EQ(largest, std::stod(field(row, 6))) << folder;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / "case_0001" / "snapshots" / "snapshot_0001_body2.csv"));
  EXPECT_NE(read_text(dir_ / "out" / "summary.txt").find("2 ok"), std::string::npos) << read_text(dir_ / "out" / "summary.txt");
  EXPECT_EQ(rollwear("plot " + q(dir_ / "out"), dir_).exit_code, 0);
}

// Kaplan-Meier by hand (summary.txt's B10 and B50, the plot's curve): lives 1, 2 (censored), 3, 4:
// F(1) = 1/4; at 3, two at risk: S = 3/4 x 1/2, F = 5/8; at 4, one at risk: F = 1. A censoring tied
// with a failure is after it (it was at risk then).
TEST(SweepSummary, KaplanMeierByHand) {
  const std::vector<KaplanMeierStep> km = kaplan_meier({{3, false}, {2, true}, {4, false}, {1, false}});
  ASSERT_EQ(km.size(), 3u);
  EXPECT_EQ(km[0].life, 1);
  EXPECT_EQ(km[0].failed_fraction, 0.25);
  EXPECT_EQ(km[1].life, 3);
  EXPECT_EQ(km[1].failed_fraction, 0.625);
  EXPECT_EQ(km[2].life, 4);
  EXPECT_EQ(km[2].failed_fraction, 1);
  const std::vector<KaplanMeierStep> tie = kaplan_meier({{1, true}, {1, false}});
  ASSERT_EQ(tie.size(), 1u);
  EXPECT_EQ(tie[0].failed_fraction, 0.5);
}

// A case that fails while running (not at input): a concave roller whose deepest point lies 50 nm short of
// its width, on a crowned path that keeps the contact there (the geometry of
// WearLoop.BodyWornThroughEndsTheLife, here read from a profile file). Without a depth limit its first
// 50 nm of wear wear it through: the wear loop ends the life at its last accepted step, LifeFailure
// WornThrough. The sweep records that row (status failed, its message) and runs the next case on the same
// thread; the exit status is 0 and summary.txt counts the failure apart. (Run as `rollwear sweep`, the way
// a user meets it.)
TEST_F(SweepFile, CaseThatFailsWhileRunningIsARowAndTheSweepGoesOn) {
  constexpr double kWidth_m = 0.020, kGrooveRadius_m = 1.0, kMargin_m = 5e-8;
  std::ostringstream profile;
  profile.precision(17);
  profile << "y_m,z_m\n";
  for (int i = 0; i <= 400; ++i) {
    const double y = -kWidth_m / 2 + kWidth_m * i / 400;
    profile << y << ',' << (kWidth_m - kMargin_m) - y * y / (2 * kGrooveRadius_m) << '\n';
  }
  write_text(dir_ / "profiles" / "concave.csv", profile.str());
  std::string base = read_text(dir_ / "base.yaml");
  base = std::regex_replace(base, std::regex("body1: \\{ crowned: \\{ Ry_m: 0.500, width_m: 0.020 \\} \\}"),
                            "body1: { file: profiles/concave.csv }");
  base = std::regex_replace(base, std::regex("body2: \\{ flat: \\{ width_m: 0.030 \\} \\}"),
                            "body2: { crowned: { Ry_m: 0.25, width_m: 0.030 } }");
  base = std::regex_replace(base, std::regex("normal: auto"), "normal: semi-hertz");
  base = std::regex_replace(base, std::regex("limits: \\{ max_depth_m: 2.0e-5, edge: true \\}"),
                            "limits: { max_depth_m: 2.0e-8, edge: false }");
  // steps of at most 5 nm of depth: no trial step wears through before the 20 and 30 nm limits
  base = std::regex_replace(base, std::regex("stepping: \\{[^}]*\\}"), "stepping: { method: fixed-depth, max_depth_step_m: 5.0e-9 }");
  ASSERT_NE(base.find("fixed-depth"), std::string::npos);
  ASSERT_NE(base.find("concave.csv"), std::string::npos);
  ASSERT_NE(base.find("max_depth_m: 2.0e-8"), std::string::npos);
  write_text(dir_ / "base.yaml", base);
  // case 1 has no depth limit (0): it wears through; cases 0 and 2 stop at 20 and 30 nm
  const fs::path sweep = sweep_file("axes:\n  - { key: wear.limits.max_depth_m, values: [2.0e-8, 0, 3.0e-8] }\n");
  const Process r = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "out") + " -j 1 -q", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream table(read_text(dir_ / "out" / "results.csv"));
  std::vector<std::string> rows;
  for (std::string line; std::getline(table, line);) rows.push_back(line);
  ASSERT_EQ(rows.size(), 4u) << read_text(dir_ / "out" / "results.csv");
  EXPECT_EQ(row_status(rows[1], 1), CaseStatus::Ok) << rows[1];
  EXPECT_EQ(row_status(rows[2], 1), CaseStatus::Failed) << rows[2];
  EXPECT_EQ(row_status(rows[3], 1), CaseStatus::Ok) << rows[3];  // run after the failure, on the same thread
  EXPECT_NE(rows[2].find(",failed,"), std::string::npos) << rows[2];  // ended_by
  EXPECT_NE(rows[2].find("the last accepted step"), std::string::npos) << rows[2];
  EXPECT_NE(rows[2].find("body 1 is worn through"), std::string::npos) << rows[2];
  EXPECT_TRUE(fs::exists(dir_ / "out" / "case_0001" / "report.txt"));  // its outputs up to the failure
  EXPECT_EQ(read_text(dir_ / "out" / "case_0001" / "row.csv"), rows[2] + "\n");
  EXPECT_NE(read_text(dir_ / "out" / "summary.txt").find("2 ok, 1 not ok"), std::string::npos)
      << read_text(dir_ / "out" / "summary.txt");
}

// A sweep says at once how many cases and how much output it plans, and refuses above kSweepMaxCases before
// any case is read, unless forced (issue 26: a sweep of 1e6 cases printed, wrote and refused nothing for
// over a minute, reading every case first). The refusal takes well under a second: no case is read.
TEST_F(SweepFile, HugeSweepIsRefusedAtOnceSayingItsPlanUnlessForced) {
  const fs::path sweep = sweep_file(
      "random:\n  method: monte-carlo\n  count: 1000000\n  seed: 1\n"
      "  inputs:\n    - { key: friction.mu, distribution: uniform, min: 0.2, max: 0.4 }\n");
  const auto t0 = std::chrono::steady_clock::now();
  const Process r = rollwear("sweep " + q(sweep) + " -o " + q(dir_ / "huge") + " -q", dir_);
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.exit_code, 2) << r.err;
  for (const char* word : {"plans 1000000 cases, about ", "MB of output", "more than 10000 cases are refused", "--force"})
    EXPECT_NE(r.err.find(word), std::string::npos) << word << " in " << r.err;
  EXPECT_LT(elapsed_s, 10.0);  // reading the million cases took minutes; the plan needs the base case alone
  EXPECT_FALSE(fs::exists(dir_ / "huge" / case_folder_name(0)));

  // the plan's output estimate is of the size the cases write (a wear life: its folder), within a factor 3
  const Sweep small = read_sweep(sweep_file("axes:\n  - { key: load.normal_load_N, values: [1000, 2000] }\n").string());
  SweepRunOptions o;
  o.output_directory = dir_ / "small";
  o.threads = 1;
  o.max_cases = 1;  // a small limit: refused without reading a case, then run forced
  EXPECT_THROW(run_sweep(small, o), contact::CaseError);
  EXPECT_FALSE(fs::exists(o.output_directory / case_folder_name(0)));
  o.force = true;
  run_sweep(small, o);
  double bytes = 0;
  for (const auto& f : fs::recursive_directory_iterator(o.output_directory))
    if (f.is_regular_file()) bytes += static_cast<double>(f.file_size());
  const SweepPlan plan = plan_sweep(small, 1, 1);
  EXPECT_EQ(plan.cases, 2);
  EXPECT_GT(plan.bytes, bytes / 3) << bytes;
  EXPECT_LT(plan.bytes, bytes * 3) << bytes;
}

}  // namespace
