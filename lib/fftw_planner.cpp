#include "lib/fftw_planner.h"

namespace contact {

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace contact
