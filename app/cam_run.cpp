// `rollwear run` on a cam case (app/cam_run.h).
#include "app/cam_run.h"

#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/revolution_dissipation.h"
#include "lib/io/csv.h"
#include "lib/io/errors.h"
#include "lib/numeric.h"

namespace app {

namespace fs = std::filesystem;

bool is_cam_case(const std::string& path) {
  try {
    const YAML::Node doc = YAML::LoadFile(path);
    return doc.IsMap() && doc["cam"].IsDefined();
  } catch (const std::exception&) {
    return false;
  }
}

namespace {

std::string snapshot_path(const char* what, int k) { return fmt::format("snapshots/{}_{:04d}.csv", what, k); }

// the previous run's snapshot files (this command's naming only), and the folder if that leaves it empty
void remove_previous_snapshots(const fs::path& dir) {
  static const std::regex kName("(wear_map|roller_wear)_[0-9]{4}\\.csv");
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir / "snapshots", ec))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kName))
      fs::remove(entry.path(), ec);
  if (fs::is_empty(dir / "snapshots", ec)) fs::remove(dir / "snapshots", ec);
}

// per angle step: the power and energy, and where the contact sits on the cam (its polar angle and radius
// in the cam's frame: the plot's outline of the cam)
std::string dissipation_csv(const cam::Revolution& r, const cam::RevolutionDissipation& rev) {
  std::string out = "# the unworn periodic revolution's dissipation per angle step\n"
                    "cam_angle_deg,cam_arc_m,rolling_speed_m_per_s,power_W,energy_J,contact_angle_deg,contact_radius_m\n";
  for (std::size_t k = 0; k < rev.size(); ++k) {
    const cam::AngleDissipation& a = rev[k];
    const cam::CamKinematics& kin = r.rows[k].kin;
    const double P = cam::total_power_W(a);
    fmt::format_to(std::back_inserter(out), "{:.8g},{:.10g},{:.10g},{:.10g},{:.10g},{:.8g},{:.10g}\n",
                   a.theta_rad * cam::kDegPerRad, a.cam_arc_m, a.rolling_speed_m_per_s, P, P * a.duration_s,
                   kin.contact_angle_rad * cam::kDegPerRad, std::hypot(kin.contact_x_m, kin.contact_y_m));
  }
  return out;
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

int run_cam_life_command(const std::string& case_path, const std::string& output_option, bool quiet) {
  const double cpu0 = cpu_seconds();
  const cam::CamCase c = cam::read_cam_case(case_path);
  if (!c.wear) {
    const auto it = c.locations.find("cam");
    throw contact::CaseError((it != c.locations.end() ? it->second : case_path) +
                             ": cam.wear: missing: `rollwear run` on a cam case needs the wear laws, revolutions and "
                             "limits (docs/cam-follower.md §13); `rollwear cam` runs one revolution without them");
  }
  const cam::CamModel& m = c.model;
  const fs::path dir = !output_option.empty()           ? fs::path(output_option)
                       : !c.output_directory.empty()    ? fs::path(c.output_directory)
                                                        : fs::path("out") / c.name;

  // the unworn periodic revolution: kinematics, loads, the roller's motion, the dissipation
  std::unique_ptr<cam::CamLifeSetup> setup;
  try {
    cam::RollerDynamicsSettings dynamics;  // the case's cam.tangential, as rollwear cam reads it
    dynamics.law.grid = {c.solver.nx, c.solver.ny};
    dynamics.periodicity_rtol = c.solver.periodic_rtol;
    dynamics.max_revolutions = c.solver.max_revolutions;
    setup = cam::set_up_cam_life(c.name, m, *c.wear, dynamics);
  } catch (const cam::CamError& e) {
    throw cam::case_error_of(c, e);
  }
  const cam::Revolution& r = setup->revolution;
  if (r.status == cam::RevolutionStatus::Jump) {
    fmt::print("status: jump (the contact is lost around cam angle {:.6g} deg; no impact model): no life\n",
               r.jump_at_theta_rad * cam::kDegPerRad);
    return contact::kExitFailure;
  }
  const cam::PeriodicMotion& motion = setup->motion;
  const cam::RevolutionDissipation& unworn_rev = setup->unworn;
  const cam::CamLifeModel& life_model = setup->life;
  const cam::DissipationOf producer = setup->producer();
  const cam::DissipationTotals totals = cam::dissipation_totals(unworn_rev);
  fmt::print("cam {}: {:.6g} rad/s, {} angle steps, cam circumference {:.6g} m\n", c.name, m.omega_rad_per_s,
             r.rows.size(), r.cam_circumference_m);
  fmt::print("roller: periodic after {} revolutions, sliding at {} of {} angle steps\n", motion.revolutions,
             motion.sliding_steps, r.rows.size());
  fmt::print("dissipated per revolution {:.6g} J (mean {:.6g} W), peak {:.6g} W at cam angle {:.4g} deg\n",
             totals.energy_J, totals.energy_J * m.omega_rad_per_s / (2 * contact::kPi), totals.max_power_W,
             totals.max_power_theta_rad * cam::kDegPerRad);

  fs::create_directories(dir / "snapshots");
  remove_previous_snapshots(dir);
  fs::create_directories(dir / "snapshots");
  contact::write_files_atomic({{dir / "revolution.csv", cam::revolution_csv(r)},
                               {dir / "dissipation.csv", dissipation_csv(r, unworn_rev)}});

  std::string life_csv = "# case: " + c.name +
                         "\nstep,revolutions,max_depth_m,lift_loss_m,lift_loss_at_deg,energy_J\n"
                         "0,0,0,0,0,0\n";
  int snapshots = 0;
  cam::CamLifeHooks hooks;
  hooks.on_snapshot = [&](double N, const cam::CamWearState& s) {
    contact::write_files_atomic(
        {{dir / snapshot_path("wear_map", snapshots), cam::wear_map_csv(life_model.grid, s, N, c.name)},
         {dir / snapshot_path("roller_wear", snapshots), cam::roller_wear_csv(life_model.grid, s, N, c.name)}});
    ++snapshots;
  };
  hooks.on_step = [&](const cam::CamLifeStep& step) {
    fmt::format_to(std::back_inserter(life_csv), "{},{:.10g},{:.10g},{:.10g},{:.6g},{:.10g}\n", step.step, step.N,
                   step.max_depth_m, step.lift_loss.max_m, step.lift_loss.at_theta_rad * cam::kDegPerRad,
                   step.energy_J);
    if (!quiet) spdlog::info("step {}: N {:.6g}, max depth {:.4g} m, lift loss {:.4g} m", step.step, step.N,
                             step.max_depth_m, step.lift_loss.max_m);
  };
  const cam::CamLifeResult life = cam::run_cam_life(life_model, producer, hooks);
  const double cpu = cpu_seconds() - cpu0;

  const double hours = life.N * 2 * contact::kPi / m.omega_rad_per_s / 3600;
  std::string report = fmt::format(
      "case: {}\nlife: {:.6g} cam revolutions ({:.6g} h at {:.6g} rad/s)\nended by: {}\nwhy: {}\n"
      "max depth: {:.6g} m\nmax lift loss: {:.6g} m at cam angle {:.4g} deg\n"
      "worn volume: track {:.6g} m^3, roller {:.6g} m^3\ndissipated: {:.6g} J\n"
      "steps: {} ({} rejected), evaluations of the wear rate: {}, revolutions solved: {}\n"
      "worn revolutions: {} angle steps, {} normal solves (the rest shared a contact), {} F(delta) and {} creep-law "
      "evaluations, {} warm starts retried cold\ncpu: {:.3g} s\n",
      c.name, life.N, hours, m.omega_rad_per_s, cam::to_string(life.ended_by), life.message, life.max_depth_m,
      life.lift_loss.max_m, life.lift_loss.at_theta_rad * cam::kDegPerRad, life.cam_volume_m3, life.roller_volume_m3,
      life.energy_J, life.steps, life.rejected, life.rhs_evals, life.revolutions_solved, setup->worn->stats().angles,
      setup->worn->stats().contacts_solved, setup->worn->stats().approach_evaluations,
      setup->worn->stats().creep_evaluations, setup->worn->stats().cold_retries, cpu);
  contact::write_files_atomic({{dir / "life.csv", life_csv}, {dir / "report.txt", report}});
  fmt::print("{}", report);
  fmt::print("wrote {} (revolution.csv, dissipation.csv, life.csv, report.txt, {} wear maps in snapshots/)\n",
             dir.string(), snapshots);
  const bool failed = life.ended_by == cam::CamLifeEnd::Failed || life.ended_by == cam::CamLifeEnd::NotRun;
  if (failed) spdlog::error("the life failed: {}", life.message);
  return failed ? contact::kExitFailure : 0;
}

}  // namespace app
