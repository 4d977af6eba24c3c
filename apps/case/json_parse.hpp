#pragma once
// Parsing JSON text for the case model, checked while it is read: nesting depth bounded,
// duplicate keys and numbers outside the double range rejected, each naming the key path.
#include <string>

#include <nlohmann/json.hpp>

namespace dc::case_json {

/// The deepest nesting of arrays and objects a case may have (a case needs fewer than 10).
inline constexpr int kMaxJsonDepth = 64;

/// Parses `text`. Throws InputError naming the key path (below `base_path`; the top level is
/// `origin`) for a nesting deeper than kMaxJsonDepth, a duplicate key in an object or a number
/// that is not a finite double (1e999); malformed JSON is rethrown as nlohmann's parse_error.
nlohmann::json parse_json_checked(const std::string& text, const std::string& origin,
                                  const std::string& base_path = "", bool ignore_comments = true);

}  // namespace dc::case_json
