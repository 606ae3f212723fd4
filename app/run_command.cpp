// rollwear run: a wear or cam life into its output folder (app/commands.h, session/life_run.h).
#include "app/commands.h"
#include "lib/errors.h"
#include "session/life_run.h"

namespace app {

CLI::App* add_run_command(CLI::App& app, RunOptions& opt, CommonOptions& common) {
  CLI::App* sub = app.add_subcommand(
      "run", "The wear of the case's bodies over their life (wear: section): the worn profiles, the contact and "
             "the dissipated energy per duty cycle, integrated over revolutions until a limit ends the life. "
             "Writes summary.csv (one row per accepted step), snapshots/ (worn profiles), report.txt and, "
             "while running, checkpoint.txt.");
  sub->footer(
      "A run killed at any moment continues from its last checkpoint with --resume and ends with the same\n"
      "result (bit-identical with fixed stepping, within the tolerance with adaptive stepping). A folder\n"
      "holding an unfinished run is not overwritten unless --restart is given. Ctrl-C prints the --resume\n"
      "command. The folder is locked while the run owns it (.rollwear.lock): a second run there exits 1,\n"
      "naming the PID that holds it. A new run removes the previous run's snapshots and report, nothing else.\n"
      "On a cam case (a cam: section) Ctrl-C or SIGTERM lets the life's current step finish and saves it first.\n"
      "Exit status: 0 success (whatever limit ended the life), 2 bad input, 1 any other failure.");
  sub->add_option("case", opt.case_path, "Case file (YAML) with a wear: section, e.g. cases/paper-wear.yaml")
      ->required();
  sub->add_option("-o,--output", opt.output_directory,
                  "Output directory (default: the case's output.directory, else out/<case name>)");
  sub->add_flag("--resume", opt.resume, "Continue the run from the output directory's checkpoint.txt");
  sub->add_flag("--restart", opt.restart, "Start afresh even if the output directory holds an unfinished run");
  sub->add_flag("-q,--quiet", opt.quiet, "No progress line");
  add_log_level_option(*sub, common);
  return sub;
}

int run_run_command(const RunOptions& opt) {
  const session::LifeRunEnd end = session::run_life_in_folder(
      {opt.case_path, opt.output_directory, opt.resume, opt.restart, opt.quiet});
  return end == session::LifeRunEnd::Failed ? contact::kExitFailure : 0;
}

}  // namespace app
