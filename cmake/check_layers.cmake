# The stages of the build, bottom to top, and the check that no source includes a header of a stage
# above its own (docs/conventions.md, "Layout"). Run at build time (the target rollwear_layers, which
# every library depends on): an include against the order fails the build and names the file and line.
#   cmake -DROOT=<source dir> -DSTAMP=<file written on success> -P cmake/check_layers.cmake
# rank of a repository path: the stage it belongs to (lib/ itself is the base: numerics, errors, formatting,
# the grid, the elastic pair, the patch, histories)
function(rollwear_stage_rank path out)
  set(rank -1)
  if(path MATCHES "^lib/(normal|lubrication|thermal)/")
    # the normal problem, and beside it the film thickness and the flash temperature (plain inputs:
    # radii, loads, a grid and a heat flux)
    set(rank 1)
  elseif(path MATCHES "^lib/tangential/")
    set(rank 2)
  elseif(path MATCHES "^lib/model/")
    set(rank 3)
  elseif(path MATCHES "^lib/io/")
    set(rank 4)
  elseif(path MATCHES "^lib/[^/]+$")
    set(rank 0)
  elseif(path MATCHES "^wear/")
    set(rank 5)
  elseif(path MATCHES "^cam/")
    set(rank 6)
  elseif(path MATCHES "^session/")
    set(rank 7)
  elseif(path MATCHES "^(app|python)/")
    set(rank 8)
  endif()
  set(${out} ${rank} PARENT_SCOPE)
endfunction()

if(NOT ROOT)
  message(FATAL_ERROR "check_layers.cmake: -DROOT=<source dir> is required")
endif()
file(GLOB_RECURSE sources RELATIVE "${ROOT}"
  "${ROOT}/lib/*.h" "${ROOT}/lib/*.cpp" "${ROOT}/wear/*.h" "${ROOT}/wear/*.cpp" "${ROOT}/cam/*.h" "${ROOT}/cam/*.cpp"
  "${ROOT}/session/*.h" "${ROOT}/session/*.cpp")
set(violations "")
foreach(source IN LISTS sources)
  rollwear_stage_rank("${source}" own)
  file(STRINGS "${ROOT}/${source}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*$" "\\1" header "${line}")
    rollwear_stage_rank("${header}" theirs)
    if(theirs GREATER own)
      string(APPEND violations "  ${source} includes ${header}, a stage above its own\n")
    endif()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "Includes against the order of the stages (lib/ base -> lib/normal, lib/lubrication, lib/thermal -> "
                      "lib/tangential -> "
                      "lib/model -> lib/io -> wear -> cam -> session -> app, python):\n${violations}")
endif()
if(STAMP)
  file(WRITE "${STAMP}" "stages in order\n")
endif()
