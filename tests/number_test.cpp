// round_trip (lib/number.h) writes std::to_chars(general)'s text from Dragonbox's digits: every byte is
// checked against std::to_chars (the reference: the shortest text that reads back exactly, C++17
// [charconv.to.chars]), and the text read back with strtod gives the same double.
#include <gtest/gtest.h>

#include <charconv>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "lib/number.h"

namespace {

using namespace contact;

std::string to_chars_text(double v) {
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general);
  return std::string(buf, r.ptr);
}

void expect_same_text(double v) {
  const std::string ours = round_trip(v);
  ASSERT_EQ(ours, to_chars_text(v)) << "bits " << std::hex << [&] {
    uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }();
  if (std::isfinite(v)) {
    const double back = std::strtod(ours.c_str(), nullptr);
    ASSERT_EQ(std::memcmp(&back, &v, sizeof v), 0) << ours;  // the same bits, -0 included
  }
}

TEST(Number, RoundTripIsToCharsTextAtTheEdges) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double v : {0.0, -0.0, 1.0, -1.0, 0.1, 0.0002, 0.0001, 0.00012345, 1e-5, 123456.0, 1e15, 1e16, 1e17,
                   1234567890123456.0, 12345678901234567.0, 1.5e3, 1500.0, 1e21, 1e22, 1e23, 1.0 / 3.0, -449.78,
                   -1.25e8, 9.999999999999999e22, DBL_MAX, -DBL_MAX, DBL_MIN, DBL_TRUE_MIN, 4.9e-324, 2.2e-308,
                   1e100, 1e-100, 1.7976931348623157e308, inf, -inf, std::nan("")})
    expect_same_text(v);
  for (int e = -325; e <= 308; ++e) {  // every power of ten and its neighbours
    const double p = std::pow(10.0, e);
    expect_same_text(p);
    expect_same_text(std::nextafter(p, 0.0));
    expect_same_text(std::nextafter(p, inf));
  }
}

// about 0.1 s at -O1: 200 000 random bit patterns (every exponent, subnormals) and field-like values
TEST(Number, RoundTripIsToCharsTextOnRandomDoubles) {
  std::mt19937_64 rng(14);
  for (int i = 0; i < 100000; ++i) {
    const uint64_t b = rng();
    double v;
    std::memcpy(&v, &b, sizeof v);
    expect_same_text(v);
  }
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 100000; ++i) expect_same_text(u(rng) * (i % 2 ? 3e8 : 2e-3));
}

}  // namespace
