// The quasi-steady dissipation of the periodic revolution on worn states, evaluated again and again over a
// cam's life (docs/cam-follower.md §12, §15): the same result as worn_revolution_dissipation
// (cam/cam_life.h) at each angle, made cheaper by keeping what does not change between evaluations.
//   - Made once: per angle step the cam's radius, the motion's loads and speeds (held at the unworn
//     revolution's, as the life assumes), the arc cells and weights the contact's arc falls between; per
//     profile node its lateral cells and weights; the strips' fixed extent.
//   - Per evaluation: the roller's worn profile once (it is the same at every angle); the track's rows
//     interpolated to the track's nodes once per arc cell used.
//   - Angles that share a contact are solved once: where an angle step's inputs (cam radius, normal and
//     tangential load, speeds, the roller's motion) equal the last solved step's to kSameInputRtol and its
//     worn track profile equals that step's within the approach's tolerance (below), its contact,
//     creepage and strip powers are that step's (on the dwells every step of the base circle meets the
//     same worn track, to within the solves' own noise). The error this admits is below what the normal
//     solve resolves.
//   - Warm starts: each angle's semi-Hertzian search starts from its approach at the last evaluation, and
//     the creep law's inversion searches around its last creepage: fewer evaluations of F(delta) and of
//     the steady law for the same tolerances (SemiHertzOptions::load_rtol, kCreepForceRtol); the search's
//     first step takes the angle's last slope d ln F / d ln delta (SemiHertzOptions::initial_slope). Where
//     F(delta) crosses the load once, the result differs from a cold start only within those tolerances;
//     where it crosses more than once (worn gaps), the warm search may keep another root than the cold one
//     (measured in docs/cam-follower.md §15). A warm-started solve that does not converge is solved again
//     from the solver's own start.
//   - The skip (WornRevolutionOptions::skip_stride > 1; cam.wear.skip): only every stride-th angle step is
//     computed at first; the steps between two computed ones are interpolated (strip powers, pressures and
//     the next evaluation's warm starts linear in the angle step) where the two's strip powers agree to
//     skip_power_rtol of the largest, otherwise the middle step is computed and each half looked at again.
//     Its error against every step solved is measured in docs/cam-follower.md §15.
// Not thread-safe (the warm starts are state); one per life.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "cam/cam_wear.h"
#include "cam/creep_law.h"
#include "cam/revolution.h"
#include "cam/revolution_dissipation.h"
#include "cam/roller_motion.h"
#include "lib/normal/profile.h"

namespace cam {

// two angle steps' inputs are the same contact when their cam radius, loads and speeds agree to this
// (relative): rounding in the kinematics of a dwell, never a real change of the rise or return
constexpr double kSameInputRtol = 1e-12;
// ... and their worn track profiles agree to within what the normal solve resolves: the approach's own
// tolerance, SemiHertzOptions::load_rtol times the solved step's approach (F ~ delta^(3/2), so delta is
// found to about 2/3 of that): a difference of the track's depth below it changes the contact less than
// the solve's root finding does. (On a dwell the worn rows differ by some 1e-9 of the deepest wear, the
// dissipation's own noise at that tolerance fed back through the wear.)
struct WornRevolutionStats {
  long evaluations = 0;            // worn revolutions evaluated
  long same_input_angles = 0;      // angle steps whose inputs equal the step before's (the dwells)
  long angles = 0;                 // angle steps over them
  long contacts_solved = 0;        // normal solves (the rest reused a shared contact)
  long approach_evaluations = 0;   // F(delta) evaluations of the semi-Hertzian searches
  long creep_evaluations = 0;      // steady solves of the creep law's inversions
  long cold_retries = 0;           // warm-started normal solves that did not converge, solved again cold
  long interpolated_angles = 0;    // angle steps the skip interpolated (of `angles`)
};

struct WornRevolutionOptions {
  bool share_contacts = true;  // solve angles that share a contact once
  bool warm_start = true;      // start each angle's searches from its last evaluation's
  bool warm_slope = true;      // ... the semi-Hertzian one's first step with its last slope (false: Hertz's 3/2)
  // The skip (docs/cam-follower.md §15): every skip_stride-th angle step computed (solved or shared); between
  // two computed steps whose strip powers differ by at most skip_power_rtol of the revolution's largest strip
  // power the steps are interpolated (strip powers and pressures linear in the angle step), otherwise the
  // middle step is computed and each half looked at again. 1: every angle step computed.
  int skip_stride = 1;
  double skip_power_rtol = 0.01;
};

class WornRevolution {
 public:
  // m, r, motion, unworn, g as worn_revolution_dissipation takes them (copied: the object stands alone)
  WornRevolution(const CamModel& m, const Revolution& r, const RollerMotion& motion, const contact::Profiles& unworn,
                 const CamWearGrid& g, const CreepLawSettings& law, WornRevolutionOptions options = {});

  // the dissipation on state s; throws what the solvers throw
  RevolutionDissipation operator()(const CamWearState& s);

  const WornRevolutionStats& stats() const { return stats_; }

  // What an evaluation leaves to the next: per angle step its warm starts (the approach, the slope, the
  // creepage and whether it has one) and the statistics so far, as numbers (kMemoryHead statistics, then
  // kMemoryPerAngle per angle step). Everything else the evaluator keeps is made once or within an
  // evaluation, so an evaluator restored with another's memory evaluates as that one would, to the bit: a
  // resumed life's checkpoint holds it (docs/cam-follower.md §13, "Checkpoint and resume"). restore throws
  // std::invalid_argument for a memory of another size (another revolution's).
  std::vector<double> memory() const;
  void restore(const std::vector<double>& memory);
  static constexpr std::size_t kMemoryHead = 8, kMemoryPerAngle = 4;

 private:
  struct Angle {
    RevolutionRow row;
    RollerAngle roller;
    double cam_radius_m = 0;
    int a0 = 0, a1 = 0;  // the arc cells the contact's arc lies between, and the weight of a1
    double wa = 0;
    bool same_inputs_as_previous = false;  // kinematics and motion equal to step k-1's (kSameInputRtol)
    double approach_m = 0;                 // the last evaluation's (0: none yet)
    double approach_slope = 0;             // d ln F / d ln delta there (SemiHertzResult::approach_slope)
    double xi = 0;                         // the last evaluation's creepage
    bool xi_known = false;
  };
  struct NodeWeights {
    Eigen::ArrayXi l0, l1;
    Eigen::ArrayXd wl;
  };

  const Eigen::ArrayXd& track_row_at_nodes(int arc_cell, const CamWearState& s);

  CamModel model_;
  contact::Profiles unworn_;
  CamWearGrid grid_;
  CreepLawSettings law_;
  WornRevolutionOptions options_;
  double duration_s_ = 0;
  std::vector<Angle> angles_;
  NodeWeights roller_nodes_, track_nodes_;
  // per arc cell, its row of depths at the track's nodes, made at most once per evaluation
  std::vector<Eigen::ArrayXd> track_rows_;
  std::vector<long> track_row_made_;
  // per angle, the worn track profile at its nodes when it was last solved (what shares compare with)
  std::vector<Eigen::ArrayXd> solved_track_z_;
  WornRevolutionStats stats_;
};

}  // namespace cam
