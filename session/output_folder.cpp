// The output folder: its place, its lock, the signals' clean-up, stale temporaries, the size estimate
// (session/output_folder.h).
#include "session/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <regex>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

namespace session {

std::filesystem::path output_directory(const std::string& option, const std::string& case_directory,
                                       const std::string& case_name) {
  if (!option.empty()) return option;
  if (!case_directory.empty()) return case_directory;
  return std::filesystem::path("out") / case_name;
}

namespace {

// The program's own file names in an output folder (every command's, a sweep's case folders included): what
// it may delete there, and nothing else.
const std::regex& own_output_name() {
  static const std::regex kNames(
      "(summary\\.csv|strips\\.csv|fields\\.csv|timeseries\\.csv|strip_power\\.csv|strip_energy\\.csv|"
      "snapshot_[0-9]+\\.csv|snapshot_[0-9]{4}_body[12]\\.csv|checkpoint\\.txt|report\\.txt|"
      "revolution\\.csv|dissipation\\.csv|life\\.csv|(wear_map|roller_wear)_[0-9]{4}\\.csv|"
      "case\\.yaml|row\\.csv|results\\.csv|sweep\\.txt|summary\\.txt|\\.validate\\.yaml|finished\\.csv)");
  return kNames;
}

}  // namespace

void remove_stale_temporaries(const std::filesystem::path& dir) {
  static const std::regex kTemporary("(.+)\\.tmp\\.([0-9]{1,10})");
  for (const std::filesystem::path& d : {dir, dir / "snapshots"}) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(d, ec)) {
      const std::string name = entry.path().filename().string();
      std::smatch m;
      if (!std::regex_match(name, m, kTemporary) || !std::regex_match(m[1].str(), own_output_name())) continue;
      const long pid = std::strtol(m[2].str().c_str(), nullptr, 10);
      if (pid > 0 && pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
        std::filesystem::remove(entry.path(), ec);
        spdlog::info("removed {}, the temporary file of a killed run (PID {})", entry.path().string(), pid);
      }
    }
  }
}

void check_transient_output_size(const contact::ContactCase& c, const contact::TransientCase& t, bool fields,
                                 const std::filesystem::path& dir, bool force) {
  contact::check_transient_output(c, t, fields, force);  // output.max_bytes: the library's check (Python's too)
  const contact::TransientOutputEstimate estimate = contact::estimate_transient_output(t, fields);
  std::filesystem::path existing = std::filesystem::absolute(dir);
  while (!std::filesystem::exists(existing) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  std::error_code space_ec;
  const double free_bytes = static_cast<double>(std::filesystem::space(existing, space_ec).available);
  const bool over_disk = !space_ec && estimate.bytes > free_bytes / 2;
  spdlog::debug("transient: about {:.3g} steps, {:.3g} MB of output estimated", estimate.steps, estimate.bytes / 1e6);
  if (over_disk && !force)
    throw contact::CaseError(fmt::format(
        "{}transient.t_end_s, transient.dt_s, solver.nx, solver.ny, output.max_bytes: the run would write about {:.3g} "
        "bytes ({:.3g} GB: about {:.3g} steps of {} strips), more than half the free disk ({:.3g} bytes free in {}); "
        "shorten t_end_s, coarsen the grid, or run with --force",
        contact::where(c, "transient.t_end_s"), estimate.bytes, estimate.bytes / 1e9, estimate.steps,
        contact::transient_grid(t).y_m.size(), free_bytes, existing.string()));
}

namespace interrupted {
namespace {
constexpr int kMaxFiles = 4;
char g_paths[kMaxFiles][4096];
volatile std::sig_atomic_t g_count = 0;
char g_lock[4096];  // the output folder's lock file (OutputLock), "" when none
char g_message[8192];
volatile std::sig_atomic_t g_message_size = 0;

volatile std::sig_atomic_t g_defer = 0;      // 1: the next signal is only recorded
volatile std::sig_atomic_t g_requested = 0;  // the signal recorded, 0 none
char g_note[1024];
volatile std::sig_atomic_t g_note_size = 0;

void end_now(int sig) {
  for (int k = 0; k < g_count; ++k) ::unlink(g_paths[k]);
  if (g_lock[0] != '\0') ::unlink(g_lock);
  if (g_message_size > 0 && ::write(STDERR_FILENO, g_message, static_cast<std::size_t>(g_message_size)) < 0) {
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void on_signal(int sig) {
  if (g_defer != 0) {
    g_defer = 0;
    g_requested = sig;
    if (g_note_size > 0 && ::write(STDERR_FILENO, g_note, static_cast<std::size_t>(g_note_size)) < 0) {
    }
    return;
  }
  end_now(sig);
}

void install() {
  static bool installed = false;
  if (installed) return;
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_signal);
  installed = true;
}
}  // namespace

void remove_on_signal(const std::filesystem::path& tmp) {
  const std::string p = tmp.string();
  if (g_count >= kMaxFiles || p.size() >= sizeof g_paths[0]) return;
  std::memcpy(g_paths[g_count], p.c_str(), p.size() + 1);
  install();
  g_count = g_count + 1;
}

// the line printed on stderr when a signal ends the process (cut to the buffer)
void say_on_signal(const std::string& line) {
  const std::size_t n = std::min(line.size(), sizeof g_message);
  g_message_size = 0;
  std::memcpy(g_message, line.data(), n);
  g_message_size = static_cast<std::sig_atomic_t>(n);
  install();
}

// the lock file, removed on a signal too (the lock itself goes with the process)
void remove_lock_on_signal(const std::filesystem::path& lock) {
  const std::string p = lock.string();
  if (p.size() >= sizeof g_lock) return;
  std::memcpy(g_lock, p.c_str(), p.size() + 1);
  install();
}
void forget_lock() { g_lock[0] = '\0'; }

void forget() { g_count = 0; }  // the files were renamed into place

void defer_next_signal(const std::string& note) {
  const std::size_t n = std::min(note.size(), sizeof g_note);
  g_note_size = 0;
  std::memcpy(g_note, note.data(), n);
  g_note_size = static_cast<std::sig_atomic_t>(n);
  g_requested = 0;
  install();
  g_defer = 1;
}
void stop_deferring() { g_defer = 0; }
int requested_signal() { return g_requested; }

void end_by(int sig) {
  std::fflush(stdout);
  std::fflush(stderr);
  end_now(sig);
  std::_Exit(128 + sig);  // not reached: the signal's default action ends the process
}
}  // namespace interrupted

OutputLock::OutputLock(const std::filesystem::path& dir) : path_(dir / ".rollwear.lock") {
  std::error_code ec;
  created_ = !std::filesystem::exists(dir, ec);
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create the output folder {}: {}", dir.string(), ec.message()));
  dir_ = dir;
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error(fmt::format("{}: cannot create the lock file: {}", path_.string(), std::strerror(errno)));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const std::string holder = holder_pid();
      ::close(fd_);
      fd_ = -1;
      if (err == EWOULDBLOCK)
        throw std::runtime_error(fmt::format(
            "{} is in use by another rollwear run (PID {}, lock file {}); wait for it to end, or give another "
            "output folder with -o", dir.string(), holder.empty() ? "unknown" : holder, path_.string()));
      throw std::runtime_error(fmt::format("{}: cannot lock: {}", path_.string(), std::strerror(err)));
    }
    // the file locked must still be the one at the path (a finishing run removes it after unlocking)
    struct stat held {}, named {};
    if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size()))
        spdlog::debug("{}: cannot write the PID", path_.string());
      interrupted::remove_lock_on_signal(path_);
      return;
    }
    ::close(fd_);
    fd_ = -1;
  }
  throw std::runtime_error(fmt::format("{}: cannot lock (the lock file keeps being replaced)", path_.string()));
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  std::error_code ec;
  interrupted::forget_lock();
  std::filesystem::remove(path_, ec);  // while still locked: a waiting run then retries on a new file
  ::close(fd_);
  if (created_ && std::filesystem::is_empty(dir_, ec)) std::filesystem::remove(dir_, ec);  // refused before writing
}

std::string OutputLock::holder_pid() const {
  std::ifstream in(path_);
  std::string pid;
  in >> pid;
  return pid.size() <= 20 && pid.find_first_not_of("0123456789") == std::string::npos ? pid : std::string();
}

}  // namespace session
