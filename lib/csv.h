// Result files: CSV text built in memory (so it can be tested), then written atomically. SI units,
// each in its column's name; numbers at full double precision (%.17g), so a file reads back exactly.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lib/patch.h"
#include "lib/tangential.h"

namespace contact {

// Writes text to path through a temporary file in the same directory (path + ".tmp.<pid>"), then
// renames it over path: a reader sees the old file or the new one, never a part. Creates the parent
// directories. On failure removes the temporary file and throws std::runtime_error naming path.
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

struct OutputFile {
  std::filesystem::path path;
  std::string text;
};
// Several files: all temporary files are written first, then renamed one by one, so a failure while
// writing (disk full, no permission) replaces none of them.
void write_files_atomic(const std::vector<OutputFile>& files);

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
std::string summary_csv(const std::string& name, const ContactPatch& patch, const TangentialProblem& problem,
                        const TangentialSolution& solution, TangentialScheme scheme);

// a text field quoted as RFC 4180 wants when it holds a comma, a quote or a line break
std::string csv_text(const std::string& text);

}  // namespace contact
