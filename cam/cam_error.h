// A cam design refused by the model's own checks, with what and where as data: the kind, the cam angle at
// which the check failed and the case key that governs it (relative to the cam: section, e.g.
// "min_radius_m"). The command line puts it at that key's line of the case file (exit 2): the design, not
// the solver, is at fault. Decisions read `kind`, never the message.
#pragma once

#include <stdexcept>
#include <string>

namespace cam {

enum class CamErrorKind {
  AccelerationJump,  // a lift law whose acceleration jumps at a segment boundary (harmonic next to a dwell)
  TableFit,          // the table's spline acceleration departs from the data's central differences
  Undercut,          // convex pitch curve with rho_pitch - R_roller < min_radius_m
  PressureAngle,     // |phi| above max_pressure_angle_deg
  Geometry,          // sizes that admit no cam (offset >= prime radius, ...)
};

struct CamError : std::invalid_argument {
  CamError(CamErrorKind kind_, double angle_rad_, std::string key_, const std::string& what)
      : std::invalid_argument(what), kind(kind_), angle_rad(angle_rad_), key(std::move(key_)) {}
  CamErrorKind kind;
  double angle_rad;  // the cam angle where the check failed (NaN when it is not about an angle)
  std::string key;   // the governing key under cam:
};

constexpr double kDegPerRad = 57.295779513082320876798;

}  // namespace cam
