// rollwear transient: the tangential problem stepped in time over the case's histories (app/commands.h).
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "app/commands.h"
#include "lib/io/case_run.h"
#include "lib/model/contact_model.h"
#include "lib/io/case.h"
#include "lib/io/csv.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"
#include "session/output_folder.h"
#include "session/progress.h"

namespace app {

using namespace contact;

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

namespace {

// what the stdout summary needs from the steps
struct RunLog {
  TransientRecord last;
  double t_s = 0;                                                   // end of the last step
  GrossSliding sliding;  // lib/tangential/satran.h
};

void print_transient_summary(const ContactCase& c, const TransientCase& t, const TransientResult& res,
                             const RunLog& log) {
  const TransientRecord& r = res.end;  // the last whole step (the shortened last step runs a cruder scheme)
  fmt::print("case {} ({}), {} x {} grid, {} scheme{}\n", c.name, c.path, res.grid.nx, res.grid.ny,
             to_string(t.settings.scheme),
             std::string(tangential_traits(c.solver.tangential).run_note) +
                 (t.inertia ? ", roller inertia" : ""));
  fmt::print("  steps           {}", res.steps);
  if (res.fallback_steps > 0)
    fmt::print(", {} of them upwind at CFL < 1 (the fallback: less accurate than shift)", res.fallback_steps);
  fmt::print("\n");
  fmt::print("  end             t  = {:.6g} s, rolled q = {:.6g} mm\n", res.t_end_s, res.q_end_m * 1e3);
  fmt::print("  end step        step {} ({}), V = {:.6g} m/s, xi = {:.6g}, F = {:.6g} N\n", r.step,
             to_string(r.scheme), r.speed_m_per_s, r.xi, r.normal_load_N);
  fmt::print("  creep forces    Fx = {:.6g} N, Fy = {:.6g} N, Mz = {:.6g} N m\n", r.Fx_N, r.Fy_N, r.Mz_N_m);
  fmt::print("  dissipated      P  = {:.6g} W (end step), E = {:.6g} J over the run\n", r.power_W,
             res.dissipated_J);
  fmt::print("  stick fraction     {:.4f}\n", r.stick_fraction);
  if (log.last.shortened)
    fmt::print("  shortened step  step {} ({}, covers {:.3f} dx to end at t_end_s): P = {:.6g} W, Fx = {:.6g} N\n",
               log.last.step, to_string(log.last.scheme), log.last.cfl, log.last.power_W, log.last.Fx_N);
  if (t.inertia) {
    fmt::print("  roller spin     omega1 = {:.6g} rad/s, omega1 R1 = {:.6g} m/s (path {:.6g} m/s)\n",
               r.omega1_rad_per_s, r.omega1_rad_per_s * t.inertia->R1_m,
               value_at(t.inertia->path_speed_m_per_s, res.t_end_s));
    const GrossSliding& g = log.sliding;
    if (g.start_step == 0)
      fmt::print("  gross sliding   none (|F| stayed below mu F)\n");
    else if (g.end_step == 0)
      fmt::print("  gross sliding   from t = {:.6g} s (step {}: |F| = mu F) to the end\n", g.start_s, g.start_step);
    else
      fmt::print("  gross sliding   from t = {:.6g} s (step {}: |F| = mu F), ended at t = {:.6g} s (step {}: |F| < mu F)\n",
                 g.start_s, g.start_step, g.end_s, g.end_step);
  }
  for (std::size_t k = 0; k < res.snapshots.size(); ++k)
    fmt::print("  snapshot {}      t  = {:.6g} s\n", k + 1, res.snapshots[k].t_s);
  // the error estimate a wear life reports (docs/fidelity.md): none here
  fmt::print("  error estimate     {}\n", c.solver.tangential == TangentialScheme::Exact
                                            ? "none needed: Kalker's exact theory ran"
                                            : "not estimated against the exact physics (solver: { tangential: exact } "
                                              "solves it; docs/fidelity.md)");
}

}  // namespace

int run_transient_command(const TransientOptions& opt) {
  const ContactCase c = read_contact_case(opt.case_path);
  TransientCase t = transient_case_of(c);
  const bool fields = c.output.fields && !opt.no_fields;
  if (!fields) t.settings.snapshot_times_s.clear();  // not computed either
  const std::filesystem::path dir = session::output_directory(opt.output_directory, c.output.directory, c.name);

  // the strips the run puts the contact on, to label the streamed strip powers (checked at the end)
  const Eigen::ArrayXd y_m = transient_grid(t).y_m;

  // the output's size before the run: refused above output.max_bytes or half the free disk, unless --force
  session::check_transient_output_size(c, t, fields, dir, opt.force);

  const session::OutputLock lock(dir);
  session::remove_stale_temporaries(dir);
  session::interrupted::say_on_signal(fmt::format(
      "\nrollwear: interrupted; the run's temporary files were removed and nothing was written to {}\n", dir.string()));

  // every step streams to the temporary files; the files open with the first step, so a run refused
  // before it starts writes nothing
  std::optional<StreamedFile> timeseries, strip_power;
  RunLog log;
  session::Progress progress("transient", opt.quiet);
  const StepObserver observe = [&](const TransientRecord& r, const Eigen::ArrayXd& power_W_per_m) {
    if (!timeseries) {
      timeseries.emplace(dir / "timeseries.csv");
      session::interrupted::remove_on_signal(timeseries->temporary_path());
      timeseries->append(transient_header());
      if (fields) {  // a field: per strip and step, 25 times timeseries.csv (docs/benchmarks.md, "Outputs")
        strip_power.emplace(dir / "strip_power.csv");
        session::interrupted::remove_on_signal(strip_power->temporary_path());
        strip_power->append(strip_power_header());
      }
    }
    timeseries->append(transient_row(r));
    if (strip_power) strip_power->append(strip_power_rows(r, y_m, power_W_per_m));
    log.last = r;
    log.t_s += r.dt_s;
    track_gross_sliding(r, t.mu, log.sliding);
    progress.update(log.t_s / t.settings.t_end_s,
                    fmt::format("step {}, t {:.4e} / {:.4e} s", r.step, log.t_s, t.settings.t_end_s));
  };

  const TransientResult res = run_transient_case(c, t, observe);  // lib/io/case_run.h
  progress.clear();
  if (!timeseries) throw std::logic_error("transient: the run took no step");
  if (res.grid.ny != y_m.size() || (res.grid.y_m != y_m).any())
    throw std::logic_error("transient: the run's strips differ from transient_grid's");
  if (res.snapshots.size() != t.settings.snapshot_times_s.size())
    spdlog::warn("transient: {} of {} snapshots recorded", res.snapshots.size(), t.settings.snapshot_times_s.size());

  // the tables of the whole run, then every file into place at once
  std::vector<OutputFile> files = {{dir / "strip_energy.csv", strip_energy_csv(res.grid, res.strip_energy_J_per_m)}};
  for (std::size_t k = 0; k < res.snapshots.size(); ++k)
    files.push_back({dir / fmt::format("snapshot_{}.csv", k + 1), snapshot_csv(res.grid, res.snapshots[k])});
  const std::string run_name = transient_run_name(c.solver.tangential, t.settings.scheme);  // lib/model/
  files.push_back({dir / "summary.csv", transient_summary_csv(c.name, run_name, res, log.sliding.end_s)});

  print_transient_summary(c, t, res, log);
  std::vector<StreamedFile*> streamed = {&*timeseries};
  if (strip_power) streamed.push_back(&*strip_power);
  write_files_atomic(files, streamed);
  if (!strip_power) std::filesystem::remove(dir / "strip_power.csv");  // an earlier run's: not this run's
  session::interrupted::forget();
  spdlog::info("wrote {} files to {}", files.size() + streamed.size(), dir.string());
  return 0;
}

}  // namespace app
