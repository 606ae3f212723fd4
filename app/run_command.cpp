// rollwear run: a wear or cam life into its output folder (app/commands.h, session/life_run.h).
#include "app/commands.h"
#include "lib/errors.h"
#include "session/life_run.h"

namespace app {

int run_run_command(const RunOptions& opt) {
  const session::LifeRunEnd end = session::run_life_in_folder(
      {opt.case_path, opt.output_directory, opt.resume, opt.restart, opt.quiet});
  return end == session::LifeRunEnd::Failed ? contact::kExitFailure : 0;
}

}  // namespace app
