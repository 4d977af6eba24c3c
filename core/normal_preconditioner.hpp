#pragma once
// FFT preconditioner for the normal contact problem (4.7) solved by conjugate gradients on the
// contact set I: M^-1 r = R_I F^-1 [ F(R_I r) / S ], with S the spectrum of the compliance
// kernel on a periodic box the size of the grid and R_I the restriction to I. The half-space
// kernel behaves like 1 / |k| in wavenumber, so the compliance's condition number grows with
// the grid; dividing by its spectrum removes that growth (the idea of Vollebregt, J. Comput.
// Phys. 257, 2014, for CONTACT's NormCG), leaving iteration counts nearly independent of the
// grid. The spectrum is computed once per grid and operator and reused by every solve.
#include <memory>
#include <vector>

#include "grid.hpp"
#include "linear_operator.hpp"
#include "padded_fft.hpp"

namespace dc {

class NormalPreconditioner {
 public:
  /// Built from the operator's response to a unit load at the grid centre (one apply; any
  /// operator kind), wrapped onto a periodic box of FFT-friendly size >= the grid.
  NormalPreconditioner(const LinearOperator& compliance, const Grid& grid);

  /// z = scale * M^-1 r on the elements where active[i] != 0 (z = 0 elsewhere). `scale`
  /// converts to a scaled operator (C / c0: scale = c0). Allocates nothing.
  void apply(const double* r, const char* active, double scale, double* z) const;

 private:
  std::size_t n_;
  std::vector<double> inverse_symbol_;  ///< 1 / (S mx my), one real value per complex entry
  mutable PaddedFft fft_;
  mutable std::vector<double> work_;
};

}  // namespace dc
