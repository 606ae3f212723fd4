// A sweep (`rollwear sweep`, docs/sweeps.md): many independent wear lives of one base case, each with
// some of its keys replaced. The sweep file names the base case and how it varies:
//
//   base: paper-wear.yaml                     # relative to the sweep file
//   output: { directory: out/sweep-grid }     # optional; -o overrides; default out/<sweep file stem>
//   combine: product                          # product (default) or zip of the axes
//   axes:                                     # any key of the case by its path
//     - { key: friction.mu, values: [0.2, 0.3, 0.4] }
//     - { key: load.normal_load_N, linear: { from: 1000, to: 2000, count: 5 } }
//     - { key: wear.body1.archard_k, log: { from: 1.0e-5, to: 1.0e-4, count: 3 } }
//
// or random sampling:
//
//   random:
//     method: latin-hypercube                 # monte-carlo | latin-hypercube
//     count: 32
//     seed: 2026
//     inputs:
//       - { key: wear.body1.archard_k, distribution: lognormal, median: 1.0e-4, sigma_ln: 0.3 }
//       - { key: friction.mu, distribution: uniform, min: 0.2, max: 0.4 }
//       - { key: load.normal_load_N, distribution: normal, mean: 1500, sd: 100 }
//       - { key: kinematics.xi, distribution: truncated-normal, mean: 1.0e-3, sd: 3.0e-4, min: 0, max: 2.0e-3 }
//
// Case i's inputs depend on (seed, i) alone (and, for a Latin hypercube, the count): each draw is
// SplitMix64 keyed by (seed, i, input) and transformed by the inverse CDFs below, written here in
// plain arithmetic and <cmath> (no std::*_distribution, whose results differ between standard
// libraries), so threads, shards and a resumed run see the same cases.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "lib/io/case.h"
#include "session/sweep_random.h"
#include "wear/wear_loop.h"

namespace YAML {
class Node;  // <yaml-cpp/yaml.h>, which only session/sweep*.cpp need
}  // namespace YAML

namespace session {

// ---- the sweep file ----

enum class Combine { Product, Zip };
// what each case is: a wear life (`rollwear run`, the base case has a wear: section) or a steady contact
// (`rollwear contact`, the base case has none)
enum class SweepKind { Wear, Contact };
enum class Sampling { Grid, MonteCarlo, LatinHypercube };

struct SweepAxis {
  std::string key;
  std::string location;  // FILE:LINE:COL of the axis in the sweep file
  std::vector<double> values;
};

struct Sweep {
  std::string path;               // the sweep file
  std::filesystem::path base_path;  // the base case (resolved against the sweep file's folder)
  std::string output_directory;   // output.directory, "" when not given
  bool case_files = true;         // output.case_files: each case's folder (case_NNNN/) written; false: the table alone
  SweepKind kind = SweepKind::Wear;  // from the base case: Contact when it has no wear: section
  // the base case has wear.fatigue, wear.limits.shakedown or scuffing true, or a thermal: section (the cases whose
  // report.txt has the failure margins, docs/fatigue.md): results.csv gains the margin columns (kMarginColumns)
  bool margins = false;
  Sampling sampling = Sampling::Grid;
  Combine combine = Combine::Product;
  std::vector<SweepAxis> axes;    // grid
  std::vector<RandomInput> inputs;  // random
  long count = 0;                 // random: the number of cases
  std::uint64_t seed = 0;
  std::vector<std::vector<double>> correlation;  // random: target rank correlations of the inputs, or empty
  std::vector<std::vector<double>> samples;      // random: every case's inputs (count x inputs), drawn by read_sweep
};

// reads the sweep file; CaseError (file, line, key) on any problem of the file itself. The cases are
// checked by validate_cases.
Sweep read_sweep(const std::string& path);

// the varied keys, in the order of the results table's columns
std::vector<std::string> varied_keys(const Sweep& s);
// the number of cases
long case_count(const Sweep& s);
// case i's values of the varied keys (product: the last axis varies fastest). Random: Monte Carlo draws
// depend on (seed, i) alone; a Latin hypercube's on (seed, count); with a correlation: on all of them.
std::vector<double> case_inputs(const Sweep& s, long i);

// ---- the plan ----

// A sweep of more cases than this (in the shard run) is refused before any case is read, unless forced
// (`rollwear sweep --force`, Python sweep(force=True)): reading and checking 1e6 cases alone takes minutes,
// and their folders hundreds of GB.
constexpr long kSweepMaxCases = 10000;
// What a sweep (its shard) will do, known at once: from the case count and the base case alone, no case
// read. The output per case, estimated: a results row (24 bytes a number, lib/io/case.h kCsvBytesPerNumber),
// and with output.case_files the case's folder: its case.yaml (the base's size), and for a wear life its
// worn profiles at the start, the end and each of wear.snapshots_revolutions (4 columns a node of the worn
// bodies) and its summary.csv (kPlannedSummaryRows rows of the step's values).
constexpr double kPlannedSummaryRows = 100;  // the shipped lives take about a hundred steps (cases/paper-wear.yaml: 91-97)
struct SweepPlan {
  long cases = 0;            // the whole sweep's
  long shard_cases = 0;      // the shard's
  double bytes_per_case = 0;
  double bytes = 0;          // the shard's output, estimated
};
SweepPlan plan_sweep(const Sweep& s, int shard_k, int shard_n);
// "N cases (shard k/n: M), about X MB of output (Y kB a case)"
std::string to_string(const SweepPlan& p, int shard_k, int shard_n);

// ---- the cases ----

// the base case's YAML with its relative profile files made absolute (the generated case lives elsewhere)
YAML::Node load_base_case(const Sweep& s);
// case i's YAML text: the base with the varied keys replaced (numbers as lib/number.h round_trip
// writes them) and name: <base name>-NNNN. CaseError at the key's entry in the sweep file when the
// base case has no such mapping, or holds a mapping or a list there.
std::string case_yaml(const Sweep& s, const YAML::Node& base, long i, const std::vector<double>& inputs);

// A case as validated, kept to run: its inputs, its text (case.yaml; "" for a contact case without case
// files, whose text is not needed) and, for a contact sweep, the case as read.
struct SweepCase {
  long index = 0;
  std::vector<double> inputs;
  std::string text;
  std::shared_ptr<const contact::ContactCase> contact;  // SweepKind::Contact only
};

// Every case of `indices` read before any runs: by the wear case reader and model (as `rollwear run` would)
// or, for a contact sweep, by the contact case reader and validate_steady (as `rollwear contact` would).
// A refused case is a CaseError naming the sweep file, the line of the axis (or input) whose value alone the
// reader refuses, the key, the case and the reader's own message; a combination refused while each value
// alone passes names every varied key. Returns the cases, in the order of `indices`.
std::vector<SweepCase> validate_cases(const Sweep& s, const std::vector<long>& indices);

// ---- the results table ----

// how a case ended, the results table's status column: ok (a limit or the budget ended the life), failed
// (the wear loop failed: LifeEnd::Failed or NotRun), bad_input (a CaseError), error (any other exception)
enum class CaseStatus { Ok, Failed, BadInput, Error };
std::string to_string(CaseStatus s);
// the inverse of to_string; throws std::invalid_argument naming the word
CaseStatus parse_case_status(const std::string& word);

// a contact case's outputs: the `rollwear contact` summary's numbers (nan when it did not run)
struct ContactOutputs {
  double a_m = std::numeric_limits<double>::quiet_NaN(), b_m = a_m;  // semi-axes (rolling, lateral)
  double p0_Pa = a_m, approach_m = a_m;
  double Fx_N = a_m, Fy_N = a_m, Mz_N_m = a_m;  // creep forces and spin moment
  double power_W = a_m, stick_fraction = a_m;
};

// one case's row: index, the varied inputs, then a wear case's life_revolutions, ended_by, max_depth_m,
// worn_volume_m3 (the margins), fidelity, exact_solves, error_power_rel, error_power_l1 or a contact case's a_m, b_m, p0_Pa, approach_m, Fx_N, Fy_N, Mz_N_m, power_W,
// stick_fraction; then status, message
struct CaseOutcome {
  long index = 0;
  std::vector<double> inputs;
  SweepKind kind = SweepKind::Wear;
  ContactOutputs contact;  // SweepKind::Contact
  double life_revolutions = std::numeric_limits<double>::quiet_NaN();
  wear::LifeEnd ended_by = wear::LifeEnd::NotRun;
  double max_depth_m = std::numeric_limits<double>::quiet_NaN();
  double worn_volume_m3 = std::numeric_limits<double>::quiet_NaN();
  // the case has the failure margins (Sweep::margins, has_failure_margins): its row carries them after
  // worn_volume_m3, each report.txt's value (wear::failure_margins), NaN where the report has none
  bool margins = false;
  double max_damage = std::numeric_limits<double>::quiet_NaN();
  double depth_fraction = std::numeric_limits<double>::quiet_NaN();
  double shakedown_margin = std::numeric_limits<double>::quiet_NaN();
  double scuffing_margin_K = std::numeric_limits<double>::quiet_NaN();
  // a wear case's fidelity and error estimate (kErrorColumns; report.txt's, docs/fidelity.md)
  std::string fidelity;
  long exact_solves = 0;
  double error_power_rel = std::numeric_limits<double>::quiet_NaN();
  double error_power_l1 = std::numeric_limits<double>::quiet_NaN();
  CaseStatus status = CaseStatus::Error;  // the pessimistic default
  std::string message;
};
// a wear sweep whose base case has the failure margins (margins) has these columns after worn_volume_m3, in this
// order (max_damage first: where a fatigue sweep has always had it)
inline constexpr const char* kMarginColumns = "max_damage,depth_fraction,shakedown_margin,scuffing_margin_K";
// a wear sweep's last output columns (after the margins, before status): which fidelity ran, its exact-physics
// solves and its error estimate against the exact physics (docs/fidelity.md; NaN where not estimated)
inline constexpr const char* kErrorColumns = "fidelity,exact_solves,error_power_rel,error_power_l1";
std::string results_header(const std::vector<std::string>& keys, SweepKind kind = SweepKind::Wear, bool margins = false);
std::string results_row(const CaseOutcome& o);  // one line, ending in '\n'
// a row's status (the inputs before it are `keys` columns); std::invalid_argument for a line that has none
CaseStatus row_status(const std::string& row, std::size_t keys, SweepKind kind = SweepKind::Wear, bool margins = false);
// the leading index of a row; throws std::invalid_argument for a line that has none
long row_index(const std::string& row);

// "case_0007"
std::string case_folder_name(long i);

// Runs one case in `dir` (case.yaml written there first): the wear life as `rollwear run` runs it,
// writing summary.csv, snapshots/ and report.txt, then row.csv (its results row: the mark that the case
// is finished). Never throws for the case's own failure: that is the row's status and message.
CaseOutcome run_case(const std::string& yaml_text, long index, const std::vector<double>& inputs,
                     const std::filesystem::path& dir);

// Runs one contact case as `rollwear contact` does (solve_contact_case, lib/io/case_run.h), fields when the case
// asks for them (output.fields). With `dir` not empty, writes there case.yaml (`text`), summary.csv,
// strips.csv, fields.csv (when asked) and then row.csv (the mark that the case is finished); with `dir`
// empty, no file. Never throws for the case's own failure: that is the row's status and message.
CaseOutcome run_contact_case(const contact::ContactCase& c, const std::string& text, long index,
                             const std::vector<double>& inputs, const std::filesystem::path& dir);

// case i of the sweep generated, read and run as run_sweep's threads run it, into out/case_NNNN/ (when
// s.case_files): what an MPI rank does with a case it is dealt (session/sweep_mpi.h)
CaseOutcome run_sweep_case(const Sweep& s, const YAML::Node& base, long i, const std::filesystem::path& out);

// the cases of shard k (1-based) of n: i with i % n == k - 1
std::vector<long> shard_indices(long count, int k, int n);

struct SweepRunOptions {
  std::filesystem::path output_directory;
  int shard_k = 1, shard_n = 1;
  int threads = 1;
  // called from the thread that runs run_sweep, at most every `progress_interval_s`, and at the end
  std::function<void(long done, long failed, long total, double elapsed_s)> progress;
  double progress_interval_s = 1.0;
  // a shard of more than max_cases cases is refused (CaseError, before any case is read) unless force
  long max_cases = kSweepMaxCases;
  bool force = false;
  // asked from the same thread at the same moments (every progress_interval_s): true stops the sweep. No
  // new case starts, the running ones finish (their rows kept for a resume), and run_sweep throws
  // SweepCancelled without writing results.csv. The Python bindings check for Ctrl-C here.
  std::function<bool()> cancelled;
  // When set, the pending cases run elsewhere instead of on `threads` threads (rollwear sweep under MPI,
  // session/sweep_mpi.h): called once with every pending case (index, case text), it calls finished(row) with
  // each case's results row, in any order, from the calling thread, and returns when every case has one.
  std::function<void(const std::vector<std::pair<long, std::string>>& pending,
                     const std::function<void(const std::string& row)>& finished)>
      dispatch;
};
// run_sweep stopped by SweepRunOptions::cancelled
struct SweepCancelled : std::runtime_error {
  using std::runtime_error::runtime_error;
};
struct SweepRunSummary {
  long cases = 0;    // this shard's
  long resumed = 0;  // finished before this run (row.csv present, same case.yaml): not run again
  long failed = 0;   // status other than ok, this shard's
};
// validates the shard's cases, runs those not finished on `threads` threads (one case per thread), then
// writes results.csv (this shard's rows, by index), sweep.txt (the sweep's fingerprint, case count, shard,
// sampling, seed and axes) and, for the whole sweep (shard 1/1), summary.txt atomically. A finished case whose case.yaml differs from the one generated now is a CaseError
// (the sweep changed: use another folder).
SweepRunSummary run_sweep(const Sweep& s, const SweepRunOptions& o);

// joins the results.csv of shard folders into the whole sweep's table (rows sorted by index); CaseError
// when the folders are of different sweeps, a case is in two of them, or a case is missing. `sweep_txt`
// receives the first folder's sweep.txt (the input of sweep_summary).
std::string merge_results(const std::vector<std::filesystem::path>& dirs, std::string* sweep_txt = nullptr);

}  // namespace session
