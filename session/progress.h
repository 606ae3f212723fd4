// The progress of a long run on stderr (the transient's steps, a wear life's). On a terminal: one line redrawn
// in place with '\r', from 1 s into the run, at most 5 times a second. Otherwise: a plain info line at most
// every 5 s. Nothing when quiet.
#pragma once

#include <chrono>
#include <string>

namespace session {

class Progress {
  using Clock = std::chrono::steady_clock;

 public:
  Progress(std::string label, bool quiet);
  ~Progress() { clear(); }
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // done: the fraction of the run done, in [0, 1] (for the ETA); what: the state of the run
  void update(double done, const std::string& what);
  // removes the line from the terminal (before the summary is printed)
  void clear();

 private:
  static double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
  static std::string eta(double s);

  std::string label_;
  bool quiet_, terminal_, drawn_ = false;
  Clock::time_point start_, last_;
};

}  // namespace session
