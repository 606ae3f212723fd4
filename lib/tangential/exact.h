// Kalker's exact theory of the tangential problem for quasi-identical bodies on the elastic
// half-space (docs/exact-theory.md): piecewise-constant tractions on the cells of a ContactPatch's
// grid, Cerruti's influence coefficients integrated over each rectangle in closed form, steady
// rolling with Coulomb friction and an unknown slip direction.
//
// Discrete steady problem (rolling speed V, material flowing from the leading edge x = +a to the
// trailing edge x = -a, docs/physics.md §1). On each cell i of the contact (normal pressure p > 0),
//   u = A tau                                   (displacement difference, every cell of the grid)
//   s_i / V = w_i + (u_i - u_(i+1)) / dx       (u_(i+1): the cell one dx upstream, towards x = +a)
//   w_i = ( xi_j - phi y_j ,  eta + phi x_i )   (rigid creepage; xi_j = xi + the strip's Heathcote offset)
//   |tau_i| <= mu p_i;  s_i = 0 (stick) or tau_i = -mu p_i s_i / |s_i| (slip).
// This is Kalker's steady discretisation: the rolled distance per "time step" is dx, so the previous
// displacement field is the current one shifted by one cell. Outside the contact tau = 0, but u is
// not: the grid is extended internally by one row of cells ahead of the leading edge so that the
// upstream displacement of the first contact cell is A tau too.
//
// Method (exact.cpp): the all-stick (linear) problem by GMRES with FFT products and a march as
// preconditioner; when its tractions exceed mu p somewhere, a semi-smooth Newton iteration on the
// stick and slip sets, each step one preconditioned GMRES solve.
// Convergence is judged on the fixed-point residual: with u = A tau fresh from a convolution, each
// contact cell's own Coulomb problem (all other tractions frozen) is solved, and
//   residual = max_i |tau_i(cell's own solve) - tau_i| / max_i max(|tau_i|, |tau_i(cell's own solve)|),
// converged when residual <= tol; at full stick, on GMRES's relative residual <= stick_tol. The
// status carries the number and the GMRES iterations (one FFT product each).
#pragma once

#include <Eigen/Core>

#include "lib/patch.h"
#include "lib/solve_status.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace contact {

// Surface displacement difference (both bodies, quasi-identical: shear modulus G and Poisson's
// ratio nu of docs/physics.md §1) at the offset (x, y) from the centre of a dx x dy rectangle that
// carries a unit uniform tangential traction, in m/Pa:
//   xx: u_x from tau_x,  yy: u_y from tau_y,  xy: u_x from tau_y = u_y from tau_x.
// Cerruti's point-force solution integrated in closed form (docs/exact-theory.md).
struct TangentialInfluence {
  double xx = 0, xy = 0, yy = 0;
};
TangentialInfluence cerruti_rectangle_influence(double x_m, double y_m, double dx_m, double dy_m, double G_Pa,
                                                double nu);

// The same in plane strain (two-dimensional: the cell a strip dx wide along x, infinitely long in y,
// docs/exact-theory.md §6): line loads on the half-plane of both bodies,
//   xx: -2 (1 - nu)/(pi G) I(x),  yy: -2/(pi G) I(x) (antiplane),  xy: 0,
//   I(x) = integral of ln|t| over [x - dx/2, x + dx/2]   (lengths in metres: the constant of the
// two-dimensional displacement, which rolling differences out, is the one of that unit).
TangentialInfluence line_load_influence(double x_m, double dx_m, double G_Pa, double nu);

struct ExactOptions {
  double tol = 1e-9;              // on the fixed-point residual above
  int max_iterations = 200;       // active-set iterations (each one GMRES solve on the stick cells)
  int max_stick_iterations = 20000;  // GMRES iterations (FFT products) over the whole solve
  double stick_tol = 1e-11;       // GMRES: relative residual of the all-stick solve (the linear theory);
                                  // later solves go to max(stick_tol, min(0.3, max(residual, tol/residual)))
  bool plane_strain = false;      // two-dimensional (Carter's problem): one strip (ny = 1) of infinite
                                  // width with line_load_influence; forces are those of the strip's dy
                                  // (the steady solve from 400 cells on starts from its own solution on
                                  // half the cells: grid sequencing, docs/exact-theory.md §6)
};

struct ExactSolution {
  TangentialSolution fields;  // tractions, slip, power, forces, as the fast solvers report them
                              // (strip_trailing_W_per_m is zero: no energy leaves with the material).
                              // The power is the trapezoidal one (docs/exact-theory.md §4, "Dissipation"):
                              // per cell D_i = -(tau_prev,i + tau_i)/2 . S_i/dt, tau_prev,i the previous
                              // traction of the material now at x_i (steady: tau_(i+1)), S_i its slip over
                              // the step with the rigid slip at its mid position; power_W_per_m2 holds it per
                              // cell (the release of the traction of material leaving the contact on the last
                              // cell it was in), strip_power_W_per_m per strip. In steady rolling its sum is the
                              // creep work -V (xi Fx + eta Fy + phi Mz) to rounding; over a rolling step by
                              // dq = dx it is the work of the creepages minus the change of the elastic energy.
                              // The slip fields are the solve's (Coulomb's law holds with them).
  Eigen::ArrayXXd u_x_m, u_y_m;  // ((nx + 1) x ny) displacement difference A tau at the cell centres,
                                 // the last row one cell ahead of the grid's leading edge
  Eigen::ArrayXd u_behind_x_m, u_behind_y_m;  // (ny) A tau one cell behind the grid's trailing edge (row -1):
                                              // computed when a traction lies on row 0 (the power of the
                                              // material leaving there, now or at the next step); else empty
  double grid_power_W = 0;                 // the solve's own product -sum tau . s dA (the upwind slip): it falls
  Eigen::ArrayXd grid_strip_power_W_per_m;  // short of the creep work at first order (docs/exact-theory.md §4)
  SolveStatus status;
  int stick_iterations = 0;       // GMRES iterations of the all-stick start
  int active_set_iterations = 0;  // after it (0: the all-stick solution was admissible)
  int products = 0;               // FFT products A tau over the whole solve (the main cost)
  Eigen::ArrayXXd dtau_x_Pa, dtau_y_Pa;  // ((nx + 1) x ny) the change of the tractions from the start a
                                         // warm-started solve was given (empty without one): the next
                                         // rolling step's first guess of its own change
};

// The patch on half the cells each way: 2 x 2 cells merged (their mean pressure, so the same load; the mean
// Heathcote offset of each pair of strips, exact for an offset linear in y). nx and ny even and at least 4,
// else std::invalid_argument. The fields of the semi-elliptic strips (half_length_m, strip_peak_Pa, the
// moment and edge pressures) are not carried: the exact theory reads the cell pressures only. The coarse grid
// of the grid sequencing below and of the grid extrapolation (grid_extrapolation.h).
ContactPatch halved_patch(const ContactPatch& patch);

// Steady rolling on the patch's grid. G_Pa, nu: combined constants (combined_shear_modulus_Pa,
// combined_poisson). mu > 0; speed_m_per_s >= 0 scales only the slip velocities and the power.
// A patch with a cell of non-finite or negative pressure, G <= 0, nu outside [0, 0.5), mu <= 0,
// non-finite creepages or options out of range: std::invalid_argument.
// An unconverged solve is returned with its status (MaxIterations or Failed) and a spdlog::warn;
// the caller decides. From 40 x 40 cells on (both even), a solve not converged within 12 Newton
// iterations from the all-stick start starts again from its own solution on half the cells each way
// (grid sequencing, docs/exact-theory.md §3); its status then counts the fine grid's last solve.
// start (optional): a previous steady solution on a grid of the same cell counts (nx x ny; otherwise it
// is not used), e.g. the last evaluation of a life on a slightly changed patch: the Newton iteration
// starts from its tractions (clipped to the new bound) and its stick and slip sets instead of the
// all-stick solve; when that has not converged within 3 Newton iterations the solve starts again cold
// (it pays on small changes: docs/exact-theory.md §5).
// The answer is the same to the tolerance (the problem is solved to the same fixed-point residual).
ExactSolution solve_exact_steady(const ContactPatch& patch, double G_Pa, double nu, const Creepages& creepages,
                                 double mu, double speed_m_per_s, const ExactOptions& opt = {},
                                 const ExactSolution* start = nullptr);

// One step of transient rolling by one cell, dq = dx (Kalker's transient discretisation): the
// previous step's displacement difference (previous->u_x_m, u_y_m; previous == nullptr: a start
// from rest, u = 0) has moved one cell downstream, so cell i sees the previous u of cell i + 1:
//   s_i / V = w_i + (u_i - u_prev,(i+1)) / dx,   u = A tau.
// Each step is a problem with the symmetric positive definite A (no transport inside the step);
// the same method solves it with a diagonal preconditioner, the Newton iteration starting from the
// previous step's tractions (a warm start; the patch and grid must be the previous step's).
// Steady rolling is its fixed point. solve_exact_roll below is the general step (dq <= dx).
ExactSolution solve_exact_rolling_step(const ContactPatch& patch, double G_Pa, double nu, const Creepages& creepages,
                                       double mu, double speed_m_per_s, const ExactSolution* previous,
                                       const ExactOptions& opt = {});

// One step of transient rolling over the rolled distance dq_m in [0, dx] taking dt_s > 0. The
// material now at cell i was at x_i + dq at the previous step: the previous displacement difference
// there is interpolated linearly between cells i and i + 1 (theta = dq/dx), and the slip over the step
//   S_i = w_i dq + u_i - u_prev(x_i + dq),   u = A tau,
// obeys Coulomb's law; the slip velocities reported are S/dt, the creep work (dq/dt)(xi Fx + eta Fy +
// phi Mz). dq = dx is solve_exact_rolling_step at V = dx/dt (the same numbers: theta = 1 takes cell
// i + 1 exactly); dq = 0 (V = 0) is a standing contact: no rigid slip, the previous field held, only
// a change of the load or the bound moves the tractions. Linear interpolation is first order: the
// step converges to the dq = dx one as the grid is refined (docs/exact-theory.md).
ExactSolution solve_exact_roll(const ContactPatch& patch, double G_Pa, double nu, const Creepages& creepages,
                               double mu, double dq_m, double dt_s, const ExactSolution* previous,
                               const ExactOptions& opt = {});

// The 'transient' run of a case with the exact theory (solver.tangential: exact): the steps of
// Satran's shift scheme (dq = dx, shortened to the longest step dt_s or to land on t_end_s, the
// creepages and speed at mid-step, the contact at the step's end), each one solve_exact_roll from
// the previous step's solution. The grid is the one of the largest load (or c.patch's) and stays:
// a changing load changes the cells in contact on it and their bound, the carried displacement is
// on the same cells, so nothing is re-mapped. Records hold the step's end values; the balance
// residual is nan (the half-space stores elastic energy outside the contact, no discrete balance
// is defined). No inertia, scheme shift only (SettingError otherwise, as run_transient's);
// an unconverged step throws std::runtime_error with its status. final_state is left at rest.
// Its steps' tolerance: tol 1e-6 on the fixed-point residual, the linear solves to 1e-8 (the
// rolling step's forces are within 1e-8 of the step solved to 1e-12 already at tol 1e-4,
// docs/exact-theory.md §5; the steady default 1e-9 would cost 2.5x the time per step).
ExactOptions exact_run_options();
// A wear life's duty cycle (settings.skip_steady): tol 1e-4 on the fixed-point residual, the linear solves to
// 1e-4. The start-stop duty cycle of cases/start-stop-wear.yaml dissipates within 2e-6 (20 x 20) and 7e-8
// (40 x 40) of its energy with exact_run_options(), in half the time (docs/exact-theory.md §7).
ExactOptions exact_duty_cycle_options();
// settings.skip_steady: once the creepages and the load have stayed the same over 2a of rolling (nx whole steps)
// and the last step's tractions are within 1e-3 mu p_max of the steady solution of those inputs (solved once
// per stretch), or within 1e-2 once a step no longer changes them (the steps stopped within their tolerance),
// the rest of the stretch is that solution's power times its duration, and the state after it that solution
// (run_shift_steps' skip, lib/tangential/shift_run.h).
TransientResult run_exact_transient(const TransientCase& c, const StepObserver& observe = {},
                                    const ExactOptions& opt = exact_run_options());

// Shift (no rolling): the bodies' rigid shift (shift_x_m, shift_y_m) of body 1 over body 2 during
// a time step dt_s, from the previous state (previous == nullptr: from rest). Per cell the slip
// over the step is S_i = shift + u_i - u_prev,i (no transport), with Coulomb's law on S; the slip
// velocities reported are S/dt, the creep work V (xi Fx + eta Fy) is (shift . F)/dt.
// Loaded monotonically from rest this is the Cattaneo-Mindlin problem.
ExactSolution solve_exact_shift(const ContactPatch& patch, double G_Pa, double nu, double shift_x_m, double shift_y_m,
                                double mu, double dt_s, const ExactSolution* previous, const ExactOptions& opt = {});

// Shift with a prescribed total tangential force (Fx_N, Fy_N) on body 1 instead of the rigid shift:
// the shift that gives it, found by an outer iteration on the shift solve (each evaluation one shift
// solve, warm-started from the last one's tractions): Broyden's method on
// T(F) = (1 - (1 - |F|/(mu Fn))^(2/3)) F/|F|, which Mindlin's relation makes linear in the shift for
// a circle at nu = 0 (T = -shift/scale, scale = 3 mu Fn (2 - nu)/(8 G sqrt(ab))) and close to it
// otherwise, from the Jacobian -I/scale, a step halved back when it does not reduce |F - F_target|.
// It finds both components when x and y are coupled (nu > 0 on an ellipse), and a shift back when
// the target unloads from the previous state. |F_target| must be below the grid's mu sum(p dA) (at
// it every shift beyond gross sliding gives the same force: std::invalid_argument).
// force_tol_N (0: 1e-8 mu Fn) bounds |F - F_target|; not reached within 40 shift solves: status
// MaxIterations with the best evaluation (and a spdlog::warn); a shift solve that fails: its status.
struct ExactShiftForce {
  ExactSolution solution;            // the shift solve at the shift found
  double shift_x_m = 0, shift_y_m = 0;  // the rigid shift of body 1 over body 2 over the step
  int shift_solves = 0;              // solve_exact_shift evaluations
};
ExactShiftForce solve_exact_shift_force(const ContactPatch& patch, double G_Pa, double nu, double Fx_N, double Fy_N,
                                        double mu, double dt_s, const ExactSolution* previous,
                                        const ExactOptions& opt = {}, double force_tol_N = 0);

}  // namespace contact
