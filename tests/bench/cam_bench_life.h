// What the cam benchmarks share: the life they wear a case's bodies with to reach the states they measure
// on (docs/cam-follower.md §9, §12, §15): Euler's fixed depth steps of 1e-6 m with every angle step solved,
// whatever the case's own stepping and skip, so that "the 8 µm state" is the same state in every program
// and stays so when the shipped case's stepping changes.
#pragma once

#include <memory>

#include "cam/cam_life.h"
#include "cam/worn_revolution.h"

namespace bench {

struct CamBenchLife {
  cam::CamLifeModel model;                    // the case's life, its limits kept, stepped as above
  std::shared_ptr<cam::WornRevolution> worn;  // every angle step solved (no skip)
  cam::DissipationOf producer;                // the unworn revolution at the unworn state, else worn's
};

inline CamBenchLife cam_bench_life(const cam::CamLifeSetup& setup) {
  CamBenchLife b;
  b.model = setup.life;
  b.model.stepping.method = wear::IntegratorOptions::Method::FixedDepth;
  b.model.stepping.max_depth_step_m = 1e-6;
  b.model.scheme = wear::IntegratorOptions::Scheme::Euler;
  b.model.snapshots_revolutions.clear();
  b.worn = std::make_shared<cam::WornRevolution>(setup.model, setup.revolution, setup.motion.motion,
                                                 setup.unworn_profiles, setup.life.grid, setup.dynamics.law);
  b.producer = [&setup, worn = b.worn](const cam::CamWearState& s) {
    if ((s.cam_depth_m == 0).all() && (s.roller_depth_m == 0).all()) return setup.unworn;
    return (*worn)(s);
  };
  return b;
}

// the case's bodies worn until the deeper of them reaches depth_m (no other limit)
inline cam::CamLifeResult cam_worn_to_depth(const cam::CamLifeSetup& setup, double depth_m) {
  CamBenchLife b = cam_bench_life(setup);
  b.model.max_depth_m = depth_m;
  b.model.max_lift_loss_m = 0;
  return cam::run_cam_life(b.model, b.producer);
}

}  // namespace bench
