// The command-line program run from a test: its exit status and what it printed.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/test_text.h"

namespace rollwear_test {

struct CommandRun {
  int exit_code = -1;
  std::string out, err;
};

// `rollwear ARGS` (the build's program, ROLLWEAR_EXE) through the shell, its output kept in dir's stdout.txt and
// stderr.txt
inline CommandRun rollwear(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const int status = std::system(("'" + std::string(ROLLWEAR_EXE) + "' " + args + " >'" + out.string() + "' 2>'" +
                                  err.string() + "'").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
}

}  // namespace rollwear_test
