#pragma once
// One iteration of a native solver, kept for its report: a stagnating or cycling run shows here.
#include <cstddef>

namespace dc {

struct IterationRecord {
  int iteration = 0;
  double change = 0.0;      ///< relative change of the unknowns in the iteration (the stopping measure)
  std::size_t active = 0;   ///< elements in the contact set after it
  std::size_t entered = 0;  ///< elements that entered the set
  std::size_t left = 0;     ///< elements that left it
};

}  // namespace dc
