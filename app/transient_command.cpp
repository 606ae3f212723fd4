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
