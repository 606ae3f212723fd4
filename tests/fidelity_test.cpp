// The fidelity of a wear life (lib/fidelity.h, wear/wear_loop.h, docs/fidelity.md): the corrected fidelity's
// life against the exact physics' on the same grid, its schedule, its checkpoint, and the error estimate every
// life reports against a direct comparison on the same state.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

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

// the fast models alone on the case's grid (no correction, no exact physics)
WearModel paper_wear_model_fast(WearCase c) {
  c.contact.solver.fidelity = contact::Fidelity::Fast;
  c.contact.solver.correction_grid = 0;
  return make_wear_model(c);
}

LifeResult life_of(const WearCase& c) {
  const WearModel m = make_wear_model(c);
  WearCache cache;
  return run_life(m, c, {}, {}, cache);
}

// Reference: the exact physics' life on the same grid (20 x 20, computed here, about 2 s; the stored
// 20 x 20 reference at rtol 1e-4 is 7.4970e7 revolutions, tests/data/reference_lives/paper-wear.csv). The
// corrected life comes closer to it than the fast one. Measured here (no snapshots): exact 7.4974e7, fast
// +23.6 % (the semi-Hertzian edge limit is not the 20 x 20 half-space's), corrected -0.21 % (50 exact solves);
// with the case's snapshots (`rollwear run`, which restart the integration there) +23.9 % and +0.43 %
// (docs/fidelity.md). The bound, 4 %, lies between the fast life's error and the corrected one's; both numbers
// are printed.
// The corrected life's end is the exact physics' edge: the half-space edge value (delta x the distance of the
// contact's lateral edge past the body's end / the contact's half-width) and the semi-Hertzian one (the gap at
// the overlap's end against the interpenetration bound) are different functions of the state, so their offset
// is not held to the end (with the limits left to it the life ends at 2.81e7, -62.6 %); the limits are the exact
// physics' own from the correction where its contact's edge is within one half-width of the end (measured at
// 1.1-1.4e7 revolutions, 9-15 % of the life). Checked: the life ends with them in force, and the exact edge value
// on its final state is 0 to within 1 % of the approach (measured 9e-19 m).
TEST(Fidelity, CorrectedLifeIsCloserToTheExactLifeThanTheFastOnTheSameGrid) {
  constexpr int kGrid = 20;
  constexpr double kCorrectedWithin = 0.04;
  const LifeResult exact = life_of(paper_wear(contact::Fidelity::Exact, kGrid));
  const LifeResult fast = life_of(paper_wear(contact::Fidelity::Fast, kGrid));
  const WearCase cc = paper_wear(contact::Fidelity::Corrected, kGrid);
  const WearModel cm = make_wear_model(cc);
  WearCache cache;
  const LifeResult corrected = run_life(cm, cc, {}, {}, cache);
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
  // ended by the exact physics' own edge value, not the fast one plus an offset
  ASSERT_EQ(corrected.ended_by, LifeEnd::Edge);
  EXPECT_TRUE(cache.correction.exact_limits);
  ASSERT_EQ(corrected.state.size(), cm.state_size());
  WearCache fresh;
  const NormalState n = exact_normal_state(cm, corrected.state, fresh);
  std::cout << "[ measured ] exact edge value on the corrected life's final state " << n.edge_limit_m << " m (approach "
            << n.approach_m << " m)\n";
  EXPECT_LT(std::abs(n.edge_limit_m), 0.01 * n.approach_m);
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

// A coarser correction grid compares like with like: the correction's fast rate and its error estimate are the
// fast models' on the correction grid (not the case's), so at the correction's state the corrected rate is the
// coarse exact rate plus the ratio times the fast models' change from the coarse grid to the case's.
TEST(Fidelity, CoarserCorrectionGridComparesTheExactPhysicsWithTheFastModelsOnItsOwnGrid) {
  WearCase c = paper_wear(contact::Fidelity::Corrected, 20);
  c.contact.solver.correction_grid = 12;
  const WearModel m = make_wear_model(c);
  ASSERT_EQ(m.correction_fast.size(), 1u);
  ASSERT_EQ(m.limits_physics.size(), 1u);
  WearCache cache;
  Eigen::VectorXd h = initial_state(m);
  for (int i = 0; i < m.n1; ++i) h(i) = 2e-6 * std::max(0.0, 1 - std::abs(m.profiles.body1.y_m(i)) / 2e-3);
  ASSERT_TRUE(update_correction(m, 1, h, cache));
  WearCache coarse_cache, fine_cache, exact_cache;
  exact_cache.halfspace_warm_start = false;
  const WearRate coarse = wear_rate(m.correction_fast.front(), h, coarse_cache);
  const WearRate fine = wear_rate(paper_wear_model_fast(c), h, fine_cache);
  const WearRate exact = wear_rate(m.exact_physics.front(), h, exact_cache);
  const FidelityCorrection& k = cache.correction;
  const double scale = exact.dstate_dN.head(m.n1).cwiseAbs().maxCoeff();
  EXPECT_LT((k.fast_rate - coarse.dstate_dN.head(m.n1)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_GT((k.fast_rate - fine.dstate_dN.head(m.n1)).cwiseAbs().maxCoeff(), 1e-6 * scale);  // the grids differ
  EXPECT_LT((k.exact_rate - exact.dstate_dN.head(m.n1)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_EQ(k.fast_energy_J, fine.energy_per_revolution_J);  // the schedule's: the case grid's fast power
  EXPECT_NEAR(cache.error.power_rel, coarse.energy_per_revolution_J / exact.energy_per_revolution_J - 1, 1e-12);
  // the corrected rate at the correction's state: x + c (f - f_n), per node
  const Eigen::ArrayXd x = exact.dstate_dN.head(m.n1).array(), fn = coarse.dstate_dN.head(m.n1).array(),
                       f = fine.dstate_dN.head(m.n1).array();
  const double e = kCorrectionFloor * fn.abs().maxCoeff();
  const Eigen::ArrayXd expected = (x + (x + e) / (fn + e) * (f - fn)).max(0.0);
  const WearRate g = wear_rate(m, h, cache);
  EXPECT_LT((g.dstate_dN.head(m.n1).array() - expected).abs().maxCoeff(), 1e-9 * scale);
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
// Also with a coarser correction grid (its fast models and its case-grid limits are functions of the state).
TEST(Fidelity, CorrectedLifeStoppedAndResumedFromItsCheckpointIsTheUninterruptedOneToTheBit) {
  for (int correction_grid : {0, 10}) {
  SCOPED_TRACE(correction_grid);
  WearCase c = paper_wear(contact::Fidelity::Corrected, 16);
  c.contact.solver.correction_grid = correction_grid;
  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = 2e-6;
  c.wear.limits.max_depth_m = 2e-5;
  LifeResult whole;
  ASSERT_NO_FATAL_FAILURE(expect_resumed_life_is_the_whole_one(c, 5, "fidelity_checkpoint.txt", whole));
  EXPECT_GT(whole.exact_solves, 2);
  }
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

// a shipped case (cases/NAME.yaml) at a fidelity on an n x n grid, every running condition of a collective too
WearCase shipped_case(const std::string& name, contact::Fidelity fidelity, int n) {
  WearCase c = read_wear_case((kSource / "cases" / (name + ".yaml")).string());
  std::vector<contact::ContactCase*> contacts = {&c.contact};
  for (WearCondition& k : c.wear.collective) contacts.push_back(&k.contact);
  for (contact::ContactCase* k : contacts) {
    k->solver.fidelity = fidelity;
    if (fidelity == contact::Fidelity::Exact) {
      k->solver.normal = contact::NormalChoice::Halfspace;
      k->solver.tangential = contact::TangentialScheme::Exact;
    }
    k->solver.nx = k->solver.ny = n;
  }
  return c;
}

// a state worn in the crown's middle (a tent 2 um deep, 4 mm wide): no longer Hertz's, still inside the roller
Eigen::VectorXd worn_crown(const WearModel& m) {
  Eigen::VectorXd h = initial_state(m);
  for (int i = 0; i < m.n1; ++i) h(i) = 2e-6 * std::max(0.0, 1 - std::abs(m.profiles.body1.y_m(i)) / 2e-3);
  return h;
}

// The steady part of a transient duty cycle: the longest stretch of constant speed > 0, creepages and load between
// the histories' breakpoints. cases/start-stop-wear.yaml's is its run at 1.8 m/s from 1 ms to 0.501 s; a cycle
// that only ramps has none, and one with two constant speeds takes the stretch that rolls further.
TEST(Fidelity, TransientDutyCyclesSteadyPartIsItsLongestConstantStretch) {
  const WearCase c = shipped_case("start-stop-wear", contact::Fidelity::Fast, 40);
  const contact::TransientCase t = contact::transient_case_of(c.contact);
  const std::optional<SteadyPart> part = steady_part(t.inputs, t.settings.t_end_s);
  ASSERT_TRUE(part);
  EXPECT_EQ(part->t0_s, 1.0e-3);
  EXPECT_EQ(part->t1_s, 0.501);
  EXPECT_EQ(part->speed_m_per_s, 1.8);
  EXPECT_EQ(part->creepages.xi, 1.0e-3);
  EXPECT_EQ(part->creepages.eta, 0.0);
  contact::TransientInputs ramp = t.inputs;
  ramp.speed_m_per_s = contact::ramp_history(0, 0, 0.503, 1.8);
  EXPECT_FALSE(steady_part(ramp, 0.503));
  contact::TransientInputs two = t.inputs;
  two.speed_m_per_s = {{0, 1e-3, 0.1, 0.101, 0.3, 0.301}, {0, 1.0, 1.0, 2.0, 2.0, 0}};  // 0.099 m at 1, 0.398 m at 2
  const std::optional<SteadyPart> faster = steady_part(two, 0.4);
  ASSERT_TRUE(faster);
  EXPECT_EQ(faster->speed_m_per_s, 2.0);
  EXPECT_EQ(faster->t0_s, 0.101);
  two.xi = contact::ramp_history(0.2, 1e-3, 0.25, 2e-3);  // a creepage step inside the faster stretch: it splits
  const std::optional<SteadyPart> split = steady_part(two, 0.4);
  ASSERT_TRUE(split);
  EXPECT_EQ(split->t0_s, 0.101);  // [0.101, 0.2] at 2 m/s rolls 0.198 m, more than [0.25, 0.3]'s and [1e-3, 0.1]'s
  EXPECT_EQ(split->t1_s, 0.2);
  EXPECT_EQ(split->creepages.xi, 1e-3);
}

// A transient duty cycle corrected (docs/fidelity.md, "Transient duty cycles"): the exact physics and the fast
// models compared in steady rolling at the cycle's steady part, the correction applied to the fast models' whole
// cycle. At the correction's state the corrected rate is x + c (f - f0) per node: the exact steady rate plus the
// fast models' start and stop (their cycle's rate f less their steady rate f0), scaled by the ratio c. Checked on
// cases/start-stop-wear.yaml at 20 x 20 on a worn crown: the models the correction runs, that formula (1e-9), and
// that the fast models' start and stop are a small part of their cycle (measured: per-node L1 of f - f0 against f).
TEST(Fidelity, TransientDutyCycleIsCorrectedByTheExactPhysicsAtItsSteadyPart) {
  const WearCase c = shipped_case("start-stop-wear", contact::Fidelity::Corrected, 20);
  const WearModel m = make_wear_model(c);
  ASSERT_TRUE(m.transient);
  ASSERT_TRUE(m.steady_part);
  ASSERT_EQ(m.exact_physics.size(), 1u);
  ASSERT_EQ(m.correction_fast.size(), 1u);
  for (const WearModel* s : {&m.exact_physics.front(), &m.correction_fast.front()}) {
    EXPECT_FALSE(s->transient);
    EXPECT_EQ(s->speed_m_per_s, 1.8);
    EXPECT_EQ(s->creepages.xi, 1e-3);
  }
  EXPECT_EQ(m.exact_physics.front().scheme, contact::TangentialScheme::Exact);
  EXPECT_EQ(m.correction_fast.front().scheme, m.scheme);
  WearCache cache;
  const Eigen::VectorXd h = worn_crown(m);
  ASSERT_TRUE(update_correction(m, 1, h, cache));
  WearCache cycle_cache, steady_cache, exact_cache;
  exact_cache.halfspace_warm_start = false;
  const WearRate cycle = wear_rate(paper_wear_model_fast(c), h, cycle_cache);
  const WearRate steady = wear_rate(m.correction_fast.front(), h, steady_cache);
  const WearRate exact = wear_rate(m.exact_physics.front(), h, exact_cache);
  const Eigen::ArrayXd x = exact.dstate_dN.head(m.n1).array(), f0 = steady.dstate_dN.head(m.n1).array(),
                       f = cycle.dstate_dN.head(m.n1).array();
  const double scale = x.abs().maxCoeff();
  EXPECT_LT((cache.correction.fast_rate.array() - f0).abs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((cache.correction.exact_rate.array() - x).abs().maxCoeff(), 1e-12 * scale);
  EXPECT_EQ(cache.correction.fast_energy_J, cycle.energy_per_revolution_J);  // the schedule's: the cycle's
  const double e = kCorrectionFloor * f0.abs().maxCoeff();
  const Eigen::ArrayXd expected = (x + (x + e) / (f0 + e) * (f - f0)).max(0.0);
  const WearRate g = wear_rate(m, h, cache);
  EXPECT_LT((g.dstate_dN.head(m.n1).array() - expected).abs().maxCoeff(), 1e-9 * scale);
  // the estimate is the steady part's: the fast models against the exact physics there
  EXPECT_NEAR(cache.error.power_rel, steady.energy_per_revolution_J / exact.energy_per_revolution_J - 1, 1e-12);
  const double start_stop = (f - f0).abs().sum() / f.abs().sum();
  std::cout << "[ measured ] start-stop-wear 20 x 20, worn crown: the fast cycle's start and stop " << 100 * start_stop
            << " % (per-node L1 of cycle - steady); steady part: fast power " << 100 * cache.error.power_rel
            << " %, per-strip L1 " << 100 * cache.error.power_l1 << " %\n";
  EXPECT_GT(start_stop, 0);     // the cycle is not the steady part alone
  EXPECT_LT(start_stop, 0.05);  // and its start and stop are a small part of it (0.9 m rolled at 1.8 m/s)
  // the report says what the estimate compares
  EXPECT_NE(error_estimate_of(m).find("steady part"), std::string::npos) << error_estimate_of(m);
}

// The corrected transient life on 20 x 20 against the exact physics' life on the same grid (the stored
// reference, tests/data/reference_lives/start-stop-wear.csv: 7.5021e7 revolutions at rtol 1e-3, the case's
// snapshots; 35 s of CPU to compute again): the corrected life comes within 4 %, the fast one does not (+23 %
// measured, docs/accuracy-vs-exact.md). Both numbers printed.
TEST(Fidelity, CorrectedStartStopLifeIsCloserToTheExactLifeThanTheFast) {
  constexpr double kExact20 = 75021341.65, kWithin = 0.04;
  const WearCase cc = shipped_case("start-stop-wear", contact::Fidelity::Corrected, 20);
  const LifeResult corrected = life_of(cc);
  const LifeResult fast = life_of(shipped_case("start-stop-wear", contact::Fidelity::Fast, 20));
  const double corrected_error = corrected.N / kExact20 - 1, fast_error = fast.N / kExact20 - 1;
  std::cout << "[ measured ] start-stop-wear 20 x 20 against the stored exact life: fast " << fast.N << " ("
            << 100 * fast_error << " %), corrected " << corrected.N << " (" << 100 * corrected_error << " %, "
            << corrected.exact_solves << " exact solves; estimate at N " << corrected.error.N << ": power "
            << 100 * corrected.error.power_rel << " %, L1 " << 100 * corrected.error.power_l1 << " %)\n";
  EXPECT_LT(std::abs(corrected_error), kWithin);
  EXPECT_GT(std::abs(fast_error), kWithin);
  EXPECT_GT(corrected.exact_solves, 1);
  EXPECT_TRUE(std::isfinite(corrected.error.power_l1));
  EXPECT_TRUE(std::isfinite(fast.error.power_l1));  // the fast life's estimate, at the steady part
  EXPECT_EQ(fast.exact_solves, 1);
}

// A load collective corrected condition by condition: each running condition has its own exact physics (the
// transient one's at its steady part) and its own correction; at the first correction's state the collective's
// rate is the weighted sum of the conditions' corrected rates (the steady ones' equal to their exact rates);
// the estimate combines the conditions' (collective_error: the weighted energies' power error, the
// energy-weighted L1). cases/collective-duty-mix.yaml at 12 x 12.
TEST(Fidelity, CollectiveIsCorrectedConditionByCondition) {
  const WearCase c = shipped_case("collective-duty-mix", contact::Fidelity::Corrected, 12);
  const WearModel m = make_wear_model(c);
  ASSERT_EQ(m.conditions.size(), 3u);
  EXPECT_TRUE(m.exact_physics.empty());
  for (const WearModel& mk : m.conditions) EXPECT_EQ(mk.exact_physics.size(), 1u);
  EXPECT_TRUE(m.conditions[2].steady_part);
  WearCache cache;
  const Eigen::VectorXd h = worn_crown(m);
  ASSERT_TRUE(update_correction(m, 1, h, cache));
  ASSERT_TRUE(correction_made(m, cache));
  EXPECT_EQ(exact_solves(m, cache), 3);
  EXPECT_FALSE(update_correction(m, 1, h, cache));  // the same state: no condition solves again
  EXPECT_EQ(exact_solves(m, cache), 3);
  const WearRate g = wear_rate(m, h, cache);
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(m.n1);
  double energy = 0, fast = 0, l1 = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    WearCache ck = cache.conditions[k];
    const WearRate rk = wear_rate(m.conditions[k], h, ck);
    if (k < 2) {  // a steady condition at its correction's state: its exact rate
      const double scale = cache.conditions[k].correction.exact_rate.cwiseAbs().maxCoeff();
      EXPECT_LT((rk.dstate_dN.head(m.n1) - cache.conditions[k].correction.exact_rate).cwiseAbs().maxCoeff(), 1e-12 * scale);
    }
    expected += m.weights[k] * rk.dstate_dN.head(m.n1);
    const FidelityError& e = cache.conditions[k].error;
    energy += m.weights[k] * e.exact_energy_J;
    fast += m.weights[k] * e.exact_energy_J * (1 + e.power_rel);
    l1 += m.weights[k] * e.exact_energy_J * e.power_l1;
  }
  EXPECT_LT((g.dstate_dN.head(m.n1) - expected).cwiseAbs().maxCoeff(), 1e-12 * expected.cwiseAbs().maxCoeff());
  EXPECT_EQ(cache.error.N, 1);
  EXPECT_NEAR(cache.error.power_rel, fast / energy - 1, 1e-12);
  EXPECT_NEAR(cache.error.power_l1, l1 / energy, 1e-12);
  EXPECT_NE(error_estimate_of(m).find("each running condition"), std::string::npos) << error_estimate_of(m);
}

// The corrected collective stopped and resumed from its checkpoint (each condition's correction and estimate in
// blocks correction_K and error_K) ends as the uninterrupted life to the bit. 12 x 12, fixed-depth steps.
TEST(Fidelity, CorrectedCollectiveStoppedAndResumedFromItsCheckpointIsTheUninterruptedOneToTheBit) {
  WearCase c = shipped_case("collective-duty-mix", contact::Fidelity::Corrected, 12);
  c.wear.snapshots_revolutions.clear();
  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = 2e-6;
  c.wear.limits.max_depth_m = 1.6e-5;
  LifeResult whole;
  ASSERT_NO_FATAL_FAILURE(expect_resumed_life_is_the_whole_one(c, 4, "collective_corrected_checkpoint.txt", whole));
  EXPECT_GT(whole.exact_solves, 3);
  EXPECT_TRUE(std::isfinite(whole.error.power_l1));
}

// A corrected transient duty cycle stopped and resumed from its checkpoint (its correction holds the steady part's
// rates) ends as the uninterrupted life to the bit. start-stop-wear on 12 x 12, fixed-depth steps.
TEST(Fidelity, CorrectedTransientLifeStoppedAndResumedFromItsCheckpointIsTheUninterruptedOneToTheBit) {
  WearCase c = shipped_case("start-stop-wear", contact::Fidelity::Corrected, 12);
  c.wear.snapshots_revolutions.clear();
  c.wear.stepping.method = IntegratorOptions::Method::FixedDepth;
  c.wear.stepping.max_depth_step_m = 2e-6;
  c.wear.limits.max_depth_m = 1.6e-5;
  LifeResult whole;
  ASSERT_NO_FATAL_FAILURE(expect_resumed_life_is_the_whole_one(c, 4, "transient_corrected_checkpoint.txt", whole));
  EXPECT_GT(whole.exact_solves, 1);
}

// The corrected fidelity refuses, at its key with the file and line, a transient duty cycle without a steady part
// and a collective's condition without friction (naming the condition)
TEST(Fidelity, CorrectedRefusesWhatItCannotCorrectAtTheKey) {
  std::string text;
  { std::ifstream in(kSource / "cases" / "start-stop-wear.yaml"); text.assign(std::istreambuf_iterator<char>(in), {}); }
  text.replace(text.find("solver:     { normal: auto"), 26, "solver:     { fidelity: corrected, normal: auto");
  EXPECT_EQ(read_wear_case_text(text, "ok.yaml", kSource).contact.solver.fidelity, contact::Fidelity::Corrected);
  std::string ramp = text;
  const std::string table = "[[0, 0], [1.0e-3, 1.8], [0.501, 1.8], [0.502, 0]]";
  ramp.replace(ramp.find(table), table.size(), "[[0, 0], [0.503, 1.8]]");
  try {
    read_wear_case_text(ramp, "ramp.yaml", kSource);
    ADD_FAILURE() << "no error";
  } catch (const contact::CaseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("ramp.yaml:"), std::string::npos) << what;
    EXPECT_NE(what.find("solver.fidelity"), std::string::npos) << what;
    EXPECT_NE(what.find("steady part"), std::string::npos) << what;
  }
  std::string mix;
  { std::ifstream in(kSource / "cases" / "collective-duty-mix.yaml"); mix.assign(std::istreambuf_iterator<char>(in), {}); }
  mix.replace(mix.find("solver:     { normal: auto"), 26, "solver:     { fidelity: corrected, normal: auto");
  EXPECT_EQ(read_wear_case_text(mix, "mix.yaml", kSource).wear.collective.size(), 3u);
  mix.replace(mix.find("{ weight: 0.70 }"), 16, "{ weight: 0.70, friction: { mu: 0 } }");
  try {
    read_wear_case_text(mix, "mix0.yaml", kSource);
    ADD_FAILURE() << "no error";
  } catch (const contact::CaseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("friction.mu"), std::string::npos) << what;
    EXPECT_NE(what.find("wear.collective[1]"), std::string::npos) << what;
  }
}

// body1's worn depth columns of tests/data/reference_lives/CASE_profiles.csv (y_m, exact_half_m, exact_end_m, ...)
std::vector<std::vector<double>> stored_profile_columns(const fs::path& path, int columns) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::vector<double>> out(columns);
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'y') continue;
    std::stringstream row(line);
    std::string cell;
    for (int k = 0; k < columns && std::getline(row, cell, ','); ++k) out[k].push_back(std::stod(cell));
  }
  return out;
}

// the relative L1 of a per-node wear rate against a reference, weighted by the nodes' widths (as the error
// estimate's per-strip L1; for Archard's law dh/dN is the smoothed per-node power times k_E)
double rate_l1(const Eigen::ArrayXd& rate, const Eigen::ArrayXd& reference, const Eigen::ArrayXd& y) {
  return profile_area_m2((rate - reference).abs(), y) / profile_area_m2(reference.abs(), y);
}

// Held out: the corrected rate on worn states of the shipped life (paper-wear, 80 x 80, tolerance 0.1) that it
// did not correct on, against the exact physics on the same grid. The states: the life's own, each just before
// a new correction (where the correction in force has drifted furthest; the exact rate there is that new
// correction's) and four more accepted steps' states between corrections (the exact physics solved here). Issue 25's target: the
// per-strip power within 5 % L1; judged on the per-node wear rate (Archard: the smoothed per-node power x k_E).
// The fast models' L1 on the same states is printed beside it (2.5-5 %: what the correction removes).
TEST(StressFidelity, CorrectedRateOnWornStatesItDidNotCorrectOn) {
  constexpr double kTarget = 0.05;
  const WearCase c = paper_wear(contact::Fidelity::Corrected, 80);
  const WearModel m = make_wear_model(c);
  WearCache cache;
  struct Step {
    double N;
    Eigen::VectorXd state;
    FidelityCorrection correction;
  };
  std::vector<Step> steps;
  LifeHooks keep;
  keep.on_step = [&](const LifeStep& s) {
    steps.push_back({s.N, *s.state, cache.correction});
    return true;
  };
  const LifeResult life = run_life(m, c, {}, keep, cache);
  ASSERT_EQ(life.ended_by, LifeEnd::Edge);
  const Eigen::ArrayXd& y = m.profiles.body1.y_m;
  const auto corrected_at = [&](const FidelityCorrection& k, const Eigen::VectorXd& h) {
    WearCache held;
    held.correction = k;
    return wear_rate(m, h, held);
  };
  double worst = 0, worst_fast = 0;
  int checked = 0, fast_closer = 0;
  // just before each new correction: the state is the new correction's, the correction in force the last one's
  for (std::size_t i = 1; i < steps.size(); ++i) {
    const FidelityCorrection &now = steps[i].correction, &before = steps[i - 1].correction;
    if (now.solves == before.solves || now.N != steps[i].N) continue;
    const Eigen::ArrayXd x = now.exact_rate.array(), f = now.fast_rate.array();
    const WearRate g = corrected_at(before, steps[i].state);
    const double l1 = rate_l1(g.dstate_dN.head(m.n1).array(), x, y), fast_l1 = rate_l1(f, x, y);
    const double power = g.energy_per_revolution_J / now.exact_energy_J - 1;
    worst = std::max(worst, l1);
    worst_fast = std::max(worst_fast, fast_l1);
    fast_closer += fast_l1 < l1;
    ++checked;
    if (checked % 8 == 1)
      std::cout << "[ measured ] N " << steps[i].N << " (corrected at " << before.N << "): corrected rate L1 "
                << 100 * l1 << " %, power " << 100 * power << " %; fast L1 " << 100 * fast_l1 << " %\n";
  }
  // a few accepted steps' states spread over the life that are no correction's own (between two corrections):
  // the exact physics solved on the state
  const WearModel& exact = m.exact_physics.front();
  std::vector<std::size_t> between;
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (steps[i].correction.N != steps[i].N) between.push_back(i);
  ASSERT_GE(between.size(), 4u);
  int halfway = 0;
  for (int q = 0; q < 4; ++q) {
    const Step& s = steps[between[(2 * q + 1) * between.size() / 8]];
    WearCache exact_cache, fast_cache;
    exact_cache.halfspace_warm_start = false;
    const WearRate x = wear_rate(exact, s.state, exact_cache), f = wear_rate(m, s.state, fast_cache);
    const WearRate g = corrected_at(s.correction, s.state);
    const Eigen::ArrayXd xr = x.dstate_dN.head(m.n1).array();
    const double l1 = rate_l1(g.dstate_dN.head(m.n1).array(), xr, y);
    std::cout << "[ measured ] N " << s.N << " (corrected at " << s.correction.N << "): corrected rate L1 " << 100 * l1
              << " %, power " << 100 * (g.energy_per_revolution_J / x.energy_per_revolution_J - 1) << " %; fast L1 "
              << 100 * rate_l1(f.dstate_dN.head(m.n1).array(), xr, y) << " %\n";
    worst = std::max(worst, l1);
    ++checked;
    ++halfway;
  }
  std::cout << "[ measured ] " << checked << " held-out states, " << life.exact_solves << " corrections: worst corrected L1 "
            << 100 * worst << " % (the fast models' worst " << 100 * worst_fast << " %; closer than the corrected on "
            << fast_closer << ")\n";
  EXPECT_GT(checked, 20);
  EXPECT_EQ(halfway, 4);
  EXPECT_LT(worst, kTarget);
}

// A coarser correction grid: the exact physics and the fast models on 20-40 x 20-40 and their corrected rate
// (x_n + c (f - f_n) at the correction's own state), on the stored exact 80 x 80 life's worn states at half and all
// of it (tests/data/reference_lives/paper-wear_profiles.csv), against the exact physics on 80 x 80. Measured: the
// fast models move by < 0.7 % of L1 with the grid, the exact physics by 2.5-7.5 % (not monotone in n): a coarse
// correction carries the coarse exact physics' grid error, which is as large as the fast models' own error here
// (2.3-3.0 %), so no correction grid below the case's improves the rate (docs/fidelity.md). The check: on each
// state the corrected rate from the coarsest grid, 20, is not closer to the 80 x 80 exact rate than the fast rate.
TEST(StressFidelity, CoarseCorrectionGridsCarryTheCoarseExactPhysicsGridError) {
  const auto columns = stored_profile_columns(kSource / "tests/data/reference_lives/paper-wear_profiles.csv", 3);
  const WearModel fine_fast = make_wear_model(paper_wear(contact::Fidelity::Fast, 80));
  const WearModel fine_exact = make_wear_model(paper_wear(contact::Fidelity::Exact, 80));
  ASSERT_EQ(static_cast<int>(columns[1].size()), fine_fast.n1);
  const Eigen::ArrayXd& y = fine_fast.profiles.body1.y_m;
  const auto rate = [&](const WearModel& m, const Eigen::VectorXd& h) {
    WearCache cache;
    cache.halfspace_warm_start = false;
    return Eigen::ArrayXd(wear_rate(m, h, cache).dstate_dN.head(m.n1).array());
  };
  for (int column : {1, 2}) {
    Eigen::VectorXd h = initial_state(fine_fast);
    for (int i = 0; i < fine_fast.n1; ++i) h(i) = columns[column][i];
    const Eigen::ArrayXd x = rate(fine_exact, h), f = rate(fine_fast, h);
    const double fast_l1 = rate_l1(f, x, y);
    std::cout << "[ measured ] stored exact 80 x 80 " << (column == 1 ? "half" : "end") << ": fast L1 " << 100 * fast_l1 << " %\n";
    for (int n : {20, 30, 40}) {
      const Eigen::ArrayXd xn = rate(make_wear_model(paper_wear(contact::Fidelity::Exact, n)), h);
      const Eigen::ArrayXd fn = rate(make_wear_model(paper_wear(contact::Fidelity::Fast, n)), h);
      const double e = kCorrectionFloor * fn.abs().maxCoeff();
      const Eigen::ArrayXd ratio = (xn + e) / (fn + e);
      const double like_l1 = rate_l1((f * ratio + (xn - fn * ratio)).max(0.0), x, y);
      std::cout << "[ measured ]   " << n << " x " << n << ": exact L1 " << 100 * rate_l1(xn, x, y) << " %, fast "
                << 100 * rate_l1(fn, x, y) << " %, corrected (like with like) " << 100 * like_l1 << " %\n";
      if (n == 20) {
        EXPECT_GT(like_l1, fast_l1);
      }
    }
  }
}
}  // namespace
}  // namespace wear
