#include "lib/number.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace contact {

// std::to_chars(general)'s text, built from the shortest decimal digits of Dragonbox (the algorithm {fmt}
// formats with; fmt::detail::dragonbox::to_decimal is exported by libfmt). Both give the fewest digits that
// read back exactly, the closest to the value among those, so the digits are the same; the layout is
// libstdc++'s: %g's choice at its default precision 6, scientific where the decimal exponent X < -4 or
// X >= 6 (1500, 123456.7, 1.234567e+06, 1.234e-05), at least two exponent digits. tests/unit/test_number.cpp compares every byte with std::to_chars.
namespace {

// "00" to "99"
constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// exactly eight digits of x < 10^8 at p: two halves of four, each two pairs, no division waiting on another
// (a digit per 64-bit division, one after the other, costs more than Dragonbox itself)
inline void eight_digits(char* p, uint32_t x) {
  const uint32_t hi = x / 10000, lo = x % 10000;
  std::memcpy(p, kPairs + 2 * (hi / 100), 2);
  std::memcpy(p + 2, kPairs + 2 * (hi % 100), 2);
  std::memcpy(p + 4, kPairs + 2 * (lo / 100), 2);
  std::memcpy(p + 6, kPairs + 2 * (lo % 100), 2);
}

constexpr uint64_t kPow10[] = {1ull, 10ull, 100ull, 1000ull, 10000ull, 100000ull, 1000000ull, 10000000ull,
                               100000000ull, 1000000000ull, 10000000000ull, 100000000000ull, 1000000000000ull,
                               10000000000000ull, 100000000000000ull, 1000000000000000ull,
                               10000000000000000ull, 100000000000000000ull, 1000000000000000000ull};

// the decimal digits of 0 < s < 10^18 (a double's shortest significand has at most 17): all eighteen at
// buf (leading zeros included), returns how many count
inline int significand_digits(char* buf, uint64_t s) {
  const uint64_t top = s / 10000000000000000ull, rest = s % 10000000000000000ull;
  std::memcpy(buf, kPairs + 2 * top, 2);
  eight_digits(buf + 2, static_cast<uint32_t>(rest / 100000000u));
  eight_digits(buf + 10, static_cast<uint32_t>(rest % 100000000u));
  const int bits = 64 - __builtin_clzll(s);
  const int guess = (bits * 1233) >> 12;  // floor(log10(2^bits)), one short at most
  return guess + (s >= kPow10[guess] ? 1 : 0);
}

}  // namespace

char* round_trip_to(char* first, char* last, double v) {
  if (last - first < kRoundTripMaxChars || !std::isfinite(v)) {
    const std::to_chars_result r = std::to_chars(first, last, v, std::chars_format::general);
    return r.ec == std::errc() ? r.ptr : first;
  }
  char* p = first;
  if (std::signbit(v)) {
    *p++ = '-';
    v = -v;
  }
  if (v == 0) {
    *p++ = '0';
    return p;
  }
  const auto d = fmt::detail::dragonbox::to_decimal(v);
  char digits[40];  // 18 digits, then room to copy 18 at a time from any of them
  const int P = significand_digits(digits, d.significand);
  const char* dig = digits + 18 - P;
  const int X = d.exponent + P - 1;
  if (X < -4 || X >= 6) {
    *p++ = dig[0];
    if (P > 1) {
      *p++ = '.';
      std::memcpy(p, dig + 1, 17);  // fixed lengths, the excess overwritten or past the end (room for it)
      p += P - 1;
    }
    *p++ = 'e';
    *p++ = X < 0 ? '-' : '+';
    const int a = X < 0 ? -X : X;
    if (a >= 100) *p++ = static_cast<char>('0' + a / 100);
    *p++ = static_cast<char>('0' + a / 10 % 10);
    *p++ = static_cast<char>('0' + a % 10);
  } else if (X >= 0) {
    const int whole = std::min(P, X + 1);
    std::memcpy(p, dig, 17);
    p += whole;
    std::memset(p, '0', 6);
    p += X + 1 - whole;
    if (P > X + 1) {
      *p++ = '.';
      std::memcpy(p, dig + X + 1, 17);
      p += P - X - 1;
    }
  } else {
    *p++ = '0';
    *p++ = '.';
    std::memset(p, '0', 4);
    p += -X - 1;
    std::memcpy(p, dig, 17);
    p += P;
  }
  return p;
}

}  // namespace contact
