#include "subsurface_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fftw3.h>

#include "fft_planning.hpp"
#include "huge_pages.hpp"
#include "interrupt.hpp"
#include "padded_fft.hpp"

namespace dc {
namespace {
/// The zero-padded box along an axis of n elements: the kernel's 2n - 1 offsets fit, so the
/// circular convolution is the linear one on the grid; even, so that its cosine and sine
/// transforms have whole half-lengths.
int subsurface_box_length(int n) {
  if (n == 1) return 1;
  int m = fft_fast_size(2 * n - 1);
  while (m % 2 != 0) m = fft_fast_size(m + 1);
  return m;
}

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
  field_fft_ = std::make_unique<PaddedFft>(grid.nx, grid.ny, mx, my, 3);
  quadrant_.assign(grid.size(), 0.0);
  // Transform lengths along an axis of box m: cosine (REDFT00) m/2 + 1 values (offsets 0..m/2),
  // sine (RODFT00) m/2 - 1 (offsets 1..m/2-1); a box of 1 is no transform (odd tables vanish).
  const auto lengths = [](int m, int* half) {
    half[0] = m == 1 ? 1 : m / 2 + 1;
    half[1] = m == 1 ? 0 : m / 2 - 1;
  };
  lengths(mx, half_x_);
  lengths(my, half_y_);
  const std::size_t buffer = static_cast<std::size_t>(half_x_[0]) * half_y_[0];
  kernel_in_ = fftw_alloc_real(buffer);
  kernel_out_ = fftw_alloc_real(buffer);
  if (!kernel_in_ || !kernel_out_) {
    fftw_free(kernel_in_);
    fftw_free(kernel_out_);
    throw std::bad_alloc();
  }
  std::fill(kernel_in_, kernel_in_ + buffer, 0.0);
  std::lock_guard<std::mutex> lock(fft_planner_mutex());
  fftw_plan_with_nthreads(fft_threads_for(static_cast<std::size_t>(mx) * my / 4));
  for (int odd_y = 0; odd_y < 2; ++odd_y)
    for (int odd_x = 0; odd_x < 2; ++odd_x) {
      const int hx = half_x_[odd_x], hy = half_y_[odd_y];
      if (hx == 0 || hy == 0 || (hx == 1 && hy == 1)) continue;  // zero, or no transform (a copy)
      int n[2], rank = 0;
      fftw_r2r_kind kind[2];
      if (hy > 1) n[rank] = hy, kind[rank++] = odd_y ? FFTW_RODFT00 : FFTW_REDFT00;  // y slowest
      if (hx > 1) n[rank] = hx, kind[rank++] = odd_x ? FFTW_RODFT00 : FFTW_REDFT00;
      plans_[odd_x + 2 * odd_y] = fftw_plan_r2r(rank, n, kernel_in_, kernel_out_, kind, FFTW_ESTIMATE);
      if (!plans_[odd_x + 2 * odd_y]) {  // the destructor does not run for a throwing constructor
        for (void* plan : plans_)
          if (plan) fftw_destroy_plan(static_cast<fftw_plan>(plan));
        fftw_free(kernel_in_);
        fftw_free(kernel_out_);
        throw std::runtime_error("FFTW could not plan a subsurface kernel transform");
      }
    }
}

SubsurfaceField::~SubsurfaceField() {
  {
    std::lock_guard<std::mutex> lock(fft_planner_mutex());
    for (void* plan : plans_)
      if (plan) fftw_destroy_plan(static_cast<fftw_plan>(plan));
  }
  fftw_free(kernel_in_);
  fftw_free(kernel_out_);
}

void SubsurfaceField::set_tractions(const SurfaceTractions& t) {
  const std::size_t N = grid_.size();
  for (const std::vector<double>* v : {&t.p, &t.tau_x, &t.tau_y})
    if (!v->empty() && v->size() != N)
      throw std::invalid_argument("subsurface field: a traction field must have one value per element");
  if (grid_.dimension == 2 && has_nonzero(t.tau_y))
    throw std::invalid_argument("subsurface field: 2-D problems have no tau_y");
  // By Axis: kX, kY, kZ. Copies only of the fields that are not zero.
  const std::vector<double>* fields[3] = {&t.tau_x, &t.tau_y, &t.p};
  for (int load = 0; load < 3; ++load) {
    active_[load] = has_nonzero(*fields[load]);
    if (!active_[load]) continue;
    tractions_[load] = *fields[load];
    field_fft_->forward_into(fields[load]->data(), load);  // the spectra, once
  }
  has_tractions_ = true;
}

void SubsurfaceField::compute_depth(double depth, double* out, SubsurfaceMethod method) {
  if (!has_tractions_) throw std::logic_error("subsurface field: set_tractions first");
  if (!(depth >= 0.0) || !std::isfinite(depth)) throw std::invalid_argument("subsurface field: depths must be >= 0");
  if (method == SubsurfaceMethod::direct) {
    direct_depth(depth, out);
  } else {
    coefficients_.set_depth(depth);
    fft_depth(out);
  }
}

SubsurfaceResult SubsurfaceField::compute(const SurfaceTractions& t, const std::vector<double>& depths,
                                          SubsurfaceMethod method) {
  for (double d : depths)
    if (!(d >= 0.0) || !std::isfinite(d)) throw std::invalid_argument("subsurface field: depths must be >= 0");
  set_tractions(t);
  const std::size_t per_depth = kFieldComponents * grid_.size();
  SubsurfaceResult r;
  r.grid = grid_;
  r.depths = depths;
  resize_on_huge_pages(r.values, depths.size() * per_depth);  // 9 K N values: 150 MB on 256^2 at 32 depths
  for (std::size_t k = 0; k < depths.size(); ++k) {
    throw_if_interrupted();
    compute_depth(depths[k], r.values.data() + k * per_depth, method);
  }
  return r;
}

bool SubsurfaceField::transform_kernel(int c, Axis load, bool odd_x, bool odd_y) {
  const int hx = half_x_[odd_x], hy = half_y_[odd_y];
  if (hx == 0 || hy == 0) return false;
  coefficients_.fill_quadrant(c, load, quadrant_.data(), grid_.nx);
  // Cosine transforms take offsets from 0, sine transforms from 1 (the odd table is 0 at 0).
  const int sx = odd_x ? 1 : 0, sy = odd_y ? 1 : 0;
  std::fill(kernel_in_, kernel_in_ + static_cast<std::size_t>(hx) * hy, 0.0);
  for (int dj = sy; dj < grid_.ny; ++dj)
    for (int di = sx; di < grid_.nx; ++di)
      kernel_in_[(di - sx) + static_cast<std::size_t>(hx) * (dj - sy)] = quadrant_[grid_.index(di, dj)];
  if (void* plan = plans_[odd_x + 2 * odd_y])
    fftw_execute(static_cast<fftw_plan>(plan));
  else
    kernel_out_[0] = kernel_in_[0];  // a single even value
  return true;
}

void SubsurfaceField::fft_depth(double* out) {
  const std::size_t N = grid_.size(), ncplx = field_fft_->spectrum_size();
  const int mx = field_fft_->mx(), my = field_fft_->my(), mxc = mx / 2 + 1;
  const double norm = 1.0 / (static_cast<double>(mx) * my);
  const bool square = coefficients_.square_corners();
  bool kept[kFieldComponents * 3] = {};  // this depth's spectra in kept_, by c * 3 + load
  double* sum = field_fft_->spectrum();
  for (int c = 0; c < kFieldComponents; ++c) {
    double* field = out + static_cast<std::size_t>(c) * N;
    if (grid_.dimension == 2 && !plane_strain_component(c)) {
      std::fill(field, field + N, 0.0);
      continue;
    }
    // The sum over the loads of kernel spectrum x traction spectrum, straight in the inverse's buffer.
    std::fill(sum, sum + 2 * ncplx, 0.0);
    for (Axis load : {kX, kY, kZ}) {
      if (!active_[load]) continue;
      const bool odd_x = SubsurfaceCoefficients::parity_x(c, load) < 0;
      const bool odd_y = SubsurfaceCoefficients::parity_y(c, load) < 0;
      const int hx = half_x_[odd_x], hy = half_y_[odd_y];
      if (hx == 0 || hy == 0) continue;
      // Square grids: the table of the mirror pair (x <-> y) was transformed earlier at this
      // depth when its component or load comes first; this one is its transpose, and so is its
      // transform (the cosine and sine kinds exchanged with the parities).
      int mc = c;
      Axis ml = load;
      if (square) SubsurfaceCoefficients::mirror(c, load, mc, ml);
      const bool mirrored = square && (mc != c || ml != load);
      const double* spectrum = kernel_out_;
      std::size_t stride_x = 1, stride_y = static_cast<std::size_t>(hx);  // spectrum(ix, iy)
      if (mirrored && kept[mc * 3 + ml]) {
        spectrum = kept_[mc * 3 + ml].data();
        stride_x = static_cast<std::size_t>(half_x_[odd_y]);  // the pair's layout: its x is this y
        stride_y = 1;
      } else {
        if (!transform_kernel(c, load, odd_x, odd_y)) continue;
        if (mirrored && active_[ml]) {  // the pair comes later at this depth: keep this transform
          std::vector<double>& keep = kept_[c * 3 + load];
          keep.assign(kernel_out_, kernel_out_ + static_cast<std::size_t>(hx) * hy);
          kept[c * 3 + load] = true;
        }
      }
      // The wrapped table's DFT from its real transform Y: Y (even-even), -i Y (one axis odd),
      // -Y (both odd); along y the half beyond my/2 mirrored (with a sign when odd).
      const double* traction = field_fft_->stored(load);
      const int odd_axes = static_cast<int>(odd_x) + static_cast<int>(odd_y);
      for (int kx = 0; kx < mxc; ++kx) {
        const int ix = odd_x ? kx - 1 : kx;
        if (ix < 0 || ix >= hx) continue;  // the sine transform's zeros at kx = 0 and mx/2
        double* row = sum + 2 * static_cast<std::size_t>(kx) * my;
        const double* trow = traction + 2 * static_cast<std::size_t>(kx) * my;
        const double* column = spectrum + stride_x * static_cast<std::size_t>(ix);
        for (int ky = 0; ky < my; ++ky) {
          const bool upper = 2 * ky > my;
          const int k2 = upper ? my - ky : ky, iy = odd_y ? k2 - 1 : k2;
          if (iy < 0 || iy >= hy) continue;
          const double y = (odd_y && upper ? -norm : norm) * column[stride_y * static_cast<std::size_t>(iy)];
          const double tr = trow[2 * ky], ti = trow[2 * ky + 1];
          if (odd_axes == 0) {
            row[2 * ky] += y * tr;
            row[2 * ky + 1] += y * ti;
          } else if (odd_axes == 1) {
            row[2 * ky] += y * ti;
            row[2 * ky + 1] -= y * tr;
          } else {
            row[2 * ky] -= y * tr;
            row[2 * ky + 1] -= y * ti;
          }
        }
      }
    }
    field_fft_->inverse(field);
  }
}

void SubsurfaceField::direct_depth(double depth, double* out) const {
  const std::size_t N = grid_.size();
  std::fill(out, out + kFieldComponents * N, 0.0);
  const auto value = [&](int load, std::size_t e) { return active_[load] ? tractions_[load][e] : 0.0; };
  for (int js = 0; js < grid_.ny; ++js)
    for (int is = 0; is < grid_.nx; ++is) {
      const std::size_t es = grid_.index(is, js);
      const double tx = value(kX, es), ty = value(kY, es), p = value(kZ, es);
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

Voigt voigt_stress(const FieldValues& f) {
  return Voigt{f[kSxx], f[kSyy], f[kSzz], f[kSyz], f[kSxz], f[kSxy]};
}

StressMeasures stress_measures(const FieldValues& f) {
  const StressInvariants s = stress_invariants(voigt_stress(f));
  return {std::sqrt(3.0) * s.sqrt_j2, s.tresca, s.hydrostatic};
}

SubsurfaceMeasures subsurface_measures(const SubsurfaceResult& r) {
  const std::size_t N = r.grid.size(), K = r.depths.size();
  SubsurfaceMeasures m;
  resize_on_huge_pages(m.von_mises, K * N);
  resize_on_huge_pages(m.tresca, K * N);
  resize_on_huge_pages(m.hydrostatic, K * N);
  // The extremes as flat indices k * N + e, placed at the end.
  std::size_t at_von_mises = 0, at_tresca = 0, at_max_hydrostatic = 0, at_min_hydrostatic = 0;
  const double root3 = std::sqrt(3.0);
  for (std::size_t k = 0; k < K; ++k) {
    const double *xx = r.component(k, kSxx), *yy = r.component(k, kSyy), *zz = r.component(k, kSzz);
    const double *yz = r.component(k, kSyz), *xz = r.component(k, kSxz), *xy = r.component(k, kSxy);
    double* von_mises = m.von_mises.data() + k * N;
    double* tresca = m.tresca.data() + k * N;
    double* hydro = m.hydrostatic.data() + k * N;
    for (std::size_t e = 0; e < N; ++e) {
      const StressInvariants s = stress_invariants(Voigt{xx[e], yy[e], zz[e], yz[e], xz[e], xy[e]});
      von_mises[e] = root3 * s.sqrt_j2;
      tresca[e] = s.tresca;
      hydro[e] = s.hydrostatic;
    }
  }
  for (std::size_t at = 1; at < K * N; ++at) {
    if (m.von_mises[at] > m.von_mises[at_von_mises]) at_von_mises = at;
    if (m.tresca[at] > m.tresca[at_tresca]) at_tresca = at;
    if (m.hydrostatic[at] > m.hydrostatic[at_max_hydrostatic]) at_max_hydrostatic = at;
    if (m.hydrostatic[at] < m.hydrostatic[at_min_hydrostatic]) at_min_hydrostatic = at;
  }
  const auto place = [&](const std::vector<double>& values, std::size_t at) {
    if (values.empty()) return FieldExtreme{};
    const std::size_t k = at / N, e = at % N;
    const int i = static_cast<int>(e % static_cast<std::size_t>(r.grid.nx));
    const int j = static_cast<int>(e / static_cast<std::size_t>(r.grid.nx));
    return FieldExtreme{values[at], k, i, j, r.grid.xc(i), r.grid.yc(j), r.depths[k]};
  };
  m.max_von_mises = place(m.von_mises, at_von_mises);
  m.max_tresca = place(m.tresca, at_tresca);
  m.max_hydrostatic = place(m.hydrostatic, at_max_hydrostatic);
  m.min_hydrostatic = place(m.hydrostatic, at_min_hydrostatic);
  return m;
}

}  // namespace dc
