// What the cam benchmarks share: the life they wear a case's bodies with to reach the states they measure
// on (docs/cam-follower.md §9, §12, §15): Euler's fixed depth steps of 1e-6 m with every angle step solved,
// whatever the case's own stepping and skip, so that "the 8 µm state" is the same state in every program
// and stays so when the shipped case's stepping changes.
#pragma once

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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

// the numbers of a CSV file's data rows (comment lines and the header skipped), row by row
inline std::vector<std::vector<double>> csv_rows(const std::filesystem::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error(p.string() + ": cannot read");
  std::vector<std::vector<double>> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// a wear map of a rollwear run's folder (by default its highest number: the life's end) on the life's grid
// snapshot: its number KKKK, or -1 for the last
inline cam::CamWearState cam_state_of_folder(const std::filesystem::path& dir, const cam::CamWearGrid& g,
                                              std::string& which, int snapshot = -1) {
  static const std::regex kMap("wear_map_([0-9]{4})\\.csv");
  int last = -1;
  for (const auto& e : std::filesystem::directory_iterator(dir / "snapshots")) {
    std::smatch m;
    const std::string name = e.path().filename().string();
    if (std::regex_match(name, m, kMap)) last = std::max(last, std::stoi(m[1].str()));
  }
  if (snapshot >= 0) last = snapshot;
  if (last < 0) throw std::runtime_error(dir.string() + "/snapshots: no wear map");
  char k[16];
  std::snprintf(k, sizeof k, "%04d", last);
  which = (dir / "snapshots" / ("wear_map_" + std::string(k) + ".csv")).string();
  cam::CamWearState s = cam::unworn_state(g);
  const auto map = csv_rows(which), roller = csv_rows(dir / "snapshots" / ("roller_wear_" + std::string(k) + ".csv"));
  if (static_cast<long>(map.size()) != static_cast<long>(g.arc_cells) * g.track_cells ||
      static_cast<int>(roller.size()) != g.roller_cells)
    throw std::runtime_error(which + ": not this case's grid");
  for (int i = 0; i < g.arc_cells; ++i)
    for (int j = 0; j < g.track_cells; ++j) s.cam_depth_m(i, j) = map[static_cast<std::size_t>(i * g.track_cells + j)][3];
  for (int j = 0; j < g.roller_cells; ++j) s.roller_depth_m(j) = roller[static_cast<std::size_t>(j)][1];
  return s;
}

}  // namespace bench
