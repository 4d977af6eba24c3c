#include "fault_from_environment.hpp"

#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "fault_injection.hpp"

namespace dc::test {
namespace {

/// A fault and the one query it applies to (0: every query).
struct Injected {
  Fault fault = Fault::none;
  long only_query = 0;
};

std::map<std::string, Injected> parse_faults(const char* text) {
  std::map<std::string, Injected> faults;
  if (text == nullptr) return faults;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    if (item.empty()) continue;
    const auto colon = item.find(':');
    const std::string target = item.substr(0, colon);
    std::string kind = colon == std::string::npos ? "" : item.substr(colon + 1);
    long only_query = 0;  // KIND@N: the N-th query of the target only
    if (const auto at = kind.find('@'); at != std::string::npos) {
      only_query = std::strtol(kind.c_str() + at + 1, nullptr, 10);
      kind = only_query > 0 ? kind.substr(0, at) : "";
    }
    const bool known_target = target == "ipopt" || target == "nlopt" || target == "native" || target == "outer";
    const Fault fault = kind == "fail" ? Fault::fail : kind == "stall" ? Fault::stall : kind == "nan" ? Fault::nan : Fault::none;
    if (!known_target || fault == Fault::none) {
      std::cerr << "warning: DYNCONTACT_FAULT: ignoring '" << item
                << "' (test-only; TARGET:KIND[@N] with TARGET ipopt|nlopt|native|outer, KIND fail|stall|nan, N the "
                   "query it applies to)\n";
      continue;
    }
    faults[target] = {fault, only_query};
  }
  return faults;
}

Fault fault_from_environment(const std::string& target) {
  // Parsed again only when the variable changes (tests set it between cases).
  thread_local std::string text;
  thread_local std::map<std::string, Injected> faults;
  thread_local std::map<std::string, long> queries;
  const char* now = std::getenv("DYNCONTACT_FAULT");
  if ((now ? now : "") != text) {
    text = now ? now : "";
    faults = parse_faults(now);
    queries.clear();
  }
  const auto it = faults.find(target);
  if (it == faults.end()) return Fault::none;
  const long query = ++queries[target];
  return it->second.only_query == 0 || it->second.only_query == query ? it->second.fault : Fault::none;
}

}  // namespace

void install_faults_from_environment() { set_fault_source(&fault_from_environment); }

}  // namespace dc::test
