#pragma once
// Typed, key-checked reading of one JSON object of a case file (the case layer's only way of
// reading JSON; namespace dc::case_json, used by the readers read_*.cpp). Every bad value throws
// InputError naming the key path and the reason.
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "errors.hpp"
#include "number_text.hpp"

namespace dc::case_json {

using json = nlohmann::json;

/// "prefix.key" (or "key" at the top level).
inline std::string join(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

/// The JSON type of a value, for messages.
inline std::string describe(const json& j) { return j.type_name(); }

/// The largest length a case takes (m): radii, approaches, grid bounds of real bodies are far below.
inline constexpr double kMaxLength = 1e9;

/// A number with six significant digits, for messages.
inline std::string fmt(double v) { return six_digits(v); }

/// A finite number at `key` (InputError "must be a number" / "must be finite" otherwise).
inline double finite_number(const json& v, const std::string& key) {
  if (!v.is_number()) throw InputError(key, "must be a number, got " + describe(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw InputError(key, "must be finite");
  return d;
}

/// A JSON object at `path` with typed, key-checked accessors.
class JsonBlock {
 public:
  JsonBlock(const json& j, std::string path) : j_(j), path_(std::move(path)) {
    if (!j.is_object())
      throw InputError(path_.empty() ? "case" : path_, "expected an object, got " + describe(j));
  }

  /// Rejects every key not in `keys` (naming the allowed ones).
  void allow(std::initializer_list<const char*> keys) const { allow(std::vector<const char*>(keys)); }
  void allow(const std::vector<const char*>& keys) const {
    for (auto it = j_.begin(); it != j_.end(); ++it) {
      bool ok = false;
      for (const char* k : keys) ok = ok || it.key() == k;
      if (!ok) {
        std::string list;
        for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
        throw InputError(key(it.key()), "unknown key (allowed here: " + list + ")");
      }
    }
  }

  bool has(const char* k) const { return j_.contains(k); }
  std::string key(const std::string& k) const { return join(path_, k); }
  const std::string& path() const { return path_; }

  /// The object at `k` as a block (path "path.k").
  JsonBlock child(const char* k) const { return JsonBlock(at(k), key(k)); }
  const json& raw() const { return j_; }

  const json& at(const char* k) const {
    if (!j_.contains(k)) throw InputError(key(k), "missing required key");
    return j_.at(k);
  }

  double number(const char* k) const { return finite_number(at(k), key(k)); }
  double number_or(const char* k, double fallback) const { return has(k) ? number(k) : fallback; }

  int integer(const char* k) const {
    const json& v = at(k);
    if (!v.is_number()) throw InputError(key(k), "expected an integer, got " + describe(v));
    const double d = v.get<double>();
    if (d != std::floor(d) || std::abs(d) > 1e9)
      throw InputError(key(k), "expected an integer, got " + fmt(d));
    return static_cast<int>(d);
  }
  int integer_or(const char* k, int fallback) const { return has(k) ? integer(k) : fallback; }

  bool boolean(const char* k) const {
    const json& v = at(k);
    if (!v.is_boolean()) throw InputError(key(k), "expected true or false, got " + describe(v));
    return v.get<bool>();
  }
  bool boolean_or(const char* k, bool fallback) const { return has(k) ? boolean(k) : fallback; }

  std::string string(const char* k) const {
    const json& v = at(k);
    if (!v.is_string()) throw InputError(key(k), "expected a string, got " + describe(v));
    return v.get<std::string>();
  }
  std::string string_or(const char* k, const std::string& fallback) const {
    return has(k) ? string(k) : fallback;
  }

  std::string choice(const char* k, const std::string& fallback,
                     std::initializer_list<const char*> options) const {
    const std::string v = string_or(k, fallback);
    std::string list;
    for (const char* o : options) {
      if (v == o) return v;
      list += (list.empty() ? "" : ", ") + std::string(o);
    }
    throw InputError(key(k), "unknown value '" + v + "' (expected one of: " + list + ")");
  }

  std::vector<double> numbers(const char* k) const {
    const json& v = at(k);
    if (!v.is_array()) throw InputError(key(k), "expected an array of numbers, got " + describe(v));
    std::vector<double> out;
    for (const auto& e : v) {
      if (!e.is_number()) throw InputError(key(k), "expected an array of numbers, found " + describe(e));
      out.push_back(finite_number(e, key(k)));
    }
    return out;
  }

  double positive(const char* k) const {
    const double v = number(k);
    if (!(v > 0.0)) throw InputError(key(k), "must be positive, got " + fmt(v));
    return v;
  }
  /// A number in [lo, hi] (physical ranges: beyond them the program's arithmetic, not the
  /// physics, decides the answer); `unit` for the message.
  double bounded(const char* k, double lo, double hi, const char* unit) const {
    const double v = number(k);
    if (!(v >= lo && v <= hi))
      throw InputError(key(k), "must be from " + fmt(lo) + " to " + fmt(hi) + " " + unit + ", got " + fmt(v));
    return v;
  }
  /// Positive and at most `hi`.
  double positive_at_most(const char* k, double hi, const char* unit) const {
    const double v = positive(k);
    if (!(v <= hi)) throw InputError(key(k), "must be at most " + fmt(hi) + " " + unit + ", got " + fmt(v));
    return v;
  }
  double non_negative(const char* k) const {
    const double v = number(k);
    if (v < 0.0) throw InputError(key(k), "must be non-negative, got " + fmt(v));
    return v;
  }

 private:
  const json& j_;
  std::string path_;
};

}  // namespace dc::case_json
