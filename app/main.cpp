// rollwear: the command line. Parse, load the case, run, write the results; nothing else.
// One function per subcommand: add_<name>_command declares its options, run_<name> does the work.
// Exit codes (lib/io/errors.h): 0 success, 2 bad input (case file, option: CaseError), 1 any other failure.
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <limits>
#include <memory>
#include <optional>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "lib/io/case.h"
#include "lib/io/csv.h"
#include "lib/io/errors.h"
#include "lib/normal/hertz.h"
#include "lib/tangential/exact.h"
#include "lib/tangential/relaxed.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/steady.h"
#include "lib/tangential/tangential.h"
#include "lib/io/case_run.h"
#include "lib/model/contact_model.h"
#include "app/plot.h"
#include "app/sweep_command.h"
#include "app/cam_run.h"
#include "app/output_folder.h"
#include "cam/cam_case.h"
#include "cam/cam_run.h"
#include "cam/revolution.h"
#include "wear/wear_case.h"
#include "wear/wear_loop.h"
#include "wear/wear_output.h"

#ifndef ROLLWEAR_VERSION
#define ROLLWEAR_VERSION "0.1.0"  // keep equal to project(VERSION) in CMakeLists.txt
#endif

namespace {

using namespace contact;

// options every subcommand takes
struct CommonOptions {
  std::string log_level = "info";
};

void add_log_level_option(CLI::App& app, CommonOptions& common) {
  app.add_option("--log-level", common.log_level, "Messages on stderr from this level up")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}))
      ->default_str("info");
}

// the only place that sets spdlog's sinks, pattern and level
void set_up_logging(const std::string& level) {
  auto logger = spdlog::stderr_color_mt("rollwear");
  logger->set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::from_str(level));
}

// ---- contact: the normal (Hertz) and steady tangential problem of one case --------------------------

struct ContactOptions {
  std::string case_path;
  std::string output_directory;  // overrides output.directory
  bool no_fields = false;
};

CLI::App* add_contact_command(CLI::App& app, ContactOptions& opt, CommonOptions& common) {
  CLI::App* sub = app.add_subcommand(
      "contact", "Steady rolling contact of one case: the normal problem (Hertz, or on the case's profiles the "
                 "semi-Hertzian or half-space solver, as solver.normal says), then the tangential problem "
                 "(by default the relaxed model, matched to Kalker's exact theory; solver.tangential: consistent "
                 "for his simplified theory, exact for the exact theory). Prints a summary and writes summary.csv, strips.csv and "
                 "fields.csv.");
  sub->footer(
      "The summary names the normal solver that ran (and why, for solver.normal: auto) and the number of\n"
      "contact patches. strips.csv's y_m is in the profiles' lateral coordinate. With solver.tangential:\n"
      "exact the summary names the exact solve in place of the simplified theory's C11 ... L (nan in\n"
      "summary.csv), and a transient run's summary.csv says scheme exact.\n"
      "A contact that reaches a body's edge (the end of its profile) is a warning line in the summary; the\n"
      "outputs are written and the exit status stays 0 (if its normal solve converged; an unconverged one,\n"
      "at an edge or not, is exit 1).\n"
      "Exit status: 0 success, 2 bad input (case file, options), 1 any other failure.");
  sub->add_option("case", opt.case_path, "Case file (YAML), e.g. cases/paper.yaml")->required();
  sub->add_option("-o,--output", opt.output_directory,
                  "Output directory (default: the case's output.directory, else out/<case name>)");
  sub->add_flag("--no-fields", opt.no_fields, "Do not write fields.csv (the per-cell fields)");
  add_log_level_option(*sub, common);
  return sub;
}

// -o, else the case's output.directory, else out/<case name>
std::filesystem::path output_directory(const std::string& option, const ContactCase& c) {
  if (!option.empty()) return option;
  if (!c.output.directory.empty()) return c.output.directory;
  return std::filesystem::path("out") / c.name;
}

using app::OutputLock;  // app/output_folder.h
namespace interrupted = app::interrupted;

// The program's own file names in an output folder: what it may delete there, and nothing else.
const std::regex& own_output_name() {
  static const std::regex kNames(
      "(summary\\.csv|strips\\.csv|fields\\.csv|timeseries\\.csv|strip_power\\.csv|strip_energy\\.csv|"
      "snapshot_[0-9]+\\.csv|snapshot_[0-9]{4}_body[12]\\.csv|checkpoint\\.txt|report\\.txt)");
  return kNames;
}

// Temporary files a killed command left in dir and dir/snapshots: OWN_NAME.tmp.<pid> (lib/io/csv.h) of a
// process that no longer runs, removed. Files of any other name are left alone.
void remove_stale_temporaries(const std::filesystem::path& dir) {
  static const std::regex kTemporary("(.+)\\.tmp\\.([0-9]{1,10})");
  for (const std::filesystem::path& d : {dir, dir / "snapshots"}) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(d, ec)) {
      const std::string name = entry.path().filename().string();
      std::smatch m;
      if (!std::regex_match(name, m, kTemporary) || !std::regex_match(m[1].str(), own_output_name())) continue;
      const long pid = std::strtol(m[2].str().c_str(), nullptr, 10);
      if (pid > 0 && pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
        std::filesystem::remove(entry.path(), ec);
        spdlog::info("removed {}, the temporary file of a killed run (PID {})", entry.path().string(), pid);
      }
    }
  }
}

// exact_solve: the exact solve's status message (scheme Exact), printed in place of the simplified
// theory's coefficients, which that solve does not use
void print_contact_summary(const ContactCase& c, const NormalSolution& normal, const TangentialProblem& problem,
                           const TangentialSolution& s, TangentialScheme scheme, const std::string& exact_solve) {
  const ContactPatch& patch = normal.patch;
  fmt::print("case {} ({}), {} x {} grid, {} scheme\n", c.name, c.path, patch.grid.nx, patch.grid.ny,
             to_string(scheme));
  fmt::print("  normal solver      {} ({})\n", to_string(normal.solver), normal.reason);
  fmt::print("  contact patches    {}\n", normal.patches);
  if (normal.reaches_edge)
    fmt::print("  warning: the contact reaches a body's edge (the end of a profile); it is cut there\n");
  fmt::print("  normal load     F  = {:.6g} N\n", patch.normal_load_N);
  fmt::print("  semi-axes       a  = {:.6f} mm, b = {:.6f} mm\n", patch.a_m * 1e3, patch.b_m * 1e3);
  fmt::print("  peak pressure   p0 = {:.3f} MPa\n", patch.p0_Pa * 1e-6);
  fmt::print("  approach        delta = {:.4f} µm\n", patch.approach_m * 1e6);
  if (!tangential_traits(scheme).simplified_coefficients) {  // the exact theory: its solve in their place
    const ElasticPair pair = materials_of(c);
    fmt::print("  exact theory    Kalker's, on the half-space: G = {:.6g} GPa, nu = {:.4g}\n",
               combined_shear_modulus_Pa(pair) * 1e-9, combined_poisson(pair));
    fmt::print("  exact solve     {}\n", exact_solve);
  } else {
    fmt::print("  Kalker          C11 = {:.4f}, C22 = {:.4f}, C23 = {:.4f}, C33 = {:.4f}\n", problem.C.C11,
               problem.C.C22, problem.C.C23, problem.C.C33);
    fmt::print("  flexibility     L  = {:.6e} m/Pa\n", problem.L_m_per_Pa);
  }
  fmt::print("  creep forces    Fx = {:.6g} N, Fy = {:.6g} N, Mz = {:.6g} N m\n", s.Fx_N, s.Fy_N, s.Mz_N_m);
  fmt::print("  dissipated      P  = {:.6g} W, creep work = {:.6g} W\n", s.power_W, s.creep_work_W);
  fmt::print("  stick fraction     {:.4f}\n", s.stick_fraction);
}

int run_contact(const ContactOptions& opt) {
  const ContactCase c = read_contact_case(opt.case_path);
  const bool fields = c.output.fields && !opt.no_fields;
  const ContactRun run = solve_contact_case(c, fields);  // lib/io/case_run.h
  const NormalSolution& normal = run.normal;
  const ContactPatch& patch = normal.patch;
  const TangentialProblem& problem = run.problem;
  const TangentialSolution& solution = run.solution;
  const TangentialScheme scheme = run.scheme;
  const std::string& exact_solve = run.exact_solve;

  // every output computed before anything is written
  const std::filesystem::path dir = output_directory(opt.output_directory, c);
  std::vector<OutputFile> files = {
      {dir / "summary.csv", summary_csv(c.name, patch, problem, solution, scheme)},
      {dir / "strips.csv", strips_csv(in_profile_coordinates(normal), solution)},
  };
  if (fields) files.push_back({dir / "fields.csv", fields_csv(patch, solution)});

  print_contact_summary(c, normal, problem, solution, scheme, exact_solve);
  const OutputLock lock(dir);
  write_files_atomic(files);
  if (!fields) std::filesystem::remove(dir / "fields.csv");  // an earlier run's: not this run's fields
  spdlog::info("wrote {} files to {}", files.size(), dir.string());
  return 0;
}

// ---- transient: the tangential problem stepped in time over the case's histories (Satran) ---------

struct TransientOptions {
  std::string case_path;
  std::string output_directory;  // overrides output.directory
  bool no_fields = false;
  bool quiet = false;
  bool force = false;  // run even when the output is estimated above output.max_bytes or half the free disk
};

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
      "                    step's), sliding_end_s (t_s of the first step with stick; nan if none), end_step\n"
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


// The progress of a long run on stderr. On a terminal: one line redrawn in place with '\r', from
// 1 s into the run, at most 5 times a second. Otherwise: a plain info line at most every 5 s.
// Nothing when quiet.
class Progress {
  using Clock = std::chrono::steady_clock;

 public:
  Progress(std::string label, bool quiet)
      : label_(std::move(label)), quiet_(quiet), terminal_(::isatty(STDERR_FILENO) == 1), start_(Clock::now()),
        last_(start_) {}
  ~Progress() { clear(); }

  // done: the fraction of the run done, in [0, 1] (for the ETA); what: the state of the run
  void update(double done, const std::string& what) {
    if (quiet_) return;
    const Clock::time_point now = Clock::now();
    const double elapsed_s = seconds(now - start_);
    if (terminal_ ? elapsed_s < 1.0 || seconds(now - last_) < 0.2 : seconds(now - last_) < 5.0) return;
    last_ = now;
    done = std::clamp(done, 0.0, 1.0);
    const std::string line = fmt::format("{} ({:.0f} %), ETA {}", what, 100 * done,
                                         eta(done > 0 ? elapsed_s * (1 - done) / done : -1));
    if (terminal_) {
      std::fprintf(stderr, "\r%s\033[K", line.c_str());
      std::fflush(stderr);
      drawn_ = true;
    } else {
      spdlog::info("{}: {}", label_, line);
    }
  }

  // removes the line from the terminal (before the summary is printed)
  void clear() {
    if (!drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
  }

 private:
  static double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
  static std::string eta(double s) {
    if (s < 0) return "unknown";
    if (s < 60) return fmt::format("{:.0f} s", s);
    return fmt::format("{:.0f} min {:02.0f} s", std::floor(s / 60), std::fmod(s, 60));
  }

  std::string label_;
  bool quiet_, terminal_, drawn_ = false;
  Clock::time_point start_, last_;
};

// what the stdout summary needs from the steps
struct RunLog {
  TransientRecord last;
  double t_s = 0;                                                   // end of the last step
  double sliding_end_s = std::numeric_limits<double>::quiet_NaN();  // t_s of the first step with stick
  int sliding_end_step = 0;
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
    if (log.sliding_end_step > 0)
      fmt::print("  gross sliding   ended at t = {:.6g} s (step {}: first stick)\n", log.sliding_end_s,
                 log.sliding_end_step);
    else
      fmt::print("  gross sliding   throughout (no step with stick)\n");
  }
  for (std::size_t k = 0; k < res.snapshots.size(); ++k)
    fmt::print("  snapshot {}      t  = {:.6g} s\n", k + 1, res.snapshots[k].t_s);
}

int run_transient_command(const TransientOptions& opt) {
  const ContactCase c = read_contact_case(opt.case_path);
  TransientCase t = transient_case_of(c);
  const bool fields = c.output.fields && !opt.no_fields;
  if (!fields) t.settings.snapshot_times_s.clear();  // not computed either
  const std::filesystem::path dir = output_directory(opt.output_directory, c);

  // the strips the run puts the contact on, to label the streamed strip powers (checked at the end)
  const Eigen::ArrayXd y_m = transient_grid(t).y_m;

  // the output's size before the run: refused above output.max_bytes or half the free disk, unless --force
  const TransientOutputEstimate estimate = estimate_transient_output(t, fields);
  std::filesystem::path existing = std::filesystem::absolute(dir);
  while (!std::filesystem::exists(existing) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  std::error_code space_ec;
  const double free_bytes = static_cast<double>(std::filesystem::space(existing, space_ec).available);
  const bool over_max = estimate.bytes > c.output.max_bytes;
  const bool over_disk = !space_ec && estimate.bytes > free_bytes / 2;
  spdlog::debug("transient: about {:.3g} steps, {:.3g} MB of output estimated", estimate.steps, estimate.bytes / 1e6);
  if ((over_max || over_disk) && !opt.force)
    throw CaseError(fmt::format(
        "{}transient.t_end_s, transient.dt_s, solver.nx, solver.ny, output.max_bytes: the run would write about {:.3g} "
        "bytes ({:.3g} GB: about {:.3g} steps of {} strips), more than {}; shorten t_end_s, coarsen the grid, "
        "raise output.max_bytes, or run with --force",
        where(c, "transient.t_end_s"), estimate.bytes, estimate.bytes / 1e9, estimate.steps, y_m.size(),
        over_max ? fmt::format("output.max_bytes = {:.0f}", c.output.max_bytes)
                 : fmt::format("half the free disk ({:.3g} bytes free in {})", free_bytes, existing.string())));

  const OutputLock lock(dir);
  remove_stale_temporaries(dir);
  interrupted::say_on_signal(fmt::format(
      "\nrollwear: interrupted; the run's temporary files were removed and nothing was written to {}\n", dir.string()));

  // every step streams to the temporary files; the files open with the first step, so a run refused
  // before it starts writes nothing
  std::optional<StreamedFile> timeseries, strip_power;
  RunLog log;
  Progress progress("transient", opt.quiet);
  const StepObserver observe = [&](const TransientRecord& r, const Eigen::ArrayXd& power_W_per_m) {
    if (!timeseries) {
      timeseries.emplace(dir / "timeseries.csv");
      interrupted::remove_on_signal(timeseries->temporary_path());
      timeseries->append(transient_header());
      if (fields) {  // a field: per strip and step, 25 times timeseries.csv (docs/benchmarks.md, "Outputs")
        strip_power.emplace(dir / "strip_power.csv");
        interrupted::remove_on_signal(strip_power->temporary_path());
        strip_power->append(strip_power_header());
      }
    }
    timeseries->append(transient_row(r));
    if (strip_power) strip_power->append(strip_power_rows(r, y_m, power_W_per_m));
    log.last = r;
    log.t_s += r.dt_s;
    if (log.sliding_end_step == 0 && r.stick_fraction > 0) {
      log.sliding_end_step = r.step;
      log.sliding_end_s = r.t_s;
    }
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
  files.push_back({dir / "summary.csv", transient_summary_csv(c.name, run_name, res, log.sliding_end_s)});

  print_transient_summary(c, t, res, log);
  std::vector<StreamedFile*> streamed = {&*timeseries};
  if (strip_power) streamed.push_back(&*strip_power);
  write_files_atomic(files, streamed);
  if (!strip_power) std::filesystem::remove(dir / "strip_power.csv");  // an earlier run's: not this run's
  interrupted::forget();
  spdlog::info("wrote {} files to {}", files.size() + streamed.size(), dir.string());
  return 0;
}

// one line on stderr, whatever the message holds
void print_error(const std::string& message) {
  std::string line = message;
  for (char& ch : line)
    if (ch == '\n' || ch == '\r') ch = ' ';
  std::fprintf(stderr, "rollwear: error: %s\n", line.c_str());
}

}  // namespace

// ---- run: the wear loop over the life (the main job) ------------------------------------------------

struct RunOptions {
  std::string case_path;
  std::string output_directory;
  bool resume = false;
  bool restart = false;
  bool quiet = false;
};

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

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A previous run's worn profiles: the files of the program's own naming in dir/snapshots
// (snapshot_KKKK_bodyN.csv), and the folder if that leaves it empty; any other file stays.
void remove_previous_snapshots(const std::filesystem::path& dir) {
  static const std::regex kSnapshot("snapshot_[0-9]{4}_body[12]\\.csv");
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "snapshots", ec))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kSnapshot))
      std::filesystem::remove(entry.path(), ec);
  if (std::filesystem::is_empty(dir / "snapshots", ec)) std::filesystem::remove(dir / "snapshots", ec);
}

int run_run_command(const RunOptions& opt) {
  if (app::is_cam_case(opt.case_path))
    return app::run_cam_life_command(opt.case_path, opt.output_directory, opt.quiet, opt.resume, opt.restart);
  using namespace wear;
  using Clock = std::chrono::steady_clock;
  const Clock::time_point started = Clock::now();
  const WearCase c = read_wear_case(opt.case_path);
  const WearModel m = make_wear_model(c);
  const std::filesystem::path dir = output_directory(opt.output_directory, c.contact);
  const std::filesystem::path checkpoint_path = dir / "checkpoint.txt", summary_path = dir / "summary.csv";
  const double hours_per_rev = hours_per_revolution(m);
  const std::uint64_t fingerprint = case_fingerprint(read_text(opt.case_path), m);
  if (opt.resume && opt.restart) throw CaseError("--resume and --restart exclude each other");

  const OutputLock lock(dir);  // one run in the folder at a time
  remove_stale_temporaries(dir);

  // where the life starts: a checkpoint, or the unworn state
  Checkpoint cp;
  std::string summary;
  WearCache cache;
  if (opt.resume) {
    if (!std::filesystem::exists(checkpoint_path))
      throw CaseError(checkpoint_path.string() + ": no checkpoint to resume from (the run finished, "
                                  "or never started: run without --resume)");
    cp = read_checkpoint(checkpoint_path);
    if (cp.case_hash != fingerprint)
      throw CaseError(checkpoint_path.string() + ": the checkpoint belongs to another case, or " +
                                  opt.case_path + " (or a profile) changed since; run with --restart to start afresh");
    summary = summary_up_to(summary_path, cp.start.counters.steps);
    spdlog::info("run: resuming at revolution {:.6g} (step {}) from {}", cp.start.N, cp.start.counters.steps,
                 checkpoint_path.string());
  } else {
    if (std::filesystem::exists(checkpoint_path) && !opt.restart)
      throw CaseError(dir.string() + " holds an unfinished run (checkpoint.txt): continue it with --resume, "
                                  "or start afresh with --restart");
    remove_previous_snapshots(dir);  // a previous run's snapshots are not this run's
    std::filesystem::remove(dir / "report.txt");
    cp.case_hash = fingerprint;
    cp.start.state = initial_state(m);
    LifeStep s0;
    s0.state = &cp.start.state;
    s0.contact = wear_rate(m, cp.start.state, cache).contact;
    cp.start.counters = cache.counters;  // the life's solves include the unworn state's (step 0's row)
    summary = wear_summary_header(m) + wear_summary_row(m, s0, hours_per_rev);
  }

  // outputs: the worn profiles of each wearing body at a revolution
  const auto snapshot_files = [&](double N, const Eigen::VectorXd& state) {
    std::vector<OutputFile> files;
    for (int body : {1, 2})
      if ((body == 1 ? m.n1 : m.n2) > 0)
        files.push_back({dir / wear_snapshot_path(cp.snapshots_written, body),
                         wear_snapshot_csv(m, body, N, N * hours_per_rev, state)});
    ++cp.snapshots_written;
    return files;
  };
  const double earlier_s = cp.wall_s;  // run time before the resume
  const auto elapsed_s = [&] { return earlier_s + std::chrono::duration<double>(Clock::now() - started).count(); };
  // summary and checkpoint together: the summary is renamed first, so it never lags the checkpoint
  const auto save = [&](std::vector<OutputFile> files) {
    cp.wall_s = elapsed_s();
    files.push_back({summary_path, summary});
    files.push_back({checkpoint_path, checkpoint_text(cp)});
    write_files_atomic(files);
  };
  if (!opt.resume) save(snapshot_files(0, cp.start.state));
  // an interrupt (Ctrl-C) ends the process at once: the last checkpoint is where --resume continues
  interrupted::say_on_signal(fmt::format(
      "\nrollwear: interrupted; the run continues from its last checkpoint ({}) with: rollwear run {} -o {} --resume\n",
      checkpoint_path.string(), opt.case_path, dir.string()));

  // the life, step by step: a summary row each, a checkpoint every checkpoint_interval_s
  Progress progress("run", opt.quiet);
  Clock::time_point last_save = Clock::now();
  LifeHooks hooks;
  hooks.on_step = [&](const LifeStep& s) {
    summary += wear_summary_row(m, s, hours_per_rev);
    cp.start = {s.N, *s.state, s.info.next_step, s.counters};
    if (std::chrono::duration<double>(Clock::now() - last_save).count() >= c.wear.checkpoint_interval_s) {
      save({});
      last_save = Clock::now();
    }
    const double depth = max_depth_m(m, *s.state);
    double done = s.N / c.wear.revolutions;
    if (m.limits.max_depth_m > 0) done = std::max(done, depth / m.limits.max_depth_m);
    progress.update(done, fmt::format("step {}, {:.4g} revolutions ({:.4g} h), max depth {:.4g} um", s.step, s.N,
                                      s.N * hours_per_rev, depth * 1e6));
    return true;
  };
  hooks.on_snapshot = [&](double N, const Eigen::VectorXd& state) {
    save(snapshot_files(N, state));
    last_save = Clock::now();
  };
  LifeResult life;
  try {
    life = run_life(m, c, cp.start, hooks, cache);
  } catch (...) {
    progress.clear();
    if (!opt.resume && cp.start.counters.steps == 0) {
      // nothing accepted yet (e.g. bad input found at step 0): nothing to resume, and a checkpoint would
      // block the corrected rerun
      std::filesystem::remove(checkpoint_path);
      throw;
    }
    save({});  // the last accepted step: --resume continues from there (e.g. with other settings)
    spdlog::error("run: stopped at revolution {:.6g} (step {}); its state is saved in {}", cp.start.N, cp.start.counters.steps,
                  checkpoint_path.string());
    throw;
  }
  progress.clear();

  // a limit located within a step ends the life between step ends: its state is the last row
  if (life.N > cp.start.N) {
    LifeStep end;
    end.step = life.counters.steps;
    end.N = life.N;
    end.state = &life.state;
    end.info.step = life.N - cp.start.N;
    end.info.rhs_evals = life.counters.rhs_evals;
    end.info.rejected = life.counters.rejected;
    end.counters = life.counters;
    end.contact = life.contact;
    summary += wear_summary_row(m, end, hours_per_rev);
  }

  // the end: the final worn profiles and the report; the checkpoint goes (the run is complete)
  WearReport report;
  report.case_name = m.name;
  report.life = life;
  report.hours_per_revolution = hours_per_rev;
  report.wall_s = elapsed_s();
  report.resumed = opt.resume;
  std::vector<OutputFile> files = snapshot_files(life.N, life.state);
  files.push_back({summary_path, summary});
  const std::string report_text = wear_report_text(m, report);
  files.push_back({dir / "report.txt", report_text});
  write_files_atomic(files);
  std::filesystem::remove(checkpoint_path);
  fmt::print("{}", report_text);
  spdlog::info("wrote summary.csv, report.txt and {} snapshots to {}", cp.snapshots_written, dir.string());
  return life.ended_by == LifeEnd::Failed || life.ended_by == LifeEnd::NotRun ? kExitFailure : 0;
}

// ---- cam: one revolution of a disc cam with a translating roller follower ---------------------------

struct CamOptions {
  std::string case_path;
  std::string output_directory;
};

CLI::App* add_cam_command(CLI::App& app, CamOptions& opt, CommonOptions& common) {
  CLI::App* sub = app.add_subcommand(
      "cam", "One revolution of a disc cam at constant speed with a translating roller follower (cam: section, "
             "docs/cam-follower.md): lift, pressure angle, radius of curvature, loads, the Hertz contact and the "
             "roller's regime at each cam angle. Prints the jump speed and a summary; writes revolution.csv.");
  sub->footer(
      "Above the jump speed the run stops with status jump (no table written), exit 1.\n"
      "A design the model refuses (acceleration jump, table fit, undercut, pressure angle) is bad input at its\n"
      "key's line, naming the cam angle.\n"
      "Exit status: 0 success, 2 bad input (case file, options), 1 any other failure.");
  sub->add_option("case", opt.case_path, "Cam case file (YAML), e.g. cases/cam-follower.yaml")->required();
  sub->add_option("-o,--output", opt.output_directory,
                  "Output directory (default: the case's output.directory, else out/<case name>)");
  add_log_level_option(*sub, common);
  return sub;
}

int run_cam_command(const CamOptions& opt) {
  const cam::CamCase c = cam::read_cam_case(opt.case_path);
  const std::filesystem::path dir = !opt.output_directory.empty()   ? std::filesystem::path(opt.output_directory)
                                    : !c.output_directory.empty() ? std::filesystem::path(c.output_directory)
                                                                   : std::filesystem::path("out") / c.name;
  cam::CamRun run;
  try {
    run = cam::run_cam(c.model, c.solver);
  } catch (const cam::CamError& e) {
    throw cam::case_error_of(c, e);
  }
  const cam::Revolution& r = run.revolution;
  const double rpm_per_rad_s = 60 / (2 * kPi);
  fmt::print("cam {}: {:.6g} rad/s ({:.6g} rpm)\n", c.name, c.model.omega_rad_per_s,
             c.model.omega_rad_per_s * rpm_per_rad_s);
  if (std::isinf(r.jump.omega_rad_per_s))
    fmt::print("jump speed: none (the lift's acceleration is never negative)\n");
  else
    fmt::print("jump speed: {:.6g} rpm ({:.6g} rad/s), limited at cam angle {:.6g} deg\n",
               r.jump.omega_rad_per_s * rpm_per_rad_s, r.jump.omega_rad_per_s, r.jump.at_theta_rad * cam::kDegPerRad);
  if (r.status == cam::RevolutionStatus::Jump) {
    fmt::print("status: jump (the contact is lost around cam angle {:.6g} deg; no impact model): no table written\n",
               r.jump_at_theta_rad * cam::kDegPerRad);
    return kExitFailure;
  }
  double fn_max = 0, p0_max = 0, phi_max = 0, t_max = 0, rho_min = std::numeric_limits<double>::infinity();
  double at_p0 = 0, at_phi = 0;
  for (const cam::RevolutionRow& w : r.rows) {
    fn_max = std::max(fn_max, w.loads.normal_N);
    if (w.contact.p0_Pa > p0_max) p0_max = w.contact.p0_Pa, at_p0 = w.kin.theta_rad;
    if (std::abs(w.kin.pressure_angle_rad) > phi_max) phi_max = std::abs(w.kin.pressure_angle_rad), at_phi = w.kin.theta_rad;
    t_max = std::max(t_max, std::abs(w.loads.shaft_torque_N_m));
    if (w.kin.cam_curvature_per_m > 0) rho_min = std::min(rho_min, 1 / w.kin.cam_curvature_per_m);
  }
  fmt::print("status: complete, {} angle steps, cam circumference {:.6g} m\n", r.rows.size(), r.cam_circumference_m);
  fmt::print("max |pressure angle| {:.4g} deg at {:.4g} deg; min convex cam radius {:.4g} m\n", phi_max * cam::kDegPerRad,
             at_phi * cam::kDegPerRad, rho_min);
  fmt::print("max normal load {:.5g} N; max peak pressure {:.5g} MPa at {:.4g} deg; max |shaft torque| {:.5g} N m\n",
             fn_max, p0_max * 1e-6, at_p0 * cam::kDegPerRad, t_max);
  fmt::print("roller: sliding at {} of {} angle steps, rolling outside the linear range at {}\n", r.sliding_steps,
             r.rows.size(), r.outside_linear_steps);
  if (r.edge_steps > 0)
    fmt::print("warning: the contact reaches a body's edge at {} angle steps\n", r.edge_steps);
  fmt::print("{}", cam::cam_summary(run));
  const OutputLock lock(dir);
  remove_stale_temporaries(dir);
  write_files_atomic({{dir / "revolution.csv", cam::revolution_csv(run)}});
  spdlog::info("wrote revolution.csv to {}", dir.string());
  return 0;
}

int main(int argc, char** argv) {
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
  CLI::App* sweep_cmd = add_sweep_command(app, sweep_opt);
  add_log_level_option(*sweep_cmd, common);
  std::string plot_dir;
  CLI::App* plot_cmd = app.add_subcommand("plot", "PNG plots of a wear run's output folder (gnuplot): the worn "
                                                  "profiles at every snapshot, depth and peak pressure against "
                                                  "revolutions, written to OUTPUT_DIR/plots/; of a sweep's folder: the life "
                                                  "against each varied key and its distribution (docs/sweeps.md)");
  plot_cmd->add_option("output_dir", plot_dir, "The folder a 'rollwear run' wrote, e.g. out/paper-wear")->required();

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
    if (contact_cmd->parsed()) return run_contact(contact_opt);
    if (transient_cmd->parsed()) return run_transient_command(transient_opt);
    if (run_cmd->parsed()) return run_run_command(run_opt);
    if (cam_cmd->parsed()) return run_cam_command(cam_opt);
    if (plot_cmd->parsed()) return plot_command(plot_dir);
    if (sweep_cmd->parsed()) return run_sweep_command(sweep_opt);
    print_error("no subcommand ran");
    return kExitBadInput;
  } catch (const std::exception& e) {  // CaseError: bad input, 2; anything else 1 (lib/io/errors.h)
    print_error(e.what());
    return exit_status_of(e);
  } catch (...) {
    print_error("unknown failure");
    return kExitFailure;
  }
}
