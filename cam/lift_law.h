// The follower's lift s(theta) over one cam revolution and its first two derivatives in cam angle
// (docs/cam-follower.md §1). Two forms:
//   dwell-rise-dwell-return: rise of lift h over beta_r from theta = 0, dwell high, return over beta_d,
//     dwell low (on the base circle) to 2 pi. Each moving segment is, with u = (theta - theta_0)/beta:
//       cycloidal      s = h (u - sin(2 pi u)/(2 pi))       s'' = 2 pi h/beta^2 sin(2 pi u)
//       3-4-5          s = h (10u^3 - 15u^4 + 6u^5)         s'' = h/beta^2 (60u - 180u^2 + 120u^3)
//       harmonic       s = h (1 - cos(pi u))/2              s'' = pi^2 h/(2 beta^2) cos(pi u)
//     (a return is the rise mirrored: s = h - s_rise(u)). The harmonic's acceleration does not vanish at
//     its ends, so next to a dwell it jumps: make_dwell_rise_dwell_return refuses any law whose
//     acceleration jumps at a boundary, naming the angle (CamError AccelerationJump).
//   table: lift at n equally spaced angles over [0, 2 pi), fitted by a periodic quintic interpolating
//     spline (C4: s'' continuous); refused (CamError TableFit, naming the angle) where the fit's s''
//     at a node departs from the data's central difference (s_{i+1} - 2 s_i + s_{i-1})/h^2 by more than
//     `tolerance` times the largest |central difference| (a table too coarse for its acceleration, or one
//     whose acceleration jumps).
// Angles in rad, lift in m; s' in m/rad, s'' in m/rad^2.
#pragma once

#include <string>
#include <vector>

namespace cam {

enum class SegmentLaw { Dwell, Cycloidal, Polynomial345, Harmonic };

// "dwell" | "cycloidal" | "polynomial-345" | "harmonic"; throws std::invalid_argument otherwise
SegmentLaw parse_segment_law(const std::string& name);
const char* to_string(SegmentLaw law);

struct LiftSample {
  double s_m = 0;
  double ds_m_per_rad = 0;
  double d2s_m_per_rad2 = 0;
};

// a rise of h_m (negative: a fall) over beta_rad at u = (theta - start)/beta in [0, 1]
LiftSample segment_lift(SegmentLaw law, double h_m, double beta_rad, double u);

struct Segment {
  SegmentLaw law = SegmentLaw::Dwell;
  double start_rad = 0, duration_rad = 0;
  double s_start_m = 0;  // lift at its start
  double rise_m = 0;     // change of lift over it (negative for a return)
};

struct DwellRiseDwellReturn {
  SegmentLaw rise_law = SegmentLaw::Cycloidal;
  SegmentLaw return_law = SegmentLaw::Cycloidal;
  double lift_m = 0;           // > 0
  double rise_rad = 0;         // > 0
  double dwell_high_rad = 0;   // >= 0
  double return_rad = 0;       // > 0; the low dwell is the rest of the revolution (>= 0)
};

// The periodic quintic interpolating spline on n uniform nodes theta_i = i h, h = 2 pi/n: s(theta) =
// sum_j c_j B5(theta/h - j) with the centred quintic B-spline B5, whose values at the nodes are
// (1, 26, 66, 26, 1)/120; c solves that circulant system (diagonally dominant, by Jacobi iteration).
struct PeriodicQuinticSpline {
  double h_rad = 0;
  std::vector<double> c;      // (n) B-spline coefficients
  std::vector<double> lift_m; // (n) the data
};

struct LiftLaw {
  std::vector<Segment> segments;       // dwell-rise-dwell-return, covering [0, 2 pi); empty for a table
  bool is_table = false;
  PeriodicQuinticSpline table;
  double max_abs_d2s_m_per_rad2 = 0;   // over the revolution (segments: exact; table: at the nodes)
};

// relative size of an acceleration jump that refuses a law: the ends of cycloidal and 3-4-5 segments
// vanish to rounding (sin 2 pi ~ 2.4e-16); a harmonic next to a dwell jumps by its full peak
constexpr double kAccelerationJumpRtol = 1e-9;
// Jacobi sweeps of the spline system stop when a sweep changes no coefficient by more than this times
// max |s|: the contraction factor is 54/66 per sweep, so the error left is below 4.5 times that change
// (~150 sweeps; 1e-15 would stall on the rounding of 120 s/66)
constexpr double kSplineSolveRtol = 1e-13;

// throws std::invalid_argument for bad sizes (beta <= 0, lift <= 0, rise + dwell + return > 2 pi),
// CamError AccelerationJump naming the boundary's angle
LiftLaw make_dwell_rise_dwell_return(const DwellRiseDwellReturn& d);

// lift_m[i] at theta = 2 pi i/n (n >= 8); throws std::invalid_argument for too few points or non-finite
// values, CamError TableFit naming the worst node's angle when the check fails
LiftLaw make_table_law(const std::vector<double>& lift_m, double tolerance);

// s, s', s'' at any theta (taken modulo 2 pi)
LiftSample lift_at(const LiftLaw& law, double theta_rad);

}  // namespace cam
