#pragma once
// How rb writes a number for people: `print`, messages and traces all use this one form.

#include <cstddef>
#include <string>

namespace rb {

/// A number as `print` shows it: integers plainly, doubles with up to 15 significant digits and
/// no trailing zeros ("3.5", "0.333333333333333", "1e+20").
std::string formatNumber(double d);

/// Room for formatNumber's text of any double, and of any 64-bit integer.
inline constexpr std::size_t kNumberTextSize = 32;
/// formatNumber's text written into `out` (kNumberTextSize bytes); returns its length.
std::size_t formatNumberTo(double d, char* out);

}  // namespace rb
