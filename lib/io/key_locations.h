// Where each value of a case file was read: key path -> "FILE:LINE:COL" ("bodies.body1.Rx_m" ->
// "cases/paper.yaml:6:17"), so that cross-key messages point at the file too.
#pragma once

#include <map>
#include <string>

namespace contact {

using KeyLocations = std::map<std::string, std::string>;

}  // namespace contact
