// What the benchmarks share: the paper's case read from cases/paper.yaml (everything but the
// creepages, which each benchmark sets), and a way to keep results alive.
#pragma once

#include <benchmark/benchmark.h>

#include <string>

#include "lib/io/case.h"

namespace bench {

struct PaperCase {
  contact::Bodies bodies;
  contact::ElasticPair pair;
  double normal_load_N = 0;
  double mu = 0;
  double speed_m_per_s = 0;
};

inline const PaperCase& paper() {
  static const PaperCase c = [] {
    const contact::ContactCase file = contact::read_contact_case(std::string(ROLLWEAR_SOURCE_DIR) + "/cases/paper.yaml");
    return PaperCase{contact::bodies_of(file), contact::materials_of(file), contact::normal_load_of(file),
                     file.friction.mu, contact::speed_of(file)};
  }();
  return c;
}

// keeps a result alive through DoNotOptimize's const overload: the non-const one (asm "+m,r")
// corrupts doubles with GCC 12 and benchmark 1.7.1 (google/benchmark#903)
template <class T>
void keep(const T& value) {
  benchmark::DoNotOptimize(value);
}

}  // namespace bench
