#include "fault_injection.hpp"

#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>

namespace dc {
namespace {

std::map<std::string, Fault> parse_faults(const char* text) {
  std::map<std::string, Fault> faults;
  if (text == nullptr) return faults;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    if (item.empty()) continue;
    const auto colon = item.find(':');
    const std::string target = item.substr(0, colon);
    const std::string kind = colon == std::string::npos ? "" : item.substr(colon + 1);
    const bool known_target = target == "ipopt" || target == "nlopt" || target == "native" || target == "outer";
    const Fault fault = kind == "fail" ? Fault::fail : kind == "stall" ? Fault::stall : kind == "nan" ? Fault::nan : Fault::none;
    if (!known_target || fault == Fault::none) {
      std::cerr << "warning: DYNCONTACT_FAULT: ignoring '" << item
                << "' (test-only; TARGET:KIND with TARGET ipopt|nlopt|native|outer, KIND fail|stall|nan)\n";
      continue;
    }
    faults[target] = fault;
  }
  return faults;
}

}  // namespace

Fault injected_fault(const std::string& target) {
  // Parsed again only when the variable changes (tests set it between cases).
  thread_local std::string text;
  thread_local std::map<std::string, Fault> faults;
  const char* now = std::getenv("DYNCONTACT_FAULT");
  if ((now ? now : "") != text) {
    text = now ? now : "";
    faults = parse_faults(now);
  }
  const auto it = faults.find(target);
  return it == faults.end() ? Fault::none : it->second;
}

}  // namespace dc
