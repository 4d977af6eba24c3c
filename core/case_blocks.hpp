#pragma once
// The case model's readers of the common blocks, one file each (core/case_<block>.cpp), used by
// build_case (case_model.cpp). Each reads through JsonBlock and throws InputError naming the key.
#include <istream>
#include <string>

#include <nlohmann/json.hpp>

#include "case_model.hpp"
#include "json_block.hpp"

namespace dc {

/// "profile": the body's shape; a table profile's CSV read relative to `base_dir`.
ProfileSpec read_profile(const nlohmann::json& j, int dimension, const std::string& base_dir);

/// The CSV of a table profile (a header naming the columns x, y (optional) and h, then rows;
/// blank lines and lines starting with # skipped) into p.table_x/y/h, heights shifted to a
/// minimum of 0. Throws InputError naming `file_key` and the line.
void read_profile_table(std::istream& in, ProfileSpec& p, const std::string& file_key);

/// "grid": nx, ny, bounds or `extent` (the Hertz contact of `c`'s profile, materials and
/// normal load, when `has_normal`).
Grid read_grid(const nlohmann::json& j, const Case& c, bool has_normal);

/// The profile must be able to touch inside the grid (else the load cannot be carried).
void check_contact_in_grid(const Case& c);

/// {"value": v, "rate": r} at `parent.k` (both default 0): a load component v + r t.
inline ValueRate read_value_rate(const JsonBlock& parent, const char* k) {
  const JsonBlock v = parent.child(k);
  v.allow({"value", "rate"});
  // Forces (N) and moments (N m) of real machines lie far inside these bounds.
  const double value = v.has("value") ? v.bounded("value", -1e15, 1e15, "(N or N m)") : 0.0;
  const double rate = v.has("rate") ? v.bounded("rate", -1e18, 1e18, "(N/s or N m/s)") : 0.0;
  return {value, rate};
}

/// Problem finite (core/case_fe_body.cpp): fe_body, grid (x/y bounds) and normal, all required.
void read_finite_blocks(const nlohmann::json& document, Case& c, const std::string& base_dir);

}  // namespace dc
