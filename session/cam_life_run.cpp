// `rollwear run` on a cam case, and the choice between a cam and a wear case (session/life_run.h).
#include "session/life_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "cam/cam_case.h"
#include "cam/cam_life.h"
#include "cam/cam_lubrication.h"
#include "cam/revolution_dissipation.h"
#include "lib/io/csv.h"
#include "lib/errors.h"
#include "lib/normal/profile.h"
#include "lib/numeric.h"
#include "session/life_folder.h"
#include "session/output_folder.h"
#include "wear/wear_output.h"

namespace session {

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

// per angle step: the power and energy, where the contact sits on the cam (its polar angle and radius in the
// cam's frame: the plot's outline of the cam), and the roller's periodic motion the life holds (its loads,
// creepage and spin: revolution.csv's are the kinematic roller's)
// with cam.lubricant or cam.thermal, the film and the flash temperature per angle follow (cam/cam_lubrication.h)
std::string dissipation_csv(const cam::Revolution& r, const cam::RevolutionDissipation& rev,
                            const cam::RollerMotion& motion, const cam::CamLubricationSpec& spec,
                            const cam::RevolutionLubrication& lubrication) {
  std::string out = "# the unworn periodic revolution's dissipation per angle step, and the roller's periodic motion\n"
                    "cam_angle_deg,cam_arc_m,rolling_speed_m_per_s,power_W,energy_J,contact_angle_deg,contact_radius_m,"
                    "normal_load_N,tangential_load_N,xi,slip_speed_m_per_s,roller_omega_rad_per_s" +
                    cam::lubrication_csv_header(spec) + "\n";
  for (std::size_t k = 0; k < rev.size(); ++k) {
    const cam::AngleDissipation& a = rev[k];
    const cam::CamKinematics& kin = r.rows[k].kin;
    const cam::RollerAngle& m = motion.angles[k];
    const double P = cam::total_power_W(a);
    fmt::format_to(std::back_inserter(out), "{:.8g},{:.10g},{:.10g},{:.10g},{:.10g},{:.8g},{:.10g},{:.10g},{:.10g},{:.10g},"
                   "{:.10g},{:.10g}",
                   a.theta_rad * cam::kDegPerRad, a.cam_arc_m, a.rolling_speed_m_per_s, P, P * a.duration_s,
                   kin.contact_angle_rad * cam::kDegPerRad, std::hypot(kin.contact_x_m, kin.contact_y_m), m.normal_N,
                   m.tangential_N, m.xi, m.slip_speed_m_per_s, m.omega_r_rad_per_s);
    if (lubrication.angles.size() == rev.size()) out += cam::lubrication_csv_cells(spec, lubrication.angles[k]);
    out += '\n';
  }
  return out;
}

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// The case's fingerprint for its checkpoint: the case file's text (every key of the model, the wear and the
// grid is in it; a cam case reads no other file), tagged so that a wear case's checkpoint never matches.
std::uint64_t cam_case_fingerprint(const std::string& case_path) {
  std::ifstream in(case_path, std::ios::binary);
  std::ostringstream text;
  text << "rollwear cam life\n" << in.rdbuf();
  const std::string t = text.str();
  return contact::hash_words(t.data(), t.size());
}

// The cam life's state in the wear loop's checkpoint (wear/wear_output.h, hexadecimal floats: bit-exact):
// its state is the integrated state followed by the energy scale; rate_evaluations holds revolutions_solved
// and wall_s the CPU seconds so far; the blocks "rate" (the rate at the state, the next step's slope) and
// "warm_starts" (the worn revolution's memory: its per-angle warm starts and statistics) are what the rate
// carries to the next step, so that the resumed life is the uninterrupted one to the bit.
constexpr const char* kRateBlock = "rate";
constexpr const char* kWarmStartsBlock = "warm_starts";
wear::Checkpoint to_checkpoint(std::uint64_t hash, const cam::CamLifeStart& s, int snapshots, double cpu_s) {
  wear::Checkpoint c;
  c.case_hash = hash;
  c.start.N = s.N;
  c.start.state.resize(s.x.size() + 1);
  c.start.state.head(s.x.size()) = s.x;
  c.start.state(s.x.size()) = s.energy_scale;
  c.start.next_step = s.next_step;
  c.start.counters.steps = s.steps;
  c.start.counters.rejected = s.rejected;
  c.start.counters.rhs_evals = s.rhs_evals;
  c.start.counters.rate_evaluations = s.revolutions_solved;
  c.snapshots_written = snapshots;
  c.wall_s = cpu_s;
  if (s.rate.size() > 0) c.blocks.push_back({kRateBlock, s.rate});
  if (!s.producer_memory.empty())
    c.blocks.push_back({kWarmStartsBlock, Eigen::Map<const Eigen::VectorXd>(
                                              s.producer_memory.data(),
                                              static_cast<Eigen::Index>(s.producer_memory.size()))});
  return c;
}
cam::CamLifeStart from_checkpoint(const wear::Checkpoint& c) {
  cam::CamLifeStart s;
  const Eigen::Index n = c.start.state.size() - 1;
  s.N = c.start.N;
  s.x = c.start.state.head(n);
  s.energy_scale = c.start.state(n);
  s.next_step = c.start.next_step;
  s.steps = c.start.counters.steps;
  s.rejected = c.start.counters.rejected;
  s.rhs_evals = c.start.counters.rhs_evals;
  s.revolutions_solved = c.start.counters.rate_evaluations;
  for (const wear::CheckpointBlock& b : c.blocks) {
    if (b.name == kRateBlock) s.rate = b.values;
    if (b.name == kWarmStartsBlock) s.producer_memory.assign(b.values.data(), b.values.data() + b.values.size());
  }
  return s;
}

// the unworn periodic revolution (kinematics, loads, the roller's motion, the dissipation), printed; nullptr
// when the follower jumps (printed too: no life)
std::unique_ptr<cam::CamLifeSetup> set_up_life(const cam::CamCase& c) {
  const cam::CamModel& m = c.model;
  std::unique_ptr<cam::CamLifeSetup> setup;
  try {
    // with cam.lubricant.friction_by_regime the regime law's friction and wear factor per angle (cam/cam_lubrication.h)
    setup = cam::set_up_lubricated_cam_life(c.name, c.lubrication, m, *c.wear, cam::roller_dynamics_of(c.solver));
  } catch (const cam::CamError& e) {
    throw cam::case_error_of(c, e);
  }
  const cam::Revolution& r = setup->revolution;
  if (r.status == cam::RevolutionStatus::Jump) {
    fmt::print("status: jump (the contact is lost around cam angle {:.6g} deg; no impact model): no life\n",
               r.jump_at_theta_rad * cam::kDegPerRad);
    return nullptr;
  }
  const cam::PeriodicMotion& motion = setup->motion;
  const cam::DissipationTotals totals = cam::dissipation_totals(setup->unworn);
  fmt::print("cam {}: {:.6g} rad/s, {} angle steps, cam circumference {:.6g} m\n", c.name, m.omega_rad_per_s,
             r.rows.size(), r.cam_circumference_m);
  fmt::print("roller: periodic after {} revolutions, sliding at {} of {} angle steps\n", motion.revolutions,
             motion.sliding_steps, r.rows.size());
  fmt::print("dissipated per revolution {:.6g} J (mean {:.6g} W), peak {:.6g} W at cam angle {:.4g} deg\n",
             totals.energy_J, totals.energy_J * m.omega_rad_per_s / (2 * contact::kPi), totals.max_power_W,
             totals.max_power_theta_rad * cam::kDegPerRad);
  return setup;
}


}  // namespace

LifeRunEnd run_cam_life_in_folder(const LifeRunOptions& o) {
  const double cpu0 = cpu_seconds();
  const cam::CamCase c = cam::read_cam_case(o.case_path);
  if (!c.wear) {
    const auto it = c.locations.find("cam");
    throw contact::CaseError((it != c.locations.end() ? it->second : o.case_path) +
                             ": cam.wear: missing: `rollwear run` on a cam case needs the wear laws, revolutions and "
                             "limits (docs/cam-follower.md §13); `rollwear cam` runs one revolution without them");
  }
  const fs::path dir = output_directory(o.output_directory, c.output_directory, c.name);

  // one run in the folder at a time, as a wear case's; where the life starts (a checkpoint, refused unless it
  // is this case's, or the unworn state) checked before the revolution is set up, so that a refusal costs nothing
  const std::uint64_t fingerprint = cam_case_fingerprint(o.case_path);
  const LifeFolder folder({dir, o.case_path, "life.csv", fingerprint, o.resume, o.restart});

  // a signal before the life's first accepted step ends the process at once (a resumed run's checkpoint stays)
  interrupted::say_on_signal(o.resume ? folder.resume_line()
                                      : fmt::format("\nrollwear: interrupted before the life's first step; nothing to "
                                                    "resume: run rollwear run {} -o {}{} again\n", o.case_path,
                                                    dir.string(), o.restart ? " --restart" : ""));
  const std::unique_ptr<cam::CamLifeSetup> setup = set_up_life(c);
  if (!setup) return LifeRunEnd::Failed;
  const cam::CamLifeModel& life_model = setup->life;
  // the film, the flash temperature and the fatigue indicators over the unworn periodic revolution: the margins
  // beside the wear life
  cam::RevolutionLubrication lubrication;
  if (c.lubrication.any()) {
    lubrication = cam::revolution_lubrication(c.lubrication, setup->model, setup->revolution, setup->motion.motion,
                                              setup->dynamics.law);
    fmt::print("{}", cam::lubrication_summary(c.lubrication, lubrication));
  }

  std::string life_csv;
  cam::CamLifeStart start;
  if (o.resume) {
    start = from_checkpoint(folder.checkpoint());
    life_csv = folder.table_up_to(start.steps);  // rows after the checkpoint are written again
    spdlog::info("run: resuming at cam revolution {:.6g} (step {}) from {}", start.N, start.steps,
                 folder.checkpoint_path().string());
    if (start.producer_memory.empty() || start.rate.size() == 0)
      spdlog::warn("run: {} holds no warm starts (an earlier version's checkpoint): the worn contacts start cold, "
                   "and the resumed life may end elsewhere than the uninterrupted one would (docs/cam-follower.md §13)",
                   folder.checkpoint_path().string());
  } else {
    folder.start_afresh("(wear_map|roller_wear|damage_map|roller_damage)_[0-9]{4}\\.csv");
    life_csv = "# case: " + c.name + "\nstep,revolutions,max_depth_m,lift_loss_m,lift_loss_at_deg,energy_J" +
               (life_model.fatigue ? ",max_damage\n0,0,0,0,0,0,0\n" : "\n0,0,0,0,0,0\n");
  }
  fs::create_directories(dir / "snapshots");
  contact::write_files_atomic({{dir / "revolution.csv", cam::revolution_csv(setup->revolution)},
                               {dir / "dissipation.csv",
                                dissipation_csv(setup->revolution, setup->unworn, setup->motion.motion,
                                                c.lubrication, lubrication)}});

  // life.csv and the checkpoint are written together, life.csv renamed first: it never lags the checkpoint
  int snapshots = o.resume ? folder.checkpoint().snapshots_written : 0;
  const double earlier_cpu_s = o.resume ? folder.checkpoint().wall_s : 0;
  cam::CamLifeStart last;  // the last accepted step's end (x empty: none yet, nothing to checkpoint)
  const auto save = [&](std::vector<contact::OutputFile> files) {
    const wear::Checkpoint cp = to_checkpoint(fingerprint, last, snapshots, earlier_cpu_s + cpu_seconds() - cpu0);
    folder.save(std::move(files), life_csv, last.x.size() > 0 ? &cp : nullptr);
  };
  const auto is_snapshot_revolution = [&](double N) {
    return std::find(life_model.snapshots_revolutions.begin(), life_model.snapshots_revolutions.end(), N) !=
           life_model.snapshots_revolutions.end();
  };
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_save = Clock::now();
  cam::CamLifeHooks hooks;
  // the damage maps (cam.wear.fatigue) go with the wear maps of the same number, written just before them
  hooks.on_damage_snapshot = [&](double N, const cam::CamDamage& d) {
    contact::write_files_atomic(
        {{dir / snapshot_path("damage_map", snapshots), cam::damage_map_csv(life_model.grid, d, N, c.name)},
         {dir / snapshot_path("roller_damage", snapshots), cam::roller_damage_csv(life_model.grid, d, N, c.name)}});
  };
  hooks.on_snapshot = [&](double N, const cam::CamWearState& s) {
    std::vector<contact::OutputFile> files = {
        {dir / snapshot_path("wear_map", snapshots), cam::wear_map_csv(life_model.grid, s, N, c.name)},
        {dir / snapshot_path("roller_wear", snapshots), cam::roller_wear_csv(life_model.grid, s, N, c.name)}};
    ++snapshots;
    // a snapshot at a step's end (a snapshot revolution) goes with its checkpoint, which counts it; the
    // life's last one goes with the report
    if (N > 0 && last.x.size() > 0 && N == last.N && is_snapshot_revolution(N)) {
      save(std::move(files));
      last_save = Clock::now();
    } else {
      contact::write_files_atomic(files);
    }
  };
  // a row of life.csv: a step's end, or the life's end where a limit cut its last step short
  const auto append_row = [&](long step, double N, double max_depth_m, const cam::LiftLoss& lift_loss,
                              double energy_J, double max_damage) {
    fmt::format_to(std::back_inserter(life_csv), "{},{:.10g},{:.10g},{:.10g},{:.6g},{:.10g}", step, N, max_depth_m,
                   lift_loss.max_m, lift_loss.at_theta_rad * cam::kDegPerRad, energy_J);
    if (life_model.fatigue) fmt::format_to(std::back_inserter(life_csv), ",{:.10g}", max_damage);
    life_csv += "\n";
  };
  double last_row_N = o.resume ? start.N : 0;
  hooks.on_step = [&](const cam::CamLifeStep& step) {
    append_row(step.step, step.N, step.max_depth_m, step.lift_loss, step.energy_J, step.damage.value);
    last_row_N = step.N;
    last = step.resume;
    if (std::chrono::duration<double>(Clock::now() - last_save).count() >= c.wear->checkpoint_interval_s &&
        !is_snapshot_revolution(step.N)) {  // at a snapshot revolution the snapshot's save follows
      save({});
      last_save = Clock::now();
    }
    if (!o.quiet) spdlog::info("step {}: N {:.6g}, max depth {:.4g} m, lift loss {:.4g} m", step.step, step.N,
                               step.max_depth_m, step.lift_loss.max_m);
  };
  // Ctrl-C or SIGTERM during the life: the life stops after its current step (not at a snapshot revolution,
  // whose snapshot goes with that step's checkpoint), saves it, and the process ends as the wear run's does
  // on a signal, printing the --resume command; a second signal ends it at once
  hooks.stop_after = [&](const cam::CamLifeStep& step) {
    return interrupted::requested_signal() != 0 && !is_snapshot_revolution(step.N);
  };
  interrupted::defer_next_signal(
      "\nrollwear: interrupted; the life stops after its current step and saves it (a second signal stops at once)\n");
  const cam::CamLifeResult life = cam::run_cam_life(life_model, setup->producer(), hooks, start, setup->memory());
  interrupted::stop_deferring();
  if (life.ended_by == wear::LifeEnd::Stopped) {
    save({});
    spdlog::info("run: stopped after step {} at cam revolution {:.6g}; its state is saved in {}", last.steps, last.N,
                 folder.checkpoint_path().string());
    interrupted::end_by(interrupted::requested_signal());
  }

  // a limit located within a step ends the life between step ends (the step the report counts): its last row
  if (life.ended_by != wear::LifeEnd::Failed && life.N > last_row_N)
    append_row(life.steps, life.N, life.max_depth_m, life.lift_loss, life.energy_J, life.max_damage.value);

  // the end: life.csv and the report; the checkpoint goes (the run is complete) unless the life failed
  const std::string report = cam::cam_life_report_text(c.name, c.model.omega_rad_per_s, life, setup->worn->stats(),
                                                       o.resume, earlier_cpu_s + cpu_seconds() - cpu0) +
                             cam::cam_damage_report_text(life_model, life) +
                             cam::lubrication_report_text(c.lubrication, lubrication) +
                             cam::first_failure_text(c.lubrication, lubrication,
                                                     life.ended_by == wear::LifeEnd::MaxDepth ||
                                                         life.ended_by == wear::LifeEnd::LiftLoss,
                                                     wear::to_string(life.ended_by), life.N,
                                                     life.ended_by == wear::LifeEnd::Fatigue);
  if (life.ended_by == wear::LifeEnd::Failed && life.steps > 0 && last.x.size() > 0) {
    save({});  // the last accepted step: --resume continues from there (e.g. with other settings)
    spdlog::error("run: the life failed after step {}; its state is saved in {}", last.steps,
                  folder.checkpoint_path().string());
  }
  contact::write_files_atomic({{folder.table_path(), life_csv}, {dir / "report.txt", report}});
  if (life.ended_by != wear::LifeEnd::Failed) folder.remove_checkpoint();  // the run is complete
  fmt::print("{}", report);
  fmt::print("wrote {} (revolution.csv, dissipation.csv, life.csv, report.txt, {} wear maps in snapshots/)\n",
             dir.string(), snapshots);
  const bool failed = life.ended_by == wear::LifeEnd::Failed || life.ended_by == wear::LifeEnd::NotRun;
  if (failed) spdlog::error("the life failed: {}", life.message);
  return failed ? LifeRunEnd::Failed : LifeRunEnd::Ended;
}

LifeRunEnd run_life_in_folder(const LifeRunOptions& o) {
  return is_cam_case(o.case_path) ? run_cam_life_in_folder(o) : run_wear_life_in_folder(o);
}

}  // namespace session
