// rollwear sweep: many wear lives of one base case on all cores (wear/sweep.h, docs/sweeps.md).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

struct SweepOptions {
  std::string sweep_path;
  std::string output_directory;  // -o: the sweep's folder, or with --merge the merged table's
  std::string shard = "1/1";     // K/N
  int threads = 0;               // 0: every core (std::thread::hardware_concurrency)
  bool quiet = false;
  std::vector<std::string> merge;  // --merge DIR...
};

CLI::App* add_sweep_command(CLI::App& app, SweepOptions& opt);
int run_sweep_command(const SweepOptions& opt);
