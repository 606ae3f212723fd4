// rollwear's Python bindings (docs/python.md): the extension module rollwear._rollwear, which the package
// python/rollwear/__init__.py wraps. One translation unit, so that pybind11's templates compile once.
//
// - contact, transient, run: one case (a file, or a document's text from a dict), the work of the commands
//   `rollwear contact`, `transient` and `run` (lib/io/case_run.h, session/wear_life_run.h) without their files; the
//   results come back as dicts of NumPy arrays named as the commands' CSV columns.
// - sweep: `rollwear sweep` (session/sweep.h), writing its folder as the command does.
// - Errors by type (lib/errors.h), never by message: CaseError -> InputError (file, line, column, key from
//   CaseError::location), SolverError and the solvers' own failures -> SolverError, anything else -> Error.
// - The GIL is released while C++ runs; every ~50 ms a hook (the transient's step observer, the wear loop's
//   on_step, the sweep's cancelled) takes it back to run PyErr_CheckSignals, so Ctrl-C interrupts.
// - spdlog's messages go to Python's logging, logger "rollwear" (a sink that takes the GIL to log).
#include <Python.h>
#include <pybind11/pybind11.h>
#include <pybind11/numpy.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Core>
#include <spdlog/sinks/base_sink.h>
#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "lib/io/case_run.h"
#include "lib/io/case.h"
#include "lib/errors.h"
#include "lib/normal/normal.h"
#include "lib/normal/semi_hertz.h"
#include "session/output_folder.h"
#include "session/sweep.h"
#include "session/wear_life_run.h"
#include "wear/wear_case.h"
#include "wear/wear_loop.h"
#include "wear/wear_output.h"

namespace py = pybind11;

namespace {

// ---- exceptions --------------------------------------------------------------------------------------

PyObject* g_error = nullptr;        // rollwear.Error(RuntimeError): any failure
PyObject* g_input_error = nullptr;  // rollwear.InputError(Error, ValueError): bad input (CaseError)
PyObject* g_solver_error = nullptr; // rollwear.SolverError(Error): a solver failed on valid input

// Ctrl-C (or any exception a Python signal handler raised) seen by a hook: the Python error is held here and
// raised again when the call returns to Python
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

// the exception instance of class `type` with `message`, its attributes set
void raise(PyObject* type, const std::string& message, const std::vector<std::pair<const char*, py::object>>& attrs) {
  py::object e = py::reinterpret_borrow<py::object>(type)(message);
  for (const auto& [name, value] : attrs) e.attr(name) = value;
  PyErr_SetObject(type, e.ptr());
}

py::object or_none(const std::string& s) { return s.empty() ? py::none() : py::object(py::str(s)); }
py::object or_none(int v) { return v > 0 ? py::object(py::int_(v)) : py::none(); }

void translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const contact::CaseError& e) {  // bad input: exit 2 in the CLI
    const contact::InputLocation& w = e.location;
    raise(g_input_error, e.what(),
          {{"file", or_none(w.file)}, {"line", or_none(w.line)}, {"column", or_none(w.column)}, {"key", or_none(w.key)}});
  } catch (const contact::SolverError& e) {
    raise(g_solver_error, e.what(), {});
  } catch (const contact::NormalSolveError& e) {  // a normal solve that did not converge
    raise(g_solver_error, e.what(), {});
  } catch (const wear::LifeEndingGeometry& e) {
    raise(g_solver_error, e.what(), {});
  } catch (const std::invalid_argument& e) {  // thrown inside a solver on valid input (lib/errors.h)
    raise(g_solver_error, e.what(), {});
  } catch (const py::error_already_set&) {
    throw;  // pybind11 restores it
  } catch (const py::builtin_exception&) {
    throw;  // pybind11's own (a TypeError, a ValueError of a conversion)
  } catch (const std::exception& e) {  // any other failure (an output folder, the disk): exit 1 in the CLI
    raise(g_error, e.what(), {});
  }
}

// ---- logging: spdlog -> Python's logging ---------------------------------------------------------------

// Each message becomes logging.getLogger("rollwear").log(level, text). The GIL serialises the sink (its
// own mutex is a null one: a thread holding the GIL and waiting on a sink mutex would deadlock).
class PythonLogSink : public spdlog::sinks::base_sink<spdlog::details::null_mutex> {
 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override {
    if (!Py_IsInitialized() || closed()) return;
    const std::string text(msg.payload.data(), msg.payload.size());
    const int level = python_level(msg.level);
    py::gil_scoped_acquire gil;
    PyObject *type = nullptr, *value = nullptr, *trace = nullptr;
    PyErr_Fetch(&type, &value, &trace);  // a pending error (an interrupt) is kept across the call
    try {
      py::module_::import("logging").attr("getLogger")("rollwear").attr("log")(level, text);
    } catch (const py::error_already_set&) {  // logging itself failed: the message is lost, not the run
    }
    PyErr_Restore(type, value, trace);
  }
  void flush_() override {}

 public:
  static int python_level(spdlog::level::level_enum l) {
    switch (l) {
      case spdlog::level::trace:
      case spdlog::level::debug: return 10;
      case spdlog::level::info: return 20;
      case spdlog::level::warn: return 30;
      case spdlog::level::err: return 40;
      case spdlog::level::critical: return 50;
      default: return 0;
    }
  }
  static std::atomic<bool>& closed() {
    static std::atomic<bool> c{false};
    return c;
  }
};

// spdlog's level from the Python logger's effective level, so that messages nobody reads are not formatted
void sync_log_level() {
  const int py_level = py::module_::import("logging").attr("getLogger")("rollwear").attr("getEffectiveLevel")().cast<int>();
  spdlog::level::level_enum l = spdlog::level::off;
  if (py_level <= 10) l = spdlog::level::debug;
  else if (py_level <= 20) l = spdlog::level::info;
  else if (py_level <= 30) l = spdlog::level::warn;
  else if (py_level <= 40) l = spdlog::level::err;
  else if (py_level <= 50) l = spdlog::level::critical;
  spdlog::set_level(l);
}

// ---- Ctrl-C --------------------------------------------------------------------------------------------

// Called from a hook on the thread that made the call (the GIL released): at most every kCheckInterval it
// takes the GIL and runs Python's signal handlers. true when one raised (the error is then held, and the
// hook stops the run).
class SignalCheck {
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kCheckInterval{50};  // Ctrl-C answered within about this

 public:
  bool interrupted() {
    if (error_) return true;
    const Clock::time_point now = Clock::now();
    if (now - last_ < kCheckInterval) return false;
    last_ = now;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return false;
    error_.emplace();  // fetches (and clears) the exception the handler raised
    return true;
  }
  // after the call, the GIL held: raise the held exception, if any
  void rethrow() {
    if (!error_) return;
    py::error_already_set e = std::move(*error_);
    error_.reset();
    throw e;
  }

 private:
  Clock::time_point last_ = Clock::now();
  std::optional<py::error_already_set> error_;
};

// ---- arrays --------------------------------------------------------------------------------------------

py::array_t<double> array(const Eigen::ArrayXd& v) {
  py::array_t<double> a(v.size());
  if (v.size() > 0) std::memcpy(a.mutable_data(), v.data(), sizeof(double) * static_cast<std::size_t>(v.size()));
  return a;
}
py::array_t<double> array(const std::vector<double>& v) {
  py::array_t<double> a(v.size());
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), sizeof(double) * v.size());
  return a;
}
py::array_t<long> array(const std::vector<long>& v) {
  py::array_t<long> a(v.size());
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), sizeof(long) * v.size());
  return a;
}
// (nx x ny), column j = strip j, as the solvers hold it: a[i, j]
template <class T>
py::array array(const Eigen::Array<T, Eigen::Dynamic, Eigen::Dynamic>& m) {
  py::array_t<T, py::array::f_style> a({m.rows(), m.cols()});
  if (m.size() > 0) std::memcpy(a.mutable_data(), m.data(), sizeof(T) * static_cast<std::size_t>(m.size()));
  return a;
}
// rows of equal length as a (rows x n) array
py::array_t<double> matrix(const std::vector<std::vector<double>>& rows, std::size_t n) {
  py::array_t<double> a({rows.size(), n});
  double* out = a.mutable_data();
  for (const std::vector<double>& r : rows) out = std::copy(r.begin(), r.end(), out);
  return a;
}

// ---- the case: a file, or a document's text (a dict) ---------------------------------------------------

struct CaseSource {
  std::string path_or_text;
  bool is_text = false;
  std::string base_dir;  // profile files of a text are relative to it
};
constexpr const char* kDictLabel = "<dict>";

// A cam case (a top-level cam: section) is not the roller's: contact, transient and run read the roller's
// cases, so one is refused naming what it is and where it runs, not by the roller's reader ("bodies:
// required section is missing"). A document that does not parse is left to the reader, which names the place.
void refuse_cam_case(const CaseSource& s, const char* function) {
  const std::string label = s.is_text ? kDictLabel : s.path_or_text;
  int line = 0, column = 0;
  try {
    const YAML::Node doc = s.is_text ? YAML::Load(s.path_or_text) : YAML::LoadFile(s.path_or_text);
    if (!doc.IsMap()) return;
    bool cam = false;
    for (const auto& kv : doc)
      if (kv.first.IsScalar() && kv.first.Scalar() == "cam") {
        cam = true;
        line = kv.first.Mark().line + 1;
        column = kv.first.Mark().column + 1;
      }
    if (!cam) return;
  } catch (const std::exception&) {
    return;
  }
  throw contact::CaseError(
      fmt::format("{}:{}:{}: cam: a cam case; rollwear.{}() runs the roller's cases (bodies:, load:, ...): a cam case "
                  "runs on the command line, `rollwear cam CASE` (one revolution) or `rollwear run CASE` (its life)",
                  label, line, column, function),
      contact::InputLocation{label, line, column, "cam"});
}

contact::ContactCase read_case(const CaseSource& s, const char* function) {
  refuse_cam_case(s, function);
  return s.is_text ? contact::read_contact_case_text(s.path_or_text, kDictLabel, s.base_dir)
                   : contact::read_contact_case(s.path_or_text);
}
wear::WearCase read_wear(const CaseSource& s) {
  refuse_cam_case(s, "run");
  return s.is_text ? wear::read_wear_case_text(s.path_or_text, kDictLabel, s.base_dir) : wear::read_wear_case(s.path_or_text);
}

// ---- contact -------------------------------------------------------------------------------------------

py::dict contact_result(const CaseSource& source, bool fields, bool subsurface) {
  sync_log_level();
  std::optional<contact::ContactCase> c;
  std::optional<contact::ContactRun> r;
  std::array<contact::BodySubsurface, 2> below;
  {
    py::gil_scoped_release release;
    c.emplace(read_case(source, "contact"));
    subsurface = subsurface && c->output.subsurface;
    r.emplace(contact::solve_contact_case(*c, fields || subsurface));  // the subsurface needs the tractions
    if (subsurface) below = contact::subsurface_of_contact(*c, *r);
  }
  const contact::ContactPatch& p = r->normal.patch;
  const contact::TangentialSolution& s = r->solution;
  py::dict summary;  // summary.csv's columns, and what the CLI prints besides
  summary["name"] = c->name;
  summary["a_m"] = p.a_m;
  summary["b_m"] = p.b_m;
  summary["p0_Pa"] = p.p0_Pa;
  summary["approach_m"] = p.approach_m;
  summary["normal_load_N"] = p.normal_load_N;
  summary["C11"] = r->problem.C.C11;
  summary["C22"] = r->problem.C.C22;
  summary["C23"] = r->problem.C.C23;
  summary["C33"] = r->problem.C.C33;
  summary["L_m_per_Pa"] = r->problem.L_m_per_Pa;
  summary["Fx_N"] = s.Fx_N;
  summary["Fy_N"] = s.Fy_N;
  summary["Mz_N_m"] = s.Mz_N_m;
  summary["power_W"] = s.power_W;
  summary["creep_work_W"] = s.creep_work_W;
  summary["stick_fraction"] = s.stick_fraction;
  summary["scheme"] = contact::to_string(r->scheme);
  summary["nx"] = p.grid.nx;
  summary["ny"] = p.grid.ny;
  summary["normal_solver"] = contact::to_string(r->normal.solver);
  summary["normal_solver_reason"] = r->normal.reason;
  // the error estimate against the exact physics (docs/fidelity.md): a contact run makes none
  const bool exact = r->normal.solver == contact::NormalSolverKind::Halfspace && r->scheme == contact::TangentialScheme::Exact;
  summary["error_estimate"] = exact ? "none needed: the exact physics ran" : "not estimated";
  summary["patches"] = r->normal.patches;
  summary["reaches_edge"] = r->normal.reaches_edge;
  if (const auto& l = r->lubrication) {  // summary.csv's film columns (lubricant:)
    summary["entrainment_m_per_s"] = l->entrainment_m_per_s;
    summary["Rx_m"] = l->Rx_m;
    summary["ellipticity_k"] = l->film.ellipticity_k;
    summary["h_min_m"] = l->film.h_min_m;
    summary["h_central_m"] = l->film.h_central_m;
    summary["lambda"] = l->lambda;
    summary["regime"] = contact::to_string(l->regime);
    summary["regime_mu"] = l->mu;
    summary["regime_wear_factor"] = l->wear_factor;
  }
  if (const auto& t = r->thermal) {  // and its flash temperature columns (thermal:); None where not asked
    summary["v1_m_per_s"] = t->v1_m_per_s;
    summary["v2_m_per_s"] = t->v2_m_per_s;
    summary["flash_max_K"] = t->flash.max_rise_K;
    summary["heat_share_body1"] = t->flash.share_body1;
    summary["peclet_body1"] = t->flash.peclet_body1;
    summary["peclet_body2"] = t->flash.peclet_body2;
    summary["contact_temperature_C"] = t->contact_temperature_C ? py::cast(*t->contact_temperature_C) : py::none();
    summary["scuffing_margin_K"] = t->scuffing_margin_K ? py::cast(*t->scuffing_margin_K) : py::none();
  }

  py::dict strips;  // strips.csv's columns; y_m in the profiles' lateral coordinate
  strips["y_m"] = array(Eigen::ArrayXd(p.grid.y_m + r->normal.grid_y0_m));
  strips["half_length_m"] = array(p.half_length_m);
  strips["peak_pressure_Pa"] = array(p.strip_peak_Pa);
  strips["force_x_N_per_m"] = array(s.strip_force_x_N_per_m);
  strips["force_y_N_per_m"] = array(s.strip_force_y_N_per_m);
  strips["power_W_per_m"] = array(s.strip_power_W_per_m);
  strips["creep_power_W_per_m"] = array(s.strip_creep_power_W_per_m);
  strips["trailing_W_per_m"] = array(s.strip_trailing_W_per_m);

  py::dict out;
  out["summary"] = summary;
  out["strips"] = strips;
  if (fields && s.tau_x_Pa.size() > 0) {  // fields.csv's columns as (nx, ny) arrays, a[i, j] at x_m[i], y_m[j]
    py::dict f;
    f["x_m"] = array(p.grid.x_m);
    f["y_m"] = array(p.grid.y_m);
    f["pressure_Pa"] = array(p.pressure_Pa);
    f["tau_x_Pa"] = array(s.tau_x_Pa);
    f["tau_y_Pa"] = array(s.tau_y_Pa);
    f["slip_x_m_per_s"] = array(s.slip_x_m_per_s);
    f["slip_y_m_per_s"] = array(s.slip_y_m_per_s);
    f["power_W_per_m2"] = array(s.power_W_per_m2);
    f["state"] = array(s.state);
    out["fields"] = f;
  }
  if (subsurface) {  // subsurface.csv's maxima, fatigue.csv's and dang_van.csv's values, per body ("body1", "body2")
    py::dict bodies;
    for (int k = 0; k < 2; ++k) {
      const contact::Subsurface& sub = below[k].stresses;
      py::dict b;
      b["nu"] = sub.nu;
      const auto peak = [](const contact::StressPeak& q) {
        py::dict d;
        d["value_Pa"] = q.value_Pa, d["x_m"] = q.x_m, d["y_m"] = q.y_m, d["z_m"] = q.z_m;
        return d;
      };
      b["von_mises"] = peak(sub.maxima.von_mises);
      b["tresca"] = peak(sub.maxima.tresca);
      b["orthogonal_shear"] = peak(sub.maxima.orthogonal_shear);
      b["tension"] = peak(sub.maxima.tension);
      b["compression"] = peak(sub.maxima.compression);
      if (const std::optional<contact::FatigueIndicators>& fi = below[k].fatigue) {
        py::dict d;
        d["shear_yield_Pa"] = fi->shear_yield_Pa;
        d["contact"] = contact::to_string(fi->contact);
        d["traction_coefficient"] = fi->traction_coefficient;
        d["p0_over_k"] = fi->p0_over_k;
        d["limit_p0_over_k"] = fi->limit_p0_over_k;
        d["surface_limit"] = fi->surface_limit;
        d["margin"] = fi->margin;
        d["FI_surf"] = fi->FI_surf;
        d["cell_index_max"] = fi->cell_index_max;
        b["fatigue"] = d;
      }
      if (const std::optional<contact::DangVanField>& dv = below[k].dang_van) {  // dang_van.csv's row
        py::dict d;
        d["a"] = dv->constants.a;
        d["b_Pa"] = dv->constants.b_Pa;
        d["index_max"] = dv->index_max;
        d["x_m"] = dv->x_m, d["y_m"] = dv->y_m, d["z_m"] = dv->z_m;
        d["tau_Pa"] = dv->tau_Pa;
        d["hydrostatic_Pa"] = dv->hydrostatic_Pa;
        b["dang_van"] = d;
      }
      bodies[k == 0 ? "body1" : "body2"] = b;
    }
    out["subsurface"] = bodies;
  }
  return out;
}

// ---- transient -----------------------------------------------------------------------------------------

py::dict transient_result(const CaseSource& source, bool fields, bool force) {
  sync_log_level();
  SignalCheck signals;
  std::optional<contact::ContactCase> c;
  std::optional<contact::TransientCase> t;
  contact::TransientResult res;
  std::vector<contact::TransientRecord> records;
  std::vector<double> strip_power;  // step by step, ny each
  try {
    py::gil_scoped_release release;
    c.emplace(read_case(source, "transient"));
    t.emplace(contact::transient_case_of(*c));
    if (!fields) t->settings.snapshot_times_s.clear();  // not computed either
    // the arrays returned hold every step: refused above output.max_bytes before the run, as the command refuses
    contact::check_transient_output(*c, *t, fields, force);
    const contact::StepObserver observe = [&](const contact::TransientRecord& r, const Eigen::ArrayXd& power) {
      records.push_back(r);
      strip_power.insert(strip_power.end(), power.data(), power.data() + power.size());
      if (signals.interrupted()) throw Interrupted();
    };
    res = contact::run_transient_case(*c, *t, observe);
  } catch (const Interrupted&) {
    signals.rethrow();
  }
  signals.rethrow();

  const std::size_t n = records.size();
  std::vector<long> step(n), shortened(n);
  std::vector<double> cols[16];
  py::list step_scheme;
  for (std::size_t k = 0; k < n; ++k) {
    const contact::TransientRecord& r = records[k];
    step[k] = r.step;
    shortened[k] = r.shortened ? 1 : 0;
    const double v[16] = {r.t_s, r.q_m, r.dt_s, r.speed_m_per_s, r.xi, r.eta, r.phi_per_m, r.normal_load_N,
                          r.omega1_rad_per_s, r.Fx_N, r.Fy_N, r.Mz_N_m, r.power_W, r.stick_fraction,
                          r.balance_residual_W, r.cfl};
    for (int i = 0; i < 16; ++i) cols[i].push_back(v[i]);
    step_scheme.append(contact::to_string(r.scheme));
  }
  static const char* const kNames[16] = {"t_s", "q_m", "dt_s", "speed_m_per_s", "xi", "eta", "phi_per_m",
                                         "normal_load_N", "omega1_rad_per_s", "Fx_N", "Fy_N", "Mz_N_m", "power_W",
                                         "stick_fraction", "balance_residual_W", "cfl"};
  py::dict ts;  // timeseries.csv's columns
  ts["step"] = array(step);
  for (int i = 0; i < 16; ++i) ts[kNames[i]] = array(cols[i]);
  ts["shortened"] = array(shortened);
  ts["step_scheme"] = step_scheme;

  py::dict summary;  // summary.csv's: the last whole step's values
  summary["name"] = c->name;
  summary["scheme"] = contact::to_string(t->settings.scheme);
  summary["nx"] = res.grid.nx;
  summary["ny"] = res.grid.ny;
  summary["steps"] = res.steps;
  summary["t_end_s"] = res.t_end_s;
  summary["q_end_m"] = res.q_end_m;
  // the error estimate against the exact physics (docs/fidelity.md): a transient run makes none
  summary["tangential_model"] = contact::to_string(c->solver.tangential);
  summary["error_estimate"] = c->solver.tangential == contact::TangentialScheme::Exact
                                  ? "none needed: Kalker's exact theory ran" : "not estimated";
  summary["dissipated_J"] = res.dissipated_J;
  summary["Fx_N"] = res.end.Fx_N;
  summary["Fy_N"] = res.end.Fy_N;
  summary["Mz_N_m"] = res.end.Mz_N_m;
  summary["power_W"] = res.end.power_W;
  summary["stick_fraction"] = res.end.stick_fraction;
  summary["omega1_rad_per_s"] = res.end.omega1_rad_per_s;
  summary["end_step"] = res.end.step;
  summary["fallback_steps"] = res.fallback_steps;

  py::dict strips;  // strip_energy.csv, and strip_power.csv as a (steps x ny) array
  strips["y_m"] = array(res.grid.y_m);
  strips["energy_J_per_m"] = array(res.strip_energy_J_per_m);
  py::array_t<double> power({records.size(), static_cast<std::size_t>(res.grid.ny)});
  if (strip_power.size() != static_cast<std::size_t>(power.size()))
    throw std::logic_error("transient: the strip powers do not fill steps x ny");
  std::copy(strip_power.begin(), strip_power.end(), power.mutable_data());
  strips["power_W_per_m"] = power;

  py::list snapshots;  // snapshot_<k>.csv's fields, (nx, ny) each
  for (const contact::Snapshot& s : res.snapshots) {
    py::dict d;
    d["t_s"] = s.t_s;
    d["x_m"] = array(res.grid.x_m);
    d["y_m"] = array(res.grid.y_m);
    d["pressure_Pa"] = array(s.pressure_Pa);
    d["tau_x_Pa"] = array(s.tau_x_Pa);
    d["tau_y_Pa"] = array(s.tau_y_Pa);
    d["slip_x_m_per_s"] = array(s.slip_x_m_per_s);
    d["slip_y_m_per_s"] = array(s.slip_y_m_per_s);
    snapshots.append(d);
  }
  py::dict out;
  out["summary"] = summary;
  out["timeseries"] = ts;
  out["strips"] = strips;
  out["snapshots"] = snapshots;
  return out;
}

// ---- run: the wear life --------------------------------------------------------------------------------

py::dict run_result(const CaseSource& source) {
  sync_log_level();
  SignalCheck signals;
  std::optional<wear::WearCase> c;
  std::optional<wear::WearModel> m;
  wear::LifeResult life;
  double hours_per_rev = 0;
  // summary.csv's rows (step 0 unworn) and the worn profiles at the snapshot revolutions (start and end too)
  std::vector<std::vector<double>> rows;
  std::vector<double> snapshot_N;
  std::vector<Eigen::VectorXd> snapshot_state;
  {
    py::gil_scoped_release release;
    c.emplace(read_wear(source));
    m.emplace(wear::make_wear_model(*c));
    hours_per_rev = wear::hours_per_revolution(*m);
    wear::WearCache cache;
    // the life as rollwear run drives it (session/wear_life_run.h), its rows kept as numbers
    session::WearLifeObserver observer;
    observer.on_row = [&](const wear::LifeStep& s) {
      const Eigen::VectorXd& h = *s.state;
      const wear::ContactReport& k = s.contact;
      rows.push_back({static_cast<double>(s.step), s.N, s.N * hours_per_rev, wear::max_depth_m(*m, h),
                      wear::worn_volume_m3(*m, h, 1) + wear::worn_volume_m3(*m, h, 2), wear::dissipated_energy_J(*m, h),
                      k.a_m, k.b_m, k.p0_Pa, k.Fx_N, k.power_W, s.info.step, s.info.error_estimate,
                      static_cast<double>(s.info.rejected), static_cast<double>(s.info.rhs_evals),
                      wear::max_damage(*m, h)});
    };
    observer.on_step = [&](const wear::LifeStep&) {
      return !signals.interrupted();  // false stops the life (LifeEnd::Stopped)
    };
    observer.on_snapshot = [&](double N, const Eigen::VectorXd& state) {
      snapshot_N.push_back(N);
      snapshot_state.push_back(state);
    };
    const wear::LifeStart start = session::fresh_wear_start(*m, cache, observer);
    snapshot_N.push_back(0);
    snapshot_state.push_back(start.state);
    life = session::drive_wear_life(*m, *c, start, cache, observer);
    snapshot_N.push_back(life.N);
    snapshot_state.push_back(life.state);
  }
  signals.rethrow();

  static const char* const kColumns[16] = {"step", "revolutions", "hours", "max_depth_m", "worn_volume_m3",
                                           "dissipated_J", "a_m", "b_m", "p0_Pa", "Fx_N", "power_W",
                                           "step_revolutions", "error_estimate", "rejected", "rhs_evals",
                                           "max_damage"};
  py::dict steps;  // summary.csv's columns (max_damage with wear.fatigue, as summary.csv)
  const std::size_t columns = m->fatigue ? 16 : 15;
  for (std::size_t i = 0; i < columns; ++i) {
    std::vector<double> col;
    for (const std::vector<double>& r : rows) col.push_back(r[i]);
    steps[kColumns[i]] = array(col);
  }
  py::dict profiles;  // snapshots/: per wearing body y_m, z_original_m and (snapshots x nodes) depth_m, z_m
  for (int body : {1, 2}) {
    const int n = body == 1 ? m->n1 : m->n2;
    if (n == 0) continue;
    const int offset = body == 1 ? 0 : m->n1;
    const contact::Profile& p = body == 1 ? m->profiles.body1 : m->profiles.body2;
    std::vector<std::vector<double>> depth, z;
    for (const Eigen::VectorXd& h : snapshot_state) {
      depth.emplace_back(h.data() + offset, h.data() + offset + n);
      z.push_back(depth.back());
      for (int i = 0; i < n; ++i) z.back()[static_cast<std::size_t>(i)] += p.z_m(i);
    }
    py::dict d;
    d["y_m"] = array(Eigen::ArrayXd(p.y_m.head(n)));
    d["z_original_m"] = array(Eigen::ArrayXd(p.z_m.head(n)));
    d["revolutions"] = array(snapshot_N);
    d["depth_m"] = matrix(depth, static_cast<std::size_t>(n));
    d["z_m"] = matrix(z, static_cast<std::size_t>(n));
    profiles[fmt::format("body{}", body).c_str()] = d;
  }
  py::dict summary;  // report.txt's
  summary["name"] = m->name;
  summary["ended_by"] = wear::to_string(life.ended_by);
  summary["failure"] = wear::to_string(life.failure);
  summary["message"] = life.message;
  summary["revolutions"] = life.N;
  summary["hours"] = life.N * hours_per_rev;
  summary["max_depth_m"] = wear::max_depth_m(*m, life.state);
  if (m->law1) summary["worn_volume_body1_m3"] = wear::worn_volume_m3(*m, life.state, 1);
  if (m->law2) summary["worn_volume_body2_m3"] = wear::worn_volume_m3(*m, life.state, 2);
  summary["dissipated_J"] = wear::dissipated_energy_J(*m, life.state);
  summary["steps"] = life.counters.steps;
  summary["rejected"] = life.counters.rejected;
  summary["normal_solves"] = life.counters.normal_solves;
  summary["tangential_solves"] = life.counters.tangential_solves;
  // which models ran and the fast models' error estimate: report.txt's keys (wear::fidelity_report)
  summary["tangential_model"] = contact::to_string(m->scheme);
  summary["fidelity"] = contact::to_string(m->fidelity);
  summary["exact_solves"] = life.exact_solves;
  summary["error_estimate_of"] = wear::error_estimate_of(*m);
  summary["error_estimate_N"] = life.error.N;
  summary["error_power_rel"] = life.error.power_rel;
  summary["error_power_l1"] = life.error.power_l1;
  // which failure mode is how far at the end (wear::failure_margins, docs/fatigue.md): with wear.fatigue or
  // wear.limits.shakedown, the numbers report.txt writes
  const bool margins = m->fatigue || m->limits.shakedown || m->limits.scuffing || m->thermal || !life.dang_van.empty();
  if (m->limits.max_depth_m > 0 && margins)
    summary["depth_fraction"] = wear::max_depth_m(*m, life.state) / m->limits.max_depth_m;
  if (m->fatigue) {
    summary["fatigue_law"] = wear::to_string(m->fatigue->law);
    summary["max_damage"] = wear::max_damage(*m, life.state);
    summary["max_damage_y_m"] = wear::max_damage_y_m(*m, life.state);
    summary["max_tgamma_N"] = life.contact.max_tgamma_N;
  }
  if (margins && m->shear_yield_Pa > 0) summary["shakedown_margin"] = life.contact.shakedown_margin;
  if (m->thermal) {
    summary["flash_rise_K"] = life.contact.flash_rise_K;
    if (m->thermal->critical_temperature_C) summary["scuffing_margin_K"] = life.contact.scuffing_margin_K;
  }
  for (const wear::LifeDangVan& d : life.dang_van) {  // on the final worn contact (wear/dang_van_life.h)
    const std::string body = fmt::format("dang_van_body{}_", d.body);
    summary[(body + "index").c_str()] = d.field.index_max;
    summary[(body + "depth_m").c_str()] = d.field.z_m;
    summary[(body + "y_m").c_str()] = d.field.y_m;
    if (d.condition > 0) summary[(body + "condition").c_str()] = d.condition;
  }
  py::dict out;
  out["summary"] = summary;
  out["steps"] = steps;
  out["profiles"] = profiles;
  if (life.ended_by == wear::LifeEnd::Failed || life.ended_by == wear::LifeEnd::NotRun) {
    // as `rollwear run`'s exit 1: the life failed; what it reached is the exception's .result
    raise(g_solver_error, "run " + m->name + ": the life failed at revolution " + fmt::format("{:.6g}", life.N) + ": " + life.message,
          {{"result", out}});
    throw py::error_already_set();
  }
  return out;
}

// ---- sweep ---------------------------------------------------------------------------------------------

// runs the sweep into output_directory (written as `rollwear sweep` writes it); returns that folder
std::string sweep_run(const std::string& path, const std::string& output_directory, int threads, int shard_k,
                      int shard_n, bool force) {
  sync_log_level();
  SignalCheck signals;
  std::string dir;
  try {
    py::gil_scoped_release release;
    const session::Sweep s = session::read_sweep(path);
    session::SweepRunOptions o;
    if (!(shard_n >= 1 && shard_k >= 1 && shard_k <= shard_n))
      throw contact::CaseError("sweep: shard K/N needs 1 <= K <= N, got " + std::to_string(shard_k) + "/" +
                                   std::to_string(shard_n),
                               contact::InputLocation{"", 0, 0, "shard"});
    o.shard_k = shard_k;
    o.shard_n = shard_n;
    o.output_directory = session::output_directory(output_directory, s.output_directory,
                                                  std::filesystem::path(path).stem().string());
    dir = o.output_directory.string();
    if (threads < 0)  // as `rollwear sweep -j` refuses it
      throw contact::CaseError("sweep: threads: must be >= 0 (0: every core), got " + std::to_string(threads),
                               contact::InputLocation{"", 0, 0, "threads"});
    o.threads = threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
    o.progress_interval_s = 0.05;
    o.force = force;  // above session::kSweepMaxCases cases, as --force
    o.cancelled = [&] { return signals.interrupted(); };
    session::run_sweep(s, o);
  } catch (const session::SweepCancelled&) {
    signals.rethrow();
    throw;
  }
  return dir;
}

}  // namespace

PYBIND11_MODULE(_rollwear, m) {
  m.doc() = "rollwear's C++ engine; use the package rollwear (docs/python.md)";

  g_error = PyErr_NewException("rollwear.Error", PyExc_RuntimeError, nullptr);
  const py::tuple input_bases = py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError));
  g_input_error = PyErr_NewException("rollwear.InputError", input_bases.ptr(), nullptr);
  g_solver_error = PyErr_NewException("rollwear.SolverError", g_error, nullptr);
  m.attr("Error") = py::handle(g_error);
  m.attr("InputError") = py::handle(g_input_error);
  m.attr("SolverError") = py::handle(g_solver_error);
  py::register_exception_translator(&translate);

  // spdlog's default logger: Python's logging (the CLI's is stderr, set in app/main.cpp)
  auto logger = std::make_shared<spdlog::logger>("rollwear", std::make_shared<PythonLogSink>());
  spdlog::set_default_logger(logger);
  // at exit no message may reach a Python that is going away
  py::module_::import("atexit").attr("register")(py::cpp_function([] { PythonLogSink::closed() = true; }));

  m.def("contact", [](const std::string& c, bool is_text, const std::string& base_dir, bool fields, bool subsurface) {
          return contact_result({c, is_text, base_dir}, fields, subsurface);
        },
        py::arg("case"), py::arg("is_text"), py::arg("base_dir"), py::arg("fields"), py::arg("subsurface"));
  m.def("transient", [](const std::string& c, bool is_text, const std::string& base_dir, bool fields, bool force) {
          return transient_result({c, is_text, base_dir}, fields, force);
        },
        py::arg("case"), py::arg("is_text"), py::arg("base_dir"), py::arg("fields"), py::arg("force") = false);
  m.def("run", [](const std::string& c, bool is_text, const std::string& base_dir) {
          return run_result({c, is_text, base_dir});
        },
        py::arg("case"), py::arg("is_text"), py::arg("base_dir"));
  // the translator's test (python/tests): throws the C++ error named, as the engine would
  m.def("_throw_for_test", [](const std::string& kind) {
    if (kind == "case") throw contact::CaseError("f.yaml:3:5: friction.mu: bad", contact::InputLocation{"f.yaml", 3, 5, "friction.mu"});
    if (kind == "solver") throw contact::SolverError("exact steady solve: not converged");
    if (kind == "normal") throw contact::NormalSolveError("semi-hertz: no approach carries the load");
    if (kind == "invalid_argument") throw std::invalid_argument("inside a solver");
    if (kind == "runtime_error") throw std::runtime_error("out/x is in use by another rollwear run");
  });
  m.def("sweep", &sweep_run, py::arg("path"), py::arg("output_directory"), py::arg("threads"), py::arg("shard_k"),
        py::arg("shard_n"), py::arg("force") = false);
}
