// rollwear sweep under MPI (the build option ROLLWEAR_MPI, docs/sweeps.md "MPI"): started by mpirun with
// N ranks, rank 0 runs the sweep as always (validation, the folder's lock, resume, the table and the
// summary) but deals the pending cases to ranks 1..N-1 one at a time, the next case to whichever rank
// returns a row first (dynamic load balancing: lives differ in length by orders of magnitude). Each rank
// runs its case with run_case into the shared output folder and sends back the row. The table is
// the threaded run's, byte for byte (the rows are the cases' own, sorted by index).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "session/sweep.h"

namespace session::mpi {

// true when the program was started by mpirun with more than one rank (MPI initialised here then; a
// run without mpirun never initialises MPI)
bool start();
// this rank (0 without MPI)
int rank();
// rank 0: the dispatch of SweepRunOptions that deals the cases to the other ranks
std::function<void(const std::vector<std::pair<long, std::string>>&, const std::function<void(const std::string&)>&)>
dispatch();
// ranks 1..N-1: run the cases rank 0 sends until it says stop
void serve(const Sweep& s, const std::filesystem::path& output_directory);
// rank 0: tell every other rank to stop (also when the sweep failed); every rank: MPI_Finalize
void finish();

}  // namespace session::mpi
