// rollwear: the command line. Parse, load the case, run, write the results; nothing else.
// One function per subcommand: add_<name>_command declares its options, run_<name> does the work.
// Exit codes: 0 success, 2 bad input (case file, option, invalid argument), 1 any other failure.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "lib/case.h"
#include "lib/csv.h"
#include "lib/hertz.h"
#include "lib/steady.h"
#include "lib/tangential.h"

#ifndef ROLLWEAR_VERSION
#define ROLLWEAR_VERSION "0.1.0"  // keep equal to project(VERSION) in CMakeLists.txt
#endif

namespace {

using namespace contact;

constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

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
      "contact", "Steady rolling contact of one case: Hertz normal problem, then the tangential problem "
                 "(Kalker's simplified theory). Prints a summary and writes summary.csv, strips.csv and "
                 "fields.csv.");
  sub->add_option("case", opt.case_path, "Case file (YAML), e.g. cases/paper.yaml")->required();
  sub->add_option("-o,--output", opt.output_directory,
                  "Output directory (default: the case's output.directory, else out/<case name>)");
  sub->add_flag("--no-fields", opt.no_fields, "Do not write fields.csv (the per-cell fields)");
  add_log_level_option(*sub, common);
  return sub;
}

std::filesystem::path output_directory(const ContactOptions& opt, const ContactCase& c) {
  if (!opt.output_directory.empty()) return opt.output_directory;
  if (!c.output.directory.empty()) return c.output.directory;
  return std::filesystem::path("out") / c.name;
}

void print_contact_summary(const ContactCase& c, const ContactPatch& patch, const TangentialProblem& problem,
                           const TangentialSolution& s, TangentialScheme scheme) {
  fmt::print("case {} ({}), {} x {} grid, {} scheme\n", c.name, c.path, patch.grid.nx, patch.grid.ny,
             to_string(scheme));
  fmt::print("  normal load     F  = {:.6g} N\n", patch.normal_load_N);
  fmt::print("  semi-axes       a  = {:.6f} mm, b = {:.6f} mm\n", patch.a_m * 1e3, patch.b_m * 1e3);
  fmt::print("  peak pressure   p0 = {:.3f} MPa\n", patch.p0_Pa * 1e-6);
  fmt::print("  approach        delta = {:.4f} µm\n", patch.approach_m * 1e6);
  fmt::print("  Kalker          C11 = {:.4f}, C22 = {:.4f}, C23 = {:.4f}, C33 = {:.4f}\n", problem.C.C11,
             problem.C.C22, problem.C.C23, problem.C.C33);
  fmt::print("  flexibility     L  = {:.6e} m/Pa\n", problem.L_m_per_Pa);
  fmt::print("  creep forces    Fx = {:.6g} N, Fy = {:.6g} N, Mz = {:.6g} N m\n", s.Fx_N, s.Fy_N, s.Mz_N_m);
  fmt::print("  dissipated      P  = {:.6g} W, creep work = {:.6g} W\n", s.power_W, s.creep_work_W);
  fmt::print("  stick fraction     {:.4f}\n", s.stick_fraction);
}

int run_contact(const ContactOptions& opt) {
  const ContactCase c = read_contact_case(opt.case_path);
  const TangentialScheme scheme = parse_tangential_scheme(c.solver.tangential);

  // normal problem, then the steady tangential problem on its patch
  const ContactPatch patch = solve_normal_hertz(bodies_of(c), materials_of(c), c.load.normal_load_N, grid_of(c));
  const TangentialProblem problem = make_tangential_problem(patch, materials_of(c), creepages_of(c),
                                                            c.friction.mu, c.kinematics.speed_m_per_s);
  const TangentialSolution solution = solve_steady(patch, problem, scheme);

  // every output computed before anything is written
  const std::filesystem::path dir = output_directory(opt, c);
  std::vector<OutputFile> files = {
      {dir / "summary.csv", summary_csv(c.name, patch, problem, solution, scheme)},
      {dir / "strips.csv", strips_csv(patch, solution)},
  };
  if (c.output.fields && !opt.no_fields) files.push_back({dir / "fields.csv", fields_csv(patch, solution)});

  print_contact_summary(c, patch, problem, solution, scheme);
  write_files_atomic(files);
  spdlog::info("wrote {} files to {}", files.size(), dir.string());
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

int main(int argc, char** argv) {
  CLI::App app{"rollwear: wear of bodies in rolling contact (Hertz normal problem, Kalker's simplified "
               "theory for the tangential one).",
               "rollwear"};
  app.footer("Exit status: 0 success, 2 bad input (case file, options), 1 any other failure.\n"
             "Run 'rollwear SUBCOMMAND --help' for a subcommand's options.");
  app.set_version_flag("--version", std::string("rollwear ") + ROLLWEAR_VERSION);
  app.require_subcommand(1);

  CommonOptions common;
  add_log_level_option(app, common);  // accepted before the subcommand as well
  ContactOptions contact_opt;
  CLI::App* contact_cmd = add_contact_command(app, contact_opt, common);

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
    print_error("no subcommand ran");
    return kExitBadInput;
  } catch (const CaseError& e) {
    print_error(e.what());
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    print_error(e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    print_error(e.what());
    return kExitFailure;
  } catch (...) {
    print_error("unknown failure");
    return kExitFailure;
  }
}
