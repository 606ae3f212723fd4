// The tangential problem along a worn cam revolution (docs/cam-follower.md §9): the relaxed model stepped along
// the revolution on the worn state's semi-Hertzian contacts (worn_transient_revolution), with and without the
// quasi-steady skip, against the life's quasi-steady revolution (worn_revolution_dissipation). A plain program:
//   cam_transient_bench CASE.yaml [worn_depth_m = 8e-6] [step_cells = 1] [repeats = 3]
// The worn transient is the relaxed model's only: the program runs the whole case on it (the roller's steady
// law, the wear to the state, the transients), whatever the case's cam.tangential.scheme says.
// 1. sets up the case's life (the unworn periodic revolution);
// 2. wears the case to worn_depth_m (fixed-depth steps of 1e-6 m, the life's producer), as cam_life_bench does;
// 3. on that state: the full transient, the transient with the skip (the case's quasi_steady_tolerance) and the
//    quasi-steady revolution, CPU each (medians of the repeats); the skip's and the quasi-steady revolution's
//    largest error in a step's power (of the peak) and in the revolution's energy against the full transient; the
//    energy terms.
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/revolution_dissipation.h"
#include "cam/revolution_transient.h"
#include "lib/tangential/relaxed_shape.h"
#include "tests/bench/cam_bench_life.h"

namespace {

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cam_transient_bench CASE.yaml [worn_depth_m] [step_cells] [repeats]\n");
    return 2;
  }
  spdlog::set_level(spdlog::level::warn);
  const double worn_depth = argc > 2 ? std::stod(argv[2]) : 8e-6;
  const double step_cells = argc > 3 ? std::stod(argv[3]) : 1.0;
  const int repeats = argc > 4 ? std::stoi(argv[4]) : 3;
  const cam::CamCase c = cam::read_cam_case(argv[1]);
  if (!c.wear) {
    std::fprintf(stderr, "%s: no cam.wear section\n", argv[1]);
    return 2;
  }
  cam::CamSolverSettings solver = c.solver;
  solver.scheme = contact::TangentialScheme::Relaxed;  // the worn transient's model (above)
  const cam::RollerDynamicsSettings dynamics = cam::roller_dynamics_of(solver);
  double t0 = cpu_s();
  const std::unique_ptr<cam::CamLifeSetup> setup = cam::set_up_cam_life(c.name, c.model, *c.wear, dynamics);
  std::printf("set-up (unworn periodic revolution, %s model): %.3f s CPU\n", contact::to_string(solver.scheme).c_str(),
              cpu_s() - t0);
  cam::CamWearState s = cam::unworn_state(setup->life.grid);
  if (worn_depth > 0) {
    t0 = cpu_s();
    const cam::CamLifeResult worn = bench::cam_worn_to_depth(*setup, worn_depth);
    std::printf("worn to %.3g m in %ld steps (%.4g revolutions): %.3f s CPU\n", worn.max_depth_m, worn.steps, worn.N,
                cpu_s() - t0);
    s = worn.state;
  }
  cam::TransientRevolutionSettings ts;
  ts.scheme = solver.scheme;
  ts.quasi_steady_tolerance = c.solver.quasi_steady_tolerance;
  ts.relaxed_step_cells = step_cells;
  const auto transient = [&](bool skip, double& cpu) {
    std::vector<double> t;
    cam::TransientRevolution out;
    cam::TransientRevolutionSettings k = ts;
    k.skip = skip;
    for (int i = 0; i < repeats; ++i) {
      const double t1 = cpu_s();
      out = cam::worn_transient_revolution(setup->model, setup->revolution, setup->motion.motion, setup->unworn_profiles,
                                           setup->life.grid, s, setup->dynamics.law, k);
      t.push_back(cpu_s() - t1);
    }
    cpu = median(t);
    return out;
  };
  double cpu_full = 0, cpu_skip = 0;
  const cam::TransientRevolution full = transient(false, cpu_full), with = transient(true, cpu_skip);
  std::vector<double> tq;
  cam::RevolutionDissipation qs;
  for (int i = 0; i < repeats; ++i) {
    const double t1 = cpu_s();
    qs = cam::worn_revolution_dissipation(setup->model, setup->revolution, setup->motion.motion, setup->unworn_profiles,
                                          setup->life.grid, s, setup->dynamics.law);
    tq.push_back(cpu_s() - t1);
  }
  const cam::SkipComparison skip = cam::compare_skip(with, full), life = cam::compare_dissipation(qs, full.dissipation);
  const cam::DissipationTotals tf = cam::dissipation_totals(full.dissipation);
  const std::size_t n = full.dissipation.size();
  std::printf("full transient: %ld steps + %ld warm-up, %.1f ms CPU; energy %.9g J per revolution, peak power %.6g W at "
              "%.2f deg\n", full.transient_steps, full.warmup_steps, 1e3 * cpu_full, tf.energy_J, tf.max_power_W,
              tf.max_power_theta_rad * 57.29577951308232);
  std::printf("  energy: dissipated %.9g = creep work %.9g - relaxation %.4g (+ %.2g)\n", full.energy.dissipated_J,
              full.energy.creep_work_J, full.energy.relaxation_J,
              full.energy.dissipated_J - (full.energy.creep_work_J - full.energy.relaxation_J));
  std::printf("with the skip (tolerance %g): %d of %zu angle steps quasi-steady, %ld steps + %ld warm-up (%.1f %% saved), "
              "%.1f ms CPU; against the full transient: power error %.3e of the peak, energy error %.3e\n",
              ts.quasi_steady_tolerance, with.skipped_rows, n, with.transient_steps, with.warmup_steps,
              100 * skip.step_saving, 1e3 * cpu_skip, skip.max_power_error, skip.energy_error);
  std::printf("quasi-steady everywhere (the life's worn revolution), %.1f ms CPU: power error %.3e of the peak, energy "
              "error %.3e\n", 1e3 * median(tq), life.max_power_error, life.energy_error);
  // where the quasi-steady revolution's largest error is
  double worst = 0, worst_theta = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = std::abs(cam::total_power_W(qs[i]) - cam::total_power_W(full.dissipation[i]));
    if (d > worst) worst = d, worst_theta = full.dissipation[i].theta_rad;
  }
  std::printf("  its largest at %.2f deg\n", worst_theta * 57.29577951308232);
  {  // the same state's quasi-steady revolution with the other model (the motion the case's)
    cam::CreepLawSettings other = setup->dynamics.law;
    other.scheme = other.scheme == contact::TangentialScheme::Relaxed ? contact::TangentialScheme::Consistent
                                                                        : contact::TangentialScheme::Relaxed;
    const cam::RevolutionDissipation q2 = cam::worn_revolution_dissipation(
        setup->model, setup->revolution, setup->motion.motion, setup->unworn_profiles, setup->life.grid, s, other);
    std::printf("quasi-steady energy per revolution on this state: %s %.9g J, %s %.9g J\n",
                contact::to_string(setup->dynamics.law.scheme).c_str(), cam::dissipation_totals(qs).energy_J,
                contact::to_string(other.scheme).c_str(), cam::dissipation_totals(q2).energy_J);
  }
  if (argc > 6 && std::string(argv[5]) == "angle") {  // one angle's contact under both models
    const double theta = std::stod(argv[6]) / 57.29577951308232;
    std::size_t i = 0;
    while (i + 1 < n && setup->revolution.rows[i + 1].kin.theta_rad <= theta) ++i;
    const cam::RevolutionRow& row = setup->revolution.rows[i];
    const cam::RollerAngle& a = setup->motion.motion.angles[i];
    double b_min = 1e300;
    for (const cam::RevolutionRow& rr : setup->revolution.rows) b_min = std::min(b_min, rr.contact.b_m);
    if (argc > 7) {  // the worn profiles there as lateral profile files (y_m,z_m) PREFIX_roller.csv, PREFIX_track.csv
      const contact::Profiles worn = cam::worn_profiles_at(setup->unworn_profiles, setup->life.grid, s, row.contact_arc_m);
      for (const auto& [body, name] : {std::pair{&worn.body1, "_roller.csv"}, std::pair{&worn.body2, "_track.csv"}}) {
        std::FILE* f = std::fopen((std::string(argv[7]) + name).c_str(), "w");
        std::fprintf(f, "y_m,z_m\n");
        for (Eigen::Index j = 0; j < body->y_m.size(); ++j) std::fprintf(f, "%.17g,%.17g\n", body->y_m(j), body->z_m(j));
        std::fclose(f);
      }
      std::printf("cam radius %.9g m, rolling speed %.9g m/s\n", cam::cam_radius_m(row.kin), a.speed_m_per_s);
    }
    for (const contact::TangentialScheme k : {contact::TangentialScheme::Relaxed, contact::TangentialScheme::Consistent}) {
      cam::CreepLawSettings law = cam::worn_contact_settings(setup->unworn_profiles, setup->life.grid,
                                                             setup->dynamics.law, 2 * b_min / setup->dynamics.law.grid.ny);
      law.scheme = k;
      const contact::Profiles worn = cam::worn_profiles_at(setup->unworn_profiles, setup->life.grid, s, row.contact_arc_m);
      const cam::AngleContact ac = cam::angle_contact(setup->model.bodies, worn, setup->model.geometry.roller_radius_m,
                                                      row.kin, a.normal_N, setup->model.mu, law);
      const cam::CreepageForForce xi = cam::creepage_for_force(ac, a.tangential_N);
      const contact::TangentialSolution sol = cam::steady_creep(ac, xi.xi, a.speed_m_per_s);
      double off_lo = 1e300, off_hi = -1e300;
      for (int j = 0; j < ac.normal.patch.grid.ny; ++j)
        if (ac.normal.patch.half_length_m(j) > 0 && ac.normal.patch.strip_xi_offset.size() > 0) {
          off_lo = std::min(off_lo, ac.normal.patch.strip_xi_offset(j));
          off_hi = std::max(off_hi, ac.normal.patch.strip_xi_offset(j));
        }
      std::printf("%.2f deg %s: a %.4e b %.4e patches %d F_n %.4g F_t %.4g xi %.4e (offsets %.3e .. %.3e) P %.6e W, "
                  "-creep work %.6e W, Fx %.5g, stick %.3f, shape factor S %.4f\n", row.kin.theta_rad * 57.29577951308232,
                  contact::to_string(k).c_str(), ac.normal.patch.a_m, ac.normal.patch.b_m, ac.normal.patches, a.normal_N,
                  a.tangential_N, xi.xi, off_lo, off_hi, sol.power_W, -sol.creep_work_W, sol.Fx_N, sol.stick_fraction,
                  contact::relaxed_shape_factor(ac.normal.patch));
    }
  }
  if (argc > 5 && std::string(argv[5]) == "rows") {  // per angle step: the contact, creepage and both powers
    std::printf("theta_deg a_m b_m p0_Pa xi unsteadiness skipped P_full_W P_quasi_steady_W\n");
    const cam::TransientRevolution& t = full;
    for (std::size_t i = 0; i < n; ++i) {
      const double th = full.dissipation[i].theta_rad * 57.29577951308232;
      std::printf("%.2f %.4e %.4e %.4e %.6e %.3e %d %.6e %.6e\n", th, t.a_m[i], t.b_m[i], t.p0_Pa[i],
                  t.xi.empty() ? 0.0 : t.xi[i], with.unsteadiness[i], static_cast<int>(with.skipped[i]),
                  cam::total_power_W(full.dissipation[i]), cam::total_power_W(qs[i]));
    }
  }
  return 0;
}
