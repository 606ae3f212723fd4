// rollwear sweep: many lives (or contacts) of one base case on all cores (app/commands.h, session/sweep.h,
// docs/sweeps.md).

#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include <spdlog/spdlog.h>

#include "lib/io/csv.h"
#include "app/commands.h"
#include "lib/errors.h"
#include "session/output_folder.h"
#include "session/sweep.h"
#include "session/sweep_summary.h"
#ifdef ROLLWEAR_WITH_MPI
#include "session/sweep_mpi.h"
#endif

namespace app {

namespace {

using contact::CaseError;

void parse_shard(const std::string& text, int& k, int& n) {
  const std::size_t slash = text.find('/');
  try {
    std::size_t used = 0;
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    k = std::stoi(text.substr(0, slash), &used);
    if (used != slash) throw std::invalid_argument("K");
    n = std::stoi(text.substr(slash + 1), &used);
    if (used != text.size() - slash - 1) throw std::invalid_argument("N");
  } catch (const std::exception&) {
    throw CaseError("--shard: expected K/N (e.g. 2/8), got '" + contact::clipped(text) + "'");
  }
  if (!(n >= 1 && k >= 1 && k <= n)) throw CaseError("--shard: K/N needs 1 <= K <= N, got " + text);
}

std::string duration(double s) {
  if (s < 0) return "unknown";
  if (s < 60) return fmt::format("{:.0f} s", s);
  if (s < 3600) return fmt::format("{:.0f} min {:.0f} s", std::floor(s / 60), std::fmod(s, 60));
  return fmt::format("{:.0f} h {:.0f} min", std::floor(s / 3600), std::floor(std::fmod(s, 3600) / 60));
}

}  // namespace

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& opt, CommonOptions& common) {
  CLI::App* sub = app.add_subcommand(
      "sweep", "Many wear lives (or, on a base case without wear:, steady contacts as `contact` solves them) of one base case: a grid of values (lists, linear and logarithmic ranges; product or "
               "zip) or random sampling (Monte Carlo, Latin hypercube) of any keys of the case, run on all cores. "
               "Writes results.csv (a row per case) and each case's outputs in case_NNNN/ (docs/sweeps.md).");
  sub->footer(
      "Every case is read and checked before any runs: a value the case reader refuses is exit 2, naming the\n"
      "sweep file's line of the axis, the key and the case. A case that fails while running is a row with its\n"
      "status and message; the sweep goes on. Killed, the same command resumes: finished cases are not run again.\n"
      "--shard K/N runs the cases i with i mod N = K-1; --merge DIR... -o OUT joins the shards' results.csv into\n"
      "OUT/results.csv, the table the whole sweep gives.\n"
      "Exit status: 0 every case ran (failed cases included: see the status column), 2 bad input, 1 any other failure.");
  sub->add_option("sweep", opt.sweep_path, "Sweep file (YAML), e.g. cases/sweep-grid.yaml");
  sub->add_option("-o,--output", opt.output_directory,
                  "Output folder (default: the sweep's output.directory, else out/<sweep file stem>)");
  sub->add_option("--shard", opt.shard, "Run the K-th of N disjoint parts, K/N (default 1/1: the whole sweep)");
  sub->add_option("-j,--threads", opt.threads, "Cases run at once (default: the number of cores)")
      ->check(CLI::NonNegativeNumber);
  sub->add_flag("-q,--quiet", opt.quiet, "No progress line");
  sub->add_flag("--force", opt.force, "Run a sweep of more than 10000 cases in this shard (kSweepMaxCases)");
  sub->add_option("--merge", opt.merge, "Join the results of these shard folders into -o OUT")->expected(1, -1);
  add_log_level_option(*sub, common);
  return sub;
}

int run_sweep_command(const SweepOptions& opt) {
  if (!opt.merge.empty()) {
    if (!opt.sweep_path.empty()) throw CaseError("--merge takes shard folders, not a sweep file");
    if (opt.output_directory.empty()) throw CaseError("--merge needs -o OUT, the folder of the merged results.csv");
    std::vector<std::filesystem::path> dirs(opt.merge.begin(), opt.merge.end());
    std::string info;
    const std::string table = session::merge_results(dirs, &info);
    const session::OutputLock lock(opt.output_directory);
    const std::filesystem::path out = opt.output_directory;
    contact::write_files_atomic({{out / "results.csv", table}, {out / "summary.txt", session::sweep_summary(table, info)}});
    spdlog::info("merged {} folders into {}", dirs.size(), (std::filesystem::path(opt.output_directory) / "results.csv").string());
    return 0;
  }
  if (opt.sweep_path.empty()) throw CaseError("sweep: give a sweep file (or --merge DIR... -o OUT)");
  const session::Sweep s = session::read_sweep(opt.sweep_path);
  session::SweepRunOptions o;
  parse_shard(opt.shard, o.shard_k, o.shard_n);
  o.force = opt.force;
  o.output_directory = session::output_directory(opt.output_directory, s.output_directory,
                                                std::filesystem::path(opt.sweep_path).stem().string());
  o.threads = opt.threads > 0 ? opt.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
#ifdef ROLLWEAR_WITH_MPI
  // under mpirun: rank 0 runs the sweep and deals its cases to the other ranks (session/sweep_mpi.h)
  struct MpiFinish {
    bool on = false;
    ~MpiFinish() {
      if (on) session::mpi::finish();
    }
  } mpi;
  mpi.on = session::mpi::start();
  if (mpi.on && session::mpi::rank() > 0) {
    session::mpi::serve(s, o.output_directory);
    return 0;
  }
  if (mpi.on) o.dispatch = session::mpi::dispatch();
#endif
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  o.progress_interval_s = terminal ? 0.5 : 5.0;
  bool drawn = false;
  if (!opt.quiet)
    o.progress = [&](long done, long failed, long total, double elapsed_s) {
      const std::string line = fmt::format("sweep: {} / {} cases ({} failed), {} elapsed, ETA {}", done, total, failed,
                                           duration(elapsed_s), duration(done > 0 && done < total ? elapsed_s * (total - done) / done : done == total ? 0 : -1));
      if (terminal) {
        std::fprintf(stderr, "\r%s\033[K", line.c_str());
        std::fflush(stderr);
        drawn = true;
      } else {
        spdlog::info("{}", line);
      }
    };
  // glibc gives each thread's arena back to the system (madvise) whenever its top is free: with a case per
  // thread that was 1.3 s of 5.3 s on cases/sweep-grid.yaml (strace: 122 000 madvise calls, holding the
  // process's memory map lock). Kept up to 256 MiB per arena, the sweep's system time is 0.1 s.
  mallopt(M_TRIM_THRESHOLD, 256 * 1024 * 1024);
  const session::OutputLock lock(o.output_directory);
  spdlog::info("sweep {}: {} cases, shard {}/{}, {}, into {}", opt.sweep_path, session::case_count(s), o.shard_k, o.shard_n,
               o.dispatch ? std::string("dealt to the other MPI ranks") : std::to_string(o.threads) + " threads",
               o.output_directory.string());
  std::string again = "rollwear sweep " + opt.sweep_path + " -o " + o.output_directory.string();
  if (o.shard_n > 1) again += " --shard " + opt.shard;
  session::interrupted::say_on_signal("\nrollwear: interrupted; the finished cases are kept, and the sweep continues with: " + again + "\n");
  const session::SweepRunSummary r = session::run_sweep(s, o);
  if (drawn) std::fprintf(stderr, "\r\033[K");
  fmt::print("sweep {}: {} cases in this shard, {} run now, {} finished before, {} not ok; table {}\n", opt.sweep_path,
             r.cases, r.cases - r.resumed, r.resumed, r.failed, (o.output_directory / "results.csv").string());
  return 0;
}

}  // namespace app
