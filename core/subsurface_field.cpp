#include "subsurface_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>

#include "fft_planning.hpp"
#include "interrupt.hpp"
#include "padded_fft.hpp"

namespace dc {
namespace {
/// The zero-padded box along an axis of n elements: the kernel's 2n - 1 offsets fit, so the
/// circular convolution is the linear one on the grid.
int subsurface_box_length(int n) { return n == 1 ? 1 : fft_fast_size(2 * n - 1); }

/// Components a 2-D (plane strain) field has; the others are zero.
bool plane_strain_component(int c) { return c != kUy && c != kSxy && c != kSyz; }

bool has_nonzero(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return x != 0.0; });
}
}  // namespace

FieldValues SubsurfaceResult::point(std::size_t k, int i, int j) const {
  FieldValues f{};
  for (int c = 0; c < kFieldComponents; ++c) f[c] = at(k, c, i, j);
  return f;
}

SubsurfaceField::SubsurfaceField(const Grid& grid, const Elastic& material, BodySide side,
                                 const InfluenceOptions& options)
    : grid_(grid), material_(material), side_(side),
      reference_length_(options.reference_length > 0.0 ? options.reference_length : grid.nx * grid.dx),
      coefficients_(grid, material, side, options) {
  const int mx = subsurface_box_length(grid.nx), my = grid.dimension == 2 ? 1 : subsurface_box_length(grid.ny);
  kernel_fft_ = std::make_unique<PaddedFft>(2 * grid.nx - 1, 2 * grid.ny - 1, mx, my);
  field_fft_ = std::make_unique<PaddedFft>(grid.nx, grid.ny, mx, my, 1);
  const std::size_t spectrum = 2 * field_fft_->spectrum_size();
  traction_spectra_.assign(3 * spectrum, 0.0);
  sums_.assign(kFieldComponents * spectrum, 0.0);
  table_.nx = grid.nx;
  table_.ny = grid.ny;
  table_.values.assign(static_cast<std::size_t>(2 * grid.nx - 1) * static_cast<std::size_t>(2 * grid.ny - 1), 0.0);
}

SubsurfaceField::~SubsurfaceField() = default;

SubsurfaceResult SubsurfaceField::compute(const SurfaceTractions& t, const std::vector<double>& depths,
                                          SubsurfaceMethod method) {
  const std::size_t N = grid_.size();
  for (const std::vector<double>* v : {&t.p, &t.tau_x, &t.tau_y})
    if (!v->empty() && v->size() != N)
      throw std::invalid_argument("subsurface field: a traction field must have one value per element");
  if (grid_.dimension == 2 && has_nonzero(t.tau_y))
    throw std::invalid_argument("subsurface field: 2-D problems have no tau_y");
  for (double d : depths)
    if (!(d >= 0.0) || !std::isfinite(d)) throw std::invalid_argument("subsurface field: depths must be >= 0");
  const bool active[3] = {has_nonzero(t.tau_x), has_nonzero(t.tau_y), has_nonzero(t.p)};  // by Axis: kX, kY, kZ

  SubsurfaceResult r;
  r.grid = grid_;
  r.depths = depths;
  r.values.assign(depths.size() * kFieldComponents * N, 0.0);
  if (method == SubsurfaceMethod::fft) {
    // The tractions' spectra, once: times exp(+2 pi i (kx (nx-1)/mx + ky (ny-1)/my)), which
    // undoes the kernels' shift by (nx - 1, ny - 1) (they start at offset -(n - 1)).
    const int mx = field_fft_->mx(), my = field_fft_->my(), mxc = mx / 2 + 1;
    const std::size_t ncplx = field_fft_->spectrum_size();
    const std::vector<double>* fields[3] = {&t.tau_x, &t.tau_y, &t.p};
    for (int load = 0; load < 3; ++load) {
      if (!active[load]) continue;
      field_fft_->forward_into(fields[load]->data(), 0);
      const double* in = field_fft_->stored(0);
      double* out = traction_spectra_.data() + 2 * ncplx * load;
      for (int kx = 0; kx < mxc; ++kx)
        for (int ky = 0; ky < my; ++ky) {
          // Reduced exactly in integers first: cos and sin stay at round-off.
          const long long turns_x = static_cast<long long>(kx) * (grid_.nx - 1) % mx,
                          turns_y = static_cast<long long>(ky) * (grid_.ny - 1) % my;
          const double phase = 2.0 * std::numbers::pi *
                               (static_cast<double>(turns_x) / mx + static_cast<double>(turns_y) / my);
          const double c = std::cos(phase), s = std::sin(phase);
          const std::size_t e = static_cast<std::size_t>(kx) * my + ky;
          out[2 * e] = c * in[2 * e] - s * in[2 * e + 1];
          out[2 * e + 1] = s * in[2 * e] + c * in[2 * e + 1];
        }
    }
  }
  for (std::size_t k = 0; k < depths.size(); ++k) {
    throw_if_interrupted();
    double* out = r.values.data() + k * kFieldComponents * N;
    if (method == SubsurfaceMethod::direct) {
      direct_depth(t, active, depths[k], out);
    } else {
      coefficients_.set_depth(depths[k]);
      fft_depth(active, out);
    }
  }
  return r;
}

void SubsurfaceField::fft_depth(const bool active[3], double* out) {
  const std::size_t N = grid_.size(), ncplx = field_fft_->spectrum_size();
  const double norm = 1.0 / (static_cast<double>(field_fft_->mx()) * field_fft_->my());
  std::fill(sums_.begin(), sums_.end(), 0.0);
  for (Axis load : {kX, kY, kZ}) {
    if (!active[load]) continue;
    const double* traction = traction_spectra_.data() + 2 * ncplx * load;
    for (int c = 0; c < kFieldComponents; ++c) {
      if (grid_.dimension == 2 && !plane_strain_component(c)) continue;
      coefficients_.fill(c, load, table_);
      kernel_fft_->forward(table_.values.data());
      const double* kernel = kernel_fft_->spectrum();
      double* sum = sums_.data() + 2 * ncplx * c;
      for (std::size_t e = 0; e < ncplx; ++e) {
        const double kr = kernel[2 * e], ki = kernel[2 * e + 1], tr = traction[2 * e], ti = traction[2 * e + 1];
        sum[2 * e] += kr * tr - ki * ti;
        sum[2 * e + 1] += kr * ti + ki * tr;
      }
    }
  }
  for (int c = 0; c < kFieldComponents; ++c) {
    double* field = out + static_cast<std::size_t>(c) * N;
    if (grid_.dimension == 2 && !plane_strain_component(c)) {
      std::fill(field, field + N, 0.0);
      continue;
    }
    std::copy(sums_.begin() + 2 * ncplx * c, sums_.begin() + 2 * ncplx * (c + 1), field_fft_->spectrum());
    field_fft_->inverse(field);
    for (std::size_t e = 0; e < N; ++e) field[e] *= norm;
  }
}

void SubsurfaceField::direct_depth(const SurfaceTractions& t, const bool active[3], double depth, double* out) const {
  const std::size_t N = grid_.size();
  std::fill(out, out + kFieldComponents * N, 0.0);
  const auto value = [](const std::vector<double>& v, std::size_t e, bool on) { return on ? v[e] : 0.0; };
  for (int js = 0; js < grid_.ny; ++js)
    for (int is = 0; is < grid_.nx; ++is) {
      const std::size_t es = grid_.index(is, js);
      const double tx = value(t.tau_x, es, active[kX]), ty = value(t.tau_y, es, active[kY]),
                   p = value(t.p, es, active[kZ]);
      if (tx == 0.0 && ty == 0.0 && p == 0.0) continue;
      for (int j = 0; j < grid_.ny; ++j)
        for (int i = 0; i < grid_.nx; ++i) {
          const double x = (i - is) * grid_.dx, y = (j - js) * grid_.dy;
          const FieldValues f =
              grid_.dimension == 2
                  ? strip_field(material_, side_, grid_.dx, tx, p, x, depth, reference_length_)
                  : rectangle_field(material_, side_, grid_.dx, grid_.dy, tx, ty, p, x, y, depth);
          const std::size_t e = grid_.index(i, j);
          for (int c = 0; c < kFieldComponents; ++c) out[static_cast<std::size_t>(c) * N + e] += f[c];
        }
    }
}

StressMeasures stress_measures(const FieldValues& f) {
  const double sxx = f[kSxx], syy = f[kSyy], szz = f[kSzz], sxy = f[kSxy], sxz = f[kSxz], syz = f[kSyz];
  StressMeasures m;
  m.hydrostatic = (sxx + syy + szz) / 3.0;
  m.von_mises = std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                          3.0 * (sxy * sxy + sxz * sxz + syz * syz));
  Eigen::Matrix3d s;
  s << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(s, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d l = eig.eigenvalues();  // ascending
  m.tresca = 0.5 * (l(2) - l(0));
  return m;
}

SubsurfaceMeasures subsurface_measures(const SubsurfaceResult& r) {
  const std::size_t N = r.grid.size(), K = r.depths.size();
  SubsurfaceMeasures m;
  m.von_mises.resize(K * N);
  m.tresca.resize(K * N);
  m.hydrostatic.resize(K * N);
  const auto place = [&](FieldExtreme& x, double value, std::size_t k, int i, int j) {
    x = FieldExtreme{value, k, i, j, r.grid.xc(i), r.grid.yc(j), r.depths[k]};
  };
  bool first = true;
  for (std::size_t k = 0; k < K; ++k)
    for (int j = 0; j < r.grid.ny; ++j)
      for (int i = 0; i < r.grid.nx; ++i) {
        const std::size_t e = r.grid.index(i, j), at = k * N + e;
        const StressMeasures s = stress_measures(r.point(k, i, j));
        m.von_mises[at] = s.von_mises;
        m.tresca[at] = s.tresca;
        m.hydrostatic[at] = s.hydrostatic;
        if (first || s.von_mises > m.max_von_mises.value) place(m.max_von_mises, s.von_mises, k, i, j);
        if (first || s.tresca > m.max_tresca.value) place(m.max_tresca, s.tresca, k, i, j);
        if (first || s.hydrostatic > m.max_hydrostatic.value) place(m.max_hydrostatic, s.hydrostatic, k, i, j);
        if (first || s.hydrostatic < m.min_hydrostatic.value) place(m.min_hydrostatic, s.hydrostatic, k, i, j);
        first = false;
      }
  return m;
}

}  // namespace dc
