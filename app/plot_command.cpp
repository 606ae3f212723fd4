// rollwear plot: PNG plots of an output folder (app/commands.h; the plots themselves: app/plot.h).
#include "app/commands.h"
#include "app/plot.h"

namespace app {

CLI::App* add_plot_command(CLI::App& app, PlotOptions& opt) {
  CLI::App* sub = app.add_subcommand("plot", "PNG plots of a wear run's output folder (gnuplot): the worn "
                                             "profiles at every snapshot (and a fatigue run's damage along the "
                                             "track), depth and peak pressure against "
                                             "revolutions, written to OUTPUT_DIR/plots/; of a sweep's folder: the life "
                                             "against each varied key and its distribution, or a contact sweep's "
                                             "contact against each varied key (docs/sweeps.md)");
  sub->add_option("output_dir", opt.output_dir, "The folder a 'rollwear run' wrote, e.g. out/paper-wear")->required();
  sub->add_flag("-q,--quiet", opt.quiet,
                "No progress line on stderr: plot shows none (taken as run, transient and sweep take it); the "
                "PNGs written are still listed on stdout");
  return sub;
}

int run_plot_command(const PlotOptions& opt) { return plot_command(opt.output_dir); }

}  // namespace app
