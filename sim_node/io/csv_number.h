#pragma once
// A number in the CSV files: the bytes printf's "%.9g" writes (docs/command_line.md, "Output
// files"), 9 significant digits, the shorter of fixed and exponent form, trailing zeros
// dropped, at about a fifth of the instructions of std::to_chars with a precision (98
// against 490 a number: docs/benchmarks.md, "Against MoorDyn").
//
// The digits: for 1e-14 <= |x| < 1e30 (where 10^k, |k| <= 22, is a double, so one product or
// quotient y = |x| 10^k in [1e8, 1e9) carries a single rounding, |y - |x| 10^k| <= ulp(y) / 2
// < 6e-8), n = the integer nearest y is the 9-digit significand printf rounds to, unless the
// fraction of y lies within kTieMargin of 1/2 (the exact value may then lie on either side of
// the tie, or on it: printf rounds the exact binary value half to even). Those, and every
// value outside that range (tiny, subnormal, huge, inf, NaN; zero is written directly, "0" or
// "-0"), go to std::to_chars(general, 9), which the standard defines as printf in the "C"
// locale. tests/unit/csv_writer_test.cc compares both paths with snprintf.

#include <string>

namespace towsim::io {

// the most characters FormatCsvNumber writes ("-1.23456789e-308", "-nan")
inline constexpr int kCsvNumberMaxChars = 24;

// writes x as "%.9g" at `out` (room for kCsvNumberMaxChars), returns the end; no terminator
char* FormatCsvNumber(double x, char* out);

// appends x as "%.9g" to `line`
void AppendCsvNumber(double x, std::string* line);

}  // namespace towsim::io
