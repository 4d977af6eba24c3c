#include "fault_injection.hpp"

#include <atomic>

namespace dc {
namespace {
std::atomic<FaultSource> installed_source{nullptr};
}  // namespace

void set_fault_source(FaultSource source) { installed_source.store(source); }

Fault injected_fault(const std::string& target) {
  const FaultSource source = installed_source.load(std::memory_order_relaxed);
  return source == nullptr ? Fault::none : source(target);
}

}  // namespace dc
