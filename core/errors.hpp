#pragma once
// Errors raised for bad input: each names the offending key and the reason.
#include <stdexcept>
#include <string>

namespace dc {

/// Bad user input. `key` is the JSON path of the offending key (e.g. "materials.body.nu").
class InputError : public std::runtime_error {
 public:
  InputError(std::string key, const std::string& reason)
      : std::runtime_error(key + ": " + reason), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

/// A solve that produced nothing to report (every backend failed where the run cannot go on
/// without a result): exit 3, not an internal error.
class SolverFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace dc
