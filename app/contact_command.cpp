// rollwear contact: the normal and steady tangential problem of one case (app/commands.h).
#include <filesystem>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "app/commands.h"
#include "lib/io/case_run.h"
#include "lib/model/contact_model.h"
#include "lib/io/case.h"
#include "lib/io/csv.h"
#include "lib/tangential/tangential.h"
#include "session/output_folder.h"

namespace app {

using namespace contact;

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
      "With a lubricant: section the summary adds the EHL film thickness, the film parameter lambda and the\n"
      "regime with its friction and wear factors; with a thermal: section the flash temperature (Blok's\n"
      "partition) and, with critical_temperature_C, the scuffing margin (docs/lubrication-and-temperature.md).\n"
      "Exit status: 0 success, 2 bad input (case file, options), 1 any other failure.");
  sub->add_option("case", opt.case_path, "Case file (YAML), e.g. cases/paper.yaml")->required();
  sub->add_option("-o,--output", opt.output_directory,
                  "Output directory (default: the case's output.directory, else out/<case name>)");
  sub->add_flag("--no-fields", opt.no_fields, "Do not write fields.csv (the per-cell fields)");
  sub->add_flag("-q,--quiet", opt.quiet,
                "No progress line on stderr: contact shows none (taken as run, transient and sweep take it)");
  add_log_level_option(*sub, common);
  return sub;
}

namespace {

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

// the film and the regime (lubricant:), the flash temperature (thermal:)
void print_lubrication_and_thermal(const ContactRun& run) {
  if (const auto& l = run.lubrication) {
    fmt::print("  EHL film (Hamrock-Dowson, Rx = {:.4g} mm, k = {:.3g}{}, u = {:.4g} m/s)\n", l->Rx_m * 1e3,
               l->film.ellipticity_k, l->within_fit_range ? "" : ", outside the fitted 1-8", l->entrainment_m_per_s);
    fmt::print("  film thickness  h_min = {:.4g} um, h_c = {:.4g} um\n", l->film.h_min_m * 1e6,
               l->film.h_central_m * 1e6);
    fmt::print("  film parameter  lambda = {:.4g}: {} regime, mu = {:.4g}, wear factor = {:.4g}"
               " (the solve above uses friction.mu)\n",
               l->lambda, to_string(l->regime), l->mu, l->wear_factor);
  }
  if (const auto& t = run.thermal) {
    const FlashTemperature& f = t->flash;
    fmt::print("  flash temperature  max {:.4g} K above bulk (Blok: {:.3g} of the heat into body 1; "
               "Peclet L1 = {:.3g}, L2 = {:.3g})\n",
               f.max_rise_K, f.share_body1, f.peclet_body1, f.peclet_body2);
    if (t->contact_temperature_C) fmt::print("  contact temperature  {:.4g} C\n", *t->contact_temperature_C);
    if (t->scuffing_margin_K)
      fmt::print("  scuffing margin    {:.4g} K below Blok's critical temperature{}\n", *t->scuffing_margin_K,
                 *t->scuffing_margin_K < 0 ? " (past it: scuffing expected)" : "");
  }
}

}  // namespace

int run_contact_command(const ContactOptions& opt) {
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
  const std::filesystem::path dir = session::output_directory(opt.output_directory, c.output.directory, c.name);
  std::vector<OutputFile> files = {
      {dir / "summary.csv", contact_summary_csv(c.name, run)},
      {dir / "strips.csv", strips_csv(in_profile_coordinates(normal), solution)},
  };
  if (fields) files.push_back({dir / "fields.csv", fields_csv(patch, solution)});

  print_contact_summary(c, normal, problem, solution, scheme, exact_solve);
  print_lubrication_and_thermal(run);
  const session::OutputLock lock(dir);
  write_files_atomic(files);
  if (!fields) std::filesystem::remove(dir / "fields.csv");  // an earlier run's: not this run's fields
  spdlog::info("wrote {} files to {}", files.size(), dir.string());
  return 0;
}

}  // namespace app
