// Text the tests read: a file's whole text, its lines, the message of an exception.
#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace rollwear_test {

// the whole file ("" if it cannot be read)
inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// the std::invalid_argument message f throws, or "no exception"
inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no exception";
}

// text with each (from, to) applied once, in order: the first occurrence of from becomes to; a from that is not in
// the text fails the test that asked (a case file changed under the test)
inline std::string replaced(std::string text, std::initializer_list<std::pair<std::string, std::string>> swaps) {
  for (const auto& [from, to] : swaps) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace rollwear_test
