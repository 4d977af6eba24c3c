#pragma once
// A fill-reducing pivot order for a sparse symmetric matrix whose graph holds a few dense rows:
// METIS's nested dissection of the graph without them, the dense rows numbered last.
//
// Why: the KKT matrix of the finite body's sparse saddle form (nlp/finite/saddle_form.hpp) is
// the body's stresses and equilibrium rows (sparse, a mesh's graph) plus the half-space's block
// over the grid's unknowns, a clique (1024 pressures on 32^2, 2048 tractions), and the six
// inertia-relief columns M R, which touch every row. Nested dissection run on the whole graph
// (SCOTCH inside MUMPS) spends most of its time on the clique's edges, and on two threads its
// separators depend on their timing. A clique is factorised as one dense front wherever it is
// placed; placed last it is the root front, and the dissection of the rest is a mesh's.

#include <cstdint>
#include <vector>

namespace dc {

struct DenseLastOrdering {
  /// position[i] = the place (1-based) of variable i in the pivot order (MUMPS's PERM_IN);
  /// empty when the ordering could not be computed (METIS failed).
  std::vector<int> position;
  int dense_rows = 0;  ///< rows numbered last
};

/// Rows counted dense in the graph given by its adjacency (CSR, no self loops, no duplicates):
/// a row is dense when its degree is far above the typical one (above 8 x the median degree and
/// above 200) and most of its neighbours are so too (a clique of such rows: the half-space
/// block and the rows over it), or when its degree exceeds 10 sqrt(n) (AMD's rule for dense
/// rows: the inertia-relief columns). A mesh's well-connected nodes (several hundred
/// neighbours, nearly all of them stresses of a few dozen) are not dense.
std::vector<bool> dense_rows_of_graph(const std::vector<std::int64_t>& adjacency_start,
                                      const std::vector<int>& adjacency);

/// The order for a symmetric n x n matrix given by `entries` coordinates (1-based rows and
/// columns as MUMPS takes them, either triangle or both, duplicates and the diagonal allowed).
DenseLastOrdering dense_last_ordering(int n, std::int64_t entries, const int* rows, const int* columns);

}  // namespace dc
