#include "app/sweep_command.h"

#include <fcntl.h>
#include <malloc.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include <spdlog/spdlog.h>

#include "lib/io/csv.h"
#include "lib/io/errors.h"
#include "wear/sweep.h"
#include "wear/sweep_summary.h"
#ifdef ROLLWEAR_WITH_MPI
#include "app/sweep_mpi.h"
#endif

namespace {

using contact::CaseError;

// the line printed when a signal ends the sweep (write(2) only: async-signal-safe), then the signal re-raised
char g_interrupted[8192];
volatile std::sig_atomic_t g_interrupted_size = 0;
char g_lock_path[4096];  // the folder's lock file, unlinked too ("" when none)
void on_signal(int sig) {
  if (g_lock_path[0] != '\0') ::unlink(g_lock_path);
  if (g_interrupted_size > 0 && ::write(STDERR_FILENO, g_interrupted, static_cast<std::size_t>(g_interrupted_size)) < 0) {
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}
void say_on_signal(const std::string& line) {
  const std::size_t n = std::min(line.size(), sizeof g_interrupted);
  std::memcpy(g_interrupted, line.data(), n);
  g_interrupted_size = static_cast<std::sig_atomic_t>(n);
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_signal);
}

// the folder held while the sweep writes into it (flock on .rollwear.lock, as the other commands hold theirs):
// a second sweep or run there fails (exit 1) instead of writing the same cases
class FolderLock {
 public:
  explicit FolderLock(const std::filesystem::path& dir) : path_(dir / ".rollwear.lock"), dir_(dir) {
    std::error_code exists_ec;
    created_ = !std::filesystem::exists(dir, exists_ec);
    std::filesystem::create_directories(dir);
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error(path_.string() + ": cannot create the lock file: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd_);
      fd_ = -1;
      throw std::runtime_error(dir.string() + " is in use by another rollwear run (lock file " + path_.string() +
                               "); wait for it to end, or give another output folder with -o");
    }
    if (path_.string().size() < sizeof g_lock_path) std::memcpy(g_lock_path, path_.c_str(), path_.string().size() + 1);
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) spdlog::debug("{}: cannot write the PID", path_.string());
  }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  ~FolderLock() {
    if (fd_ < 0) return;
    std::error_code ec;
    g_lock_path[0] = '\0';
    std::filesystem::remove(path_, ec);
    ::close(fd_);
    if (created_ && std::filesystem::is_empty(dir_, ec)) std::filesystem::remove(dir_, ec);  // refused before writing
  }

 private:
  std::filesystem::path path_, dir_;
  int fd_ = -1;
  bool created_ = false;
};

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

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& opt) {
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
  sub->add_option("--merge", opt.merge, "Join the results of these shard folders into -o OUT")->expected(1, -1);
  return sub;
}

int run_sweep_command(const SweepOptions& opt) {
  if (!opt.merge.empty()) {
    if (!opt.sweep_path.empty()) throw CaseError("--merge takes shard folders, not a sweep file");
    if (opt.output_directory.empty()) throw CaseError("--merge needs -o OUT, the folder of the merged results.csv");
    std::vector<std::filesystem::path> dirs(opt.merge.begin(), opt.merge.end());
    std::string info;
    const std::string table = wear::merge_results(dirs, &info);
    const FolderLock lock(opt.output_directory);
    const std::filesystem::path out = opt.output_directory;
    contact::write_files_atomic({{out / "results.csv", table}, {out / "summary.txt", wear::sweep_summary(table, info)}});
    spdlog::info("merged {} folders into {}", dirs.size(), (std::filesystem::path(opt.output_directory) / "results.csv").string());
    return 0;
  }
  if (opt.sweep_path.empty()) throw CaseError("sweep: give a sweep file (or --merge DIR... -o OUT)");
  const wear::Sweep s = wear::read_sweep(opt.sweep_path);
  wear::SweepRunOptions o;
  parse_shard(opt.shard, o.shard_k, o.shard_n);
  o.output_directory = !opt.output_directory.empty() ? std::filesystem::path(opt.output_directory)
                       : !s.output_directory.empty() ? std::filesystem::path(s.output_directory)
                                                     : std::filesystem::path("out") / std::filesystem::path(opt.sweep_path).stem();
  o.threads = opt.threads > 0 ? opt.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
#ifdef ROLLWEAR_WITH_MPI
  // under mpirun: rank 0 runs the sweep and deals its cases to the other ranks (app/sweep_mpi.h)
  struct MpiFinish {
    bool on = false;
    ~MpiFinish() {
      if (on) rollwear_mpi::finish();
    }
  } mpi;
  mpi.on = rollwear_mpi::start();
  if (mpi.on && rollwear_mpi::rank() > 0) {
    rollwear_mpi::serve(s, o.output_directory);
    return 0;
  }
  if (mpi.on) o.dispatch = rollwear_mpi::dispatch();
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
  const FolderLock lock(o.output_directory);
  spdlog::info("sweep {}: {} cases, shard {}/{}, {}, into {}", opt.sweep_path, wear::case_count(s), o.shard_k, o.shard_n,
               o.dispatch ? std::string("dealt to the other MPI ranks") : std::to_string(o.threads) + " threads",
               o.output_directory.string());
  std::string again = "rollwear sweep " + opt.sweep_path + " -o " + o.output_directory.string();
  if (o.shard_n > 1) again += " --shard " + opt.shard;
  say_on_signal("\nrollwear: interrupted; the finished cases are kept, and the sweep continues with: " + again + "\n");
  const wear::SweepRunSummary r = wear::run_sweep(s, o);
  if (drawn) std::fprintf(stderr, "\r\033[K");
  fmt::print("sweep {}: {} cases in this shard, {} run now, {} finished before, {} not ok; table {}\n", opt.sweep_path,
             r.cases, r.cases - r.resumed, r.resumed, r.failed, (o.output_directory / "results.csv").string());
  return 0;
}
