// dense_last_ordering (nlp/process_tuning/dense_last_ordering.hpp): on a small synthetic KKT pattern (a mesh's
// graph, a clique over some of its rows as the half-space block, one column touching every mesh
// row as an inertia-relief column, one well-connected mesh row) the order is a permutation with
// exactly the column last (its degree above AMD's 10 sqrt(n)); the clique and the
// well-connected row stay in the dissection.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "dense_last_ordering.hpp"
#include "mumps_ordering_hook.hpp"

namespace {

struct Pattern {
  int n = 0;
  std::vector<int> rows, columns;  // 1-based, as MUMPS takes them
  void add(int i, int j) {          // 0-based, lower triangle
    rows.push_back(std::max(i, j) + 1);
    columns.push_back(std::min(i, j) + 1);
  }
};

constexpr int kSide = 40;          // the mesh: kSide^2 rows, 9-point stencil
constexpr int kClique = 300;       // the half-space block
constexpr int kHubDegree = 260;    // a well-connected mesh row, below 10 sqrt(n) = 436

/// Mesh rows 0..kSide^2-1 (row 0 also joined to kHubDegree others), then the clique, then the column.
Pattern synthetic_kkt() {
  Pattern p;
  const int mesh = kSide * kSide;
  p.n = mesh + kClique + 1;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      const int i = y * kSide + x;
      p.add(i, i);  // diagonal
      for (int dy = 0; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (dy == 0 && dx <= 0) continue;
          const int xx = x + dx, yy = y + dy;
          if (xx >= 0 && xx < kSide && yy < kSide) p.add(i, yy * kSide + xx);
        }
    }
  for (int k = 0; k < kHubDegree; ++k) p.add(0, 2 * kSide + 5 * k);
  for (int a = 0; a < kClique; ++a) {
    const int i = mesh + a;
    for (int b = 0; b <= a; ++b) p.add(i, mesh + b);
    p.add(i, (7 * a) % mesh);  // each over a few mesh rows (the face's)
    p.add(i, (7 * a + 1) % mesh);
    p.add(i, (7 * a + 1) % mesh);  // a duplicate entry, as the triplets may hold
  }
  for (int i = 0; i < mesh; ++i) p.add(p.n - 1, i);
  return p;
}

TEST(DenseLastOrdering, APermutationWithTheFullColumnLast) {
  if (!dc::mumps_ordering_hook_built()) GTEST_SKIP() << "built without METIS";
  const Pattern p = synthetic_kkt();
  const dc::DenseLastOrdering order =
      dc::dense_last_ordering(p.n, static_cast<std::int64_t>(p.rows.size()), p.rows.data(), p.columns.data());
  ASSERT_EQ(static_cast<int>(order.position.size()), p.n);
  std::vector<int> sorted = order.position;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < p.n; ++k) ASSERT_EQ(sorted[static_cast<std::size_t>(k)], k + 1) << "not a permutation";
  const int mesh = kSide * kSide;
  EXPECT_EQ(order.dense_rows, 1);
  EXPECT_EQ(order.position[static_cast<std::size_t>(p.n - 1)], p.n) << "the full column last";
  EXPECT_LT(order.position[0], p.n) << "the well-connected mesh row is not dense";
  EXPECT_LT(order.position[static_cast<std::size_t>(mesh)], p.n) << "the clique is not dense";
}

TEST(DenseLastOrdering, NoDenseRowsInAMeshAlone) {
  if (!dc::mumps_ordering_hook_built()) GTEST_SKIP() << "built without METIS";
  Pattern p;
  p.n = 50;
  for (int i = 0; i + 1 < p.n; ++i) p.add(i, i + 1);  // a path
  const dc::DenseLastOrdering order =
      dc::dense_last_ordering(p.n, static_cast<std::int64_t>(p.rows.size()), p.rows.data(), p.columns.data());
  ASSERT_EQ(static_cast<int>(order.position.size()), p.n);
  EXPECT_EQ(order.dense_rows, 0);
  std::vector<int> sorted = order.position;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < p.n; ++k) EXPECT_EQ(sorted[static_cast<std::size_t>(k)], k + 1);
}

}  // namespace
