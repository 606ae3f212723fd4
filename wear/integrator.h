// Time integration of the worn depth in revolutions (docs/integrator.md): dh/dN = f(N, h), h the
// worn depth at fixed lateral nodes (n, m), N the revolutions of the worn body.
//
// Adaptive: SUNDIALS ARKODE, ERKStep, an explicit embedded Runge-Kutta pair. The default is
// Bogacki-Shampine 3(2): 3 evaluations of f per step (FSAL) for an RHS that costs a contact solve,
// third order for loose tolerances, and an error estimate that stays honest where f is only
// piecewise smooth. ARKODE picks each step from its error estimate against rtol |h_i| + atol, and
// locates roots of g(N, h) (the lifetime limits) on its dense output.
//
// Fixed (the literature's stepping, kept for comparison): explicit Euler, h += dN f(N, h), with
//   FixedDepth  dN = max_depth_step / max_i |f_i|  (each update wears at most max_depth_step), or
//   FixedStep   dN = fixed_step,
// and a stability control: a step is halved (and counted as rejected) until f exists at its end and
// changes over it by at most the larger max_i |f_i| of its two ends (lambda dN >= -1: no
// oscillation), so that a far too large step is refused rather than wearing an absurd profile.
// The Euler solution is linear in N over a step, so a root of g on it is located exactly (to
// rounding) by regula falsi on that line: no further RHS evaluations.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

namespace wear {

// dh/dN (n, m per revolution) at revolution N and worn depth h (n, m). dhdN arrives sized n and
// filled with NaN, so a component left unset is caught. May throw: the exception surfaces from
// integrate() nested in one that names N.
using Rhs = std::function<void(double N, const Eigen::VectorXd& h_m, Eigen::VectorXd& dhdN_m)>;

// Event functions g_k(N, h), k < n_roots (g arrives sized n_roots, NaN-filled). A sign change of g_k
// (or g_k reaching 0 from either side) is an event; a g_k that is 0 at N0 is watched once it leaves 0.
using Roots = std::function<void(double N, const Eigen::VectorXd& h_m, Eigen::VectorXd& g)>;

struct IntegratorOptions {
  enum class Method {
    Adaptive,    // ARKODE ERKStep, steps from the embedded error estimate
    FixedDepth,  // explicit Euler, dN = max_depth_step / max |dh/dN|
    FixedStep,   // explicit Euler, dN = fixed_step
  } method = Method::Adaptive;
  double rtol = 1e-3;             // Adaptive: relative tolerance
  double atol = 1e-9;             // Adaptive: absolute tolerance, m (> 0: h starts at 0). The fixed
                                  // modes use rtol and atol only to weigh their error estimate
  // FixedDepth and FixedStep: the update. Euler is the wear loop's (and the default); Heun's is offered for
  // the cam's life (cam.wear.stepping.scheme, docs/cam-follower.md §15), whose Euler steps converge slowly:
  //   Heun  explicit trapezoid, h + (dN/2) (f(h) + f(h + dN f(h))): second order for a smooth rate, two
  //         evaluations per step, no history. It keeps the step control and its stability test (on the
  //         rate at Euler's predictor) and locates a root on its quadratic continuous extension
  //         h + dN (s f(h) + (s^2/2) (f(h + dN f(h)) - f(h))), s in [0, 1].
  enum class Scheme { Euler, Heun } scheme = Scheme::Euler;
  double max_depth_step = 1e-4;   // FixedDepth: max |dh| per update, m
  double fixed_step = 0;          // FixedStep: revolutions per update
  double initial_step = 0;        // Adaptive: first step, revolutions; 0 = ARKODE's estimate. On
                                  // resume, StepInfo::next_step (or ::step) of the checkpoint
  double max_step = 0;            // Adaptive and FixedDepth: revolutions; 0 = none
  long max_steps = 100000;        // accepted steps per call; then Kind::MaxSteps
  int table = -1;                 // Adaptive: ARKODE_ERKTableID; -1 = ARKODE_BOGACKI_SHAMPINE_4_2_3.
                                  // Refused: no embedding, or c_s = 1 without FSAL (SUNDIALS < 6.7.0
                                  // reuses a stale stage for those)
};

// one accepted step, as reported to on_step; counters are cumulative over this call of integrate()
struct StepInfo {
  double N = 0;                // revolutions at the end of the step
  double step = 0;             // revolutions in this step
  double next_step = 0;        // Adaptive: the step ARKODE will attempt next (resume with it);
                               // fixed modes: the step just taken
  double error_estimate = 0;   // WRMS norm of the local error estimate with weights
                               // 1/(rtol |h_i| + atol): <= 1 passes ARKODE's error test. Fixed
                               // modes: the Heun-Euler estimate (dN/2)(f(N, h) - f(N - dN, h_prev))
  double max_local_error_m = 0;  // max_i of the same local error estimate, m
  long steps = 0;              // accepted steps
  long rhs_evals = 0;          // evaluations of f
  long rejected = 0;           // steps that failed the error test (repeated failures: chatter)
};

// Why integrate() stopped. Messages carry the numbers compared.
struct IntegratorStatus {
  enum class Kind {
    ReachedEnd,  // N == N_end
    RootFound,   // roots holds the events at N (first event in N)
    Stopped,     // on_step returned false
    MaxSteps,    // max_steps accepted steps before N_end
    Failed,      // ARKODE gave up (repeated error test failures, too much accuracy asked)
  } kind = Kind::Failed;
  std::string message = "not run";  // pessimistic default
  std::vector<int> roots;           // RootFound: the k whose g_k changed sign at N, ascending
};

struct IntegratorResult {
  IntegratorStatus status;
  double N = 0;                // revolutions where it stopped (N_end, the root, or the last step)
  Eigen::VectorXd h_m;         // worn depth there (n, m)
  double last_step = 0;        // revolutions in the last accepted step (0 if none)
  double next_step = 0;        // as StepInfo::next_step after the last accepted step (0 if none)
  long steps = 0;              // accepted steps, including the one a root cut short
  long rhs_evals = 0;          // evaluations of f
  long rejected = 0;           // error test failures (Adaptive); halved steps (fixed modes)
};

// called after every accepted step with the state at its end; return false to stop (Kind::Stopped),
// e.g. to write a checkpoint and quit. A located root ends the run without a call (it is no step end).
using OnStep = std::function<bool(const StepInfo& info, const Eigen::VectorXd& h_m)>;

// Integrates dh/dN = f(N, h) from (N0, h0) up to N_end >= N0, stopping at the first event of roots
// (n_roots >= 0 functions; roots may be empty when n_roots == 0). Adaptive: the root is located to
// ARKODE's root tolerance, 100 eps (|N| + |step|), on its dense output; fixed modes: exactly
// on the Euler step's line. In both, the returned state is the first one past the root (g_k has
// changed sign or is 0). Throws std::invalid_argument for bad options or inputs, std::runtime_error
// naming the SUNDIALS call and flag when ARKODE reports an error, and a std::runtime_error naming the
// revolution (with the original exception nested) when f or roots throws or f returns a non-finite
// value. Repeated error test failures and max_steps are a status plus a spdlog::warn.
IntegratorResult integrate(const Rhs& f, const Roots& roots, int n_roots, double N0, const Eigen::VectorXd& h0_m,
                           double N_end, const IntegratorOptions& options, const OnStep& on_step = {});

}  // namespace wear
