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
