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

}  // namespace dc
