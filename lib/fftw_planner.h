// FFTW's planner keeps global state: plans are made and destroyed one at a time, by every file that plans
// (lib/normal/halfspace.cpp, lib/tangential/exact.cpp, lib/subsurface/subsurface.cpp), under this one mutex.
// fftw_execute on distinct plans is thread-safe and needs no lock.
#pragma once

#include <mutex>

namespace contact {

std::mutex& fftw_planner_mutex();

}  // namespace contact
