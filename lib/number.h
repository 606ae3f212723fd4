// Numbers as text, one way each (files and messages alike):
//   round_trip(v)    the shortest text that reads back as the same double (std::to_chars, %g style:
//                    the fewest significant digits that round-trip): "0.0002", "1e-09", "-449.78",
//                    "-1.25e+08", "nan", "inf". Every number the CSV files hold, and a value a
//                    message quotes so that the user can paste it back.
//   six_digits(v)    six significant digits ("%.6g"), for a derived quantity in a message.
#pragma once

#include <charconv>
#include <cstdio>
#include <string>
#include <system_error>

namespace contact {

// the longest shortest-round-trip double: sign, 17 digits, point, "e-308"
constexpr int kRoundTripMaxChars = 32;

// writes round_trip(v) at first (std::to_chars(general)'s text, byte for byte), returns its end; first
// itself if [first, last) is too short
char* round_trip_to(char* first, char* last, double v);

inline std::string round_trip(double v) {
  char buf[kRoundTripMaxChars];
  return std::string(buf, round_trip_to(buf, buf + sizeof buf, v));
}

inline void append_round_trip(std::string& out, double v) {
  char buf[kRoundTripMaxChars];
  out.append(buf, round_trip_to(buf, buf + sizeof buf, v));
}

inline std::string six_digits(double v) {
  char buf[kRoundTripMaxChars];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace contact
