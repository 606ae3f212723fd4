// The fidelity of a wear life (lib/fidelity.h, wear/wear_loop.h, docs/fidelity.md): the corrected fidelity's
// life against the exact physics' on the same grid, its schedule, its checkpoint, and the error estimate every
// life reports against a direct comparison on the same state.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <iostream>
#include <string>

#include "lib/errors.h"
#include "lib/io/case.h"
#include "wear/profile_update.h"
#include "wear/wear_case.h"
#include "wear/wear_loop.h"
#include "wear/wear_output.h"

namespace wear {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = ROLLWEAR_SOURCE_DIR;

// the paper's roller (cases/paper-wear.yaml) at a fidelity on an n x n grid, as the case reader sets it
WearCase paper_wear(contact::Fidelity fidelity, int n) {
  WearCase c = read_wear_case((kSource / "cases" / "paper-wear.yaml").string());
  c.contact.solver.fidelity = fidelity;
  if (fidelity == contact::Fidelity::Exact) {
    c.contact.solver.normal = contact::NormalChoice::Halfspace;
    c.contact.solver.tangential = contact::TangentialScheme::Exact;
  }
  c.contact.solver.nx = c.contact.solver.ny = n;
  c.wear.snapshots_revolutions.clear();
  return c;
}

LifeResult life_of(const WearCase& c) {
  const WearModel m = make_wear_model(c);
  WearCache cache;
  return run_life(m, c, {}, {}, cache);
}

// Reference: the exact physics' life on the same grid (20 x 20, computed here, about 2 s; the stored
// 20 x 20 reference at rtol 1e-4 is 8.7664e7 revolutions, tests/data/reference_lives/paper-wear.csv). The
// corrected life comes closer to it than the fast one. Measured here (no snapshots): exact 8.7604e7, fast
// +5.77 %, corrected +1.17 % (54 exact solves); with the case's snapshots (`rollwear run`, which restart the
// integration there) +5.95 % and +2.67 % (docs/fidelity.md). The bound, 4 %, lies between the fast life's error
// and the corrected one's; both numbers are printed.
TEST(Fidelity, CorrectedLifeIsCloserToTheExactLifeThanTheFastOnTheSameGrid) {
  constexpr int kGrid = 20;
  constexpr double kCorrectedWithin = 0.04;
  const LifeResult exact = life_of(paper_wear(contact::Fidelity::Exact, kGrid));
  const LifeResult fast = life_of(paper_wear(contact::Fidelity::Fast, kGrid));
  const LifeResult corrected = life_of(paper_wear(contact::Fidelity::Corrected, kGrid));
  const double fast_error = fast.N / exact.N - 1, corrected_error = corrected.N / exact.N - 1;
  std::cout << "[ measured ] paper-wear 20 x 20: exact " << exact.N << ", fast " << fast.N << " (" << 100 * fast_error
            << " %), corrected " << corrected.N << " (" << 100 * corrected_error << " %, " << corrected.exact_solves
            << " exact solves)\n";
  EXPECT_EQ(exact.ended_by, LifeEnd::Edge);
  EXPECT_LT(std::abs(corrected_error), kCorrectedWithin);
  EXPECT_GT(std::abs(fast_error), kCorrectedWithin);
  EXPECT_LT(std::abs(corrected_error), std::abs(fast_error));
  // tens of exact solves, not one per evaluation
  EXPECT_GT(corrected.exact_solves, 1);
  EXPECT_LT(corrected.exact_solves, corrected.counters.rate_evaluations / 2);
}

// The schedule: the first call solves; the same state does not solve again; wear spread evenly over the
// profile moves no contact (the gap's shape and the fast power are unchanged); a bump worn into the contact's
// middle deeper than the tolerance x the approach solves again.
TEST(Fidelity, CorrectionIsSolvedAgainWhenTheWornGapsShapeMoves) {
  const WearModel m = make_wear_model(paper_wear(contact::Fidelity::Corrected, 20));
  WearCache cache;
  const Eigen::VectorXd h0 = initial_state(m);
  EXPECT_TRUE(update_correction(m, 0, h0, cache));
  EXPECT_EQ(cache.correction.solves, 1);
  EXPECT_FALSE(update_correction(m, 0, h0, cache));
  Eigen::VectorXd even = h0;
  even.head(m.n1).array() += 1e-6;
  EXPECT_FALSE(update_correction(m, 1, even, cache));
  EXPECT_EQ(cache.correction.solves, 1);
  Eigen::VectorXd bump = h0;
  const double depth = 2 * m.correction_tolerance * cache.correction.approach_m;
  for (int i = 0; i < m.n1; ++i)
    bump(i) = depth * std::max(0.0, 1 - std::abs(m.profiles.body1.y_m(i)) / 1e-3);  // 1 mm wide, in the contact
  EXPECT_TRUE(update_correction(m, 2, bump, cache));
  EXPECT_EQ(cache.correction.solves, 2);
  // at its own state the corrected rate is the exact physics' (the correction's definition)
  const WearRate corrected = wear_rate(m, bump, cache);
  const double scale = cache.correction.exact_rate.cwiseAbs().maxCoeff();
  EXPECT_LT((corrected.dstate_dN.head(m.n1) - cache.correction.exact_rate).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_NEAR(corrected.energy_per_revolution_J / cache.correction.exact_energy_J, 1, 1e-12);
}

// The error estimate of a fast life: its report's fields equal a direct comparison of the fast and the exact
// physics' rates on the final worn state (the total energy per revolution, and the strips' energies mapped onto
// the roller's nodes, relative L1 weighted by the nodes' widths).
TEST(Fidelity, ErrorEstimateIsTheDirectComparisonOnTheFinalState) {
  WearCase c = paper_wear(contact::Fidelity::Fast, 20);
  c.wear.revolutions = 2e7;
  const WearModel m = make_wear_model(c);
  WearCache cache;
  const LifeResult life = run_life(m, c, {}, {}, cache);
  ASSERT_EQ(life.ended_by, LifeEnd::Revolutions);
  EXPECT_EQ(life.exact_solves, 1);
  EXPECT_EQ(life.error.N, life.N);

  WearCache fresh_fast, fresh_exact;
  const WearRate fast = wear_rate(m, life.state, fresh_fast);
  const WearRate exact = wear_rate(m.exact_physics.front(), life.state, fresh_exact);
  const double power_rel = fast.energy_per_revolution_J / exact.energy_per_revolution_J - 1;
  const Eigen::ArrayXd& y = m.profiles.body1.y_m;
  const Eigen::ArrayXd uf = strips_to_nodes(fast.strip_energy_J_per_m, fast.strip_y0_m, fast.strip_dy_m, y);
  const Eigen::ArrayXd ux = strips_to_nodes(exact.strip_energy_J_per_m, exact.strip_y0_m, exact.strip_dy_m, y);
  const double l1 = profile_area_m2((uf - ux).abs(), y) / profile_area_m2(ux.abs(), y);
  std::cout << "[ measured ] paper-wear 20 x 20 at 2e7 revolutions: fast power " << 100 * power_rel
            << " %, per-strip L1 " << 100 * l1 << " %\n";
  EXPECT_NEAR(life.error.power_rel, power_rel, 1e-12);
  EXPECT_NEAR(life.error.power_l1, l1, 1e-12);
  EXPECT_GT(life.error.power_l1, 0);

  // the report names the models and carries the estimate
  WearReport report;
  report.case_name = m.name;
  report.life = life;
  const std::string text = wear_report_text(m, report);
  for (const char* key : {"tangential_model: relaxed", "fidelity: fast", "exact_solves: 1", "error_power_rel: ",
                          "error_power_l1: ", "error_estimate_N: "})
    EXPECT_NE(text.find(key), std::string::npos) << key << " in\n" << text;
}

// what a checkpoint holds at an accepted step's end, as `rollwear run` saves it (session/wear_life_run.cpp)
Checkpoint checkpoint_at(const LifeStep& s, const WearCache& cache) {
  Checkpoint cp;
  cp.start = {s.N, *s.state, s.info.next_step, s.counters};
  cp.blocks = wear_cache_blocks(cache);
  return cp;
}

// equal, or both NaN (an estimate not made)
bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// The life stopped after `stop_after` steps, its checkpoint written as text and read back, and resumed from it in
// a new cache (a new process's) ends as the uninterrupted life `whole`: its end, N, steps, exact solves, error
// estimate, final contact and state to the bit.
void expect_resumed_life_is_the_whole_one(const WearCase& c, long stop_after, const std::string& file,
                                          LifeResult& whole) {
  const WearModel m = make_wear_model(c);
  WearCache whole_cache;
  whole = run_life(m, c, {}, {}, whole_cache);
  ASSERT_EQ(whole.ended_by, LifeEnd::MaxDepth) << whole.message;
  ASSERT_GT(whole.counters.steps, stop_after + 2);

  WearCache first_cache;
  Checkpoint cp;
  LifeHooks stop;
  stop.on_step = [&](const LifeStep& s) {
    cp = checkpoint_at(s, first_cache);
    return s.step < stop_after;
  };
  ASSERT_EQ(run_life(m, c, {}, stop, first_cache).ended_by, LifeEnd::Stopped);
  const fs::path path = fs::path(::testing::TempDir()) / file;
  { std::ofstream(path) << checkpoint_text(cp); }
  const Checkpoint back = read_checkpoint(path);
  WearCache resumed_cache;
  restore_wear_cache(m, back.blocks, resumed_cache);
  const LifeResult resumed = run_life(m, c, back.start, {}, resumed_cache);

  EXPECT_EQ(resumed.ended_by, whole.ended_by);
  EXPECT_EQ(resumed.N, whole.N);
  EXPECT_EQ(resumed.counters.steps, whole.counters.steps);
  EXPECT_EQ(resumed.exact_solves, whole.exact_solves);
  EXPECT_TRUE(same_number(resumed.error.power_l1, whole.error.power_l1)) << resumed.error.power_l1;
  EXPECT_EQ(resumed.contact.p0_Pa, whole.contact.p0_Pa);
  EXPECT_EQ(resumed.contact.power_W, whole.contact.power_W);
  ASSERT_EQ(resumed.state.size(), whole.state.size());
  for (Eigen::Index i = 0; i < whole.state.size(); ++i) ASSERT_EQ(resumed.state(i), whole.state(i)) << "node " << i;
}

// The corrected life stopped after a few fixed steps and resumed from what a checkpoint holds (its state, N,
// counters and correction, through the checkpoint's text) ends as the uninterrupted life to the bit.
TEST(Fidelity, CorrectedLifeStoppedAndResumedFromItsCheckpointIsTheUninterruptedOneToTheBit) {
  WearCase c = paper_wear(contact::Fidelity::Corrected, 16);
  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = 2e-6;
  c.wear.limits.max_depth_m = 2e-5;
  LifeResult whole;
  ASSERT_NO_FATAL_FAILURE(expect_resumed_life_is_the_whole_one(c, 5, "fidelity_checkpoint.txt", whole));
  EXPECT_GT(whole.exact_solves, 2);
}

// A half-space life (solver.normal halfspace) starts each half-space solve from the last one's pressures
// (WearCache::halfspace_warm_start), so a resume that solved its start again would start elsewhere and end within
// the solver's tolerance only; the checkpoint carries that last solve. The paper's roller on a coarse 12 x 12
// grid, fixed-depth steps of 2 um to 20 um (10 steps), stopped after 4 and resumed: the fast fidelity on the
// half-space, the exact fidelity (half-space and exact theory), and the corrected one on a half-space normal.
WearCase halfspace_wear(contact::Fidelity fidelity) {
  WearCase c = paper_wear(fidelity, 12);
  c.contact.solver.normal = contact::NormalChoice::Halfspace;
  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = 2e-6;
  c.wear.limits.max_depth_m = 2e-5;
  return c;
}

TEST(HalfspaceResume, FastLifeStoppedAndResumedFromItsCheckpointIsTheUninterruptedOneToTheBit) {
  LifeResult whole;
  expect_resumed_life_is_the_whole_one(halfspace_wear(contact::Fidelity::Fast), 4, "hs_fast_checkpoint.txt", whole);
}

TEST(HalfspaceResume, ExactLifeStoppedAndResumedFromItsCheckpointIsTheUninterruptedOneToTheBit) {
  LifeResult whole;
  expect_resumed_life_is_the_whole_one(halfspace_wear(contact::Fidelity::Exact), 4, "hs_exact_checkpoint.txt", whole);
}

TEST(HalfspaceResume, CorrectedLifeOnAHalfspaceNormalStoppedAndResumedIsTheUninterruptedOneToTheBit) {
  LifeResult whole;
  expect_resumed_life_is_the_whole_one(halfspace_wear(contact::Fidelity::Corrected), 4, "hs_corrected_checkpoint.txt",
                                       whole);
}

// A load collective on the half-space: each running condition starts its solves from its own last one, and the
// checkpoint holds each (halfspace_normal_K). cases/collective-duty-mix.yaml (steady cruise, heavy, a start-stop
// transient) at 12 x 12, fixed-depth steps of 2 um to 10 um, stopped after 2 and resumed.
TEST(HalfspaceResume, CollectiveLifeStoppedAndResumedIsTheUninterruptedOneToTheBit) {
  WearCase c = read_wear_case((kSource / "cases" / "collective-duty-mix.yaml").string());
  c.contact.solver.normal = contact::NormalChoice::Halfspace;
  c.contact.solver.nx = c.contact.solver.ny = 12;
  for (WearCondition& k : c.wear.collective) {
    k.contact.solver.normal = contact::NormalChoice::Halfspace;
    k.contact.solver.nx = k.contact.solver.ny = 12;
  }
  c.wear.snapshots_revolutions.clear();
  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = 2e-6;
  c.wear.limits.max_depth_m = 1e-5;
  LifeResult whole;
  ASSERT_NO_FATAL_FAILURE(expect_resumed_life_is_the_whole_one(c, 2, "hs_collective_checkpoint.txt", whole));
  EXPECT_EQ(whole.contact.normal_solver, contact::NormalSolverKind::Halfspace);
}

// A checkpoint of format version 2 holds the corrected fidelity's correction in lines of its own: it is read into
// the blocks `correction` and `error`, every number to the bit; a block cut short is refused naming it.
TEST(HalfspaceResume, CheckpointOfVersion2ReadsItsCorrectionIntoTheBlocks) {
  const std::string text =
      "rollwear-wear-checkpoint 2\ncase_hash 00000000000000ab\nN 0x1p+23\nnext_step 0x0p+0\nsteps 3\nrhs_evals 4\n"
      "rejected 0\nrate_evaluations 9\nlimit_evaluations 5\nnormal_solves 6\ntangential_solves 6\n"
      "snapshots_written 1\nwall_s 0x1p-3\nstate 3\n0x1p-20\n0x1p-21\n0x1p-10\n"
      "correction 0x1p+3 0x1p+1 0x1p+0 0x1p-18 -0x1p-30 0x1p+4 1 7 3\n0x1p-20\n0x1p-22\n0x1p-11\n"
      "0x1p-40 0x1p-41\n0x1p-42 0x1p-43\nerror 0x1p+3 -0x1p-5 0x1p-6\nend\n";
  const fs::path path = fs::path(::testing::TempDir()) / "version2_checkpoint.txt";
  { std::ofstream(path) << text; }
  const Checkpoint cp = read_checkpoint(path);
  EXPECT_EQ(cp.start.N, 0x1p+23);
  EXPECT_EQ(cp.start.counters.steps, 3);
  WearModel m;
  m.n1 = 2;  // a state of 3: two nodes and the energy
  WearCache cache;
  restore_wear_cache(m, cp.blocks, cache);
  const FidelityCorrection& k = cache.correction;
  ASSERT_TRUE(k.valid);
  EXPECT_EQ(k.N, 8.0);
  EXPECT_EQ(k.exact_energy_J, 2.0);
  EXPECT_EQ(k.fast_energy_J, 1.0);
  EXPECT_EQ(k.approach_m, 0x1p-18);
  EXPECT_EQ(k.edge_offset_m, -0x1p-30);
  EXPECT_EQ(k.pressure_offset_Pa, 16.0);
  EXPECT_TRUE(k.exact_limits);
  EXPECT_EQ(k.solves, 7);
  ASSERT_EQ(k.state.size(), 3);
  EXPECT_EQ(k.state(1), 0x1p-22);
  ASSERT_EQ(k.exact_rate.size(), 2);
  EXPECT_EQ(k.exact_rate(1), 0x1p-42);
  EXPECT_EQ(k.fast_rate(1), 0x1p-43);
  EXPECT_EQ(cache.error.N, 8.0);
  EXPECT_EQ(cache.error.power_rel, -0x1p-5);
  EXPECT_EQ(cache.error.power_l1, 0x1p-6);
  // written again, it is version 3's blocks, and reads back to the same correction
  Checkpoint again = cp;
  again.blocks = wear_cache_blocks(cache);
  { std::ofstream(path) << checkpoint_text(again); }
  const Checkpoint back = read_checkpoint(path);
  ASSERT_NE(find_block(back.blocks, "correction"), nullptr);
  WearCache cache2;
  restore_wear_cache(m, back.blocks, cache2);
  EXPECT_EQ(cache2.correction.fast_rate(0), 0x1p-41);
  EXPECT_EQ(cache2.error.power_l1, 0x1p-6);
  // a block cut short
  std::vector<CheckpointBlock> cut = back.blocks;
  for (CheckpointBlock& b : cut)
    if (b.name == "correction") b.values.conservativeResize(b.values.size() - 1);
  try {
    restore_wear_cache(m, cut, cache2);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'correction'"), std::string::npos) << e.what();
  }
}

// The case keys: exact sets the half-space and the exact theory; it refuses another model named beside it;
// corrected needs friction and a steady duty cycle
TEST(Fidelity, CaseKeysSetAndRefuseAtTheirKey) {
  std::string text;
  { std::ifstream in(kSource / "cases" / "paper-wear.yaml"); text.assign(std::istreambuf_iterator<char>(in), {}); }
  const auto with_solver = [&](const std::string& solver) {
    std::string t = text;
    const std::size_t at = t.find("solver:");
    t.replace(at, t.find('\n', at) - at, "solver: " + solver);
    return t;
  };
  const WearCase exact = read_wear_case_text(with_solver("{ fidelity: exact, nx: 20, ny: 20 }"), "e.yaml", kSource);
  EXPECT_EQ(exact.contact.solver.normal, contact::NormalChoice::Halfspace);
  EXPECT_EQ(exact.contact.solver.tangential, contact::TangentialScheme::Exact);
  try {
    read_wear_case_text(with_solver("{ fidelity: exact, tangential: consistent }"), "x.yaml", kSource);
    ADD_FAILURE() << "no error";
  } catch (const contact::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.tangential"), std::string::npos) << e.what();
  }
  std::string no_friction = with_solver("{ fidelity: corrected }");
  no_friction.replace(no_friction.find("mu: 0.3"), 7, "mu: 0.0");
  try {
    read_wear_case_text(no_friction, "f.yaml", kSource);
    ADD_FAILURE() << "no error";
  } catch (const contact::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("friction.mu"), std::string::npos) << e.what();
  }
  try {
    read_wear_case_text(with_solver("{ fidelity: fastest }"), "u.yaml", kSource);
    ADD_FAILURE() << "no error";
  } catch (const contact::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.fidelity"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace wear
