// `rollwear run` on a cam case (a document with a cam: section, docs/cam-follower.md §13): the periodic
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
// stops it after its current step, saved, with the --resume command printed (app/output_folder.h).
#pragma once

#include <string>

namespace app {

// true when the file is a YAML mapping with a top-level cam: key (any other file, or one that does not
// parse, is left to the wear case's reader and its errors)
bool is_cam_case(const std::string& path);

// returns the exit status: 0 whatever limit ended the life; 1 a failure (the revolution's jump, the
// roller's motion not periodic, a solve failing); throws contact::CaseError for bad input (exit 2)
// (exit 2 also for --resume without a checkpoint, a checkpoint of another or a changed case, or an
// unfinished run's folder without --restart)
int run_cam_life_command(const std::string& case_path, const std::string& output_option, bool quiet,
                         bool resume = false, bool restart = false);

}  // namespace app
