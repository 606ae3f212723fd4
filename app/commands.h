// rollwear's subcommands: each has its options and help (add_<name>_command, in app/main.cpp, which wires them:
// CLI11, a header library slow to compile, compiled once) and does its work (run_<name>_command) in
// app/<name>_command.cpp. They parse and print; the output folder, the lives and the sweeps are session/'s. Each
// returns the exit status; errors are thrown and mapped to a status by main (lib/errors.h: 2 bad input, 1 any other
// failure).
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;  // <CLI/CLI.hpp>, included by app/main.cpp alone
}  // namespace CLI

namespace app {

// options every subcommand takes
struct CommonOptions {
  std::string log_level = "info";
};
void add_log_level_option(CLI::App& app, CommonOptions& common);

// contact: the normal and steady tangential problem of one case
struct ContactOptions {
  std::string case_path;
  std::string output_directory;  // overrides output.directory
  bool no_fields = false;
  bool no_subsurface = false;  // overrides output.subsurface
  bool quiet = false;  // -q: taken as run, transient and sweep take it; contact shows no progress line
};
CLI::App* add_contact_command(CLI::App& app, ContactOptions& opt, CommonOptions& common);
int run_contact_command(const ContactOptions& opt);

// transient: the tangential problem stepped in time over the case's histories
struct TransientOptions {
  std::string case_path;
  std::string output_directory;  // overrides output.directory
  bool no_fields = false;
  bool quiet = false;
  bool force = false;  // run even when the output is estimated above output.max_bytes or half the free disk
};
CLI::App* add_transient_command(CLI::App& app, TransientOptions& opt, CommonOptions& common);
int run_transient_command(const TransientOptions& opt);

// run: a wear or cam life into its folder (session/life_run.h)
struct RunOptions {
  std::string case_path;
  std::string output_directory;
  bool resume = false;
  bool restart = false;
  bool quiet = false;
};
CLI::App* add_run_command(CLI::App& app, RunOptions& opt, CommonOptions& common);
int run_run_command(const RunOptions& opt);

// cam: one revolution of a disc cam with a translating roller follower
struct CamOptions {
  std::string case_path;
  std::string output_directory;
  bool quiet = false;  // -q: taken as run, transient and sweep take it; cam shows no progress line
};
CLI::App* add_cam_command(CLI::App& app, CamOptions& opt, CommonOptions& common);
int run_cam_command(const CamOptions& opt);

// sweep: many lives (or contacts) of one base case (session/sweep.h)
struct SweepOptions {
  std::string sweep_path;
  std::string output_directory;  // -o: the sweep's folder, or with --merge the merged table's
  std::string shard = "1/1";     // K/N
  int threads = 0;               // 0: every core (std::thread::hardware_concurrency)
  bool quiet = false;
  bool force = false;            // run a shard of more than session::kSweepMaxCases cases
  std::vector<std::string> merge;  // --merge DIR...
};
CLI::App* add_sweep_command(CLI::App& app, SweepOptions& opt, CommonOptions& common);
int run_sweep_command(const SweepOptions& opt);

// plot: PNG plots of an output folder (app/plot.h)
struct PlotOptions {
  std::string output_dir;
  bool quiet = false;  // -q: taken as run, transient and sweep take it; plot shows no progress line
};
CLI::App* add_plot_command(CLI::App& app, PlotOptions& opt);
int run_plot_command(const PlotOptions& opt);

}  // namespace app
