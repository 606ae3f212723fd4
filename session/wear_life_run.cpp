// A wear life driven to its end (session/wear_life_run.h), and `rollwear run` on a wear case (session/life_run.h).
#include "session/wear_life_run.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include "lib/io/csv.h"
#include "session/life_folder.h"
#include "session/life_run.h"
#include "session/output_folder.h"
#include "session/progress.h"
#include "wear/wear_output.h"

namespace session {

using namespace wear;

wear::LifeStart fresh_wear_start(const WearModel& m, WearCache& cache, const WearLifeObserver& o) {
  LifeStart start;
  start.state = initial_state(m);
  LifeStep s0;
  s0.state = &start.state;
  s0.contact = wear_rate(m, start.state, cache).contact;
  start.counters = cache.counters;  // the life's solves include the unworn state's (step 0's row)
  if (o.on_row) o.on_row(s0);
  return start;
}

wear::LifeResult drive_wear_life(const WearModel& m, const WearCase& c, const LifeStart& start, WearCache& cache,
                                 const WearLifeObserver& o) {
  double last_N = start.N;  // the last row's revolutions
  LifeHooks hooks;
  hooks.on_step = [&](const LifeStep& s) {
    if (o.on_row) o.on_row(s);
    last_N = s.N;
    return o.on_step ? o.on_step(s) : true;
  };
  hooks.on_snapshot = o.on_snapshot;
  LifeResult life = run_life(m, c, start, hooks, cache);

  // a limit located within a step ends the life between step ends: its state is the last row
  if (life.N > last_N) {
    LifeStep end;
    end.step = life.counters.steps;
    end.N = life.N;
    end.state = &life.state;
    end.info.step = life.N - last_N;
    end.info.rhs_evals = life.counters.rhs_evals;
    end.info.rejected = life.counters.rejected;
    end.counters = life.counters;
    end.contact = life.contact;
    if (o.on_row) o.on_row(end);
  }
  if (has_dang_van(c) && life.ended_by != LifeEnd::Failed && life.ended_by != LifeEnd::NotRun &&
      life.ended_by != LifeEnd::Stopped) {
    const auto t0 = std::chrono::steady_clock::now();
    life.dang_van = dang_van_on_worn(m, c, life.state);
    spdlog::info("Dang Van's index on the final worn contact: {:.3f} s",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return life;
}

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

LifeRunEnd run_wear_life_in_folder(const LifeRunOptions& opt) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point started = Clock::now();
  const WearCase c = read_wear_case(opt.case_path);
  const WearModel m = make_wear_model(c);
  const std::filesystem::path dir = output_directory(opt.output_directory, c.contact.output.directory, c.contact.name);
  const double hours_per_rev = hours_per_revolution(m);
  const std::uint64_t fingerprint = case_fingerprint(read_text(opt.case_path), m);
  const LifeFolder folder({dir, opt.case_path, "summary.csv", fingerprint, opt.resume, opt.restart});  // one run at a time
  const std::filesystem::path checkpoint_path = folder.checkpoint_path();

  // where the life starts: a checkpoint, or the unworn state
  Checkpoint cp;
  std::string summary;
  WearCache cache;
  WearLifeObserver observer;
  observer.on_row = [&](const LifeStep& s) { summary += wear_summary_row(m, s, hours_per_rev); };
  if (opt.resume) {
    cp = folder.checkpoint();
    try {  // what the rate carried there (the correction, the last half-space solve)
      restore_wear_cache(m, cp.blocks, cache);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(checkpoint_path.string() + ": " + e.what());
    }
    summary = folder.table_up_to(cp.start.counters.steps);
    spdlog::info("run: resuming at revolution {:.6g} (step {}) from {}", cp.start.N, cp.start.counters.steps,
                 checkpoint_path.string());
  } else {
    folder.start_afresh("snapshot_[0-9]{4}_body[12]\\.csv");  // a previous run's are not this run's
    cp.case_hash = fingerprint;
    summary = wear_summary_header(m);
    cp.start = fresh_wear_start(m, cache, observer);
    cp.blocks = wear_cache_blocks(cache);
  }

  // outputs: the worn profiles of each wearing body at a revolution
  const auto snapshot_files = [&](double N, const Eigen::VectorXd& state) {
    std::vector<contact::OutputFile> files;
    for (int body : {1, 2})
      if ((body == 1 ? m.n1 : m.n2) > 0)
        files.push_back({dir / wear_snapshot_path(cp.snapshots_written, body),
                         wear_snapshot_csv(m, body, N, N * hours_per_rev, state)});
    ++cp.snapshots_written;
    return files;
  };
  const double earlier_s = cp.wall_s;  // run time before the resume
  const auto elapsed_s = [&] { return earlier_s + std::chrono::duration<double>(Clock::now() - started).count(); };
  // summary and checkpoint together: the summary is renamed first, so it never lags the checkpoint
  const auto save = [&](std::vector<contact::OutputFile> files) {
    cp.wall_s = elapsed_s();
    folder.save(std::move(files), summary, &cp);
  };
  if (!opt.resume) save(snapshot_files(0, cp.start.state));
  // an interrupt (Ctrl-C) ends the process at once: the last checkpoint is where --resume continues
  interrupted::say_on_signal(folder.resume_line());

  // the life, step by step: a summary row each, a checkpoint every checkpoint_interval_s
  Progress progress("run", opt.quiet);
  Clock::time_point last_save = Clock::now();
  observer.on_step = [&](const LifeStep& s) {
    cp.start = {s.N, *s.state, s.info.next_step, s.counters};
    cp.blocks = wear_cache_blocks(cache);  // at this step's end: the rate was just evaluated there
    // at a snapshot revolution the snapshot's save follows and carries this step: a checkpoint here would not count
    // the snapshot, and a run killed before the snapshot's save would resume past it (the cam's run does the same)
    const auto& at = c.wear.snapshots_revolutions;
    if (std::chrono::duration<double>(Clock::now() - last_save).count() >= c.wear.checkpoint_interval_s &&
        std::find(at.begin(), at.end(), s.N) == at.end()) {
      save({});
      last_save = Clock::now();
    }
    const double depth = max_depth_m(m, *s.state);
    double done = s.N / c.wear.revolutions;
    if (m.limits.max_depth_m > 0) done = std::max(done, depth / m.limits.max_depth_m);
    progress.update(done, fmt::format("step {}, {:.4g} revolutions ({:.4g} h), max depth {:.4g} um", s.step, s.N,
                                      s.N * hours_per_rev, depth * 1e6));
    return true;
  };
  observer.on_snapshot = [&](double N, const Eigen::VectorXd& state) {
    save(snapshot_files(N, state));
    last_save = Clock::now();
  };
  LifeResult life;
  try {
    life = drive_wear_life(m, c, cp.start, cache, observer);
  } catch (...) {
    progress.clear();
    if (!opt.resume && cp.start.counters.steps == 0) {
      // nothing accepted yet (e.g. bad input found at step 0): nothing to resume, and a checkpoint would
      // block the corrected rerun
      folder.remove_checkpoint();
      throw;
    }
    save({});  // the last accepted step: --resume continues from there (e.g. with other settings)
    spdlog::error("run: stopped at revolution {:.6g} (step {}); its state is saved in {}", cp.start.N,
                  cp.start.counters.steps, checkpoint_path.string());
    throw;
  }
  progress.clear();

  // the end: the final worn profiles and the report; the checkpoint goes (the run is complete)
  WearReport report;
  report.case_name = m.name;
  report.life = life;
  report.hours_per_revolution = hours_per_rev;
  report.wall_s = elapsed_s();
  report.resumed = opt.resume;
  std::vector<contact::OutputFile> files = snapshot_files(life.N, life.state);
  // the error estimate above the header row (the rows' columns stay as they were)
  const std::size_t header_row = summary.find("\nstep,");
  if (header_row != std::string::npos) summary.insert(header_row + 1, wear_summary_error_line(m, life));
  files.push_back({folder.table_path(), summary});
  const std::string report_text = wear_report_text(m, report);
  files.push_back({dir / "report.txt", report_text});
  contact::write_files_atomic(files);
  folder.remove_checkpoint();
  fmt::print("{}", report_text);
  spdlog::info("wrote summary.csv, report.txt and {} snapshots to {}", cp.snapshots_written, dir.string());
  return life.ended_by == LifeEnd::Failed || life.ended_by == LifeEnd::NotRun ? LifeRunEnd::Failed : LifeRunEnd::Ended;
}

}  // namespace session
