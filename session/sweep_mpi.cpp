// rollwear sweep under MPI (session/sweep_mpi.h).
#include "session/sweep_mpi.h"

#include <mpi.h>

#include <cstdlib>
#include <stdexcept>

#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

namespace session::mpi {

namespace {
constexpr int kCaseTag = 1;  // rank 0 -> a rank: the index of the case to run
constexpr int kStopTag = 2;  // rank 0 -> a rank: no more cases
constexpr int kRowTag = 3;   // a rank -> rank 0: the case's results row
bool g_active = false;

int world_size() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}
}  // namespace

bool start() {
  // started by mpirun (Open MPI, MPICH/PMI or PMIx): only then is MPI initialised
  if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE") && !std::getenv("PMIX_RANK")) return false;
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised && MPI_Init(nullptr, nullptr) != MPI_SUCCESS) throw std::runtime_error("MPI_Init failed");
  g_active = world_size() > 1;
  if (!g_active) MPI_Finalize();
  return g_active;
}

int rank() {
  if (!g_active) return 0;
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

std::function<void(const std::vector<std::pair<long, std::string>>&, const std::function<void(const std::string&)>&)>
dispatch() {
  return [](const std::vector<std::pair<long, std::string>>& pending, const std::function<void(const std::string&)>& finished) {
    std::size_t next = 0;
    int busy = 0;
    const auto send_next = [&](int to) {
      long index = pending[next++].first;
      MPI_Send(&index, 1, MPI_LONG, to, kCaseTag, MPI_COMM_WORLD);
      ++busy;
    };
    for (int r = 1; r < world_size() && next < pending.size(); ++r) send_next(r);
    while (busy > 0) {
      MPI_Status status;
      MPI_Probe(MPI_ANY_SOURCE, kRowTag, MPI_COMM_WORLD, &status);
      int n = 0;
      MPI_Get_count(&status, MPI_CHAR, &n);
      std::string row(static_cast<std::size_t>(n), '\0');
      MPI_Recv(row.data(), n, MPI_CHAR, status.MPI_SOURCE, kRowTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      --busy;
      if (next < pending.size()) send_next(status.MPI_SOURCE);  // the next case to the rank that is free
      finished(row);
    }
  };
}

void serve(const Sweep& s, const std::filesystem::path& output_directory) {
  const YAML::Node base = load_base_case(s);
  for (long ran = 0;; ++ran) {
    long index = -1;
    MPI_Status status;
    MPI_Recv(&index, 1, MPI_LONG, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    if (status.MPI_TAG == kStopTag) {
      spdlog::info("sweep: rank {} ran {} cases", rank(), ran);
      return;
    }
    const CaseOutcome c = run_sweep_case(s, base, index, output_directory);
    const std::string row = results_row(c);
    MPI_Send(row.data(), static_cast<int>(row.size()), MPI_CHAR, 0, kRowTag, MPI_COMM_WORLD);
  }
}

void finish() {
  if (!g_active) return;
  if (rank() == 0) {
    long none = -1;
    for (int r = 1; r < world_size(); ++r) MPI_Send(&none, 1, MPI_LONG, r, kStopTag, MPI_COMM_WORLD);
  }
  g_active = false;
  MPI_Finalize();
}

}  // namespace session::mpi
