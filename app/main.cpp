// rollwear: the command line. Wires the subcommands (app/commands.h, one file each: app/<name>_command.cpp),
// sets up the logging, and maps what a command throws to the exit status.
// Exit codes (lib/errors.h): 0 success, 2 bad input (case file, option: CaseError), 1 any other failure.
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "app/commands.h"
#include "lib/errors.h"

#ifndef ROLLWEAR_VERSION
#define ROLLWEAR_VERSION "0.1.0"  // keep equal to project(VERSION) in CMakeLists.txt
#endif

namespace app {

void add_log_level_option(CLI::App& app, CommonOptions& common) {
  app.add_option("--log-level", common.log_level, "Messages on stderr from this level up")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}))
      ->default_str("info");
}

}  // namespace app

namespace {

// the only place that sets spdlog's sinks, pattern and level
void set_up_logging(const std::string& level) {
  auto logger = spdlog::stderr_color_mt("rollwear");
  logger->set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::from_str(level));
}

// one line on stderr, whatever the message holds
void print_error(const std::string& message) {
  std::string line = message;
  for (char& ch : line)
    if (ch == '\n' || ch == '\r') ch = ' ';
  std::fprintf(stderr, "rollwear: error: %s\n", line.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  using namespace app;
  using contact::kExitBadInput;
  using contact::kExitFailure;
  CLI::App app{"rollwear: wear of bodies in rolling contact (Hertz normal problem; for the tangential one, "
               "steady or transient, a fast model matched to Kalker's exact theory by default, or his simplified "
               "theory).",
               "rollwear"};
  app.footer("Exit status: 0 success, 2 bad input (case file, options), 1 any other failure (a solver's with\n"
             "its cause, or an output folder another run holds).\n"
             "Run 'rollwear SUBCOMMAND --help' for a subcommand's options.");
  app.set_version_flag("--version", std::string("rollwear ") + ROLLWEAR_VERSION);
  app.require_subcommand(1);

  CommonOptions common;
  add_log_level_option(app, common);  // accepted before the subcommand as well
  ContactOptions contact_opt;
  CLI::App* contact_cmd = add_contact_command(app, contact_opt, common);
  TransientOptions transient_opt;
  CLI::App* transient_cmd = add_transient_command(app, transient_opt, common);
  RunOptions run_opt;
  CLI::App* run_cmd = add_run_command(app, run_opt, common);
  CamOptions cam_opt;
  CLI::App* cam_cmd = add_cam_command(app, cam_opt, common);
  SweepOptions sweep_opt;
  CLI::App* sweep_cmd = add_sweep_command(app, sweep_opt, common);
  PlotOptions plot_opt;
  CLI::App* plot_cmd = add_plot_command(app, plot_opt);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    print_error(std::string(e.what()) + " (see rollwear --help)");
    return kExitBadInput;
  }

  try {
    set_up_logging(common.log_level);
    if (contact_cmd->parsed()) return run_contact_command(contact_opt);
    if (transient_cmd->parsed()) return run_transient_command(transient_opt);
    if (run_cmd->parsed()) return run_run_command(run_opt);
    if (cam_cmd->parsed()) return run_cam_command(cam_opt);
    if (plot_cmd->parsed()) return run_plot_command(plot_opt);
    if (sweep_cmd->parsed()) return run_sweep_command(sweep_opt);
    print_error("no subcommand ran");
    return kExitBadInput;
  } catch (const std::exception& e) {  // CaseError: bad input, 2; anything else 1 (lib/errors.h)
    print_error(e.what());
    return contact::exit_status_of(e);
  } catch (...) {
    print_error("unknown failure");
    return kExitFailure;
  }
}
