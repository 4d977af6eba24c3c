#pragma once
// Which compliance operator of the half-space a solve builds (linear_operator.hpp); chosen by the
// solver's options (nlp/solver_options.hpp).

namespace dc {

/// The half-space's compliance operator (core/linear_operator.hpp).
enum class OperatorKind {
  automatic,  ///< "auto": dense up to kDenseAutoLimit entries, else FFT
  dense,      ///< "dense": the whole influence matrix
  fft,        ///< "fft": matrix-free, by FFT convolution
};

}  // namespace dc
