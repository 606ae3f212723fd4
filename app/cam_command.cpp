// rollwear cam: one revolution of a disc cam with a translating roller follower (app/commands.h).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <spdlog/spdlog.h>

#include "app/commands.h"
#include "cam/cam_case.h"
#include "cam/periodic_revolution.h"
#include "cam/revolution.h"
#include "lib/io/csv.h"
#include "lib/errors.h"
#include "lib/numeric.h"
#include "session/output_folder.h"

namespace app {

using namespace contact;

int run_cam_command(const CamOptions& opt) {
  const cam::CamCase c = cam::read_cam_case(opt.case_path);
  const std::filesystem::path dir = session::output_directory(opt.output_directory, c.output_directory, c.name);
  cam::CamRun run;
  try {
    run = cam::run_cam(c.model, c.solver, c.lubrication);
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
  const session::OutputLock lock(dir);
  session::remove_stale_temporaries(dir);
  write_files_atomic({{dir / "revolution.csv", cam::revolution_csv(run)}});
  spdlog::info("wrote revolution.csv to {}", dir.string());
  return 0;
}

}  // namespace app
