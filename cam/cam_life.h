// The cam's life in cam revolutions (docs/cam-follower.md §12): the worn depths of the track's map and of
// the roller (cam/cam_wear.h) obey dh/dN = f(h), N the cam revolutions,
//   f(h): worn profiles at each angle (worn_profiles_at) -> the periodic revolution's dissipation (the
//         caller's producer, DissipationOf) -> wear_per_revolution -> smoothed across the width (the wear
//         loop's volume-conserving Gaussian filter, wear/profile_update.h, on the lateral cells' centres:
//         wear features narrower than the cut-off are not kept, as running-in and debris spread them),
// integrated by the one life driver (wear/life.h: the project's integrator, adaptive ARKODE or fixed steps with
// their stability control; the case's stepping keys are a wear case's) until a limit ends the life:
//   max_depth      the deepest wear of either body reaches max_depth_m;
//   lift_loss      the follower's lift has dropped by max_lift_loss_m at some cam angle.
//   fatigue        with the model's fatigue (cam/cam_damage.h), the largest damage of a track cell or a roller
//                  cell reaches 1 (max D - 1).
// Each is a signed, continuous function of the state (g < 0 inside the life), handed to the driver as its
// limits, as the roller's wear loop hands its own: it locates them on the integrator's dense output
// (adaptive) or its step's line (fixed).
//
// The lift loss. The roller's centre is the cam surface's offset by R_r along the contact normal n, which
// makes the pressure angle phi with the follower's axis. Wear lowers the bodies' unloaded surfaces under
// the contact by delta (normal_recession_m: the cam's and the roller's depths at the point of closest
// approach across the width), so the pitch curve moves inwards by delta along n. The follower keeps its
// axis: its centre moves along the axis by the Delta d whose component along n is delta,
//   Delta d cos phi = delta   ->   lift loss = delta / cos phi,
// to first order in delta / rho (the pitch curve's tangential shift moves the contact point along the
// curve, a second-order change of d). The elastic approach is the unworn one's (the load changes by
// k Delta d, a relative change of k delta / F of order 1e-3 here: 0.4 N of 150 N at a 20 um lift loss). The lift-loss limit reads the largest
// loss over the revolution's angle steps.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cam/cam_damage.h"
#include "cam/cam_wear.h"
#include "cam/revolution.h"
#include "cam/roller_dynamics.h"
#include "cam/worn_revolution.h"
#include "lib/normal/profile.h"
#include "wear/integrator.h"
#include "wear/life.h"
#include "wear/wear_case.h"

namespace cam {


// where the lift loss is read: the cam angle, the contact's arc on the cam there, the pressure angle
struct LiftLossSample {
  double theta_rad = 0;
  double arc_m = 0;
  double pressure_angle_rad = 0;
};
// one sample per angle step of a complete revolution (its rows' theta, contact_arc_m and phi)
std::vector<LiftLossSample> lift_loss_samples(const Revolution& r);

struct LiftLoss {
  double max_m = 0;         // the largest loss over the samples
  double at_theta_rad = 0;  // where
};
// delta / cos phi at each sample, and its largest
Eigen::ArrayXd lift_loss_m(const contact::Profiles& unworn, const CamWearGrid& g, const CamWearState& s,
                           const std::vector<LiftLossSample>& samples);
LiftLoss max_lift_loss(const contact::Profiles& unworn, const CamWearGrid& g, const CamWearState& s,
                       const std::vector<LiftLossSample>& samples);

// max_lift_loss made once for a grid and samples, then evaluated on many states (the life's limit is
// probed at every step and root iteration): the profiles' nodes, their unworn gap and lateral weights, and
// the samples' arc weights kept; the same arithmetic, so the same result to the bit.
class LiftLossProbe {
 public:
  LiftLossProbe(const contact::Profiles& unworn, const CamWearGrid& g, std::vector<LiftLossSample> samples);
  LiftLoss operator()(const CamWearState& s) const;

 private:
  struct Weights {
    int c0 = 0, c1 = 0;
    double w1 = 0;
  };
  CamWearGrid grid_;
  std::vector<LiftLossSample> samples_;
  std::vector<Weights> sample_arc_;             // per sample, its arc cells
  std::vector<double> gap0_;                    // per roller node in the overlap: the unworn gap
  std::vector<Weights> roller_lat_, track_lat_; // ... its lateral cells on the roller's and the track's grid
  double gap0_min_ = 0;
};

// the periodic revolution's dissipation on the worn geometry (what the revolution's tangential solve
// makes, with worn_profiles_at at each angle); may throw
using DissipationOf = std::function<RevolutionDissipation(const CamWearState& worn)>;

// The quasi-steady dissipation (cam/revolution_dissipation.h) on the worn geometry: at each angle step the
// contact on worn_profiles_at(unworn, g, s, the row's arc) under the motion's normal load, the roller's
// creepage the one that gives the motion's creep force F_t on that contact (the force is what the roller's
// inertia and bearing ask for, which wear does not change; where the law cannot give it, the motion's
// creepage), and the steady solution's strip powers. The unworn state gives the producer's own result.
// The worn contacts' strips: over the profiles' lateral overlap, fixed for the life, a whole number of strips
// per roller cell (the lateral cells), each no wider than max_strip_m (0: one per cell; the life gives the
// unworn revolution's narrowest 2 b / ny, the law's resolution of the unworn contact), so that a lobe of contact entering or leaving changes the strips'
// sums continuously (with the strips over the contact's own extent every strip moved, and the
// revolution's dissipation jumped by up to 17 % at an angle for a 1e-4 change of the depths:
// docs/cam-follower.md §14). And never Hertz's closed form (CreepLawSettings::worn): a worn profile that still
// fits a constant curvature would switch the solver, and the rate would jump by up to 2e-3 where it stops fitting.
CreepLawSettings worn_contact_settings(const contact::Profiles& unworn, const CamWearGrid& g, CreepLawSettings law,
                                       double max_strip_m = 0);

RevolutionDissipation worn_revolution_dissipation(const CamModel& m, const Revolution& r, const RollerMotion& motion,
                                                  const contact::Profiles& unworn, const CamWearGrid& g,
                                                  const CamWearState& s, const CreepLawSettings& law);

struct CamLifeModel {
  std::string name;
  CamWearGrid grid;
  CamWearLaws laws;
  contact::Profiles unworn;                // roller (body 1) and track (body 2), unworn
  std::vector<LiftLossSample> samples;     // the lift-loss limit's
  double revolutions = 0;                  // the budget
  double max_depth_m = 0;                  // 0 = no such limit
  double max_lift_loss_m = 0;              // 0 = no such limit
  wear::WearStepping stepping;
  wear::IntegratorOptions::Scheme scheme = wear::IntegratorOptions::Scheme::Euler;  // the fixed steps' update
  double smoothing_wavelength_m = 0;       // the rate's lateral filter on each arc cell's row and the roller's
  std::vector<double> snapshots_revolutions;  // increasing, in (0, revolutions]
  // the track's and the roller's fatigue damage (cam/cam_damage.h, docs/cam-follower.md §19): integrated with
  // the depths, stored as D damage_scale_m (the depth limit, or 1e-4 m without one: the integrator's tolerances
  // and a fixed-depth step weigh damage 1 as the depth limit), the life ending where its largest reaches 1
  std::optional<wear::FatigueSection> fatigue;
  double damage_scale_m = 1e-4;
};

// the model of a case's wear: section (spec) on the grid of its unworn revolution (the circumference and
// the angles its steps sweep, rev the unworn revolution's dissipation)
CamLifeModel make_cam_life_model(const std::string& name, const CamWearSpec& spec, double mu,
                                 const contact::Profiles& unworn, double roller_radius_m,
                                 double circumference_m, const RevolutionDissipation& rev,
                                 std::vector<LiftLossSample> samples);

// A producer with a memory (WornRevolution's warm starts: what one evaluation leaves to the next), as numbers:
// save gives it, restore puts it back. Both empty: a producer without one (a function of the state alone).
struct ProducerMemory {
  std::function<std::vector<double>()> save;
  std::function<void(const std::vector<double>&)> restore;
};

// Where a life starts: the unworn state (x empty, the default), or an accepted step's end saved by a
// checkpoint (CamLifeStep::resume; docs/cam-follower.md §13, "Checkpoint and resume"). It holds everything
// run_cam_life and its producer carry from step to step: a fixed-stepping life resumed from it repeats the
// uninterrupted one's arithmetic, to the bit.
struct CamLifeStart {
  double N = 0;
  Eigen::VectorXd x;          // the integrated state: track map (column-major) | roller | scaled energy
  double energy_scale = 0;    // e = E energy_scale, fixed by the unworn revolution's rate
  double next_step = 0;       // adaptive: the step ARKODE would have tried next (0: its estimate)
  long steps = 0, rejected = 0, rhs_evals = 0, revolutions_solved = 0;  // the life's so far
  // the rate at x as the step evaluated it (the next step's slope; sized as x), empty: evaluated again. With a
  // producer that has a memory it is not a function of x alone, and evaluating it again would move the memory
  Eigen::VectorXd rate;
  std::vector<double> producer_memory;  // the producer's memory after that evaluation (ProducerMemory::save)
};

struct CamLifeStep {
  long step = 0;
  double N = 0;
  const CamWearState* state = nullptr;
  double max_depth_m = 0;
  LiftLoss lift_loss;
  double energy_J = 0;  // dissipated since N = 0
  CamDamageMax damage;  // with the model's fatigue: the largest damage and where (else value 0)
  CamLifeStart resume;  // the start that continues the life from this step's end (a checkpoint's content)
};

struct CamLifeHooks {
  std::function<void(const CamLifeStep&)> on_step;                          // after each accepted step
  std::function<void(double N, const CamWearState& state)> on_snapshot;     // at 0, each snapshot, the end
  // with the model's fatigue: the damage there, called just before on_snapshot with the same N
  std::function<void(double N, const CamDamage& damage)> on_damage_snapshot;
  // after on_step: true ends the life there, wear::LifeEnd::Stopped, with no end snapshot (a kill's state)
  std::function<bool(const CamLifeStep&)> stop_after;
};

struct CamLifeResult {
  wear::LifeEnd ended_by = wear::LifeEnd::NotRun;  // the cam's limits: MaxDepth, LiftLoss, Fatigue
  wear::LifeFailure failure = wear::LifeFailure::None;
  std::string message;
  double N = 0;
  CamWearState state;
  double max_depth_m = 0;
  LiftLoss lift_loss;
  double energy_J = 0;             // dissipated over the life
  double cam_volume_m3 = 0;        // worn from the track: sum of cell depth x cell area
  double roller_volume_m3 = 0;     // worn from the roller: 2 pi R_r x its worn area
  // with the model's fatigue: the damage at the end, its largest and where, and the end's largest strip T-gamma
  CamDamage damage;
  CamDamageMax max_damage;
  double max_tgamma_N = 0, max_tgamma_at_rad = 0;
  long steps = 0, rejected = 0, rhs_evals = 0;
  long revolutions_solved = 0;     // calls of the dissipation producer
};

// Integrates from the unworn state (or start: no snapshot at 0 then, the snapshots after start.N only) to the
// first limit (located) or the budget. memory: the producer's, saved into each step's CamLifeStart and restored
// from start's. Throws std::invalid_argument for a bad model or a start of another size (its rate or its
// producer's memory included); an exception of the producer or the integrator's failure ends the life Failed
// with its message (the state the last accepted step's).
CamLifeResult run_cam_life(const CamLifeModel& m, const DissipationOf& dissipation, const CamLifeHooks& hooks = {},
                           const CamLifeStart& start = {}, const ProducerMemory& memory = {});

// The life's report (report.txt, and printed): the keys every life writes (wear::life_report_text, its numbers
// to 6 digits), then the cam's own: speed_rad_per_s, lift_loss_m, lift_loss_at_deg, worn_volume_track_m3,
// worn_volume_roller_m3, revolutions_solved, and the worn revolutions' work (worn_angle_steps,
// interpolated_angle_steps, normal_solves, approach_evaluations, creep_evaluations, cold_retries), cpu_s
std::string cam_life_report_text(const std::string& case_name, double omega_rad_per_s, const CamLifeResult& life,
                                 const WornRevolutionStats& worn, bool resumed, double cpu_s);

// with the model's fatigue, the lines report.txt adds after cam_life_report_text's (docs/cam-follower.md §19):
// fatigue_law, max_damage, max_damage_body, max_damage_at_deg, max_damage_arc_m, max_damage_y_m, max_tgamma_N,
// max_tgamma_at_deg; "" without
std::string cam_damage_report_text(const CamLifeModel& m, const CamLifeResult& life);

// A case's life, set up: the unworn revolution (status Jump: nothing else is set), the roller's periodic
// motion, the unworn quasi-steady dissipation (the same producer as on the worn geometry, so that the rate
// is continuous at the unworn state: Satran along the revolution, §9, needs Hertz's profiles), the life's model, and the producer of the dissipation on a worn state
// (worn_revolution_dissipation with this revolution and motion, evaluated by one WornRevolution,
// cam/worn_revolution.h, shared by the producers made: its warm starts and shared contacts; the unworn state
// gives `unworn` itself). Held by pointer: the producer refers to it.
struct CamLifeSetup {
  CamModel model;
  Revolution revolution;
  RollerDynamicsSettings dynamics;
  PeriodicMotion motion;
  contact::Profiles unworn_profiles;
  RevolutionDissipation unworn;
  CamLifeModel life;
  std::shared_ptr<WornRevolution> worn;  // the producer's evaluator (its statistics: worn->stats())
  DissipationOf producer() const;
  ProducerMemory memory() const;         // the evaluator's (WornRevolution::memory, restore)
};
// Throws CamError for a design the model refuses (the caller places it in the case), std::runtime_error
// when the roller's motion is not periodic, and what the solvers throw.
// dynamics: the roller's spin and the creep law's grid (from the case's cam.tangential, as rollwear cam's)
std::unique_ptr<CamLifeSetup> set_up_cam_life(const std::string& name, const CamModel& model, const CamWearSpec& spec,
                                              const RollerDynamicsSettings& dynamics = {});

// the state's worn volumes
double cam_worn_volume_m3(const CamWearGrid& g, const CamWearState& s);
double roller_worn_volume_m3(const CamWearGrid& g, const CamWearState& s);

}  // namespace cam
