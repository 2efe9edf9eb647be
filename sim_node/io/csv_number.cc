#include "io/csv_number.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace towsim::io {
namespace {

// 10^k, exact as doubles for k <= 22
constexpr double kPow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                               1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                               1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr int kMaxPow10 = 22;
// |fraction of y - 1/2| below this goes to the exact path: the rounding of y is at most 6e-8
// (csv_number.h), so beyond it y and |x| 10^k round to the same integer
constexpr double kTieMargin = 1e-6;
constexpr int kDigits = 9;  // "%.9g"
constexpr char kTwoDigits[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

char* Exact(double x, char* out) {
  return std::to_chars(out, out + kCsvNumberMaxChars, x, std::chars_format::general, kDigits)
      .ptr;
}

// y = a 10^k with one rounding (|k| <= kMaxPow10)
double Scale(double a, int k) { return k >= 0 ? a * kPow10[k] : a / kPow10[-k]; }

}  // namespace

char* FormatCsvNumber(double x, char* out) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  const bool negative = (bits >> 63) != 0;
  if (biased == 0 && (bits << 1) == 0) {  // +0, -0: "0", "-0"
    if (negative) *out++ = '-';
    *out++ = '0';
    return out;
  }
  if (biased == 0 || biased == 0x7ff) return Exact(x, out);  // subnormal, inf, NaN
  // the decimal exponent e of |x| (10^e <= |x| < 10^(e+1)), first guessed from the binary
  // one to within one: floor(e2 log10 2)
  const double a = std::fabs(x);
  int e = ((biased - 1023) * 78913) >> 18;  // 78913 / 2^18 = log10 2 + 3e-6, an arithmetic shift
  int k = kDigits - 1 - e;  // y = a 10^k in [1e8, 1e9)
  if (k < -kMaxPow10 + 1 || k > kMaxPow10 - 1) return Exact(x, out);
  double y = Scale(a, k);
  if (y >= 1e9) {
    ++e;
    y = Scale(a, --k);
  } else if (y < 1e8) {
    --e;
    y = Scale(a, ++k);
  }
  std::uint32_t n = static_cast<std::uint32_t>(y);  // floor(y), y > 0
  const double fraction = y - n;                    // exact (Sterbenz)
  if (std::fabs(fraction - 0.5) < kTieMargin) return Exact(x, out);
  n += fraction > 0.5 ? 1u : 0u;
  if (n >= 1000000000u) {  // 999999999.5 and up carry into the next decade
    n /= 10;
    ++e;
  }
  if (n < 100000000u) return Exact(x, out);  // not reached: y in [1e8, 1e9) after the guess
  // the digits, then room so that every copy below has a fixed size (inlined moves, not a
  // call): a copy may carry digits beyond the ones kept, which the next write or the end
  // pointer leaves out (at most 1 + 2 + 3 + 9 = 15 or 1 + 9 + 1 + 8 = 19 characters written)
  char digits[2 * kDigits] = {};
  for (int i = kDigits - 1; i > 0; i -= 2) {  // two at a time from the back, the odd one last
    std::memcpy(digits + i - 1, kTwoDigits + 2 * (n % 100), 2);
    n /= 100;
  }
  digits[0] = static_cast<char>('0' + n);
  int count = kDigits;  // significant digits left once the trailing zeros are dropped
  while (count > 1 && digits[count - 1] == '0') --count;
  if (negative) *out++ = '-';
  if (e < -4 || e >= kDigits) {  // d.ddde+XX, at least two exponent digits
    *out++ = digits[0];
    if (count > 1) {
      *out++ = '.';
      std::memcpy(out, digits + 1, kDigits - 1);
      out += count - 1;
    }
    *out++ = 'e';
    *out++ = e < 0 ? '-' : '+';
    const int m = e < 0 ? -e : e;  // <= 30 here
    std::memcpy(out, kTwoDigits + 2 * m, 2);
    return out + 2;
  }
  if (e >= 0) {  // ddd.ddd: e + 1 digits before the point
    std::memcpy(out, digits, kDigits);
    out += e + 1;
    if (count > e + 1) {
      *out++ = '.';
      std::memcpy(out, digits + e + 1, kDigits - 1);
      out += count - e - 1;
    }
    return out;
  }
  std::memcpy(out, "0.000", 5);  // 0.000ddd: -e - 1 zeros after the point
  out += 2 - e - 1;
  std::memcpy(out, digits, kDigits);
  return out + count;
}

void AppendCsvNumber(double x, std::string* line) {
  char text[kCsvNumberMaxChars];
  line->append(text, FormatCsvNumber(x, text) - text);
}

}  // namespace towsim::io
