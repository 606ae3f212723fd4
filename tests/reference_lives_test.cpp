// The exact-physics reference lives stored in tests/data/reference_lives (scripts/reference-lives makes them:
// a shipped case with solver { normal: halfspace, tangential: exact } over grids and wear tolerances, and the
// default path beside it; docs/accuracy-vs-exact.md, "Reference lives"):
// - the stored series is converged in the wear step (rtol 1e-3 against 1e-4 on the finest grid);
// - the stored default row is what the default path gives now (the table in the docs stays true);
// - (stress label, seconds) the coarsest exact-physics lives of paper-wear and collective-duty-mix are repeated by
//   today's code.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/log_capture.h"
#include "wear/wear_case.h"
#include "wear/wear_loop.h"

namespace wear {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = ROLLWEAR_SOURCE_DIR;

// grid (or "extrapolated", "default") and rtol -> revolutions
std::map<std::string, double> stored_lives(const std::string& name) {
  std::ifstream in(kSource / "tests" / "data" / "reference_lives" / (name + ".csv"));
  EXPECT_TRUE(in) << name;
  std::map<std::string, double> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("grid,", 0) == 0) continue;
    std::stringstream s(line);
    std::string grid, rtol, revolutions;
    std::getline(s, grid, ',');
    std::getline(s, rtol, ',');
    std::getline(s, revolutions, ',');
    out[grid + "/" + rtol] = std::stod(revolutions);
  }
  return out;
}

// edge_off: the case's edge limit off (scripts/reference-lives --no-edge)
double shipped_life(const std::string& name, const std::string& solver = "", const std::string& stepping = "",
                    bool edge_off = false) {
  std::ifstream in(kSource / "cases" / (name + ".yaml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string t = text.str();
  if (edge_off) t = std::regex_replace(t, std::regex("edge: true"), "edge: false");
  if (!solver.empty()) t = std::regex_replace(t, std::regex("\nsolver:[^\n]*"), "\nsolver: " + solver);
  if (!stepping.empty()) t = std::regex_replace(t, std::regex("\n  stepping:[^\n]*"), "\n  stepping: " + stepping);
  const WearCase c = read_wear_case_text(t, name, kSource / "cases");
  const WearModel m = make_wear_model(c);
  WearCache cache;
  return run_life(m, c, LifeStart{}, LifeHooks{}, cache).N;
}

// the finest grid stored with both wear-step tolerances (the script's wear-step study), "" if none
std::string finest_wear_step_grid(const std::map<std::string, double>& lives) {
  std::string finest;
  for (const auto& [key, life] : lives) {
    const std::string grid = key.substr(0, key.find('/'));
    if (grid.empty() || !std::isdigit(static_cast<unsigned char>(grid[0]))) continue;
    if (lives.count(grid + "/0.001") && lives.count(grid + "/0.0001") &&
        (finest.empty() || std::stoi(grid) > std::stoi(finest)))
      finest = grid;
  }
  return finest;
}

// On the finest grid stored the exact-physics life moves by 0.021 % (paper-wear, 80 x 80) and 0.023 % (eta,
// 40 x 40) from rtol 1e-3 to 1e-4: the grid's error (20 -> 40: 12 % and 11 %, to the edge limit) dominates. The transient duty
// cycles (start-stop-wear, collective-duty-mix) are stored on 20 x 20 only. The default rows are the shipped
// cases' lives today (a few seconds each: the transient cases roll their duty cycle at every wear-rate evaluation).
TEST(ReferenceLives, StoredLivesAreConvergedInTheWearStepAndTheDefaultIsToday) {
  for (const std::string name : {"paper-wear", "paper-wear-eta", "start-stop-wear", "collective-duty-mix"}) {
    const std::map<std::string, double> lives = stored_lives(name);
    const std::string finest = finest_wear_step_grid(lives);
    ASSERT_TRUE(!finest.empty() && lives.count("default/")) << name;
    EXPECT_NEAR(lives.at(finest + "/0.001") / lives.at(finest + "/0.0001"), 1.0, 5e-3) << name;
    EXPECT_NEAR(shipped_life(name) / lives.at("default/"), 1.0, 1e-6)
        << name << ": the default path's life moved; rerun scripts/reference-lives and update docs/accuracy-vs-exact.md";
  }
}

// the stored row's `column` (the header's names), as text; "" if the row or column is missing
std::string stored_column(const std::string& name, const std::string& grid, const std::string& column) {
  std::ifstream in(kSource / "tests" / "data" / "reference_lives" / (name + ".csv"));
  std::vector<std::string> header;
  std::string line;
  const auto split = [](const std::string& l) {
    std::vector<std::string> out;
    std::stringstream s(l);
    for (std::string f; std::getline(s, f, ',');) out.push_back(f);
    return out;
  };
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // the csv module's line ends
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = split(line);
    if (header.empty()) {
      header = f;
      continue;
    }
    if (f.empty() || f[0] != grid) continue;
    for (std::size_t k = 0; k < header.size() && k < f.size(); ++k)
      if (header[k] == column) return f[k];
  }
  return "";
}

// Richardson's limit of lives on grids n, 2n, 4n at their observed order: (limit, order)
std::pair<double, double> richardson(double a, double b, double c) {
  const double p = std::log2((b - a) / (c - b));
  return {c + (c - b) / (std::exp2(p) - 1), p};
}

// The grid study of the paper-wear life ended by the depth limit (the edge limit off; the edge crossing of a
// wear-flattened crown converges too slowly to extrapolate, docs/accuracy-vs-exact.md): the lives on 20, 40, 80,
// 160 are in an asymptotic range (successive differences of one sign, shrinking), the stored limit is Richardson's
// from 40, 80, 160, and the limit from 20, 40, 80 agrees with it within the stored uncertainty (measured: 0.09 %
// apart, uncertainty 0.39 %): the extrapolation is not an artefact of one triple of grids.
TEST(ReferenceLives, DepthLimitedPaperWearLifeConvergesInTheGrid) {
  const std::string name = "paper-wear_no-edge";
  const std::map<std::string, double> lives = stored_lives(name);
  const std::string rtol = stored_column(name, "extrapolated", "rtol");
  ASSERT_FALSE(rtol.empty()) << name << ": no extrapolated row";
  std::vector<double> N;
  for (const char* g : {"20", "40", "80", "160"}) {
    ASSERT_TRUE(lives.count(std::string(g) + "/" + rtol)) << g;
    N.push_back(lives.at(std::string(g) + "/" + rtol));
  }
  for (std::size_t k = 2; k < N.size(); ++k) {
    EXPECT_GT((N[k] - N[k - 1]) * (N[k - 1] - N[k - 2]), 0) << k;
    EXPECT_LT(std::abs(N[k] - N[k - 1]), std::abs(N[k - 1] - N[k - 2])) << k;
  }
  const auto [fine, order] = richardson(N[1], N[2], N[3]);
  const auto coarse = richardson(N[0], N[1], N[2]).first;
  // to the stored lives' ten digits
  EXPECT_NEAR(lives.at("extrapolated/" + rtol) / fine, 1.0, 1e-7);
  EXPECT_NEAR(std::stod(stored_column(name, "extrapolated", "order")) / order, 1.0, 1e-6);
  const double uncertainty = std::stod(stored_column(name, "extrapolated", "uncertainty"));
  EXPECT_LT(uncertainty, 0.01);
  EXPECT_NEAR(coarse / fine, 1.0, uncertainty) << coarse << " " << fine;
}

// The depth-limited paper-wear life with the exact theory's grid extrapolation (solver.grid_extrapolation,
// docs/exact-theory.md §4), stored in grid_extrapolation/ by scripts/reference-lives: on 40, 80, 160 its lives
// converge from above (the plain ones from below), and on 80 x 80 it is within the 0.5 % of the grid limit,
// both of its own series' Richardson limit and of the plain series' (measured +0.12 % and +0.49 %); the two limits
// agree within the plain one's uncertainty (0.36 % apart, uncertainty 0.39 %). The plain 80 x 80 life misses the
// 0.5 % (-0.97 %).
TEST(ReferenceLives, ExtrapolatedPaperWearLifeOn80IsWithinHalfAPercentOfTheGridLimit) {
  const std::string name = "grid_extrapolation/paper-wear_no-edge", plain_name = "paper-wear_no-edge";
  const std::map<std::string, double> lives = stored_lives(name), plain = stored_lives(plain_name);
  const std::string rtol = stored_column(name, "extrapolated", "rtol");
  ASSERT_FALSE(rtol.empty()) << name << ": no extrapolated row";
  ASSERT_EQ(rtol, stored_column(plain_name, "extrapolated", "rtol"));
  std::vector<double> N;
  for (const char* g : {"40", "80", "160"}) {
    ASSERT_TRUE(lives.count(std::string(g) + "/" + rtol)) << g;
    N.push_back(lives.at(std::string(g) + "/" + rtol));
  }
  EXPECT_LT(N[1], N[0]);  // from above
  EXPECT_LT(N[2], N[1]);
  EXPECT_LT(N[1] - N[2], N[0] - N[1]);
  const double own = richardson(N[0], N[1], N[2]).first, limit = plain.at("extrapolated/" + rtol);
  EXPECT_NEAR(lives.at("extrapolated/" + rtol) / own, 1.0, 1e-7);
  constexpr double kTarget = 0.005;  // the 0.5 %
  EXPECT_NEAR(N[1] / own, 1.0, kTarget) << N[1] << " " << own;
  EXPECT_NEAR(N[1] / limit, 1.0, kTarget) << N[1] << " " << limit;
  EXPECT_NEAR(own / limit, 1.0, std::stod(stored_column(plain_name, "extrapolated", "uncertainty")));
  EXPECT_GT(std::abs(plain.at("80/" + rtol) / limit - 1), kTarget) << "the plain 80 x 80 life";
}

// The stored 20 x 20 life with the grid extrapolation (the depth limit, rtol 1e-3), run again: about 2 s.
TEST(StressReferenceLives, ExtrapolatedPaperWearRepeatsItsStoredLife) {
  const std::map<std::string, double> lives = stored_lives("grid_extrapolation/paper-wear_no-edge");
  ASSERT_TRUE(lives.count("20/0.001"));
  const rollwear_test::ExpectWarnings warnings;  // the worn contact reaches the roller's ends: with the edge limit off
  const double N =
      shipped_life("paper-wear", "{ normal: halfspace, tangential: exact, grid_extrapolation: true, nx: 20, ny: 20 }",
                   "{ method: adaptive, rtol: 0.001, atol_m: 1.0e-9, max_steps: 1000000 }", true);
  EXPECT_NEAR(N / lives.at("20/0.001"), 1.0, 1e-3) << N;  // to the wear step's accuracy: see below
  EXPECT_GE(warnings.count(), 1);
  for (const std::string& m : warnings.messages())
    EXPECT_NE(m.find("reaches the end of the profiles' overlap"), std::string::npos) << m;
}

// The coarsest stored exact-physics life (20 x 20, rtol 1e-4), run again: about 5 s.
TEST(StressReferenceLives, PaperWearRepeatsItsStoredExactPhysicsLife) {
  const std::map<std::string, double> lives = stored_lives("paper-wear");
  ASSERT_TRUE(lives.count("20/0.0001"));
  const double N = shipped_life("paper-wear", "{ normal: halfspace, tangential: exact, nx: 20, ny: 20 }",
                                "{ method: adaptive, rtol: 0.0001, atol_m: 1.0e-10, max_steps: 1000000 }");
  // not to the bit: a change of the half-space solver at its rounding level (the kernel from corner values, the
  // direct displacement updates) moved this life by 1.9e-4 and the collective's by 3.8e-4, through the adaptive
  // step sequence, which follows the rates' last digits. So the bound is the wear step's own accuracy here
  // (rtol 1e-3 against 1e-4 differ by up to 2.6e-3 among the stored lives), not the solvers' tolerance.
  EXPECT_NEAR(N / lives.at("20/0.0001"), 1.0, 1e-3) << N;
}

// The collective's stored 20 x 20 exact-physics life (rtol 1e-3), run again: about 35 s of CPU. Its conditions
// run on threads, each planning its own half-space and exact-theory FFTs: before the two solvers shared one FFTW
// planner lock this run corrupted the heap or failed a plan (2 of 3 runs).
TEST(StressReferenceLives, CollectiveRepeatsItsStoredExactPhysicsLife) {
  const std::map<std::string, double> lives = stored_lives("collective-duty-mix");
  ASSERT_TRUE(lives.count("20/0.001"));
  const double N = shipped_life("collective-duty-mix", "{ normal: halfspace, tangential: exact, nx: 20, ny: 20 }",
                                "{ method: adaptive, rtol: 0.001, atol_m: 1.0e-9, max_steps: 1000000 }");
  EXPECT_NEAR(N / lives.at("20/0.001"), 1.0, 1e-3) << N;  // to the wear step's accuracy: see above
}

}  // namespace
}  // namespace wear
