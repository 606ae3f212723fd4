// The output folder a life is driven into (session/life_folder.h).
#include "session/life_folder.h"

#include <regex>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "lib/errors.h"

namespace session {

namespace {

// the options, checked before the folder is locked
const LifeFolderOptions& checked(const LifeFolderOptions& o) {
  if (o.resume && o.restart) throw contact::CaseError("--resume and --restart exclude each other");
  return o;
}

}  // namespace

LifeFolder::LifeFolder(const LifeFolderOptions& o) : o_(checked(o)), lock_(o.dir) {
  remove_stale_temporaries(o_.dir);
  const std::filesystem::path path = checkpoint_path();
  if (o_.resume) {
    if (!std::filesystem::exists(path))
      throw contact::CaseError(path.string() + ": no checkpoint to resume from (the run finished, or never passed its "
                                               "first checkpoint: run without --resume)");
    cp_ = wear::read_checkpoint(path);
    if (cp_.case_hash != o_.fingerprint)
      throw contact::CaseError(path.string() + ": the checkpoint belongs to another case, or " + o_.case_path +
                               " (or a profile) changed since; run with --restart to start afresh");
  } else if (std::filesystem::exists(path) && !o_.restart) {
    throw contact::CaseError(o_.dir.string() + " holds an unfinished run (checkpoint.txt): continue it with --resume, "
                                               "or start afresh with --restart");
  }
}

std::string LifeFolder::table_up_to(long steps) const { return wear::summary_up_to(table_path(), steps); }

std::string LifeFolder::resume_line() const {
  return fmt::format(
      "\nrollwear: interrupted; the run continues from its last checkpoint ({}) with: rollwear run {} -o {} --resume\n",
      checkpoint_path().string(), o_.case_path, o_.dir.string());
}

void LifeFolder::start_afresh(const std::string& snapshot_names) const {
  const std::regex names(snapshot_names);
  std::error_code ec;
  const std::filesystem::path snapshots = o_.dir / "snapshots";
  for (const auto& entry : std::filesystem::directory_iterator(snapshots, ec))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), names))
      std::filesystem::remove(entry.path(), ec);
  if (std::filesystem::is_empty(snapshots, ec)) std::filesystem::remove(snapshots, ec);
  std::filesystem::remove(o_.dir / "report.txt");
  std::filesystem::remove(checkpoint_path());  // --restart: the unfinished run's
}

void LifeFolder::save(std::vector<contact::OutputFile> files, const std::string& table,
                      const wear::Checkpoint* cp) const {
  files.push_back({table_path(), table});
  if (cp) files.push_back({checkpoint_path(), wear::checkpoint_text(*cp)});
  contact::write_files_atomic(files);
  if (cp) interrupted::say_on_signal(resume_line());  // a signal from now on: resume from here
}

void LifeFolder::remove_checkpoint() const { std::filesystem::remove(checkpoint_path()); }

}  // namespace session
