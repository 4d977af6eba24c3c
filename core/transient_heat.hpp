#pragma once
// The time-stepped surface temperature of one half-space heated on its surface by a flux that
// moves over it (the transient counterpart of moving_heat_source.hpp's quasi-steady form).
//
// Frame: the grid is fixed to the contact; the material moves through it at -V(t) along x (the
// heat source moves at V over the material, moving_heat_source.hpp's sign). In that frame the
// temperature rise theta(x, y, z, t) (z >= 0 into the body) obeys
//   d theta/dt = kappa lap theta + V d theta/dx,   -K d theta/dz = q(x, y, t) at z = 0,        (1)
// theta -> 0 far away and theta = 0 at t = 0 (Carslaw & Jaeger 1959, 1.6 with the frame's
// convection term).
// On the grid's zero-padded periodic box (mx x my, FFT) each mode k = (kx, ky) of theta obeys
// a 1-D problem in z, discretised by finite volumes on a depth grid z_0 = 0 < z_1 < ... < z_nz
// (cells growing by `depth_ratio` from dz_0, theta(z_nz) = 0; node l's cell
// w_l = (dz_(l-1) + dz_l)/2, w_0 = dz_0/2):
//   W theta' = -A theta + i kx V W theta + e_0 kappa q_k / K,   A = S + kappa |k|^2 W,          (2)
// S the conduction, (S theta)_l = kappa (theta_l - theta_(l+1))/dz_l + kappa (theta_l -
// theta_(l-1))/dz_(l-1), W = diag(w_l). With D = -W^-1 A and f = W^-1 e_0 kappa q_k / K, the
// exact step of h with V and q constant over it (q fixed to the contact) is
//   theta_n = e^(i kx V h) e^(D h) theta_(n-1) + (D + i kx V)^-1 (e^(i kx V h) e^(D h) - I) f.  (3)
// The translation e^(i kx V h) is kept exact and e^(D h) is taken as backward Euler's
// R = (W + h A)^-1 W, so a step is (a real-shifted and a complex-shifted tridiagonal solve per
// mode, Thomas' algorithm, both diagonally dominant: no pivoting)
//   theta_n = e^(i kx V h) R theta_(n-1) + q_k u_k,
//   u_k = -(A - i kx V W)^-1 (e^(i kx V h) W (W + h A)^-1 e_0 - e_0) kappa / K,                  (4)
// whose steady state is the semi-discrete one, -(A - i kx V W)^-1 e_0 kappa q_k / K, for any step
// (R and A commute): a constant source reaches the quasi-steady map (moving_heat_source.hpp)
// up to the grids' errors, and a source switched on follows backward Euler's transient (its
// relative error -1/(8n) after n steps of a 1-D flux: the generating function (1 - z)^(-3/2)).
// By linearity a step is the free part (old state, no heat) plus the response to the flux;
// both are computed and the flux's share chosen after (the partition between two bodies).
// The box's far field (5): periodic images of the heat would come back into the contact (the
// trail left behind re-enters at the leading edge after mx dx / V). A fringe (Nordstrom, Nordin
// & Henningson 1999, SIAM J. Sci. Comput. 20, 1365) removes them: after each sub-step theta is
// multiplied, at every depth, by 1 - s(d) in the padding, s rising smoothly from 0 at a quarter
// of the padding's width from the grid to 1 at its middle (d the periodic distance from the
// grid), so that material enters the box at the bulk temperature and the trail is absorbed.
// A step is cut into sub-steps over which the material moves at most an eighth of the padding,
// so that no heat crosses the fringe within one. The fringe acts as a cold boundary at about a
// quarter of the padding from the grid: the transient is exact until the heat's diffusion
// length reaches it (a stationary source's steady rise is low by about Q/(2 pi K D) at the
// distance D of the fringe). Cost per step: O(mx my nz) for the solves and 2 nz FFTs of the box
// per sub-step (the fringe; twice that for each sub-step but the last, of the state and of the
// response): O(N log N) per depth, matrix-free.
#include <complex>
#include <string>
#include <vector>

#include "grid.hpp"
#include "moving_heat_source.hpp"
#include "padded_fft.hpp"

namespace dc {

struct TransientHeatOptions {
  int padding = 2;               ///< box / grid per direction (>= 2; 2-D: along x only)
  double first_cell = 0.25;      ///< dz_0 / min(sqrt(kappa h), 1/|k|max)
  double depth_ratio = 1.15;     ///< dz_(l+1) / dz_l
  double depth_lengths = 5.0;    ///< depth of the grid / sqrt(kappa duration)
};

/// One half-space's transient surface temperature on a grid (1)-(3). Allocates in the
/// constructor only; not thread-safe.
class TransientHeat {
 public:
  /// `step`: the time step the depth grid resolves (s, > 0), `duration`: the run's length it
  /// reaches (s, >= step). Errors (InputError) name `key`.conductivity / `key`.diffusivity.
  TransientHeat(const Grid& grid, const ThermalProperties& properties, double step, double duration,
                const TransientHeatOptions& options = {}, const std::string& key = "surface");
  TransientHeat(const TransientHeat&) = delete;
  TransientHeat& operator=(const TransientHeat&) = delete;

  /// Prepares a step of `h` (s, > 0) with the source at `speed` (m/s along +x, over the
  /// material) and `flux` (grid.size() values, W/m^2, the whole flux into this surface): the
  /// element-centre temperatures of the free part (`free`) and of the flux's response
  /// (`response`), both grid.size(). The state is unchanged until commit().
  void prepare(double h, double speed, const double* flux, double* free, double* response);
  /// Ends the prepared step with `share` times its flux (the temperature free + share response).
  void commit(double share);
  /// prepare + commit(1): the surface temperature after the step into `temperature`.
  void step(double h, double speed, const double* flux, double* temperature);

  int depth_nodes() const { return nz_; }
  double depth() const { return depth_; }
  double first_cell() const { return dz_.front(); }
  int box_x() const { return mx_; }
  int box_y() const { return my_; }
  /// The heat in the box (J; 2-D J/m): (K/kappa) sum_l w_l int theta(x, y, z_l) dA, the
  /// (0, 0) mode. A flux Q (W) applied for t puts Q t in, less what left through the depth
  /// grid's bottom and into the fringe.
  double heat_content() const;
  int last_substeps() const { return last_substeps_; }  ///< of the last prepared step

 private:
  /// b = (S + shift W)^-1 b for one mode's depth column (Thomas; S (3)'s conduction, W its cells).
  void solve_shifted(std::complex<double> shift, std::complex<double>* b);
  /// The same for a real shift and two right-hand sides.
  void solve_real_shifted(double shift, std::complex<double>* b1, std::complex<double>* b2);
  /// (5) at every depth of a mode-major field.
  void apply_fringe(std::vector<std::complex<double>>& field);

  Grid grid_;
  ThermalProperties properties_;
  int mx_, my_, nz_;
  std::size_t modes_;
  double depth_;
  std::vector<double> dz_, cell_;       ///< dz_l (l < nz), w_l
  std::vector<double> wave_x_, wave2_;  ///< kx and |k|^2 per mode
  std::vector<double> fringe_;          ///< 1 - s per box point (x fastest), the per-step factor
  std::vector<std::complex<double>> state_;  ///< theta_k(z_l): mode-major, nz per mode (DFT scale)
  std::vector<std::complex<double>> response_;  ///< the prepared step's flux response, the same layout
  std::vector<std::complex<double>> unit_;      ///< (4)'s u_k(z_l) of a unit flux, the same layout
  double unit_step_ = 0.0, unit_speed_ = 0.0;   ///< the sub-step and speed unit_ is for (0: none yet)
  std::vector<std::complex<double>> flux_;   ///< q_k of the prepared step
  std::vector<std::complex<double>> work_;    ///< Thomas' sweep
  std::vector<double> real_work_;             ///< Thomas' sweep, real shift
  std::vector<double> box_;                  ///< one box field
  bool prepared_ = false;
  int last_substeps_ = 1;
  PaddedFft surface_fft_;  ///< the grid block in the box
  PaddedFft box_fft_;      ///< the whole box (the fringe at every depth)
};

}  // namespace dc
