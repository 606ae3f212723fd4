// rollwear: the command line. Declares every subcommand's options and help (add_<name>_command, here: the only
// file that compiles CLI11, a header library slow to compile) and wires each to its work
// (run_<name>_command in app/<name>_command.cpp), sets up the logging, and maps what a command throws to the exit
// status.
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

CLI::App* add_contact_command(CLI::App& app, ContactOptions& opt, CommonOptions& common) {
  CLI::App* sub = app.add_subcommand(
      "contact", "Steady rolling contact of one case: the normal problem (Hertz, or on the case's profiles the "
                 "semi-Hertzian or half-space solver, as solver.normal says), then the tangential problem "
                 "(by default the relaxed model, matched to Kalker's exact theory; solver.tangential: consistent "
                 "for his simplified theory, exact for the exact theory), then the stresses below the surface of "
                 "both bodies. Prints a summary and writes summary.csv, strips.csv, fields.csv, subsurface.csv, "
                 "subsurface_section.csv and, for a body with shear_yield_Pa, fatigue.csv (with dang_van, dang_van.csv).");
  sub->footer(
      "The summary names the normal solver that ran (and why, for solver.normal: auto) and the number of\n"
      "contact patches. strips.csv's y_m is in the profiles' lateral coordinate. With solver.tangential:\n"
      "exact the summary names the exact solve in place of the simplified theory's C11 ... L (nan in\n"
      "summary.csv), and a transient run's summary.csv says scheme exact.\n"
      "A contact that reaches a body's edge (the end of its profile) is a warning line in the summary; the\n"
      "outputs are written and the exit status stays 0 (if its normal solve converged; an unconverged one,\n"
      "at an edge or not, is exit 1).\n"
      "The subsurface stresses (docs/subsurface.md) are each body's under the cells' tractions, on 31 planes\n"
      "from the surface to 1.5 min(a, b): their maxima (subsurface.csv) and the x-z section through the most\n"
      "loaded cell (subsurface_section.csv). With bodies.bodyN.shear_yield_Pa, the shakedown margin and the\n"
      "surface fatigue index of that body (fatigue.csv); with bodies.bodyN.dang_van: { a, b_Pa }, Dang Van's\n"
      "index of that body over one rolling pass, its largest value and where (dang_van.csv).\n"
      "With a lubricant: section the summary adds the EHL film thickness, the film parameter lambda and the\n"
      "regime with its friction and wear factors; with a thermal: section the flash temperature (Blok's\n"
      "partition) and, with critical_temperature_C, the scuffing margin (docs/lubrication-and-temperature.md).\n"
      "Exit status: 0 success, 2 bad input (case file, options), 1 any other failure.");
  sub->add_option("case", opt.case_path, "Case file (YAML), e.g. cases/paper.yaml")->required();
  sub->add_option("-o,--output", opt.output_directory,
                  "Output directory (default: the case's output.directory, else out/<case name>)");
  sub->add_flag("--no-fields", opt.no_fields, "Do not write fields.csv (the per-cell fields)");
  sub->add_flag("--no-subsurface", opt.no_subsurface,
                "Do not compute the stresses below the surface (subsurface.csv, subsurface_section.csv, fatigue.csv, "
                "dang_van.csv)");
  sub->add_flag("-q,--quiet", opt.quiet,
                "No progress line on stderr: contact shows none (taken as run, transient and sweep take it)");
  add_log_level_option(*sub, common);
  return sub;
}

CLI::App* add_transient_command(CLI::App& app, TransientOptions& opt, CommonOptions& common) {
  CLI::App* sub = app.add_subcommand(
      "transient",
      "Transient rolling contact of one case: the tangential problem stepped in time (by default the relaxed "
      "model; Satran with solver.tangential: consistent) over the "
      "case's histories of load, speed and creepages, or with the roller's inertia. Needs a transient: "
      "section. Writes timeseries.csv, strip_power.csv, strip_energy.csv, snapshot_<k>.csv, summary.csv.");
  sub->footer(
      "Outputs (in the output directory; SI units, numbers at full precision):\n"
      "  timeseries.csv    one row per step: step,t_s,q_m,dt_s,speed_m_per_s,xi,eta,phi_per_m,normal_load_N,\n"
      "                    omega1_rad_per_s,Fx_N,Fy_N,Mz_N_m,power_W,stick_fraction,balance_residual_W,cfl,\n"
      "                    shortened,step_scheme (t_s, q_m: where the forces hold, the middle of a whole\n"
      "                    shift step, else its end; shortened 1: the last step, cut short to end at t_end_s;\n"
      "                    step_scheme: what the step ran, upwind in a shift run being the fallback at CFL < 1)\n"
      "  strip_power.csv   step,t_s,y_m,power_W_per_m: one row per strip and step (not with --no-fields)\n"
      "  strip_energy.csv  y_m,energy_J_per_m: each strip's power integrated over the run\n"
      "  snapshot_<k>.csv  x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,t_s: the fields\n"
      "                    for the k-th time of transient.snapshots_s (k from 1), at the end of the step that\n"
      "                    reached it; t_s is that step's end\n"
      "  summary.csv       name,scheme,nx,ny,steps,t_end_s,q_end_m,dissipated_J, then the last whole step's\n"
      "                    Fx_N,Fy_N,Mz_N_m,power_W,stick_fraction,omega1_rad_per_s (not the shortened last\n"
      "                    step's), sliding_end_s (t_s of the first step whose creep force falls below mu F\n"
      "                    after gross sliding; nan if the contact never slid whole or slid to the end), end_step\n"
      "                    (the step those values are from) and fallback_steps (upwind steps of a shift run)\n"
      "The time series stream to temporary files during the run; every file is renamed into place at the\n"
      "end, so a failed or interrupted run leaves no partial file (SIGINT, SIGTERM, SIGHUP remove the\n"
      "temporaries at once; those of a killed run are removed by the next command on the folder).\n"
      "Before it runs, the output is estimated (one step per dx rolled and per dt_s); a run estimated above\n"
      "output.max_bytes (default 1 GiB) or half the free disk is refused (exit 2) unless --force.\n"
      "Progress: on a terminal one line redrawn in place; otherwise an info line every 5 s.\n"
      "Exit status: 0 success, 2 bad input (case file, options, a step that breaks CFL, an output estimated\n"
      "too large), 1 any other failure (a solver's, or the folder held by another run).");
  sub->add_option("case", opt.case_path, "Case file (YAML) with a transient: section, e.g. cases/paper-startup.yaml")
      ->required();
  sub->add_option("-o,--output", opt.output_directory,
                  "Output directory (default: the case's output.directory, else out/<case name>)");
  sub->add_flag("--no-fields", opt.no_fields,
                "Do not write the fields: the snapshot_<k>.csv (nor compute them) and strip_power.csv (per strip "
                "and step; strip_energy.csv keeps its integral)");
  sub->add_flag("-q,--quiet", opt.quiet,
                "No progress line on stderr (the summary still goes to stdout, log messages by --log-level)");
  sub->add_flag("--force", opt.force,
                "Run even if the output is estimated above output.max_bytes or half the free disk");
  add_log_level_option(*sub, common);
  return sub;
}

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

CLI::App* add_cam_command(CLI::App& app, CamOptions& opt, CommonOptions& common) {
  CLI::App* sub = app.add_subcommand(
      "cam", "One revolution of a disc cam at constant speed with a translating roller follower (cam: section, "
             "docs/cam-follower.md): lift, pressure angle, radius of curvature, loads, the Hertz contact and the "
             "roller's regime at each cam angle; with cam.lubricant and cam.thermal the film, lambda, the lubrication "
             "regime and the flash temperature at each angle (docs/cam-follower.md §17); with cam.roller.shear_yield_Pa or "
             "cam.track.shear_yield_Pa the traction coefficient, Johnson's shakedown margin and the surface fatigue "
             "index at each angle (§18). Prints the jump speed and a "
             "summary; writes revolution.csv.");
  sub->footer(
      "Above the jump speed the run stops with status jump (no table written), exit 1.\n"
      "A design the model refuses (acceleration jump, table fit, undercut, pressure angle) is bad input at its\n"
      "key's line, naming the cam angle.\n"
      "Exit status: 0 success, 2 bad input (case file, options), 1 any other failure.");
  sub->add_option("case", opt.case_path, "Cam case file (YAML), e.g. cases/cam-follower.yaml")->required();
  sub->add_option("-o,--output", opt.output_directory,
                  "Output directory (default: the case's output.directory, else out/<case name>)");
  sub->add_flag("-q,--quiet", opt.quiet,
                "No progress line on stderr: cam shows none (taken as run, transient and sweep take it)");
  add_log_level_option(*sub, common);
  return sub;
}

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& opt, CommonOptions& common) {
  CLI::App* sub = app.add_subcommand(
      "sweep", "Many wear lives (or, on a base case without wear:, steady contacts as `contact` solves them) of one base case: a grid of values (lists, linear and logarithmic ranges; product or "
               "zip) or random sampling (Monte Carlo, Latin hypercube) of any keys of the case, run on all cores. "
               "Writes results.csv (a row per case) and each case's outputs in case_NNNN/ (docs/sweeps.md).");
  sub->footer(
      "Every case is read and checked before any runs: a value the case reader refuses is exit 2, naming the\n"
      "sweep file's line of the axis, the key and the case. A case that fails while running is a row with its\n"
      "status and message; the sweep goes on. Killed, the same command resumes: finished cases are not run again.\n"
      "--shard K/N runs the cases i with i mod N = K-1; --merge DIR... -o OUT joins the shards' results.csv into\n"
      "OUT/results.csv, the table the whole sweep gives.\n"
      "Exit status: 0 every case ran (failed cases included: see the status column), 2 bad input, 1 any other failure.");
  sub->add_option("sweep", opt.sweep_path, "Sweep file (YAML), e.g. cases/sweep-grid.yaml");
  sub->add_option("-o,--output", opt.output_directory,
                  "Output folder (default: the sweep's output.directory, else out/<sweep file stem>)");
  sub->add_option("--shard", opt.shard, "Run the K-th of N disjoint parts, K/N (default 1/1: the whole sweep)");
  sub->add_option("-j,--threads", opt.threads, "Cases run at once (default: the number of cores)")
      ->check(CLI::NonNegativeNumber);
  sub->add_flag("-q,--quiet", opt.quiet, "No progress line");
  sub->add_flag("--force", opt.force, "Run a sweep of more than 10000 cases in this shard (kSweepMaxCases)");
  sub->add_option("--merge", opt.merge, "Join the results of these shard folders into -o OUT")->expected(1, -1);
  add_log_level_option(*sub, common);
  return sub;
}

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
