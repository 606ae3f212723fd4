// rollwear contact: the normal and steady tangential problem of one case (app/commands.h).
#include <array>
#include <filesystem>
#include <optional>
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
  // which models ran, and the error estimate a wear life reports (docs/fidelity.md): none here
  const bool exact = normal.solver == NormalSolverKind::Halfspace && scheme == TangentialScheme::Exact;
  fmt::print("  error estimate     {}\n", exact ? "none needed: the exact physics ran (half-space, Kalker's exact theory)"
                                                : "not estimated against the exact physics (solver: { normal: halfspace, "
                                                  "tangential: exact } solves it; docs/fidelity.md)");
}

// the subsurface maxima and, where a body has k, its fatigue indicators
void print_subsurface_summary(const ContactPatch& patch, const std::array<BodySubsurface, 2>& bodies) {
  const auto at = [](const StressPeak& s) {
    return fmt::format("at depth {:.4f} mm (x = {:.4f} mm, y = {:.4f} mm)", s.z_m * 1e3, s.x_m * 1e3, s.y_m * 1e3);
  };
  for (int k = 0; k < 2; ++k) {
    const Subsurface& s = bodies[k].stresses;
    const SubsurfaceMaxima& m = s.maxima;
    fmt::print("  below body {} (nu = {:.4g}):\n", k + 1, s.nu);
    fmt::print("    von Mises        {:.3f} MPa {} = {:.3f} p0\n", m.von_mises.value_Pa * 1e-6, at(m.von_mises),
               m.von_mises.value_Pa / patch.p0_Pa);
    fmt::print("    Tresca (s1-s3)/2 {:.3f} MPa {} = {:.3f} p0\n", m.tresca.value_Pa * 1e-6, at(m.tresca),
               m.tresca.value_Pa / patch.p0_Pa);
    fmt::print("    |sigma_xz|       {:.3f} MPa {}\n", m.orthogonal_shear.value_Pa * 1e-6, at(m.orthogonal_shear));
    fmt::print("    largest s1       {:.3f} MPa {}\n", m.tension.value_Pa * 1e-6, at(m.tension));
    fmt::print("    smallest s3      {:.3f} MPa {}\n", m.compression.value_Pa * 1e-6, at(m.compression));
    if (const std::optional<FatigueIndicators>& f = bodies[k].fatigue) {
      fmt::print("    fatigue, k = {:.1f} MPa: p0/k = {:.3f}, shakedown limit {:.3f} ({} contact, {} limit) at "
                 "traction {:.4f}: margin {:+.1f} %\n",
                 f->shear_yield_Pa * 1e-6, f->p0_over_k, f->limit_p0_over_k, to_string(f->contact),
                 f->surface_limit ? "surface" : "subsurface", f->traction_coefficient, f->margin * 100);
      fmt::print("    surface fatigue  FI_surf = {:.4f}, per cell (|tau| - k)/p at most {:.4f} (x = {:.4f} mm, "
                 "y = {:.4f} mm)\n",
                 f->FI_surf, f->cell_index_max, f->cell_x_m * 1e3, f->cell_y_m * 1e3);
    }
    if (const std::optional<DangVanField>& d = bodies[k].dang_van)
      fmt::print("    Dang Van         index {:.4f} (a = {:.3g}, b = {:.1f} MPa; >= 1: crack initiation) at depth "
                 "{:.4f} mm, y = {:.4f} mm (peaking at x = {:.4f} mm): tau = {:.3f} MPa, p_h = {:.3f} MPa\n",
                 d->index_max, d->constants.a, d->constants.b_Pa * 1e-6, d->z_m * 1e3, d->y_m * 1e3, d->x_m * 1e3,
                 d->tau_Pa * 1e-6, d->hydrostatic_Pa * 1e-6);
  }
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
  const bool subsurface = c.output.subsurface && !opt.no_subsurface;
  const ContactRun run = solve_contact_case(c, fields || subsurface);  // lib/io/case_run.h
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
  std::array<BodySubsurface, 2> below;
  bool fatigue = false, dang_van = false;
  if (subsurface) {
    below = subsurface_of_contact(c, run);
    const std::vector<const Subsurface*> bodies = {&below[0].stresses, &below[1].stresses};
    files.push_back({dir / "subsurface.csv", subsurface_csv(bodies)});
    files.push_back({dir / "subsurface_section.csv",
                     subsurface_section_csv(in_profile_coordinates(normal).grid, bodies)});  // y as strips.csv's
    fatigue = below[0].fatigue || below[1].fatigue;
    if (fatigue)
      files.push_back({dir / "fatigue.csv", fatigue_csv({below[0].fatigue ? &*below[0].fatigue : nullptr,
                                                         below[1].fatigue ? &*below[1].fatigue : nullptr})});
    dang_van = below[0].dang_van || below[1].dang_van;
    if (dang_van)
      files.push_back({dir / "dang_van.csv", dang_van_csv({below[0].dang_van ? &*below[0].dang_van : nullptr,
                                                           below[1].dang_van ? &*below[1].dang_van : nullptr})});
  }

  print_contact_summary(c, normal, problem, solution, scheme, exact_solve);
  print_lubrication_and_thermal(run);
  if (subsurface) print_subsurface_summary(patch, below);
  const session::OutputLock lock(dir);
  write_files_atomic(files);
  if (!fields) std::filesystem::remove(dir / "fields.csv");  // an earlier run's: not this run's fields
  if (!subsurface) {
    std::filesystem::remove(dir / "subsurface.csv");
    std::filesystem::remove(dir / "subsurface_section.csv");
  }
  if (!fatigue) std::filesystem::remove(dir / "fatigue.csv");
  if (!dang_van) std::filesystem::remove(dir / "dang_van.csv");
  spdlog::info("wrote {} files to {}", files.size(), dir.string());
  return 0;
}

}  // namespace app
