// Result files: CSV text built in memory (so it can be tested), then written atomically. SI units,
// each in its column's name; numbers in the shortest text that reads back exactly (lib/number.h).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lib/grid.h"
#include "lib/patch.h"
#include "lib/subsurface/dang_van.h"
#include "lib/subsurface/shakedown.h"
#include "lib/subsurface/subsurface.h"
#include "lib/tangential/satran.h"
#include "lib/tangential/tangential.h"

namespace contact {

// Writes text to path through a temporary file in the same directory (path + ".tmp.<pid>"), then
// renames it over path: a reader sees the old file or the new one, never a part. Creates the parent
// directories. On failure removes the temporary file and throws std::runtime_error naming path.
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

struct OutputFile {
  std::filesystem::path path;
  std::string text;
};
// A file written piece by piece while a run streams its results (a time series): the pieces go to a
// temporary file next to path (path + ".tmp.<pid>", opened, with the parent directories, by the
// constructor); write_files_atomic renames it over path at the end. Destroyed before that (an
// error), it removes the temporary file: a failed or killed run never leaves a torn path.
// Throws std::runtime_error naming path when the file cannot be opened or written.
class StreamedFile {
 public:
  explicit StreamedFile(std::filesystem::path path);
  ~StreamedFile();
  StreamedFile(const StreamedFile&) = delete;
  StreamedFile& operator=(const StreamedFile&) = delete;

  void append(const std::string& text);
  const std::filesystem::path& path() const { return path_; }
  const std::filesystem::path& temporary_path() const { return tmp_; }
  bool committed() const { return committed_; }

 private:
  friend void write_files_atomic(const std::vector<OutputFile>&, const std::vector<StreamedFile*>&);
  void close();  // flushes and closes; throws naming path on failure

  std::filesystem::path path_, tmp_;
  int in_flight_slot_ = -1;  // tmp_'s registration for unlink_temporaries_in_flight
  std::ofstream out_;
  bool committed_ = false;
};

// Several files: all temporary files are written first, then renamed one by one, so a failure while
// writing (disk full, no permission) replaces none of them. Streamed files are closed first and
// renamed with the others.
void write_files_atomic(const std::vector<OutputFile>& files, const std::vector<StreamedFile*>& streamed = {});

// Unlinks every temporary file that write_files_atomic or a StreamedFile has open at this moment (each is
// registered from before it is created until it is renamed or removed). Async-signal-safe (atomic flags,
// fixed buffers, unlink(2)): for a handler that ends the process on a signal (session/output_folder.h), so
// that no temporary outlives the stop, whichever write the signal fell into.
void unlink_temporaries_in_flight() noexcept;

// fields.csv: one row per grid cell, strip by strip (j outer, i inner):
//   x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,power_W_per_m2,state
// state: 0 outside, 1 stick, 2 slip. Throws std::invalid_argument if the shapes disagree.
std::string fields_csv(const ContactPatch& patch, const TangentialSolution& solution);

// strips.csv: one row per strip:
//   y_m,half_length_m,peak_pressure_Pa,force_x_N_per_m,force_y_N_per_m,power_W_per_m,
//   creep_power_W_per_m,trailing_W_per_m
std::string strips_csv(const ContactPatch& patch, const TangentialSolution& solution);

// summary.csv: a header and one row:
//   name,a_m,b_m,p0_Pa,approach_m,C11,C22,C23,C33,L_m_per_Pa,Fx_N,Fy_N,Mz_N_m,power_W,creep_work_W,
//   stick_fraction,scheme,nx,ny
// (the caller sets C11 ... L_m_per_Pa to nan for a solve of the exact theory, which does not use them)
std::string summary_csv(const std::string& name, const ContactPatch& patch, const TangentialProblem& problem,
                        const TangentialSolution& solution, TangentialScheme scheme);
struct ContactRun;  // lib/io/case_run.h
// summary_csv of a steady run, with the film's columns when it has a lubricant (entrainment_m_per_s,
// Rx_m, ellipticity_k, h_min_m, h_central_m, lambda, regime, regime_mu, regime_wear_factor) and the flash
// temperature's when it has a thermal: section (v1_m_per_s, v2_m_per_s, flash_max_K, heat_share_body1,
// peclet_body1, peclet_body2, contact_temperature_C, scuffing_margin_K; nan where not asked); a dry
// case's is summary_csv's, byte for byte
std::string contact_summary_csv(const std::string& name, const ContactRun& run);

// ---- below the surface (lib/subsurface/) ----

// subsurface.csv: the maxima of each body's stresses below the surface, one row per body and measure (y_m in
// the coordinate the caller gave them: `rollwear contact` the profiles', as strips.csv's):
//   body,nu,measure,value_Pa,x_m,y_m,z_m
// measure: von_mises, tresca ((sigma1 - sigma3)/2), orthogonal_shear (|sigma_xz|), tension (largest sigma1),
// compression (smallest sigma3); z_m the depth into that body. bodies[k] is body k + 1.
std::string subsurface_csv(const std::vector<const Subsurface*>& bodies);

// subsurface_section.csv: each body's stresses on the x-z section through its most loaded cell (the strip
// section_strip, at y_m), one row per plane and cell (body outer, then plane, then x):
//   body,y_m,x_m,z_m,sigma_xx_Pa,sigma_yy_Pa,sigma_zz_Pa,sigma_xy_Pa,sigma_xz_Pa,sigma_yz_Pa,von_mises_Pa,
//   tresca_Pa,sigma_1_Pa,sigma_2_Pa,sigma_3_Pa
std::string subsurface_section_csv(const Grid& grid, const std::vector<const Subsurface*>& bodies);

// fatigue.csv: one row per body with a shear yield stress (bodies[k] is body k + 1, null: none):
//   body,shear_yield_Pa,contact,traction_coefficient,p0_over_k,limit_p0_over_k,surface_limit,margin,FI_surf,
//   cell_index_max,cell_x_m,cell_y_m
std::string fatigue_csv(const std::vector<const FatigueIndicators*>& bodies);

// dang_van.csv: one row per body with Dang Van's constants (bodies[k] is body k + 1, null: none), its largest
// index over one rolling pass and where (the material point's y and depth z, the x where its history peaks),
// with the mesoscopic shear and the hydrostatic stress there:
//   body,a,b_Pa,index_max,x_m,y_m,z_m,tau_Pa,hydrostatic_Pa
std::string dang_van_csv(const std::vector<const DangVanField*>& bodies);

// ---- the transient run (lib/tangential/satran.h) ----

// timeseries.csv: the header, then one row per step (transient_row):
//   step,t_s,q_m,dt_s,speed_m_per_s,xi,eta,phi_per_m,normal_load_N,omega1_rad_per_s,Fx_N,Fy_N,Mz_N_m,
//   power_W,stick_fraction,balance_residual_W,cfl,shortened,step_scheme
// t_s and q_m are where the forces hold (TransientRecord): mid-step for exact shift steps. shortened: 1
// for the last step, cut short to end at t_end_s; step_scheme: what the step ran (shift, standstill,
// upwind, lax-friedrichs; upwind in a shift run is the fallback at CFL < 1).
std::string transient_header();
std::string transient_row(const TransientRecord& r);

// strip_power.csv, long format: the header, then per step one row per strip (strip_power_rows):
//   step,t_s,y_m,power_W_per_m
// y_m: the strips of the run's grid; power_W_per_m: the step's dissipated energy per width / dt.
std::string strip_power_header();
std::string strip_power_rows(const TransientRecord& r, const Eigen::ArrayXd& y_m,
                             const Eigen::ArrayXd& power_W_per_m);

// strip_energy.csv: y_m,energy_J_per_m, one row per strip (the run's time integral of the strip power)
std::string strip_energy_csv(const Grid& grid, const Eigen::ArrayXd& energy_J_per_m);

// snapshot_<k>.csv: the fields at the end of the step that reached the k-th snapshot time, one row
// per grid cell, strip by strip (j outer, i inner), with that step's end time in the last column:
//   x_m,y_m,pressure_Pa,tau_x_Pa,tau_y_Pa,slip_x_m_per_s,slip_y_m_per_s,t_s
// Throws std::invalid_argument if the shapes disagree.
std::string snapshot_csv(const Grid& grid, const Snapshot& s);

// summary.csv of a transient run: a header and one row:
//   name,scheme,nx,ny,steps,t_end_s,q_end_m,dissipated_J,Fx_N,Fy_N,Mz_N_m,power_W,stick_fraction,
//   omega1_rad_per_s,sliding_end_s,end_step,fallback_steps
// Fx_N ... omega1_rad_per_s: the run's end values, result.end (the last whole step's record, not the
// step cut short to end at t_end_s), whose number is end_step; sliding_end_s: the end of gross sliding,
// GrossSliding::end_s (lib/tangential/satran.h), nan if the contact never slid whole or slid to the end; fallback_steps: the
// shift run's steps that ran upwind at CFL < 1.
std::string transient_summary_csv(const std::string& name, TransientScheme scheme, const TransientResult& result,
                                  double sliding_end_s);
// the same with the scheme column given: "exact" for a run of the exact theory (its steps are the
// shift scheme's, the theory is not Satran's)
std::string transient_summary_csv(const std::string& name, const std::string& scheme, const TransientResult& result,
                                  double sliding_end_s);

// a text field quoted as RFC 4180 wants when it holds a comma, a quote or a line break
std::string csv_text(const std::string& text);

}  // namespace contact
