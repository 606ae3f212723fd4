// Why an iterative solver stopped. Messages carry the numbers compared, e.g.
//   "residual 3.1e-09 <= tol 1e-08 after 14 iterations".
// Non-convergence is a status plus a spdlog::warn; the caller decides whether to stop.
#pragma once

#include <string>

namespace contact {

struct SolveStatus {
  enum class Kind { Converged, MaxIterations, Failed } kind = Kind::Failed;
  std::string message = "not run";  // pessimistic default
  int iterations = 0;
  double residual = 0;

  bool converged() const { return kind == Kind::Converged; }
};

}  // namespace contact
