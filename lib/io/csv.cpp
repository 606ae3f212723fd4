#include "lib/io/csv.h"
#include "lib/io/case_run.h"
#include "lib/subsurface/stress_measures.h"
#include "lib/number.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <limits>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

namespace contact {
namespace fs = std::filesystem;

namespace {

// one number, exact on reading back, in the fewest characters (lib/number.h)
void put(std::string& out, double v) { append_round_trip(out, v); }

void check_shape(const char* what, Eigen::Index rows, Eigen::Index cols, Eigen::Index nx, Eigen::Index ny) {
  if (rows != nx || cols != ny)
    throw std::invalid_argument(fmt::format("csv: {} is {} x {}, the grid {} x {}", what, rows, cols, nx, ny));
}
void check_length(const char* what, Eigen::Index n, Eigen::Index ny) {
  if (n != ny) throw std::invalid_argument(fmt::format("csv: {} has {} strips, the grid {}", what, n, ny));
}

// the per-cell fields of a file on grid g: the grid's coordinates and each field's shape checked
using CellField = std::pair<const char*, const Eigen::ArrayXXd*>;
void check_cell_fields(const Grid& g, std::initializer_list<CellField> fields) {
  check_length("grid x_m", g.x_m.size(), g.nx);
  check_length("grid y_m", g.y_m.size(), g.ny);
  for (const auto& [what, a] : fields) check_shape(what, a->rows(), a->cols(), g.nx, g.ny);
}

// one row per cell (strip j by strip, i along it): x_m, y_m, each field, then last(i, j) for the last column
template <class Last>
void put_cell_rows(std::string& out, const Grid& g, std::initializer_list<CellField> fields, const Last& last) {
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      put(out, g.x_m(i));
      out += ',';
      put(out, g.y_m(j));
      out += ',';
      for (const CellField& f : fields) {
        put(out, (*f.second)(i, j));
        out += ',';
      }
      last(i, j);
      out += '\n';
    }
  }
}

// The temporaries being written, for a signal handler to unlink (unlink_temporaries_in_flight): fixed
// slots, each claimed by an atomic flag (the sweep's threads write at once), its path written before the
// flag says "in use" and the flag cleared before the slot is reused, so that the handler reads only whole
// paths. A path too long, or no free slot, goes unregistered (the next run's stale-temporary sweep removes
// such a file: session/output_folder.h).
constexpr int kInFlightSlots = 64;
constexpr std::size_t kInFlightPath = 4096;
struct InFlightSlot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 in use
  char path[kInFlightPath];
};
InFlightSlot g_in_flight[kInFlightSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots' flags");

int register_in_flight(const fs::path& tmp) {
  const std::string p = tmp.string();
  if (p.size() >= kInFlightPath) return -1;
  for (int k = 0; k < kInFlightSlots; ++k) {
    int expected = 0;
    if (g_in_flight[k].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_in_flight[k].path, p.c_str(), p.size() + 1);
      g_in_flight[k].state.store(2);
      return k;
    }
  }
  return -1;
}

void release_in_flight(int slot) {
  if (slot >= 0) g_in_flight[slot].state.store(0);
}

// a temporary registered for the signal handler while it exists
class InFlight {
 public:
  explicit InFlight(const fs::path& tmp) : slot_(register_in_flight(tmp)) {}
  ~InFlight() { release_in_flight(slot_); }
  InFlight(const InFlight&) = delete;
  InFlight& operator=(const InFlight&) = delete;

 private:
  int slot_;
};

fs::path temporary_for(const fs::path& path) {
  fs::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());
  return tmp;
}

// writes text to tmp; throws naming path (the file meant) on failure, leaving tmp for the caller
void write_temporary(const fs::path& path, const fs::path& tmp, const std::string& text) {
  if (path.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw std::runtime_error("cannot write " + path.string() + ": " + ec.message());
  }
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.flush();
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
}

void remove_quietly(const fs::path& p) {
  std::error_code ignored;
  fs::remove(p, ignored);
}

}  // namespace

StreamedFile::StreamedFile(fs::path path)
    : path_(std::move(path)), tmp_(temporary_for(path_)), in_flight_slot_(register_in_flight(tmp_)) {
  write_temporary(path_, tmp_, "");  // creates the parent directories and an empty temporary file
  out_.open(tmp_, std::ios::binary | std::ios::app);
  if (!out_) {
    remove_quietly(tmp_);
    release_in_flight(in_flight_slot_);
    throw std::runtime_error("cannot write " + path_.string() + ": " + std::strerror(errno));
  }
}

StreamedFile::~StreamedFile() {
  if (!committed_) {
    out_.close();
    remove_quietly(tmp_);
  }
  release_in_flight(in_flight_slot_);
}

void StreamedFile::append(const std::string& text) {
  out_.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out_) throw std::runtime_error("cannot write " + path_.string() + ": " + std::strerror(errno));
}

void StreamedFile::close() {
  if (!out_.is_open()) return;
  out_.flush();
  out_.close();
  if (!out_) throw std::runtime_error("cannot write " + path_.string() + ": " + std::strerror(errno));
}

void write_files_atomic(const std::vector<OutputFile>& files, const std::vector<StreamedFile*>& streamed) {
  // the streamed files complete, then every other file to its temporary name
  // (on failure the streamed files' temporaries go with their owners)
  for (StreamedFile* s : streamed) s->close();
  std::vector<fs::path> written;
  // each temporary registered before it exists and until it is renamed or removed: a signal that ends the
  // process in between unlinks it (unlink_temporaries_in_flight)
  std::vector<std::unique_ptr<InFlight>> in_flight;
  try {
    for (const OutputFile& f : files) {
      const fs::path tmp = temporary_for(f.path);
      written.push_back(tmp);
      in_flight.push_back(std::make_unique<InFlight>(tmp));
      write_temporary(f.path, tmp, f.text);
    }
  } catch (...) {
    for (const fs::path& tmp : written) remove_quietly(tmp);
    throw;
  }

  // then each over its final name
  for (StreamedFile* s : streamed) {
    std::error_code ec;
    fs::rename(s->tmp_, s->path_, ec);
    if (ec) {
      for (const fs::path& tmp : written) remove_quietly(tmp);
      throw std::runtime_error("cannot write " + s->path_.string() + ": " + ec.message());
    }
    s->committed_ = true;
    spdlog::debug("wrote {}", s->path_.string());
  }
  for (std::size_t k = 0; k < files.size(); ++k) {
    std::error_code ec;
    fs::rename(written[k], files[k].path, ec);
    if (ec) {
      for (std::size_t rest = k; rest < files.size(); ++rest) remove_quietly(written[rest]);
      throw std::runtime_error("cannot write " + files[k].path.string() + ": " + ec.message());
    }
    spdlog::debug("wrote {} ({} bytes)", files[k].path.string(), files[k].text.size());
  }
}

void write_file_atomic(const fs::path& path, const std::string& text) { write_files_atomic({{path, text}}); }

void unlink_temporaries_in_flight() noexcept {
  for (InFlightSlot& slot : g_in_flight)
    if (slot.state.load() == 2) ::unlink(slot.path);
}

std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) {
    if (ch == '"') quoted += '"';
    quoted += ch;
  }
  return quoted + "\"";
}

std::string fields_csv(const ContactPatch& patch, const TangentialSolution& s) {
  const Grid& g = patch.grid;
  const std::initializer_list<CellField> fields = {
      {"pressure_Pa", &patch.pressure_Pa},       {"tau_x_Pa", &s.tau_x_Pa},
      {"tau_y_Pa", &s.tau_y_Pa},                 {"slip_x_m_per_s", &s.slip_x_m_per_s},
      {"slip_y_m_per_s", &s.slip_y_m_per_s},     {"power_W_per_m2", &s.power_W_per_m2}};
  check_cell_fields(g, fields);
  check_shape("state", s.state.rows(), s.state.cols(), g.nx, g.ny);

  std::string out = "x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,power_W_per_m2,state\n";
  out.reserve(out.size() + static_cast<std::size_t>(g.nx) * g.ny * 200);
  put_cell_rows(out, g, fields, [&](int i, int j) { fmt::format_to(std::back_inserter(out), "{}", s.state(i, j)); });
  return out;
}

std::string strips_csv(const ContactPatch& patch, const TangentialSolution& s) {
  const Grid& g = patch.grid;
  check_length("grid y_m", g.y_m.size(), g.ny);
  check_length("half_length_m", patch.half_length_m.size(), g.ny);
  check_length("strip_peak_Pa", patch.strip_peak_Pa.size(), g.ny);
  check_length("strip_force_x_N_per_m", s.strip_force_x_N_per_m.size(), g.ny);
  check_length("strip_force_y_N_per_m", s.strip_force_y_N_per_m.size(), g.ny);
  check_length("strip_power_W_per_m", s.strip_power_W_per_m.size(), g.ny);
  check_length("strip_creep_power_W_per_m", s.strip_creep_power_W_per_m.size(), g.ny);
  check_length("strip_trailing_W_per_m", s.strip_trailing_W_per_m.size(), g.ny);

  std::string out =
      "y_m,half_length_m,peak_pressure_Pa,force_x_N_per_m,force_y_N_per_m,power_W_per_m,"
      "creep_power_W_per_m,trailing_W_per_m\n";
  for (int j = 0; j < g.ny; ++j) {
    const double row[] = {g.y_m(j),
                          patch.half_length_m(j),
                          patch.strip_peak_Pa(j),
                          s.strip_force_x_N_per_m(j),
                          s.strip_force_y_N_per_m(j),
                          s.strip_power_W_per_m(j),
                          s.strip_creep_power_W_per_m(j),
                          s.strip_trailing_W_per_m(j)};
    for (std::size_t k = 0; k < std::size(row); ++k) {
      if (k > 0) out += ',';
      put(out, row[k]);
    }
    out += '\n';
  }
  return out;
}

std::string summary_csv(const std::string& name, const ContactPatch& patch, const TangentialProblem& problem,
                        const TangentialSolution& s, TangentialScheme scheme) {
  std::string out =
      "name,a_m,b_m,p0_Pa,approach_m,C11,C22,C23,C33,L_m_per_Pa,Fx_N,Fy_N,Mz_N_m,power_W,creep_work_W,"
      "stick_fraction,scheme,nx,ny\n";
  out += csv_text(name);
  for (const double v : {patch.a_m, patch.b_m, patch.p0_Pa, patch.approach_m, problem.C.C11, problem.C.C22,
                         problem.C.C23, problem.C.C33, problem.L_m_per_Pa, s.Fx_N, s.Fy_N, s.Mz_N_m, s.power_W,
                         s.creep_work_W, s.stick_fraction}) {
    out += ',';
    put(out, v);
  }
  fmt::format_to(std::back_inserter(out), ",{},{},{}\n", to_string(scheme), patch.grid.nx, patch.grid.ny);
  return out;
}

std::string contact_summary_csv(const std::string& name, const ContactRun& run) {
  std::string base = summary_csv(name, run.normal.patch, run.problem, run.solution, run.scheme);
  if (!run.lubrication && !run.thermal) return base;
  const std::size_t eol = base.find('\n');
  std::string header = base.substr(0, eol), row = base.substr(eol + 1);
  row.pop_back();  // its newline
  const auto add = [&](const char* column, double v) {
    header += ',';
    header += column;
    row += ',';
    put(row, v);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (const auto& l = run.lubrication) {
    add("entrainment_m_per_s", l->entrainment_m_per_s);
    add("Rx_m", l->Rx_m);
    add("ellipticity_k", l->film.ellipticity_k);
    add("h_min_m", l->film.h_min_m);
    add("h_central_m", l->film.h_central_m);
    add("lambda", l->lambda);
    header += ",regime";
    row += ',';
    row += to_string(l->regime);
    add("regime_mu", l->mu);
    add("regime_wear_factor", l->wear_factor);
  }
  if (const auto& t = run.thermal) {
    add("v1_m_per_s", t->v1_m_per_s);
    add("v2_m_per_s", t->v2_m_per_s);
    add("flash_max_K", t->flash.max_rise_K);
    add("heat_share_body1", t->flash.share_body1);
    add("peclet_body1", t->flash.peclet_body1);
    add("peclet_body2", t->flash.peclet_body2);
    add("contact_temperature_C", t->contact_temperature_C.value_or(nan));
    add("scuffing_margin_K", t->scuffing_margin_K.value_or(nan));
  }
  return header + '\n' + row + '\n';
}

}  // namespace contact

namespace contact {

std::string transient_header() {
  return "step,t_s,q_m,dt_s,speed_m_per_s,xi,eta,phi_per_m,normal_load_N,omega1_rad_per_s,Fx_N,Fy_N,Mz_N_m,"
         "power_W,stick_fraction,balance_residual_W,cfl,shortened,step_scheme\n";
}

std::string transient_row(const TransientRecord& r) {
  std::string out = std::to_string(r.step);
  for (const double v : {r.t_s, r.q_m, r.dt_s, r.speed_m_per_s, r.xi, r.eta, r.phi_per_m, r.normal_load_N,
                         r.omega1_rad_per_s, r.Fx_N, r.Fy_N, r.Mz_N_m, r.power_W, r.stick_fraction,
                         r.balance_residual_W, r.cfl}) {
    out += ',';
    put(out, v);
  }
  out += r.shortened ? ",1," : ",0,";
  out += to_string(r.scheme);
  out += '\n';
  return out;
}

std::string strip_power_header() { return "step,t_s,y_m,power_W_per_m\n"; }

std::string strip_power_rows(const TransientRecord& r, const Eigen::ArrayXd& y_m, const Eigen::ArrayXd& power) {
  check_length("strip power", power.size(), y_m.size());
  std::string out;
  out.reserve(static_cast<std::size_t>(y_m.size()) * 64);
  std::string head = std::to_string(r.step) + ',';
  put(head, r.t_s);
  head += ',';
  for (Eigen::Index j = 0; j < y_m.size(); ++j) {
    out += head;
    put(out, y_m(j));
    out += ',';
    put(out, power(j));
    out += '\n';
  }
  return out;
}

std::string strip_energy_csv(const Grid& g, const Eigen::ArrayXd& energy_J_per_m) {
  check_length("grid y_m", g.y_m.size(), g.ny);
  check_length("strip_energy_J_per_m", energy_J_per_m.size(), g.ny);
  std::string out = "y_m,energy_J_per_m\n";
  for (int j = 0; j < g.ny; ++j) {
    put(out, g.y_m(j));
    out += ',';
    put(out, energy_J_per_m(j));
    out += '\n';
  }
  return out;
}

std::string snapshot_csv(const Grid& g, const Snapshot& s) {
  const std::initializer_list<CellField> fields = {
      {"pressure_Pa", &s.pressure_Pa},       {"tau_x_Pa", &s.tau_x_Pa},          {"tau_y_Pa", &s.tau_y_Pa},
      {"slip_x_m_per_s", &s.slip_x_m_per_s}, {"slip_y_m_per_s", &s.slip_y_m_per_s}};
  check_cell_fields(g, fields);

  std::string out = "x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,t_s\n";
  out.reserve(out.size() + static_cast<std::size_t>(g.nx) * g.ny * 180);
  std::string t;
  put(t, s.t_s);
  put_cell_rows(out, g, fields, [&](int, int) { out += t; });
  return out;
}

std::string transient_summary_csv(const std::string& name, TransientScheme scheme, const TransientResult& res,
                                  double sliding_end_s) {
  return transient_summary_csv(name, to_string(scheme), res, sliding_end_s);
}

std::string transient_summary_csv(const std::string& name, const std::string& scheme, const TransientResult& res,
                                  double sliding_end_s) {
  std::string out =
      "name,scheme,nx,ny,steps,t_end_s,q_end_m,dissipated_J,Fx_N,Fy_N,Mz_N_m,power_W,stick_fraction,"
      "omega1_rad_per_s,sliding_end_s,end_step,fallback_steps\n";
  const TransientRecord& end = res.end;
  out += csv_text(name);
  fmt::format_to(std::back_inserter(out), ",{},{},{},{}", csv_text(scheme), res.grid.nx, res.grid.ny, res.steps);
  for (const double v : {res.t_end_s, res.q_end_m, res.dissipated_J, end.Fx_N, end.Fy_N, end.Mz_N_m,
                         end.power_W, end.stick_fraction, end.omega1_rad_per_s, sliding_end_s}) {
    out += ',';
    put(out, v);
  }
  fmt::format_to(std::back_inserter(out), ",{},{}\n", end.step, res.fallback_steps);
  return out;
}

std::string subsurface_csv(const std::vector<const Subsurface*>& bodies) {
  std::string out = "body,nu,measure,value_Pa,x_m,y_m,z_m\n";
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const SubsurfaceMaxima& m = bodies[k]->maxima;
    const std::pair<const char*, const StressPeak*> rows[] = {{"von_mises", &m.von_mises},
                                                             {"tresca", &m.tresca},
                                                             {"orthogonal_shear", &m.orthogonal_shear},
                                                             {"tension", &m.tension},
                                                             {"compression", &m.compression}};
    for (const auto& [name, peak] : rows) {
      fmt::format_to(std::back_inserter(out), "{},", k + 1);
      put(out, bodies[k]->nu);
      out += ',';
      out += name;
      for (const double v : {peak->value_Pa, peak->x_m, peak->y_m, peak->z_m}) {
        out += ',';
        put(out, v);
      }
      out += '\n';
    }
  }
  return out;
}

std::string subsurface_section_csv(const Grid& g, const std::vector<const Subsurface*>& bodies) {
  std::string out =
      "body,y_m,x_m,z_m,sigma_xx_Pa,sigma_yy_Pa,sigma_zz_Pa,sigma_xy_Pa,sigma_xz_Pa,sigma_yz_Pa,von_mises_Pa,"
      "tresca_Pa,sigma_1_Pa,sigma_2_Pa,sigma_3_Pa\n";
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const int j = bodies[k]->section_strip;
    for (const StressPlane& plane : bodies[k]->planes) {
      if (plane.xx.rows() != g.nx || plane.xx.cols() != g.ny)
        throw std::invalid_argument("subsurface_section_csv: a plane is not on the grid");
      for (int i = 0; i < g.nx; ++i) {
        const StressTensor s = plane.at(i, j);
        const std::array<double, 3> p = principal_stresses(s);
        fmt::format_to(std::back_inserter(out), "{}", k + 1);
        for (const double v : {g.y_m(j), g.x_m(i), plane.z_m, s.xx, s.yy, s.zz, s.xy, s.xz, s.yz, von_mises_Pa(s),
                               (p[0] - p[2]) / 2, p[0], p[1], p[2]}) {
          out += ',';
          put(out, v);
        }
        out += '\n';
      }
    }
  }
  return out;
}

std::string fatigue_csv(const std::vector<const FatigueIndicators*>& bodies) {
  std::string out =
      "body,shear_yield_Pa,contact,traction_coefficient,p0_over_k,limit_p0_over_k,surface_limit,margin,FI_surf,"
      "cell_index_max,cell_x_m,cell_y_m\n";
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const FatigueIndicators* f = bodies[k];
    if (!f) continue;
    fmt::format_to(std::back_inserter(out), "{},", k + 1);
    put(out, f->shear_yield_Pa);
    fmt::format_to(std::back_inserter(out), ",{}", to_string(f->contact));
    for (const double v : {f->traction_coefficient, f->p0_over_k, f->limit_p0_over_k}) {
      out += ',';
      put(out, v);
    }
    out += f->surface_limit ? ",1" : ",0";
    for (const double v : {f->margin, f->FI_surf, f->cell_index_max, f->cell_x_m, f->cell_y_m}) {
      out += ',';
      put(out, v);
    }
    out += '\n';
  }
  return out;
}

std::string dang_van_csv(const std::vector<const DangVanField*>& bodies) {
  std::string out = "body,a,b_Pa,index_max,x_m,y_m,z_m,tau_Pa,hydrostatic_Pa\n";
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const DangVanField* d = bodies[k];
    if (!d) continue;
    fmt::format_to(std::back_inserter(out), "{}", k + 1);
    for (const double v : {d->constants.a, d->constants.b_Pa, d->index_max, d->x_m, d->y_m, d->z_m, d->tau_Pa,
                           d->hydrostatic_Pa}) {
      out += ',';
      put(out, v);
    }
    out += '\n';
  }
  return out;
}

}  // namespace contact
