#pragma once
// FFTW planning shared by every transform of the library: one planner lock (FFTW's planner
// is not thread-safe), the thread count, and the transform lengths FFTW handles fast.
// Plans are made with FFTW_ESTIMATE only: the same input gives the same result on every run
// (FFTW_MEASURE may pick a different algorithm, and so different round-off, from run to run).
#include <cstddef>
#include <mutex>

namespace dc {

/// Lock held while creating or destroying FFTW plans.
std::mutex& fft_planner_mutex();

/// Threads used by the transforms: the hardware's cores, or DYNCONTACT_THREADS when set (>= 1).
int fft_threads();

/// Threads for a transform of `points` real values: 1 below the size where threads pay off.
int fft_threads_for(std::size_t points);

/// Smallest m >= n whose prime factors are 2, 3 and 5 (lengths FFTW transforms fastest; with
/// 7 allowed, spence-69 spent 16 % more in its 189-point transforms than in 192-point ones).
int fft_good_size(int n);

/// The transform length m >= n of least estimated time (m times a per-point cost measured with
/// FFTW_ESTIMATE plans on this kind of machine): odd lengths cost about twice an even one,
/// every factor 3 (up to three) 20 % more, factors 5 beyond two 10 % each. For the zero-padded
/// box of an exact linear convolution, whose result does not depend on the box beyond round-off:
/// n = 607 gives 640, not 625 (2.2x slower); 181 gives 200, not 192 (1.2x).
int fft_fast_size(int n);

}  // namespace dc
