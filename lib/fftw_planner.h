// FFTW's planner keeps global state: plans are made and destroyed one at a time, by every file that plans
// (lib/normal/halfspace.cpp, lib/tangential/exact.cpp, lib/subsurface/subsurface.cpp), under this one mutex.
// fftw_execute on distinct plans is thread-safe and needs no lock.
#pragma once

#include <mutex>

namespace contact {

std::mutex& fftw_planner_mutex();

// The smallest n >= at_least whose prime factors are 2, 3, 5 and 7 only (at_least >= 1): a length FFTW
// transforms with its own codelets. A zero-padded convolution may pad to it instead of exactly twice the
// grid: a length with a larger prime factor (82 = 2 x 41, 322 = 2 x 7 x 23) takes FFTW's generic
// algorithms, 1.1 to 3 times slower per transform (docs/exact-theory.md §5).
int fft_size(int at_least);

}  // namespace contact
