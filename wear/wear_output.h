// The files of a wear run (`rollwear run`, docs/wear-loop.md), built as text so they can be tested,
// then written atomically (lib/io/csv.h). Numbers at full precision: the shortest text that reads back
// as the same double (lib/number.h).
//
//   summary.csv                        '# ' comment lines (case, bodies, law), then
//     step,revolutions,hours,max_depth_m,worn_volume_m3,dissipated_J,a_m,b_m,p0_Pa,Fx_N,power_W,
//     step_revolutions,error_estimate,rejected,rhs_evals[,max_damage]
//                                      one row per accepted step (max_damage with wear.fatigue); step 0 is the unworn state; a limit
//                                      located within a step adds a last row at the limit (the step
//                                      cut short: error_estimate 0)
//   snapshots/snapshot_KKKK_BODY.csv   '# case: ', '# body: ', '# revolutions: ', '# hours: ', then
//     y_m,z_original_m,z_m,depth_m[,damage]
//                                      one row per profile node of a worn body (damage: with wear.fatigue, the
//                                      Miner damage of the reference body's node, on its snapshots only)
//   report.txt                         'key: value' lines: the predicted life and what ended it
//                                      (life_report_text)
//   checkpoint.txt                     the state to resume from and what the rate carries from step to step
//                                      (hexadecimal floats: bit-exact; "---- checkpoint ----" below)
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "wear/wear_loop.h"

namespace wear {

// comment lines and the header row of summary.csv
std::string wear_summary_header(const WearModel& m);
// one row; step 0 (the unworn state) has step_revolutions, error_estimate, rejected and rhs_evals 0
std::string wear_summary_row(const WearModel& m, const LifeStep& s, double hours_per_revolution);

// the worn profile of one body (1 or 2) in the state
std::string wear_snapshot_csv(const WearModel& m, int body, double N, double hours, const Eigen::VectorXd& state);
// "snapshots/snapshot_0003_body1.csv"
std::filesystem::path wear_snapshot_path(int index, int body);

// The report of every life, the roller's and the cam's (report.txt, and printed as it is): 'key: value'
// lines, first the keys every life writes, in this order,
//   case, ended_by, failure (a failed life's only), message, revolutions, hours, max_depth_m, dissipated_J,
//   steps, rejected_steps, rhs_evals, resumed,
// then the life's own keys in its order (LifeReport::own). The shared numbers are written with `digits`
// significant digits, or (0) at full precision: the shortest text that reads back as the same double.
struct LifeReport {
  std::string case_name;
  LifeEnd ended_by = LifeEnd::NotRun;
  LifeFailure failure = LifeFailure::None;
  std::string message;
  double revolutions = 0;   // of the life's reference body (the cam: cam revolutions)
  double hours = 0;
  double max_depth_m = 0;   // the deepest wear of either body
  double dissipated_J = 0;  // over the life
  LifeCounters counters;    // steps, rejected_steps, rhs_evals are written
  bool resumed = false;
  int digits = 0;
  std::vector<std::pair<std::string, std::string>> own;  // the life's own keys and their values, as written
};
std::string life_report_text(const LifeReport& r);

struct WearReport {
  std::string case_name;
  LifeResult life;
  double hours_per_revolution = 0;  // the counters are the life's (LifeResult::counters)
  double wall_s = 0;
  bool resumed = false;
};
std::string wear_report_text(const WearModel& m, const WearReport& r);
// which models ran and the fast models' error estimate (docs/fidelity.md): report.txt's keys tangential_model,
// fidelity, correction_tolerance (corrected), exact_solves, error_estimate_of, error_estimate_N, error_power_rel, error_power_l1
std::vector<std::pair<std::string, std::string>> fidelity_report(const WearModel& m, const LifeResult& l);
// what the error estimate compares (report.txt's error_estimate_of): the steady duty cycle, a transient one's steady
// part, a collective's conditions, or "not estimated: WHY"
std::string error_estimate_of(const WearModel& m);
// which failure mode is how far at the end of the life (docs/fatigue.md), with wear.fatigue, wear.limits.shakedown,
// wear.limits.scuffing, a thermal: section or Dang Van's index only: report.txt's keys depth_fraction (max depth /
// wear.limits.max_depth_m, with a depth limit), fatigue_law, max_damage, max_damage_y_m, max_tgamma_N (with fatigue),
// shakedown_margin (with the reference body's k), flash_rise_K and scuffing_margin_K (with thermal:); with
// bodies.bodyN.dang_van (LifeResult::dang_van), dang_van_bodyN_index, _depth_m, _y_m (and a collective's _condition)
std::vector<std::pair<std::string, std::string>> failure_margins(const WearModel& m, const LifeResult& l);
// the same as a comment line of summary.csv, written above its header row at the end of the run
std::string wear_summary_error_line(const WearModel& m, const LifeResult& l);

// the mean rolling speed of the duty cycle, and the hours one revolution of the reference body takes
double hours_per_revolution(const WearModel& m);

// ---- checkpoint ----

// What a life carries from one step to the next besides its state, in named blocks of numbers, each written as
// "block NAME COUNT" and its COUNT numbers in hexadecimal floats (bit-exact), so that a resumed life is the
// uninterrupted one to the bit. The cam's: "rate" (the rate at the state) and "warm_starts" (its worn
// revolution's memory; session/cam_life_run.cpp). The roller's (wear_cache_blocks): "correction" and "error"
// (the corrected fidelity's correction in force and its error estimate) and "halfspace_normal" (the last
// half-space solve: the next one starts from its pressures, and a rate or limit at its state reuses it).
struct CheckpointBlock {
  std::string name;  // one word
  Eigen::VectorXd values;
};

// the numbers of a block, put in order (an array: its sizes, then its values column by column) ...
struct BlockWriter {
  std::vector<double> values;
  void put(double v) { values.push_back(v); }
  void put(const Eigen::ArrayXd& a);
  void put(const Eigen::ArrayXXd& a);
  CheckpointBlock block(std::string name) const;
};
// ... and taken back in the same order; throws std::runtime_error naming the block for one that is not what
// was put (too short, a size out of range, numbers left over)
struct BlockReader {
  const CheckpointBlock& block;
  Eigen::Index at = 0;
  double number();
  long integer(long max);  // a whole number in [0, max]
  Eigen::ArrayXd array();
  Eigen::ArrayXXd array2d();
  void finish() const;  // every number taken
};
// the block of that name, or nullptr
const CheckpointBlock* find_block(const std::vector<CheckpointBlock>& blocks, const std::string& name);

struct Checkpoint {
  std::uint64_t case_hash = 0;  // the case as read (files and profiles): a resume of another case is refused
  LifeStart start;
  int snapshots_written = 0;    // snapshot files written so far (the initial one included)
  double wall_s = 0;            // run time so far
  std::vector<CheckpointBlock> blocks;  // after the state, in this order
};

// The roller's wear loop's memory across evaluations (WearCache) that changes its results: the corrected
// fidelity's correction and error estimate, and each half-space solve's (the case's running condition's, or
// each running condition's of a collective, "halfspace_normal_K"); none for a deterministic normal solver
// (Hertz, semi-Hertz), whose solve a resumed run repeats to the bit.
std::vector<CheckpointBlock> wear_cache_blocks(const WearCache& cache);
// those blocks into a new cache for the model (other blocks ignored); throws std::runtime_error for a block
// that is not what wear_cache_blocks wrote for this model
void restore_wear_cache(const WearModel& m, const std::vector<CheckpointBlock>& blocks, WearCache& cache);

// the case's fingerprint: its file's text, the model's state size and its profiles
std::uint64_t case_fingerprint(const std::string& case_text, const WearModel& m);

std::string checkpoint_text(const Checkpoint& c);
// throws std::runtime_error "PATH:LINE: what" for a file that is not a checkpoint of this version
Checkpoint read_checkpoint(const std::filesystem::path& path);

// the summary.csv text of a run being resumed: its comment lines, header and the rows up to and
// including step `steps` (rows written after the checkpoint are dropped: they will be written again)
std::string summary_up_to(const std::filesystem::path& path, long steps);

}  // namespace wear
