# Precompiled headers for the libraries and the program: the outside headers nearly every source includes
# (Eigen, spdlog with fmt, the standard library's most used) parsed once per group of targets instead of once
# per source. A GCC precompiled header serves only the flags it was made with (-fPIC among them), so each
# group is targets that compile with the same flags: its first target makes the header, the others reuse it.
# The test binary has its own (tests/CMakeLists.txt: gtest too, and -O1).
set(ROLLWEAR_PRECOMPILED_HEADERS
  <Eigen/Core> <spdlog/spdlog.h>
  <algorithm> <array> <cmath> <filesystem> <fstream> <functional> <limits> <map> <memory> <optional>
  <stdexcept> <string> <utility> <vector>)

function(rollwear_precompile_headers first)
  target_precompile_headers(${first} PRIVATE ${ROLLWEAR_PRECOMPILED_HEADERS})
  foreach(target IN LISTS ARGN)
    target_precompile_headers(${target} REUSE_FROM ${first})
  endforeach()
endfunction()
