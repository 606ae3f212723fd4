// The output folder a life is driven into (`rollwear run` on a wear or a cam case): one run there at a time
// (OutputLock, session/output_folder.h), where the life starts (afresh, or from the folder's checkpoint.txt,
// refused when it is another case's), and the step table written with the checkpoint, the table renamed first
// so that it never lags the checkpoint. The wear life (session/wear_life_run.h) and the cam life
// (session/cam_life_run.h) share it; checkpoint.txt's format is wear::checkpoint_text's (wear/wear_output.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "lib/io/csv.h"
#include "session/output_folder.h"
#include "wear/wear_output.h"

namespace session {

struct LifeFolderOptions {
  std::filesystem::path dir;
  std::string case_path;          // named in the messages and in the --resume command
  std::string table_name;         // the table of accepted steps: summary.csv (wear), life.csv (cam)
  std::uint64_t fingerprint = 0;  // the case's: a checkpoint with another one is refused
  bool resume = false, restart = false;
};

class LifeFolder {
 public:
  // Locks the folder (std::runtime_error when another run holds it), removes the temporaries of a killed run and
  // checks where the life starts; CaseError (exit 2) for --resume with --restart, --resume without a checkpoint
  // or with another case's (or a changed case's), and a folder holding an unfinished run without --restart.
  explicit LifeFolder(const LifeFolderOptions& o);

  const std::filesystem::path& dir() const { return o_.dir; }
  bool resuming() const { return o_.resume; }
  const wear::Checkpoint& checkpoint() const { return cp_; }  // the one resumed from
  std::filesystem::path checkpoint_path() const { return o_.dir / "checkpoint.txt"; }
  std::filesystem::path table_path() const { return o_.dir / o_.table_name; }
  // the resumed run's table up to and including step `steps` (the rows after its checkpoint are written again)
  std::string table_up_to(long steps) const;
  // what a signal prints once a checkpoint exists: how to continue from it
  std::string resume_line() const;

  // a fresh start: the previous run's snapshot files (in snapshots/, whole names matching the regular expression
  // snapshot_names; std::regex compiled in life_folder.cpp alone), its report and its checkpoint removed; any
  // other file stays
  void start_afresh(const std::string& snapshot_names) const;
  // files, then the table, then the checkpoint (when cp is given), in one atomic write; with a checkpoint, a
  // signal from then on prints the --resume command. The one place a life's checkpoint is written.
  void save(std::vector<contact::OutputFile> files, const std::string& table, const wear::Checkpoint* cp) const;
  void remove_checkpoint() const;

 private:
  LifeFolderOptions o_;
  OutputLock lock_;
  wear::Checkpoint cp_;
};

}  // namespace session
