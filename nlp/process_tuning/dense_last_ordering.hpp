#pragma once
// A fill-reducing pivot order for a sparse symmetric matrix: METIS's nested dissection of its
// graph without its dense rows, those numbered last.
//
// Why: MUMPS in Debian has no METIS and orders with SCOTCH, which on the KKT matrix of the
// finite body's sparse saddle form (nlp/finite/saddle_form.hpp: the body's stresses and
// equilibrium rows, the half-space block over the grid's unknowns, a clique of 1024 pressures
// on 32^2) spent 12 s of a 50 s run at 50k dofs (7 s of it on the clique), on two threads whose
// timing changed its separators (3 of 18 runs twice as dear). METIS orders the same graph in
// 4 s, reproducibly, with fewer flops. The rows that touch nearly everything (the six
// inertia-relief columns M R) are left out of the dissection, as AMD leaves out dense rows.
// The clique stays in: numbered last as well, its factorisation cost 6.0e10 flops against
// 4.3e10 at 50k dofs (docs/finite.md, "Performance").

#include <cstdint>
#include <vector>

namespace dc {

struct DenseLastOrdering {
  /// position[i] = the place (1-based) of variable i in the pivot order (MUMPS's PERM_IN);
  /// empty when the ordering could not be computed (METIS failed).
  std::vector<int> position;
  int dense_rows = 0;  ///< rows numbered last
};

/// Rows counted dense in a graph given by where each row's adjacency starts (CSR, no self
/// loops, no duplicates, n + 1 entries):
/// AMD's rule, degree above max(16, 10 sqrt(n)).
std::vector<bool> dense_rows_of_graph(const std::vector<std::int64_t>& adjacency_start);

/// The order for a symmetric n x n matrix given by `entries` coordinates (1-based rows and
/// columns as MUMPS takes them, either triangle or both, duplicates and the diagonal allowed).
DenseLastOrdering dense_last_ordering(int n, std::int64_t entries, const int* rows, const int* columns);

}  // namespace dc
