#include "shakedown_result.hpp"

namespace dc {

const char* to_string(ShakedownStatus status) {
  switch (status) {
    case ShakedownStatus::optimal: return "optimal";
    case ShakedownStatus::not_converged: return "not_converged";
    case ShakedownStatus::unbounded: return "unbounded";
    case ShakedownStatus::failed: return "failed";
  }
  return "?";
}

const char* to_string(ShakedownVerdict verdict) {
  switch (verdict) {
    case ShakedownVerdict::elastic: return "elastic";
    case ShakedownVerdict::elastic_shakedown: return "shakedown";  // CASES.md names
    case ShakedownVerdict::beyond_shakedown: return "beyond";
    case ShakedownVerdict::undetermined: return "undetermined";
  }
  return "?";
}

}  // namespace dc
