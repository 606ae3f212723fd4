// rollwear plot: PNG plots of an output folder (app/commands.h; the plots themselves: app/plot.h).
#include "app/commands.h"
#include "app/plot.h"

namespace app {

int run_plot_command(const PlotOptions& opt) { return plot_command(opt.output_dir); }

}  // namespace app
