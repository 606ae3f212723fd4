// The progress of a long run on stderr (session/progress.h).
#include "session/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

namespace session {

Progress::Progress(std::string label, bool quiet)
    : label_(std::move(label)), quiet_(quiet), terminal_(::isatty(STDERR_FILENO) == 1), start_(Clock::now()),
      last_(start_) {}

void Progress::update(double done, const std::string& what) {
  if (quiet_) return;
  const Clock::time_point now = Clock::now();
  const double elapsed_s = seconds(now - start_);
  if (terminal_ ? elapsed_s < 1.0 || seconds(now - last_) < 0.2 : seconds(now - last_) < 5.0) return;
  last_ = now;
  done = std::clamp(done, 0.0, 1.0);
  const std::string line = fmt::format("{} ({:.0f} %), ETA {}", what, 100 * done,
                                       eta(done > 0 ? elapsed_s * (1 - done) / done : -1));
  if (terminal_) {
    std::fprintf(stderr, "\r%s\033[K", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
  } else {
    spdlog::info("{}: {}", label_, line);
  }
}

void Progress::clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

std::string Progress::eta(double s) {
  if (s < 0) return "unknown";
  if (s < 60) return fmt::format("{:.0f} s", s);
  return fmt::format("{:.0f} min {:02.0f} s", std::floor(s / 60), std::fmod(s, 60));
}

}  // namespace session
