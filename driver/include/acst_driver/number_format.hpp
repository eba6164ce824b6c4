#pragma once
// Fast decimal output for the CSV: 10 significant digits, the same text as printf("%.10g")
// except that a value exactly halfway between two 10-digit decimals may round the other way
// (the scaled value is rounded once in binary). Values outside [1e-4, 1e10) and non-finite ones
// go through std::to_chars (general, 10 digits), which matches %.10g.
#include <charconv>
#include <cmath>
#include <algorithm>
#include <cstdint>
#include <string>

namespace acst::driver {

inline void append_number(std::string& out, double v) {
  const double a = std::fabs(v);
  if (a == 0.0) {
    out += '0';
    return;
  }
  if (!(a >= 1e-4 && a < 1e10)) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 10);
    out.append(buf, r.ptr);
    return;
  }
  // Decimal exponent e with 10^e <= a < 10^(e+1), from the nearest doubles to the powers of ten
  // (all exact integers from 1e0 up, so a * 10^(9 - e) is a single rounding).
  static const double decade[] = {1e-4, 1e-3, 1e-2, 1e-1, 1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  static const double scale[] = {1e13, 1e12, 1e11, 1e10, 1e9, 1e8, 1e7, 1e6, 1e5, 1e4, 1e3, 1e2, 1e1, 1e0};
  int k = 0;
  while (k < 13 && a >= decade[k + 1]) ++k;
  int e = k - 4;
  std::int64_t n = std::llround(a * scale[k]);  // 10 significant digits, in [1e9, 1e10]
  if (n >= 10000000000LL) {  // rounded up to the next decade
    n /= 10;
    ++e;
  }
  if (e > 9 || n < 1000000000LL) {  // 1e10 after rounding (printf switches to an exponent)
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 10);
    out.append(buf, r.ptr);
    return;
  }
  char digits[10];
  for (int i = 9; i >= 0; --i) {
    digits[i] = static_cast<char>('0' + n % 10);
    n /= 10;
  }
  int last = 9;  // drop trailing zeros of the fraction
  const int point = e + 1;  // digits before the decimal point (<= 0: "0.000ddd")
  while (last >= std::max(point, 1) && digits[last] == '0') --last;
  if (v < 0) out += '-';
  if (point <= 0) {
    out += "0.";
    out.append(static_cast<std::size_t>(-point), '0');
    out.append(digits, static_cast<std::size_t>(last + 1));
  } else {
    out.append(digits, static_cast<std::size_t>(point));
    if (last >= point) {
      out += '.';
      out.append(digits + point, static_cast<std::size_t>(last + 1 - point));
    }
  }
}

}  // namespace acst::driver
