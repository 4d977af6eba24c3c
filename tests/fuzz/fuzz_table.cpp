// libFuzzer target: arbitrary bytes as the CSV table of a table profile (read_profile_table),
// then the heights interpolated on a small grid over the table, as a case with that table does.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "case_readers.hpp"
#include "fuzz_support.hpp"
#include "grid.hpp"
#include "profile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  dc::fuzz::expect_input_errors_only([&] {
    dc::ProfileSpec p;
    p.type = dc::ProfileType::table;
    p.file = "table.csv";
    dc::read_profile_table(in, p, "profile.file");
    const auto [x0, x1] = std::minmax_element(p.table_x.begin(), p.table_x.end());
    const auto [y0, y1] = std::minmax_element(p.table_y.begin(), p.table_y.end());
    const bool one_row = *y0 == *y1;
    if (!(*x1 > *x0) || (!one_row && !(*y1 > *y0))) return;
    const dc::Grid g = one_row ? dc::Grid::make(2, 8, 1, *x0, *x1, 0.0, 0.0)
                               : dc::Grid::make(3, 8, 8, *x0, *x1, *y0, *y1);
    (void)dc::profile_heights(p, g);
  });
  return 0;
}
