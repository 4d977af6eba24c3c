#include "dense_last_ordering.hpp"

#if defined(DYNCONTACT_WITH_MUMPS_ORDERING)
#include <metis.h>
#else
using idx_t = int;  // no METIS in this build: dense_last_ordering gives no order
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace dc {

namespace {
// AMD's threshold for dense rows (SuiteSparse AMD_DEFAULT_DENSE, at least 16).
constexpr double kDenseOverSqrtN = 10.0;
constexpr double kDenseDegreeFloor = 16.0;
}  // namespace

std::vector<bool> dense_rows_of_graph(const std::vector<std::int64_t>& start) {
  const std::size_t n = start.size() - 1;
  const double dense_degree = std::max(kDenseDegreeFloor, kDenseOverSqrtN * std::sqrt(static_cast<double>(n)));
  std::vector<bool> dense(n);
  for (std::size_t i = 0; i < n; ++i) dense[i] = static_cast<double>(start[i + 1] - start[i]) > dense_degree;
  return dense;
}

DenseLastOrdering dense_last_ordering(int n, std::int64_t entries, const int* rows, const int* columns) {
  DenseLastOrdering out;
  if (n <= 0) return out;
  const auto size = static_cast<std::size_t>(n);
  // The graph: both directions of every off-diagonal entry, then each list sorted and unique.
  std::vector<std::int64_t> start(size + 1, 0);
  for (std::int64_t k = 0; k < entries; ++k) {
    const int i = rows[k] - 1, j = columns[k] - 1;
    if (i == j || i < 0 || j < 0 || i >= n || j >= n) continue;
    ++start[static_cast<std::size_t>(i) + 1];
    ++start[static_cast<std::size_t>(j) + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int> adjacency(static_cast<std::size_t>(start[size]));
  {
    std::vector<std::int64_t> next(start.begin(), start.end() - 1);
    for (std::int64_t k = 0; k < entries; ++k) {
      const int i = rows[k] - 1, j = columns[k] - 1;
      if (i == j || i < 0 || j < 0 || i >= n || j >= n) continue;
      adjacency[static_cast<std::size_t>(next[static_cast<std::size_t>(i)]++)] = j;
      adjacency[static_cast<std::size_t>(next[static_cast<std::size_t>(j)]++)] = i;
    }
  }
  std::vector<std::int64_t> unique_start(size + 1, 0);
  std::int64_t kept = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const auto first = adjacency.begin() + start[i], last = adjacency.begin() + start[i + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    unique_start[i] = kept;
    kept = static_cast<std::int64_t>(std::copy(first, end, adjacency.begin() + kept) - adjacency.begin());
  }
  unique_start[size] = kept;
  adjacency.resize(static_cast<std::size_t>(kept));
  if (kept > std::numeric_limits<idx_t>::max()) return out;  // beyond METIS's indices

  const std::vector<bool> dense = dense_rows_of_graph(unique_start);
  // The sparse rows renumbered 0.. in their order, their graph without the dense rows.
  std::vector<idx_t> local(size, -1);
  idx_t sparse = 0;
  for (std::size_t i = 0; i < size; ++i)
    if (!dense[i]) local[i] = sparse++;
  std::vector<idx_t> xadj(static_cast<std::size_t>(sparse) + 1, 0), adjncy;
  adjncy.reserve(adjacency.size());
  for (std::size_t i = 0; i < size; ++i) {
    if (dense[i]) continue;
    for (std::int64_t k = unique_start[i]; k < unique_start[i + 1]; ++k) {
      const idx_t j = local[static_cast<std::size_t>(adjacency[static_cast<std::size_t>(k)])];
      if (j >= 0) adjncy.push_back(j);
    }
    xadj[static_cast<std::size_t>(local[i]) + 1] = static_cast<idx_t>(adjncy.size());
  }
  adjacency = {};  // freed before METIS runs
  std::vector<idx_t> perm(static_cast<std::size_t>(sparse)), iperm(static_cast<std::size_t>(sparse));
#if !defined(DYNCONTACT_WITH_MUMPS_ORDERING)
  return out;
#else
  if (sparse > 0) {
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    idx_t vertices = sparse;
    if (METIS_NodeND(&vertices, xadj.data(), adjncy.data(), nullptr, options, perm.data(), iperm.data()) != METIS_OK)
      return out;
  }
#endif
  // METIS's iperm[v] is the place of vertex v in its order; the dense rows follow in index order.
  out.position.assign(size, 0);
  int next_dense = static_cast<int>(sparse);
  for (std::size_t i = 0; i < size; ++i)
    out.position[i] = dense[i] ? ++next_dense : static_cast<int>(iperm[static_cast<std::size_t>(local[i])]) + 1;
  out.dense_rows = n - static_cast<int>(sparse);
  return out;
}

}  // namespace dc
