// The integrator facade (integrator.h, docs/integrator.md).
//
// Adaptive. ARKODE's ERKStep in ARK_ONE_STEP mode, with the stop time N_end: one call per accepted
// step, so every step is reported, and no step passes N_end. After a step, ERKStepGetEstLocalErrors
// holds the embedded estimate e = h(order q) - h(order q-1) of that step and ERKStepGetErrWeights the
// weights w_i = 1/(rtol |h_i| + atol) its error test used (ARKODE refreshes them at the start of the
// next step), so
//   error_estimate = sqrt(mean_i (e_i w_i)^2)   (<= 1 for an accepted step).
// A root of g is located by ARKODE (Hiebert & Shampine's Illinois algorithm on the dense output).
//
// Fixed. Explicit Euler, h_{k+1} = h_k + dN f_k. Over the step the discrete solution is the line
// h(s) = h_k + s dN f_k, s in [0, 1], so a sign change of g_k between the step's ends is located on
// that line by the Illinois variant of regula falsi (bisection if a bracket fails to halve in two
// tries), to ARKODE's root tolerance, with calls to roots only. f is evaluated once per step, at
// its end (the next step needs it), which also gives the Heun-Euler local error estimate
//   e = (dN/2) (f(N_{k+1}, h_{k+1}) - f(N_k, h_k))   (trapezoid minus Euler).
//
// Callbacks from C. An exception from f or roots (or a non-finite dh/dN) is caught in the callback,
// which returns -1 (unrecoverable) to ARKODE; it is rethrown once ERKStepEvolve has returned.
#include "wear/integrator.h"

#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace wear {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kRootTol = 100 * kEps;   // root located to kRootTol (|N| + |step|), as ARKODE
constexpr double kEndTol = 100 * kEps;    // a step ending this close to N_end (relative) ends there
constexpr int kDefaultTable = ARKODE_BOGACKI_SHAMPINE_4_2_3;
constexpr int kMaxRootIterations = 200;
constexpr int kMaxHalvings = 20;  // fixed modes: a step is halved at most this often (to ~1e-6 of it)

// f(N, h) into dhdN; an exception or a non-finite value is reported with N
void evaluate_rate(const Rhs& f, double N, const Eigen::VectorXd& h, Eigen::VectorXd& dhdN) {
  dhdN.setConstant(h.size(), kNaN);
  try {
    f(N, h, dhdN);
  } catch (const std::exception& e) {
    std::throw_with_nested(std::runtime_error(
        fmt::format("wear::integrate: the wear rate threw at N {:.10g} revolutions: {}", N, e.what())));
  } catch (...) {
    std::throw_with_nested(
        std::runtime_error(fmt::format("wear::integrate: the wear rate threw at N {:.10g} revolutions", N)));
  }
  if (dhdN.size() != h.size())
    throw std::runtime_error(fmt::format("wear::integrate: the wear rate at N {:.10g} revolutions has {} components, "
                                         "the depth {}",
                                         N, dhdN.size(), h.size()));
  for (Eigen::Index i = 0; i < dhdN.size(); ++i)
    if (!std::isfinite(dhdN[i]))
      throw std::runtime_error(fmt::format("wear::integrate: dh/dN is not finite at N {:.10g} revolutions: "
                                           "component {} is {}",
                                           N, i, dhdN[i]));
}

// g(N, h) into g (n_roots); as evaluate_rate
void evaluate_roots(const Roots& roots, int n_roots, double N, const Eigen::VectorXd& h, Eigen::VectorXd& g) {
  g.setConstant(n_roots, kNaN);
  try {
    roots(N, h, g);
  } catch (const std::exception& e) {
    std::throw_with_nested(
        std::runtime_error(fmt::format("wear::integrate: the root functions threw at N {:.10g} revolutions: {}", N,
                                       e.what())));
  } catch (...) {
    std::throw_with_nested(
        std::runtime_error(fmt::format("wear::integrate: the root functions threw at N {:.10g} revolutions", N)));
  }
  if (g.size() != n_roots)
    throw std::runtime_error(fmt::format("wear::integrate: the root functions at N {:.10g} revolutions returned {} "
                                         "values, n_roots {}",
                                         N, g.size(), n_roots));
  for (Eigen::Index k = 0; k < g.size(); ++k)
    if (std::isnan(g[k]))
      throw std::runtime_error(
          fmt::format("wear::integrate: root function {} is NaN at N {:.10g} revolutions", k, N));
}

// g_k has an event between a and b: it was nonzero at a and is zero or of the other sign at b
bool crosses(double ga, double gb) { return ga != 0 && (gb == 0 || (ga < 0) != (gb < 0)); }

// ERKStep before SUNDIALS 6.7.0 takes the last stage of a step as f(N_{k+1}, h_{k+1}) whenever
// c_s = 1, also when a_s != b, i.e. when the method is not FSAL; the next step then starts from a
// stale stage and the results are wrong (upstream CHANGELOG, 6.7.0 bug fixes). Those tables are refused.
constexpr bool kArkodeTreatsEndStageAsFsal =
    SUNDIALS_VERSION_MAJOR < 6 || (SUNDIALS_VERSION_MAJOR == 6 && SUNDIALS_VERSION_MINOR < 7);

struct TableFree {
  void operator()(ARKodeButcherTable B) const { ARKodeButcherTable_Free(B); }
};

// why ARKODE's ERK table `table` cannot be used ("" if it can)
std::string table_problem(int table) {
  if (table < ARKODE_MIN_ERK_NUM || table > ARKODE_MAX_ERK_NUM)
    return fmt::format("unknown ERK table id {} (ARKODE {} has {}..{})", table, SUNDIALS_VERSION, ARKODE_MIN_ERK_NUM,
                       ARKODE_MAX_ERK_NUM);
  const std::unique_ptr<std::remove_pointer_t<ARKodeButcherTable>, TableFree> B(
      ARKodeButcherTable_LoadERK(static_cast<ARKODE_ERKTableID>(table)));
  if (!B) return fmt::format("ARKodeButcherTable_LoadERK({}) returned NULL", table);
  if (B->p == 0) return fmt::format("ERK table {} has no embedded method: no error estimate to adapt the step", table);
  const int s = B->stages;
  bool end_stage_is_solution = true;  // a_s == b: the last stage is f at the step's solution
  for (int j = 0; j < s; ++j) end_stage_is_solution = end_stage_is_solution && B->A[s - 1][j] == B->b[j];
  if (kArkodeTreatsEndStageAsFsal && B->c[s - 1] == 1 && !end_stage_is_solution)
    return fmt::format("ERK table {} has c_s = 1 but a_s != b: ERKStep of SUNDIALS {} wrongly reuses its last stage "
                       "(fixed in 6.7.0)",
                       table, SUNDIALS_VERSION);
  return "";
}

std::string valid_tables() {
  std::string s;
  for (int t = ARKODE_MIN_ERK_NUM; t <= ARKODE_MAX_ERK_NUM; ++t)
    if (table_problem(t).empty()) s += (s.empty() ? "" : ", ") + std::to_string(t);
  return s;
}

void check_inputs(const Rhs& f, const Roots& roots, int n_roots, double N0, const Eigen::VectorXd& h0, double N_end,
                  const IntegratorOptions& o) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("wear::integrate: " + what); };
  if (!f) fail("no wear rate function");
  if (n_roots < 0) fail(fmt::format("n_roots must be >= 0, got {}", n_roots));
  if (n_roots > 0 && !roots) fail(fmt::format("n_roots is {} but no root functions", n_roots));
  if (h0.size() == 0) fail("the depth h0 is empty");
  if (!h0.allFinite()) fail("the depth h0 is not finite");
  if (!std::isfinite(N0) || !std::isfinite(N_end)) fail(fmt::format("N0 {} and N_end {} must be finite", N0, N_end));
  if (N_end < N0) fail(fmt::format("N_end {} < N0 {}: integration runs forward only", N_end, N0));
  if (o.max_steps <= 0) fail(fmt::format("max_steps must be > 0, got {}", o.max_steps));
  if (!(o.max_step >= 0)) fail(fmt::format("max_step must be >= 0, got {}", o.max_step));
  switch (o.method) {
    case IntegratorOptions::Method::Adaptive:
      if (!(o.rtol > 0 && o.rtol < 1)) fail(fmt::format("rtol must be in (0, 1), got {}", o.rtol));
      if (!(o.atol > 0 && std::isfinite(o.atol))) fail(fmt::format("atol must be > 0 (m), got {}", o.atol));
      if (!(o.initial_step >= 0)) fail(fmt::format("initial_step must be >= 0, got {}", o.initial_step));
      if (o.table != -1) {
        const std::string problem = table_problem(o.table);
        if (!problem.empty()) fail(fmt::format("table: {}; usable ids: {}", problem, valid_tables()));
      }
      break;
    case IntegratorOptions::Method::FixedDepth:
      if (!(o.max_depth_step > 0 && std::isfinite(o.max_depth_step)))
        fail(fmt::format("max_depth_step must be > 0 (m), got {}", o.max_depth_step));
      break;
    case IntegratorOptions::Method::FixedStep:
      if (!(o.fixed_step > 0 && std::isfinite(o.fixed_step)))
        fail(fmt::format("fixed_step must be > 0 (revolutions), got {}", o.fixed_step));
      break;
  }
}

void finish_max_steps(IntegratorResult& r, long max_steps, double N_end) {
  r.status.kind = IntegratorStatus::Kind::MaxSteps;
  r.status.message = fmt::format("max_steps {} reached at N {:.10g} < N_end {:.10g}", max_steps, r.N, N_end);
  spdlog::warn("wear::integrate: {}", r.status.message);
}

std::string root_list(const std::vector<int>& roots) {
  std::string s;
  for (const int k : roots) s += (s.empty() ? "" : ", ") + std::to_string(k);
  return s;
}

// ---------------------------------------------------------------------------------------------
// adaptive: ARKODE ERKStep

// what the C callbacks need, and what they leave for the caller
struct Callbacks {
  const Rhs& f;
  const Roots& roots;
  int n_roots;
  Eigen::VectorXd h, dhdN, g;  // scratch (the RHS takes Eigen vectors)
  std::exception_ptr error;    // the first exception in a callback, rethrown after ERKStepEvolve
  std::string arkode_message;  // ARKODE's last error message, for the exception text
};

int rhs_callback(sunrealtype N, N_Vector y, N_Vector ydot, void* user_data) {
  Callbacks& cb = *static_cast<Callbacks*>(user_data);
  try {
    const Eigen::Index n = cb.h.size();
    cb.h = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(y), n);
    evaluate_rate(cb.f, N, cb.h, cb.dhdN);
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(ydot), n) = cb.dhdN;
    return 0;
  } catch (...) {
    if (!cb.error) cb.error = std::current_exception();
    return -1;  // unrecoverable: ERKStepEvolve returns ARK_RHSFUNC_FAIL
  }
}

int roots_callback(sunrealtype N, N_Vector y, sunrealtype* gout, void* user_data) {
  Callbacks& cb = *static_cast<Callbacks*>(user_data);
  try {
    cb.h = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(y), cb.h.size());
    evaluate_roots(cb.roots, cb.n_roots, N, cb.h, cb.g);
    Eigen::Map<Eigen::VectorXd>(gout, cb.n_roots) = cb.g;
    return 0;
  } catch (...) {
    if (!cb.error) cb.error = std::current_exception();
    return -1;  // ERKStepEvolve returns ARK_RTFUNC_FAIL
  }
}

// ARKODE's messages: errors are reported by the caller (exception or status), warnings are trouble
// the run survives
void error_handler(int code, const char* module, const char* function, char* msg, void* user_data) {
  Callbacks& cb = *static_cast<Callbacks*>(user_data);
  if (code < 0) {
    cb.arkode_message = fmt::format("{}: {}", function ? function : "?", msg ? msg : "");
    spdlog::debug("ARKODE {} {} ({}): {}", module ? module : "?", function ? function : "?", code, msg ? msg : "");
  } else {
    spdlog::warn("ARKODE {} {}: {}", module ? module : "?", function ? function : "?", msg ? msg : "");
  }
}

std::string flag_name(int flag) {
  char* name = ERKStepGetReturnFlagName(flag);  // malloc'ed by ARKODE
  std::string s = name ? name : "unknown flag";
  std::free(name);
  return s;
}

// throws for a negative flag, naming the call, the flag and ARKODE's message
void check(int flag, const char* call, const Callbacks& cb) {
  if (flag >= 0) return;
  std::string what = fmt::format("wear::integrate: {} failed with flag {} ({})", call, flag, flag_name(flag));
  if (!cb.arkode_message.empty()) what += ": " + cb.arkode_message;
  throw std::runtime_error(what);
}

template <class T>
void check_created(T* p, const char* call) {
  if (!p) throw std::runtime_error(fmt::format("wear::integrate: {} returned NULL", call));
}

struct ContextFree {
  void operator()(SUNContext c) const { SUNContext_Free(&c); }
};
struct VectorFree {
  void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct StepperFree {
  void operator()(void* mem) const { ERKStepFree(&mem); }
};

// the one owner of the SUNDIALS memory of a run: context, vectors, ERKStep (freed in reverse)
class ErkStepper {
 public:
  ErkStepper(double N0, const Eigen::VectorXd& h0, Callbacks& cb) {
    SUNContext context = nullptr;
    check(SUNContext_Create(nullptr, &context), "SUNContext_Create", cb);
    context_.reset(context);
    const auto n = static_cast<sunindextype>(h0.size());
    y_.reset(N_VNew_Serial(n, context));
    check_created(y_.get(), "N_VNew_Serial");
    local_error_.reset(N_VNew_Serial(n, context));
    check_created(local_error_.get(), "N_VNew_Serial");
    weights_.reset(N_VNew_Serial(n, context));
    check_created(weights_.get(), "N_VNew_Serial");
    Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(y_.get()), h0.size()) = h0;
    mem_.reset(ERKStepCreate(rhs_callback, N0, y_.get(), context));
    check_created(mem_.get(), "ERKStepCreate");
  }

  void* mem() const { return mem_.get(); }
  N_Vector y() const { return y_.get(); }
  N_Vector local_error() const { return local_error_.get(); }
  N_Vector weights() const { return weights_.get(); }
  Eigen::Map<const Eigen::VectorXd> h() const {
    return {N_VGetArrayPointer(y_.get()), static_cast<Eigen::Index>(N_VGetLength(y_.get()))};
  }

 private:
  std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextFree> context_;
  std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorFree> y_, local_error_, weights_;
  std::unique_ptr<void, StepperFree> mem_;
};

IntegratorResult integrate_adaptive(const Rhs& f, const Roots& roots, int n_roots, double N0,
                                    const Eigen::VectorXd& h0, double N_end, const IntegratorOptions& o,
                                    const OnStep& on_step) {
  Callbacks cb{f, roots, n_roots, h0, Eigen::VectorXd(h0.size()), Eigen::VectorXd(n_roots), nullptr, {}};
  ErkStepper stepper(N0, h0, cb);
  void* mem = stepper.mem();

  // options
  check(ERKStepSetUserData(mem, &cb), "ERKStepSetUserData", cb);
  check(ERKStepSetErrHandlerFn(mem, error_handler, &cb), "ERKStepSetErrHandlerFn", cb);
  check(ERKStepSStolerances(mem, o.rtol, o.atol), "ERKStepSStolerances", cb);
  const int table = o.table < 0 ? kDefaultTable : o.table;
  check(ERKStepSetTableNum(mem, static_cast<ARKODE_ERKTableID>(table)), "ERKStepSetTableNum", cb);
  check(ERKStepSetStopTime(mem, N_end), "ERKStepSetStopTime", cb);
  if (o.initial_step > 0) check(ERKStepSetInitStep(mem, o.initial_step), "ERKStepSetInitStep", cb);
  if (o.max_step > 0) check(ERKStepSetMaxStep(mem, o.max_step), "ERKStepSetMaxStep", cb);
  if (n_roots > 0) {
    check(ERKStepRootInit(mem, n_roots, roots_callback), "ERKStepRootInit", cb);
    check(ERKStepSetNoInactiveRootWarn(mem), "ERKStepSetNoInactiveRootWarn", cb);
  }

  IntegratorResult r;
  r.N = N0;
  r.h_m = h0;
  auto counters = [&] {
    check(ERKStepGetNumSteps(mem, &r.steps), "ERKStepGetNumSteps", cb);
    check(ERKStepGetNumRhsEvals(mem, &r.rhs_evals), "ERKStepGetNumRhsEvals", cb);
    check(ERKStepGetNumErrTestFails(mem, &r.rejected), "ERKStepGetNumErrTestFails", cb);
  };

  for (long accepted = 0;; ++accepted) {
    if (accepted >= o.max_steps) {
      counters();
      finish_max_steps(r, o.max_steps, N_end);
      return r;
    }

    // one accepted step (or the root inside it)
    double N = r.N;
    const int flag = ERKStepEvolve(mem, N_end, stepper.y(), &N, ARK_ONE_STEP);
    if (cb.error) std::rethrow_exception(cb.error);  // names the revolution; r holds the last step
    if (flag == ARK_ERR_FAILURE || flag == ARK_TOO_MUCH_ACC || flag == ARK_TOO_MUCH_WORK) {
      counters();
      r.status.kind = IntegratorStatus::Kind::Failed;
      r.status.message = fmt::format("ERKStepEvolve: {} after N {:.10g} ({} steps, {} error test failures): {}",
                                     flag_name(flag), r.N, r.steps, r.rejected, cb.arkode_message);
      spdlog::warn("wear::integrate: {}", r.status.message);
      return r;
    }
    check(flag, "ERKStepEvolve", cb);
    counters();

    // a lifetime limit inside the step: the state at the root
    if (flag == ARK_ROOT_RETURN) {
      std::vector<int> found(static_cast<std::size_t>(n_roots), 0);
      check(ERKStepGetRootInfo(mem, found.data()), "ERKStepGetRootInfo", cb);
      for (int k = 0; k < n_roots; ++k)
        if (found[static_cast<std::size_t>(k)] != 0) r.status.roots.push_back(k);
      r.N = N;
      r.h_m = stepper.h();
      r.status.kind = IntegratorStatus::Kind::RootFound;
      r.status.message = fmt::format("root {} at N {:.10g} after {} steps", root_list(r.status.roots), N, r.steps);
      return r;
    }

    // the accepted step
    StepInfo info;
    info.N = N;
    check(ERKStepGetLastStep(mem, &info.step), "ERKStepGetLastStep", cb);
    check(ERKStepGetCurrentStep(mem, &info.next_step), "ERKStepGetCurrentStep", cb);
    check(ERKStepGetEstLocalErrors(mem, stepper.local_error()), "ERKStepGetEstLocalErrors", cb);
    check(ERKStepGetErrWeights(mem, stepper.weights()), "ERKStepGetErrWeights", cb);
    info.error_estimate = N_VWrmsNorm(stepper.local_error(), stepper.weights());
    info.max_local_error_m = N_VMaxNorm(stepper.local_error());
    info.steps = r.steps;
    info.rhs_evals = r.rhs_evals;
    info.rejected = r.rejected;
    r.N = N;
    r.h_m = stepper.h();
    r.last_step = info.step;
    r.next_step = info.next_step;
    SPDLOG_TRACE("wear::integrate: step {} to N {:.10g}, dN {:.4g}, error {:.3g}", info.steps, N, info.step,
                 info.error_estimate);
    const bool go_on = on_step ? on_step(info, r.h_m) : true;
    if (flag == ARK_TSTOP_RETURN || N >= N_end) {
      r.N = N_end;
      r.status.kind = IntegratorStatus::Kind::ReachedEnd;
      r.status.message = fmt::format("reached N_end {:.10g} after {} steps ({} error test failures, {} rhs evals)",
                                     N_end, r.steps, r.rejected, r.rhs_evals);
      return r;
    }
    if (!go_on) {
      r.status.kind = IntegratorStatus::Kind::Stopped;
      r.status.message = fmt::format("on_step stopped at N {:.10g} < N_end {:.10g} after {} steps", N, N_end, r.steps);
      return r;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// fixed: explicit Euler

// the step's continuous solution h(s), s in [0, 1] (Euler's line, or a second-order scheme's extension)
using StepPoint = std::function<void(double s, Eigen::VectorXd& hs)>;

// the earliest event on the step's solution point(s), s in [0, 1], given g at both ends;
// returns s (the end where the event has happened) and the events there
std::pair<double, std::vector<int>> locate_on_line(const Roots& roots, int n_roots, double N, const StepPoint& point,
                                                   Eigen::Index n, double dN, Eigen::VectorXd ga, Eigen::VectorXd gb) {
  double a = 0, b = 1;
  double wa = 1, wb = 1;  // Illinois weights: an end kept twice in a row has its g halved
  int kept = 0;           // +1: a was kept last time, -1: b was kept
  double width_two_ago = std::numeric_limits<double>::infinity(), width_one_ago = width_two_ago;
  const double tol_s = kRootTol * (std::abs(N) + std::abs(dN)) / std::abs(dN);
  Eigen::VectorXd hs(n), gs(n_roots);
  auto events = [&](const Eigen::VectorXd& g0, const Eigen::VectorXd& g1) {
    std::vector<int> ks;
    for (int k = 0; k < n_roots; ++k)
      if (crosses(g0[k], g1[k])) ks.push_back(k);
    return ks;
  };
  for (int it = 0; it < kMaxRootIterations && b - a > tol_s; ++it) {
    // the earliest secant crossing, or the midpoint when the bracket has not halved in two tries
    double s = b;
    if (b - a > 0.5 * width_two_ago) {
      s = 0.5 * (a + b);
    } else {
      for (const int k : events(ga, gb)) {
        const double fa = wa * ga[k], fb = wb * gb[k];
        s = std::min(s, fb == 0 ? b : a + (b - a) * fa / (fa - fb));
      }
    }
    s = std::clamp(s, a + 0.5 * tol_s, b - 0.5 * tol_s);
    width_two_ago = width_one_ago;
    width_one_ago = b - a;

    // g on the line at s
    point(s, hs);
    evaluate_roots(roots, n_roots, N + s * dN, hs, gs);
    if (!events(ga, gs).empty()) {
      b = s;
      gb = gs;
      wb = 1;
      if (kept == +1) wa *= 0.5;
      kept = +1;
    } else {
      a = s;
      ga = gs;
      wa = 1;
      if (kept == -1) wb *= 0.5;
      kept = -1;
    }
  }
  return {b, events(ga, gb)};
}

// what a fixed step carries from its stability control to its root search and its acceptance
struct FixedStep {
  double N_next = 0;           // where it ends
  double dN = 0;               // its size
  Eigen::VectorXd h_next;      // the solution at its end
  Eigen::VectorXd rate_next;   // the rate there (the next step's slope)
  Eigen::VectorXd curve;       // Heun: the step's solution is h(s) = h + dN (s rate + s^2 curve), s in [0, 1]
  Eigen::VectorXd predicted;   // Heun: the rate at Euler's predictor
  Eigen::VectorXd g_next;      // the limits at its end
};

// the step's end: the next multiple of fixed_step from N0 (no summed rounding in N), or the revolutions
// that wear max_depth_step at the fastest node; a step ending within kEndTol of N_end ends there
double fixed_step_end(const IntegratorOptions& o, const Eigen::VectorXd& rate, double N, double N0, long targets,
                      double N_end) {
  const bool by_depth = o.method == IntegratorOptions::Method::FixedDepth;
  double dN = o.fixed_step;
  if (by_depth) {
    const double fastest = rate.cwiseAbs().maxCoeff();
    dN = fastest > 0 ? o.max_depth_step / fastest : std::numeric_limits<double>::infinity();
    if (o.max_step > 0) dN = std::min(dN, o.max_step);
  }
  double N_next = by_depth ? N + dN : N0 + static_cast<double>(targets + 1) * o.fixed_step;
  if (N_next >= N_end - kEndTol * std::max(std::abs(N_end), dN)) N_next = N_end;
  return N_next;
}

// Stability control: the step from r.N towards N_next is halved until the rate at its end exists (a far
// too large step wears an absurd profile, on which the contact cannot be solved) and differs from the
// rate at its start by at most the larger of the two rates' sizes. For a decaying mode dh/dN = lambda h
// that is lambda dN >= -1: Euler's factor 1 + lambda dN stays in [0, 1], so the profile cannot oscillate;
// a growing mode or a rate rising from 0 passes. A halved FixedStep goes on towards the same multiple of
// fixed_step. (Heun: the rate at Euler's predictor is tested, then its corrector's end evaluated.) Sets
// the step's end, size, solution and rate there; counts evaluations and halvings in r.
void take_stable_step(const Rhs& f, const IntegratorOptions& o, const Eigen::VectorXd& rate, double N_next,
                      FixedStep& s, IntegratorResult& r) {
  using Scheme = IntegratorOptions::Scheme;
  // the rate's change over a step is at most the larger of its sizes at the two ends (the stability test)
  const auto stable_between = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return (b - a).cwiseAbs().maxCoeff() <= std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  };
  double dN = 0;
  for (int halvings = 0;; ++halvings) {
    dN = N_next - r.N;
    bool stable = false;
    try {
      switch (o.scheme) {
        case Scheme::Euler:
          s.h_next = r.h_m + dN * rate;
          ++r.rhs_evals;
          evaluate_rate(f, N_next, s.h_next, s.rate_next);
          stable = stable_between(rate, s.rate_next);
          break;
        case Scheme::Heun:
          s.h_next = r.h_m + dN * rate;
          ++r.rhs_evals;
          evaluate_rate(f, N_next, s.h_next, s.predicted);
          stable = stable_between(rate, s.predicted);
          if (stable || halvings == kMaxHalvings) {
            s.curve = 0.5 * (s.predicted - rate);
            s.h_next = r.h_m + dN * (rate + s.curve);
            ++r.rhs_evals;
            evaluate_rate(f, N_next, s.h_next, s.rate_next);
          }
          break;
      }
    } catch (const std::exception&) {
      if (halvings == kMaxHalvings) throw;
      stable = false;
    }
    if (stable) break;
    if (halvings == kMaxHalvings) {  // a jump of f itself, not the step's doing
      spdlog::warn("wear::integrate: the rate changes by more than its size over a step of {:.4g} revolutions "
                   "at N {:.10g}, halved {} times; taking it",
                   dN, r.N, kMaxHalvings);
      break;
    }
    ++r.rejected;
    N_next = r.N + dN / 2;
  }
  s.N_next = N_next;
  s.dN = dN;
}

// A lifetime limit inside the step, g changing sign between its ends (g at its start, updated to its end
// when none does): located on the step's solution (Euler's line, exactly; Heun's quadratic extension).
// Returns true with r at the root, the step counted.
bool root_in_step(const Roots& roots, int n_roots, const IntegratorOptions& o, const Eigen::VectorXd& rate,
                  FixedStep& s, Eigen::VectorXd& g, IntegratorResult& r) {
  using Scheme = IntegratorOptions::Scheme;
  evaluate_roots(roots, n_roots, s.N_next, s.h_next, s.g_next);
  bool event = false;
  for (int k = 0; k < n_roots; ++k) event = event || crosses(g[k], s.g_next[k]);
  if (!event) {
    g.swap(s.g_next);
    return false;
  }
  const double dN = s.dN;
  const Eigen::VectorXd& h = r.h_m;
  const Eigen::VectorXd& curve = s.curve;
  const StepPoint point = [&](double t, Eigen::VectorXd& hs) {
    if (o.scheme == Scheme::Euler)
      hs = h + (t * dN) * rate;
    else
      hs = h + dN * (t * rate + (t * t) * curve);
  };
  auto [t, found] = locate_on_line(roots, n_roots, r.N, point, h.size(), dN, g, s.g_next);
  r.N = t == 1 ? s.N_next : r.N + t * dN;
  if (t == 1) {
    r.h_m = s.h_next;
  } else {
    Eigen::VectorXd hs(h.size());
    point(t, hs);
    r.h_m = std::move(hs);
  }
  ++r.steps;  // the step the root cut short counts, as in ARKODE
  r.status.kind = IntegratorStatus::Kind::RootFound;
  r.status.roots = std::move(found);
  r.status.message = fmt::format("root {} at N {:.10g} after {} steps", root_list(r.status.roots), r.N, r.steps);
  return true;
}

// The step accepted: r moves to its end, the rate at its end (evaluated by the stability control) becomes
// the next step's slope and gives this step's error estimate (Euler's: trapezoid minus Euler; Heun's: its
// update minus Euler's). Returns the step as reported to on_step.
StepInfo accept_fixed_step(const IntegratorOptions& o, Eigen::VectorXd& rate, FixedStep& s, IntegratorResult& r) {
  using Scheme = IntegratorOptions::Scheme;
  const double dN = s.dN;
  ++r.steps;
  const Eigen::ArrayXd e = o.scheme == Scheme::Euler ? Eigen::ArrayXd(((0.5 * dN) * (s.rate_next - rate)).array())
                                                     : Eigen::ArrayXd((dN * s.curve).array());
  const Eigen::ArrayXd w = 1.0 / (o.rtol * r.h_m.array().abs() + o.atol);
  StepInfo info;
  info.N = s.N_next;
  info.step = dN;
  info.next_step = dN;
  info.error_estimate = std::sqrt((e * w).square().mean());
  info.max_local_error_m = e.abs().maxCoeff();
  info.steps = r.steps;
  info.rejected = r.rejected;
  info.rhs_evals = r.rhs_evals;
  r.N = s.N_next;
  r.h_m.swap(s.h_next);
  rate.swap(s.rate_next);
  r.last_step = r.next_step = dN;
  SPDLOG_TRACE("wear::integrate: fixed step {} to N {:.10g}, dN {:.4g}", r.steps, r.N, dN);
  return info;
}

IntegratorResult integrate_fixed(const Rhs& f, const Roots& roots, int n_roots, double N0, const Eigen::VectorXd& h0,
                                 double N_end, const IntegratorOptions& o, const OnStep& on_step) {
  const bool by_depth = o.method == IntegratorOptions::Method::FixedDepth;
  IntegratorResult r;
  r.N = N0;
  r.h_m = h0;

  // the state, the rate and the limits at the start of the step
  const Eigen::Index n = h0.size();
  Eigen::VectorXd rate(n);
  FixedStep s;
  s.h_next.resize(n);
  s.rate_next.resize(n);
  s.curve = Eigen::VectorXd::Zero(n);
  s.predicted.resize(n);
  s.g_next.resize(n_roots);
  evaluate_rate(f, N0, h0, rate);
  r.rhs_evals = 1;
  Eigen::VectorXd g(n_roots);
  if (n_roots > 0) evaluate_roots(roots, n_roots, N0, h0, g);

  long targets = 0;  // FixedStep: multiples of fixed_step reached; N counts from N0 on them
  while (r.N < N_end) {
    if (r.steps >= o.max_steps) {
      finish_max_steps(r, o.max_steps, N_end);
      return r;
    }

    // the step: its size, then halved until stable
    const double N_target = fixed_step_end(o, rate, r.N, N0, targets, N_end);
    take_stable_step(f, o, rate, N_target, s, r);
    if (!by_depth && s.N_next == N_target) ++targets;

    // a lifetime limit inside the step ends the integration there
    if (n_roots > 0 && root_in_step(roots, n_roots, o, rate, s, g, r)) return r;

    // the step accepted, reported
    const StepInfo info = accept_fixed_step(o, rate, s, r);
    const bool go_on = on_step ? on_step(info, r.h_m) : true;
    if (!go_on && r.N < N_end) {
      r.status.kind = IntegratorStatus::Kind::Stopped;
      r.status.message =
          fmt::format("on_step stopped at N {:.10g} < N_end {:.10g} after {} steps", r.N, N_end, r.steps);
      return r;
    }
  }
  r.status.kind = IntegratorStatus::Kind::ReachedEnd;
  r.status.message = fmt::format("reached N_end {:.10g} after {} {} steps", N_end, r.steps,
                                 o.scheme == IntegratorOptions::Scheme::Euler ? "Euler" : "Heun");
  return r;
}
}  // namespace

IntegratorResult integrate(const Rhs& f, const Roots& roots, int n_roots, double N0, const Eigen::VectorXd& h0_m,
                           double N_end, const IntegratorOptions& options, const OnStep& on_step) {
  check_inputs(f, roots, n_roots, N0, h0_m, N_end, options);
  if (N_end == N0) {  // nothing to integrate (ARKODE would refuse tout == t0)
    IntegratorResult r;
    r.N = N0;
    r.h_m = h0_m;
    r.status.kind = IntegratorStatus::Kind::ReachedEnd;
    r.status.message = fmt::format("N_end {:.10g} == N0: no step", N_end);
    return r;
  }
  IntegratorResult r = options.method == IntegratorOptions::Method::Adaptive
                           ? integrate_adaptive(f, roots, n_roots, N0, h0_m, N_end, options, on_step)
                           : integrate_fixed(f, roots, n_roots, N0, h0_m, N_end, options, on_step);
  spdlog::debug("wear::integrate: {}", r.status.message);
  return r;
}

}  // namespace wear
