// A cam case file (docs/cam-follower.md §6, cases/cam-follower.yaml): the document's keys `name`, `cam`
// and `output`, read with the project's case reader (lib/io/yaml_reader.h): every key marked, a key left
// over is an error naming file:line:col and its key path, a bad value likewise. Every key is in SI units,
// angles in radians (keys ending _rad, the speed speed_rad_per_s); a key of the former spelling (speed_rpm,
// *_deg) is refused with its SI key and the converted value. A design the model refuses (CamError: an acceleration
// jump, a table fit, an undercut, a pressure angle) becomes a CaseError at its governing key's line.
//
//   name: cam-follower
//   cam:
//     speed_rad_per_s: 31.4159             # constant, > 0 (counter-clockwise); 300 rpm
//     base_radius_m: 0.040
//     offset_m: 0                          # follower axis at x = offset (optional)
//     mu: 0.1                              # roller-cam friction
//     min_radius_m: 0.003                  # convex pitch curve: rho_pitch - R_roller >= this
//     max_pressure_angle_rad: 0.5236       # 30 deg (the default)
//     table_tolerance: 0.02                # lift table only: relative acceleration misfit
//     angle_steps: 720
//     roller: { radius_m: 0.013, width_m: 0.010, crown_radius_m: 0.5, E_Pa: 2.1e11, nu: 0.3,
//               inertia_kg_m2: 5.0e-6, bearing_torque_N_m: 0.002, bearing_drag_N_m_s: 1.0e-5,
//               shear_yield_Pa: 1.2e9 }            # optional k: the fatigue indicators per angle (§18)
//     track:  { width_m: 0.012, crown_radius_m: .inf, E_Pa: 2.1e11, nu: 0.3, shear_yield_Pa: 1.0e9 }
//     follower: { spring_rate_N_per_m: 2.0e4, preload_N: 150, moving_mass_kg: 0.4, guide_mu: 0.05 }
//     tangential: { scheme: relaxed, nx: 40, ny: 40, quasi_steady_tolerance: 1e-3, periodic_rtol: 1e-9,
//                   max_revolutions: 30, compare_full_transient: true }    # optional, these defaults;
//                   # scheme: relaxed (kDefaultTangentialScheme) | consistent | exact (classic refused)
//     normal: { solver: auto }             # optional: auto | semi-hertz | halfspace (hertz refused: auto takes it)
//     lift: { rise_law: cycloidal, lift_m: 0.010, rise_rad: 1.7453, dwell_high_rad: 0.6981,
//             return_law: polynomial-345, return_rad: 1.7453 }
//     # or lift: { table: [[0, 0.0], [0.0174533, 1.2e-6], ...] }  # [angle_rad, lift_m], steps of 2 pi/n from 0
//     #   (each angle checked to 1e-6 rad), < 2 pi
//     lubricant: { viscosity_Pa_s: 0.009, pressure_viscosity_1_per_Pa: 1.6e-8,   # optional (docs/cam-follower.md
//                  roughness_Rq_m: { body1: 0.1e-6, body2: 0.25e-6 },          #   §17): a contact case's lubricant:
//                  friction: { boundary: 0.1, mixed: 0.05, full_film: 0.01 },  #   keys, body1 the roller, body2 the cam
//                  wear_factor: { boundary: 1, mixed: 0.3, full_film: 0 },
//                  friction_by_regime: true }   # optional: the regime law's mu and factor per angle used
//     thermal: { body1: { conductivity_W_per_m_K: 46, density_kg_per_m3: 7800, specific_heat_J_per_kg_K: 460 },
//                body2: { ... }, bulk_temperature_C: 100, critical_temperature_C: 200 }   # optional, likewise
//   output: { directory: out/cam-follower }
#pragma once

#include <optional>
#include <string>

#include "cam/cam_error.h"
#include "cam/periodic_revolution.h"
#include "cam/cam_wear.h"
#include "cam/revolution.h"
#include "lib/errors.h"
#include "lib/io/key_locations.h"

namespace cam {

struct CamCase {
  std::string path;
  std::string name;             // name: or the file's stem
  std::string output_directory; // output.directory, or "" (out/<name>)
  CamModel model;
  CamSolverSettings solver;     // cam.tangential, cam.normal
  std::optional<CamWearSpec> wear;  // cam.wear: the wear and life inputs (cam/cam_wear.h), if given
  CamLubricationSpec lubrication;   // cam.lubricant, cam.thermal (cam/cam_lubrication.h): none, dry
  contact::KeyLocations locations;
};

// throws contact::CaseError (file, line, key)
CamCase read_cam_case(const std::string& path);

// a CamError as bad input at its key's place in the case file: "FILE:LINE:COL: cam.key: what"
contact::CaseError case_error_of(const CamCase& c, const CamError& e);

}  // namespace cam
