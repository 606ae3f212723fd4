#pragma once
// FFTW's planner keeps global state: every plan in the program (the half-space's, the exact theory's) is made and
// destroyed under this one lock, whichever solver and thread makes it. One lock per solver is not enough: a
// collective's conditions run on threads, one planning a half-space workspace while another plans an exact-theory
// operator (the heap corrupted, or fftw_plan_many_dft returned null).
#include <mutex>

namespace contact {

inline std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace contact
