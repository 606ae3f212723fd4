// The output folder of a command that writes one: where it is, one run at a time (OutputLock), what a signal
// (SIGINT, SIGTERM, SIGHUP) leaves there (interrupted::), the temporaries of a killed run, and the size of a
// transient run's output estimated before it starts. Shared by every command, so that each holds its folder
// and ends on a signal the same way.
#pragma once

#include <filesystem>
#include <string>

#include "lib/io/case.h"

namespace session {

// -o (option), else the case's (or sweep's) output.directory (case_directory), else out/<case name> (a sweep:
// out/<sweep file stem>)
std::filesystem::path output_directory(const std::string& option, const std::string& case_directory,
                                       const std::string& case_name);

// Temporary files a killed command left in dir and dir/snapshots: OWN_NAME.tmp.<pid> (lib/io/csv.h), OWN_NAME one
// of the names the program writes, of a process that no longer runs: removed. Files of any other name stay.
void remove_stale_temporaries(const std::filesystem::path& dir);

// A transient run's output estimated before it runs (one step per dx rolled and per dt_s): CaseError naming
// the keys when above output.max_bytes (the library's check, lib/io/case.h check_transient_output) or half the
// free disk under dir, unless force.
void check_transient_output_size(const contact::ContactCase& c, const contact::TransientCase& t, bool fields,
                                 const std::filesystem::path& dir, bool force);

// Temporary files of the streamed output, removed if the run is interrupted (SIGINT, SIGTERM, SIGHUP); the
// handler only unlinks (async-signal-safe) and re-raises the signal. A message may go with them (the wear
// run's "continue with --resume"); the handler writes it with write(2), also async-signal-safe.
namespace interrupted {
void remove_on_signal(const std::filesystem::path& tmp);  // at most 4 files
void forget();                                            // the files were renamed into place
// the line printed on stderr when a signal ends the process (cut to 8 kB)
void say_on_signal(const std::string& line);
// the lock file, removed on a signal too (the lock itself goes with the process)
void remove_lock_on_signal(const std::filesystem::path& lock);
void forget_lock();

// A run that can stop cleanly between steps (the cam life): after defer_next_signal the next signal only
// writes note on stderr and is recorded (requested_signal); a second one ends the process at once as
// above. The run then saves its state and calls end_by(requested_signal()), which ends the process as the
// signal would have (temporaries and lock file removed, the message printed, killed by that signal).
void defer_next_signal(const std::string& note);
void stop_deferring();      // signals end the process at once again (a recorded one stays recorded)
int requested_signal();     // the signal recorded while deferring, 0 when none
[[noreturn]] void end_by(int sig);
}  // namespace interrupted

// The folder locked while a command writes into it: flock on DIR/.rollwear.lock, which holds the owner's
// PID. A second command on the same folder fails (std::runtime_error: exit 1) naming the folder and that
// PID. The folder is created if missing (and removed again, if still empty, when the lock goes). The lock
// goes with the process however it ends; the file is removed when the command ends normally or by an error.
class OutputLock {
 public:
  explicit OutputLock(const std::filesystem::path& dir);
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  ~OutputLock();

 private:
  std::string holder_pid() const;

  std::filesystem::path path_, dir_;
  int fd_ = -1;
  bool created_ = false;
};

}  // namespace session
