// The time stepping of a transient run by the shift scheme's steps, shared by the runs that solve one
// step at a time on the run's grid: Kalker's exact theory (exact.h, run_exact_transient) and the relaxed
// model (relaxed.h, run_relaxed_transient). Each step rolls dx, or less when the longest step (dt_s) or
// the end comes first, or nothing at V = 0 (a standing step); the creepages and the speed are taken at
// the step's middle, the load (and with it the contact) at its end, as Satran's runs do. The caller checks
// its own settings before (a run on a given patch with a load other than the patch's is refused here); this writes the records, the strip energies, the snapshots and the run's end.
#pragma once

#include <functional>

#include "lib/patch.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace contact {

struct ShiftStep {
  int step = 0;                // 1, 2, ...
  double t_s = 0, dt_s = 0;    // the step's start and duration
  double dq_m = 0;             // the distance it rolls, 0 <= dq <= dx
  double speed_m_per_s = 0;    // at the step's middle
  Creepages creepages;         // at the step's middle
  double normal_load_N = 0;    // at the step's end
  bool fields = false;         // a snapshot is still to come: the per-cell fields are read
};

// the step's solution on a patch with some cell in contact
using ShiftStepSolve = std::function<TangentialSolution(const ContactPatch& patch, const ShiftStep& step)>;

// Steady running skipped (settings.skip_steady), for a solver whose state settles to a steady one: after a
// whole step (dq = dx) in contact whose inputs were constant over it, when `settled()` says the solver's state
// is the steady one of those inputs (to the solver's own tolerance), the rest of the constant stretch (whole
// steps, up to one step before the next change of an input, snapshot time or t_end_s, as Satran's skip) is one
// record with the last step's strip powers times its duration; `skipped(rolled_m)` then advances the solver's
// state over the distance the stretch rolls. Unset: no step is skipped.
// `energy` (if set) gives the stretch's strip energies (J/m) and energy (J) over span_s rolling rolled_m from the
// last step's solution, in place of that step's powers times span_s (a solver whose state still relaxes).
struct ShiftSkip {
  std::function<bool()> settled;
  std::function<void(double rolled_m)> skipped;
  std::function<void(double span_s, double rolled_m, const TangentialSolution& last, Eigen::ArrayXd& strip_J_per_m,
                     double& J)>
      energy;
};

// Runs c by the shift scheme's steps; `solve` is called for every step with contact, `no_contact` (if
// set) for every step without, with the run's grid (a solver that carries the previous step forgets it there).
TransientResult run_shift_steps(const TransientCase& c, const StepObserver& observe, const ShiftStepSolve& solve,
                                const std::function<void(const Grid&)>& no_contact = {}, const ShiftSkip& skip = {});

// Adds a step's solution f, which ended at t_s after dt_s, to the run's result as run_shift_steps does: the strip
// energies and the energy, the observer's call with rec, and the snapshots (sorted times) due by t_s, from
// next_snap on (advanced past them). Shared with the relaxed model's inertia run (relaxed.h).
void add_shift_step(TransientResult& res, const TransientRecord& rec, const TangentialSolution& f,
                    const ContactPatch& patch, double dt_s, double t_s, const std::vector<double>& snapshots_s,
                    std::size_t& next_snap, const StepObserver& observe);

// the contact at load F on the run's grid, as the steps of run_shift_steps see it: c.patch if given, else
// Hertz's ellipse from the bodies (a patch without pressure at F = 0 or when no strip centre is in contact)
ContactPatch shift_run_contact(const TransientCase& c, const Grid& grid, double F);

// the run's grid: c.patch's, else the one covering Hertz's contact at the largest load
Grid shift_run_grid(const TransientCase& c);

// no cell in contact: every field and strip total zero on the grid
TangentialSolution no_contact_solution(const Grid& g);

}  // namespace contact
