#include "lib/fftw_planner.h"

#include <stdexcept>

namespace contact {

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

int fft_size(int at_least) {
  if (at_least < 1) throw std::invalid_argument("fft_size: the length must be at least 1");
  for (int n = at_least;; ++n) {
    int m = n;
    for (const int p : {2, 3, 5, 7})
      while (m % p == 0) m /= p;
    if (m == 1) return n;
  }
}

}  // namespace contact
