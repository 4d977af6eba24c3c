#pragma once
// The value ranges of a creep-force table on the command line: `start:stop:count` (count
// values evenly spaced from start to stop, both included) or a comma-separated list.
#include <string>
#include <vector>

namespace dc::table {

/// Parses `text` for `option` (e.g. "--creepage"). Throws InputError naming the option and
/// the reason: not a number, count < 1 or over kMaxTableValues, start != stop with count 1,
/// non-finite values, an empty list.
std::vector<double> parse_table_range(const std::string& option, const std::string& text);

inline constexpr int kMaxTableValues = 10000;  ///< values per range

}  // namespace dc::table
