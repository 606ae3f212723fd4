// The time of one steady contact solve in one process, as a contact sweep runs it per case
// (solve_contact_case of lib/io/case_run.h, fields as the case asks): the "one solve" that docs/sweeps.md's
// per-case overhead leaves out. Median over `passes` passes of `reps` solves each.
//   contact_case_time CASE.yaml [reps = 2000] [passes = 9]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "lib/io/case_run.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: contact_case_time CASE.yaml [reps] [passes]\n");
    return 2;
  }
  const contact::ContactCase c = contact::read_contact_case(argv[1]);
  const int reps = argc > 2 ? std::atoi(argv[2]) : 2000, passes = argc > 3 ? std::atoi(argv[3]) : 9;
  double sink = 0;
  std::vector<double> per_solve_s;
  for (int p = 0; p < passes; ++p) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < reps; ++r) sink += contact::solve_contact_case(c, c.output.fields).solution.Fx_N;
    per_solve_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps);
  }
  std::sort(per_solve_s.begin(), per_solve_s.end());
  std::printf("%s: one solve %.4f ms (median of %d passes of %d; min %.4f, max %.4f)%s\n", argv[1],
              per_solve_s[per_solve_s.size() / 2] * 1e3, passes, reps, per_solve_s.front() * 1e3,
              per_solve_s.back() * 1e3, sink == 0.123 ? " " : "");
  return 0;
}
