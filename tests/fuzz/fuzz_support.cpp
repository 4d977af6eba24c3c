#include "fuzz_support.hpp"

#include <fstream>
#include <sstream>

namespace dc::fuzz {

std::string example_text(const std::string& name) {
  std::ifstream in(std::string(DYNCONTACT_SOURCE_DIR) + "/examples/" + name + ".json", std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "fuzz: cannot read the example %s\n", name.c_str());
    std::abort();
  }
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace dc::fuzz
