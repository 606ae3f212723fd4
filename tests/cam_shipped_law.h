// The shipped cam's lift law (cases/cam-follower.yaml: 10 mm lift, a 100 deg cycloidal rise, 40 deg high dwell,
// a 100 deg 3-4-5 polynomial return), for the cam tests that build a model by hand.
#pragma once

#include "cam/lift_law.h"
#include "lib/numeric.h"

namespace cam {

inline LiftLaw shipped_lift_law() {
  constexpr double kDegree = contact::kPi / 180;
  DwellRiseDwellReturn d;
  d.lift_m = 0.01;
  d.rise_rad = 100 * kDegree;
  d.dwell_high_rad = 40 * kDegree;
  d.return_law = SegmentLaw::Polynomial345;
  d.return_rad = 100 * kDegree;
  return make_dwell_rise_dwell_return(d);
}

}  // namespace cam
