// `rollwear run`: a life driven into its output folder (session/life_folder.h), on a wear case or a cam case.
//
// On a wear case (docs/wear-loop.md): the wear of the case's bodies until a limit ends the life
// (session/wear_life_run.h), writing summary.csv (a row per accepted step), snapshots/snapshot_KKKK_bodyN.csv
// (the worn profiles at the start, each snapshot revolution, the end), report.txt and, while running,
// checkpoint.txt. A signal ends the process at once; the last checkpoint is where --resume continues.
//
// On a cam case (a document with a cam: section, docs/cam-follower.md §13): the periodic
// revolution, the roller's motion, the quasi-steady dissipation, then the wear of the track and the roller
// over cam revolutions until a limit of cam.wear ends the life (cam/cam_life.h). Writes into the output
// folder, each file atomically:
//   revolution.csv                      the unworn revolution, per angle (cam/revolution.h)
//   dissipation.csv                     per angle: cam_angle_deg, cam_arc_m, the step's power (W) and energy (J),
//                                       the roller's periodic motion (F_n, F_t, xi, slip speed, spin)
//   life.csv                            per accepted step: revolutions, max_depth_m, lift_loss_m, ...
//   snapshots/wear_map_KKKK.csv         the track's wear map (cam/cam_wear.h) at the start, each snapshot, the end
//   snapshots/roller_wear_KKKK.csv      the roller's worn depth there
//   report.txt                          the life and what ended it
//   checkpoint.txt                      while running: the state to resume from (removed at the end)
// A new run removes the previous run's snapshot files of these names, its report and its temporaries
// (NAME.tmp.PID of these names, PID gone), nothing else. A run killed part-way continues with resume
// (docs/cam-follower.md §13, "Checkpoint and resume"); a folder holding an unfinished run is not started
// afresh without restart. The folder is locked while the run owns it, and SIGINT or SIGTERM during the life
// stops it after its current step, saved, with the --resume command printed (session/output_folder.h).
#pragma once

#include <string>

namespace session {

// `rollwear run`'s options, on a wear or a cam case
struct LifeRunOptions {
  std::string case_path;
  std::string output_directory;  // -o; default the case's output.directory, else out/<case name>
  bool resume = false;           // from the folder's checkpoint.txt
  bool restart = false;          // afresh, over an unfinished run
  bool quiet = false;            // no progress line
};
// a limit or the budget ended the life (exit 0); the life failed (exit 1)
enum class LifeRunEnd { Ended, Failed };

// true when the file is a YAML mapping with a top-level cam: key (any other file, or one that does not
// parse, is left to the wear case's reader and its errors)
bool is_cam_case(const std::string& path);

// Each throws contact::CaseError for bad input (exit 2: also --resume without a checkpoint, a checkpoint of
// another or a changed case, an unfinished run's folder without --restart) and std::runtime_error for a folder
// another run holds. A cam life that jumps, or whose roller's motion is not periodic, is a failure.
LifeRunEnd run_wear_life_in_folder(const LifeRunOptions& o);
LifeRunEnd run_cam_life_in_folder(const LifeRunOptions& o);
// a cam case's life or a wear case's, as is_cam_case says
LifeRunEnd run_life_in_folder(const LifeRunOptions& o);

}  // namespace session
