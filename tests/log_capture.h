// The tests' log capture (installed by tests/test_main.cpp): spdlog's default logger records every
// message at warn or above, and a test that logged one fails at its end ("warn is trouble"), unless
// the message was logged while an ExpectWarnings guard was alive. A test that means to warn:
//   const ExpectWarnings warnings;
//   const TangentialSolution s = solve_steady(patch, problem);
//   ASSERT_EQ(warnings.count(), 1);
//   EXPECT_NE(warnings.messages()[0].find("iterations"), std::string::npos);
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rollwear_test {

class ExpectWarnings {
 public:
  ExpectWarnings();  // from here on, warnings are allowed and recorded
  ~ExpectWarnings();
  ExpectWarnings(const ExpectWarnings&) = delete;
  ExpectWarnings& operator=(const ExpectWarnings&) = delete;

  int count() const;                          // messages at warn or above since construction
  std::vector<std::string> messages() const;  // their text, oldest first

 private:
  std::size_t first_;  // index of the first message recorded after construction
};

}  // namespace rollwear_test
