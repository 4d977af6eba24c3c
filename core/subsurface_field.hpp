#pragma once
// The linear elastic field inside one body of the contact pair due to the grid's
// piecewise-constant surface tractions: the nine components (subsurface_influence.hpp, global
// frame, tension positive) at every element centre (x_i, y_j) at each of a list of depths into
// that body, with that body's own material. Two paths to the same sums
//   f_c(i, j, d) = sum over elements (i', j') and traction components t of
//                  K_ct(i - i', j - j'; d) t(i', j'):
// direct summation of the closed forms (small grids, tests), and per depth the zero-padded FFT
// convolution of the exact coefficients: the tractions transformed once (padded_fft.hpp), each
// kernel table, even or odd in each offset, by a real cosine or sine transform of its quadrant
// (FFTW's REDFT00 / RODFT00 on half the box: the DFT of the wrapped table, real or imaginary,
// at a quarter of a complex transform's work); per component the sum over the loads of the
// products, in the inverse transform's own buffer, back by PaddedFft::inverse. On a square grid
// of square elements the reflection x <-> y maps the tables onto each other's transposes
// (u_x <-> u_y, sigma_xx <-> sigma_yy, sigma_xz <-> sigma_yz, tau_x <-> tau_y): one of each
// pair is transformed, the other reads its transform transposed (pressure alone: 6 kernel
// transforms per depth instead of 9; all three loads: 15 instead of 27), and half the corner
// functions are evaluated (SubsurfaceCoefficients::set_depth).
// Plans and buffers are made by the constructor; the result and the measures' arrays (150 MB
// and 50 MB on 256^2 at 32 depths) are allocated on huge pages (huge_pages.hpp).
// Derived measures per point: von Mises sqrt(3 J2), Tresca's maximum shear (sigma_1 - sigma_3)/2
// from the principal stresses, and the hydrostatic stress sigma_kk / 3 (voigt_stress.hpp); and
// their extremes.
#include <cstddef>
#include <memory>
#include <vector>

#include "grid.hpp"
#include "influence.hpp"
#include "material.hpp"
#include "subsurface_influence.hpp"
#include "voigt_stress.hpp"

namespace dc {

class PaddedFft;

enum class SubsurfaceMethod { direct, fft };

/// Tractions on the body (docs/conventions.md), grid.size() values each in the grid's element
/// order; an empty field is zero. 2-D: p and tau_x only (tau_y empty or zero).
struct SurfaceTractions {
  std::vector<double> p, tau_x, tau_y;
};

/// The field at depths[k], component c, element e = grid.index(i, j): values[(k * 9 + c) * N + e].
struct SubsurfaceResult {
  Grid grid;
  std::vector<double> depths;
  std::vector<double> values;

  const double* component(std::size_t k, int c) const {
    return values.data() + (k * kFieldComponents + static_cast<std::size_t>(c)) * grid.size();
  }
  double at(std::size_t k, int c, int i, int j) const { return component(k, c)[grid.index(i, j)]; }
  FieldValues point(std::size_t k, int i, int j) const;
};

class SubsurfaceField {
 public:
  /// 2-D: the logarithmic displacements vanish at options.reference_length (<= 0: nx dx).
  SubsurfaceField(const Grid& grid, const Elastic& material, BodySide side, const InfluenceOptions& options = {});
  ~SubsurfaceField();
  SubsurfaceField(const SubsurfaceField&) = delete;
  SubsurfaceField& operator=(const SubsurfaceField&) = delete;

  /// The field at every element centre at each depth (>= 0, into this body): set_tractions,
  /// then compute_depth for each depth into the result. Not thread-safe.
  SubsurfaceResult compute(const SurfaceTractions& tractions, const std::vector<double>& depths,
                           SubsurfaceMethod method = SubsurfaceMethod::fft);

  /// One depth at a time (a caller that keeps one depth's field, not all): the tractions (their
  /// spectra made here, once), then the nine components at `depth` into out[c * N + e].
  void set_tractions(const SurfaceTractions& tractions);
  void compute_depth(double depth, double* out, SubsurfaceMethod method = SubsurfaceMethod::fft);

 private:
  void fft_depth(double* out);
  void direct_depth(double depth, double* out) const;

  /// The kernel's transform for parities (odd_x, odd_y) into kernel_out_; false if it is zero.
  bool transform_kernel(int component, Axis load, bool odd_x, bool odd_y);

  Grid grid_;
  Elastic material_;
  BodySide side_;
  double reference_length_;
  SubsurfaceCoefficients coefficients_;
  bool has_tractions_ = false;
  bool active_[3] = {false, false, false};  ///< by Axis: tau_x, tau_y, p not zero
  std::vector<double> tractions_[3];        ///< the active ones (the direct path)
  std::unique_ptr<PaddedFft> field_fft_;    ///< the tractions' spectra (3 stored) and the inverse
  std::vector<double> quadrant_;          ///< one table's quadrant, nx x ny
  double* kernel_in_ = nullptr;           ///< real transform buffers, (mx/2 + 1) x (my/2 + 1)
  double* kernel_out_ = nullptr;
  void* plans_[4] = {nullptr, nullptr, nullptr, nullptr};  ///< by odd_x + 2 odd_y
  int half_x_[2] = {0, 0}, half_y_[2] = {0, 0};            ///< transform lengths: even, odd
  std::vector<double> kept_[kFieldComponents * 3];         ///< square grids: spectra kept for the mirror table
};

/// One point's six stresses as a Voigt array (voigt_stress.hpp: xx, yy, zz, yz, xz, xy).
Voigt voigt_stress(const FieldValues& field);

/// Von Mises sqrt(3 J2), Tresca's maximum shear (sigma_1 - sigma_3)/2 and the hydrostatic stress
/// of one point (voigt_stress.hpp's invariants).
struct StressMeasures {
  double von_mises = 0.0, tresca = 0.0, hydrostatic = 0.0;
};
StressMeasures stress_measures(const FieldValues& field);

/// Where a measure peaks: its value, depth index, element and position (depth into the body).
struct FieldExtreme {
  double value = 0.0;
  std::size_t depth_index = 0;
  int i = 0, j = 0;
  double x = 0.0, y = 0.0, depth = 0.0;
};

/// The measures at every point (layout k * N + e) and their extremes over the field.
struct SubsurfaceMeasures {
  std::vector<double> von_mises, tresca, hydrostatic;
  FieldExtreme max_von_mises, max_tresca, max_hydrostatic, min_hydrostatic;
};
SubsurfaceMeasures subsurface_measures(const SubsurfaceResult& result);

}  // namespace dc
