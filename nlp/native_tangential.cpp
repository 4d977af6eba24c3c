// Native tangential solver: min 1/2 x'Qx + c'x over friction disks (3-D) or boxes (2-D), with a
// few dense equality rows (prescribed resultants), on a matrix-free operator Q (unit diagonal).
//
// Method: an active-set (semismooth / SQP-type) Newton method with conjugate-gradient inner
// solves and a search along the projection arc; every iterate is feasible.
//  * C = {x in disks/boxes, A x = b}. The exact projection onto C is Pi_D(z + A'nu) with nu in
//    R^m (m <= 3) the root of A Pi_D(z + A'nu) = b: a damped Newton ascent on the concave dual
//    (Levenberg-Marquardt safeguarded, increments computed without cancellation). The nu of the
//    projection of x - g (g = Qx + c) is the equality multiplier lambda (Qx + c = A'lambda + ...).
//  * Convergence: the fixed-point residual |x - Pi_C(x - g)|_inf = |x - Pi_D(x - (g - A'lambda))|_inf
//    <= tol * (size of the solution: max |x|, |Pi_C(x - g)|, capped by the largest radius or finite
//    bound), and each row |a'x - b| <= tol (|b| + sum |a_i x_i|): relative, so that a load tiny
//    against the bounds (full stick, huge friction) is still solved and not stopped at x = 0.
//  * Face, from w = x - g + A'lambda: a disk sticks where |w| <= r (both components free). Where
//    |w| > r it slips: on the circle it is linearised at x (normal n = x/|x| held, tangent free,
//    curvature mu/r of the circle with mu = -(g - A'lambda).n in the Hessian of the Lagrangian;
//    mu <= 0 releases it into the disk); inside the circle it is moved onto it along w/|w|.
//    A box variable is held at the bound that w crosses.
//  * Newton step: the quadratic model 1/2 d'(Q + D)d + g'd on that face, subject to A d = b - Ax,
//    minimised by projected CG (Gould-Hribar-Nocedal, with residual update), preconditioned by
//    1/(1 + mu/r) on slipping tangents; one operator apply per CG iteration; stopped at a relative
//    decrease min(0.1, residual) (inexact Newton: quadratic convergence once the face settles).
//  * Globalisation: x(alpha) = Pi_C(x + alpha dx) is taken when the objective decreases (Armijo;
//    the decrease 1/2 dx'(g + g+) is summed so that round-off on the circles and the multiplier
//    term do not swamp it), with up to two backtracks by quadratic interpolation; otherwise (or
//    when the residual stalls) a projected-gradient step with backtracking on the Lipschitz
//    constant, which always decreases the objective.
// Cost per outer iteration: the CG iterations, one apply per trial point, one for the fixed part
// of the step when it is not negligible. Typical: 80-220 applies from a cold start on 64^2-256^2
// Cattaneo problems, 1 from the solution.
// options.max_iter bounds the outer (Newton) iterations, and 20 * max_iter the operator applies;
// SolveOutcome::iterations counts operator applies. Never throws for a malformed program
// ("invalid program" message) or non-convergence (success = false).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "tangential_problem.hpp"
#include "interrupt.hpp"
#include "native_solvers.hpp"
#include "vector_ops.hpp"

namespace dc {
namespace {

using Vec = std::vector<double>;

double chord_dot(double ax, double ay, double bx, double by, double vx, double vy, double r);

}  // namespace

// The workspace's element types (named, not anonymous: NativeTangentialWorkspace::Storage, a
// member of a class with linkage, holds them).
namespace native_tangential_types {

struct Disk {
  std::size_t ix = 0, iy = 0;
  double r = 0.0;
};

/// A face of the feasible set: which box variables are held, which disks slip.
struct Face {
  std::vector<unsigned char> held;  ///< per box variable: 0 free, 1 at lower, 2 at upper
  std::vector<unsigned char> slip;  ///< per disk
  Vec nx, ny, curv;                 ///< per disk (slipping): outward normal, mu / r
};

}  // namespace native_tangential_types

/// Every vector of a solve, kept between solves: resized, not reallocated (vectors of n = 2N
/// doubles are above glibc's mmap threshold from 90^2 elements: fresh ones are page faults).
struct NativeTangentialWorkspace::Storage {
  std::vector<native_tangential_types::Disk> disks;
  std::vector<std::size_t> boxed, fixed;
  std::vector<unsigned char> role;
  Vec lower, upper, fixed_value;
  std::vector<const double*> rows;
  native_tangential_types::Face face;
  std::vector<Vec> a_face, a_face_minv;
  Vec minv, sqrt_minv, pre_in, u_last, work_u, work_x;
  // solve()'s iterates, and its residual per outer iteration
  Vec x, g, z, y, w, d0, hd0, dt, r, rho, p, q, xt, gt, gh, ght, history;
};

NativeTangentialWorkspace::NativeTangentialWorkspace() : storage_(std::make_unique<Storage>()) {}
NativeTangentialWorkspace::~NativeTangentialWorkspace() = default;
NativeTangentialWorkspace::NativeTangentialWorkspace(NativeTangentialWorkspace&&) noexcept = default;
NativeTangentialWorkspace& NativeTangentialWorkspace::operator=(NativeTangentialWorkspace&&) noexcept = default;

namespace {

using native_tangential_types::Disk;
using native_tangential_types::Face;

class NativeTangential {
 public:
  NativeTangential(const QuadraticProgram& qp, const SolveOptions& options, NativeTangentialWorkspace::Storage& work)
      : qp_(qp), options_(options), n_(qp.c.size()), m_(qp.equalities.size()), work_(work) {
    invalid_ = setup();
  }

  /// Fills `out` (reset_keeping_storage'd by the caller or fresh).
  void solve(SolveOutcome& out);

 private:
  // ---- set-up -------------------------------------------------------------------------------
  std::string setup();

  // ---- feasible set -------------------------------------------------------------------------
  /// x = Pi_D(u): disks, boxes and fixed variables.
  void project_d(const Vec& u, Vec& x) const;
  /// u = z + A'nu.
  void shift(const Vec& z, const Eigen::VectorXd& nu, Vec& u) const;
  /// e = b - A x.
  Eigen::VectorXd equality_defect(const Vec& x) const;
  /// x = Pi_C(z); nu is the warm start and returns the multiplier of the equality rows;
  /// u_last_ keeps z + A'nu. False when A x = b cannot be met inside the disks and boxes.
  bool project(const Vec& z, Vec& x, Eigen::VectorXd& nu);

  // ---- face and its operators ---------------------------------------------------------------
  void build_face(const Vec& x, const Vec& w);
  void to_face(Vec& v) const;          ///< orthogonal projection onto the free directions
  /// z = M^-1 v on the face: v / (1 + curvature) on slipping tangents, or with the program's
  /// preconditioner P (an approximate Q^-1) z = F D^-1/2 P D^-1/2 v, F the face's projection,
  /// D = 1 + curvature: symmetric positive definite on the face.
  void face_precondition(const Vec& v, Vec& z) const;
  void add_curvature(const Vec& v, Vec& y) const;  ///< y += D v on slipping tangents
  /// Projected preconditioned residual rho = M^-1 r with A_F rho = 0 (r is updated: its range(A_F')
  /// part is removed).
  void null_space_precondition(Vec& r, Vec& rho) const;

  /// (x1 - x0)'v without the round-off of the steps between two points of one circle: such a
  /// step is orthogonal to x0 + x1, so only its component along the chord counts (v is O(1)
  /// along the normal on slipping elements, where the chord is tiny).
  double step_dot(const Vec& x0, const Vec& x1, const Vec& v) const;

  void apply(const Vec& x, Vec& y) {
    ++applies_;
    qp_.Q->apply(x.data(), y.data());
  }
  void gradient(const Vec& x, Vec& g) {
    apply(x, g);
    for (std::size_t i = 0; i < n_; ++i) g[i] += qp_.c[i];
  }
  double objective(const Vec& x, const Vec& g) const {
    double f = 0.0;
    for (std::size_t i = 0; i < n_; ++i) f += 0.5 * x[i] * (g[i] + qp_.c[i]);
    return f;
  }
  /// Every row met relative to the size of its terms: |a'x - b| <= tol (|b| + sum |a_i x_i|).
  bool equalities_met(const Vec& x) const {
    const Eigen::VectorXd e = equality_defect(x);
    for (std::size_t k = 0; k < m_; ++k) {
      double size = std::abs(b_(static_cast<Eigen::Index>(k)));
      for (std::size_t i = 0; i < n_; ++i) size += std::abs(rows_[k][i] * x[i]);
      if (std::abs(e(static_cast<Eigen::Index>(k))) > options_.tol * size) return false;
    }
    return true;
  }
  double equality_residual(const Vec& x) const {
    return m_ == 0 ? 0.0 : equality_defect(x).lpNorm<Eigen::Infinity>();
  }

  const QuadraticProgram& qp_;
  const SolveOptions& options_;
  std::size_t n_, m_;
  std::string invalid_;

  NativeTangentialWorkspace::Storage& work_;
  std::vector<Disk>& disks_ = work_.disks;          // radius > 0
  std::vector<std::size_t>& boxed_ = work_.boxed;   // variables outside disks with lower < upper
  std::vector<std::size_t>& fixed_ = work_.fixed;   // variables held at a value (zero radius, lower == upper)
  Vec &lower_ = work_.lower, &upper_ = work_.upper, &fixed_value_ = work_.fixed_value;  // per variable
  std::vector<const double*>& rows_ = work_.rows;   // equality rows
  Eigen::VectorXd b_;
  Eigen::VectorXd eq_scale_;              // |b| + sum |a| * (size of the variable's set)
  double scale_ = 1.0;                    // max(1, largest radius / finite bound)
  double rows_norm2_ = 0.0;               // |A|_2^2 (bounds the curvature of the projection's dual)

  Face& face_ = work_.face;
  std::vector<Vec>& a_face_ = work_.a_face;            // equality rows projected on the face
  std::vector<Vec>& a_face_minv_ = work_.a_face_minv;  // M^-1 a_face_
  Vec& minv_ = work_.minv;                             // diagonal preconditioner: 1 / (1 + curvature)
  Vec& sqrt_minv_ = work_.sqrt_minv;                   // its square root (face_precondition, per CG iteration)
  Vec& pre_in_ = work_.pre_in;                         // face_precondition's scaled input
  Eigen::MatrixXd gram_pinv_;                          // (A_F M^-1 A_F')^+
  Vec& u_last_ = work_.u_last;                         // z + A'nu of the last projection
  Vec &work_u_ = work_.work_u, &work_x_ = work_.work_x;  // projection trial buffers
  int applies_ = 0;
};

std::string NativeTangential::setup() {
  if (qp_.Q == nullptr) return "no operator Q";
  if (qp_.Q->rows() != n_ || qp_.Q->cols() != n_) return "Q does not match c in size";
  if ((!qp_.lower.empty() && qp_.lower.size() != n_) || (!qp_.upper.empty() && qp_.upper.size() != n_))
    return "bounds do not match c in size";
  if (!qp_.x0.empty() && qp_.x0.size() != n_) return "x0 does not match c in size";
  disks_.clear();
  boxed_.clear();
  fixed_.clear();
  rows_.clear();
  if (qp_.lower.empty()) lower_.assign(n_, -kInf);
  else lower_ = qp_.lower;
  if (qp_.upper.empty()) upper_.assign(n_, kInf);
  else upper_ = qp_.upper;
  for (std::size_t i = 0; i < n_; ++i) {
    if (!std::isfinite(qp_.c[i])) return "c is not finite";
    if (std::isnan(lower_[i]) || std::isnan(upper_[i]) || lower_[i] > upper_[i] || lower_[i] == kInf ||
        upper_[i] == -kInf)
      return "empty bounds on variable " + std::to_string(i);
  }
  fixed_value_.assign(n_, 0.0);
  std::vector<unsigned char>& role = work_.role;  // 0 box, 1 disk, 2 fixed
  role.assign(n_, 0);
  for (const auto& d : qp_.disks) {
    if (d.ix < 0 || d.iy < 0 || static_cast<std::size_t>(d.ix) >= n_ || static_cast<std::size_t>(d.iy) >= n_ ||
        d.ix == d.iy)
      return "a disk has bad indices";
    const auto ix = static_cast<std::size_t>(d.ix), iy = static_cast<std::size_t>(d.iy);
    if (role[ix] != 0 || role[iy] != 0) return "a variable belongs to two disks";
    if (!(d.radius >= 0.0) || !std::isfinite(d.radius)) return "a disk has a negative or non-finite radius";
    const auto contains = [&](std::size_t i, double lo, double hi) { return lower_[i] <= lo && upper_[i] >= hi; };
    if (d.radius > 0.0 && contains(ix, -d.radius, d.radius) && contains(iy, -d.radius, d.radius)) {
      role[ix] = role[iy] = 1;
      disks_.push_back({ix, iy, d.radius});
    } else if (d.radius == 0.0 || (lower_[ix] == upper_[ix] && lower_[iy] == upper_[iy])) {
      // A point: the zero disk, or both components fixed by their bounds inside the disk.
      const double vx = d.radius == 0.0 ? 0.0 : lower_[ix], vy = d.radius == 0.0 ? 0.0 : lower_[iy];
      if (!contains(ix, vx, vx) || !contains(iy, vy, vy) || std::hypot(vx, vy) > d.radius)
        return "bounds and disk leave no feasible point";
      role[ix] = role[iy] = 2;
      fixed_value_[ix] = vx;
      fixed_value_[iy] = vy;
    } else {
      return "bounds that cut a disk are not supported";
    }
  }
  for (std::size_t i = 0; i < n_; ++i) {
    if (role[i] == 0 && lower_[i] == upper_[i]) {
      role[i] = 2;
      fixed_value_[i] = lower_[i];
    }
    if (role[i] == 0) boxed_.push_back(i);
    if (role[i] == 2) fixed_.push_back(i);
  }
  for (const auto& d : disks_) scale_ = std::max(scale_, d.r);
  for (std::size_t i : boxed_)
    for (double v : {lower_[i], upper_[i]})
      if (std::isfinite(v)) scale_ = std::max(scale_, std::abs(v));
  b_.resize(static_cast<Eigen::Index>(m_));
  eq_scale_.resize(static_cast<Eigen::Index>(m_));
  for (std::size_t k = 0; k < m_; ++k) {
    const auto& eq = qp_.equalities[k];
    if (eq.a.size() != n_) return "an equality row does not match c in size";
    if (!std::isfinite(eq.b)) return "an equality right-hand side is not finite";
    double s = std::abs(eq.b);
    for (std::size_t i = 0; i < n_; ++i) {
      if (!std::isfinite(eq.a[i])) return "an equality row is not finite";
      double size = scale_;
      if (role[i] == 2) size = std::abs(fixed_value_[i]);
      else if (role[i] == 0 && std::isfinite(lower_[i]) && std::isfinite(upper_[i]))
        size = std::max(std::abs(lower_[i]), std::abs(upper_[i]));
      s += std::abs(eq.a[i]) * size;
    }
    rows_.push_back(eq.a.data());
    b_(static_cast<Eigen::Index>(k)) = eq.b;
    eq_scale_(static_cast<Eigen::Index>(k)) = std::max(s, 1e-300);
  }
  if (m_ > 0) {
    Eigen::MatrixXd aat(static_cast<Eigen::Index>(m_), static_cast<Eigen::Index>(m_));
    for (std::size_t k = 0; k < m_; ++k)
      for (std::size_t l = 0; l < m_; ++l) {
        double s = 0.0;
        for (std::size_t i = 0; i < n_; ++i) s += rows_[k][i] * rows_[l][i];
        aat(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(l)) = s;
      }
    rows_norm2_ = std::max(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(aat).eigenvalues().maxCoeff(), 1e-300);
  }
  face_.held.assign(boxed_.size(), 0);
  face_.slip.assign(disks_.size(), 0);
  face_.nx.assign(disks_.size(), 0.0);
  face_.ny.assign(disks_.size(), 0.0);
  face_.curv.assign(disks_.size(), 0.0);
  return {};
}

void NativeTangential::project_d(const Vec& u, Vec& x) const {
  x.resize(n_);
  for (std::size_t i : boxed_) x[i] = std::clamp(u[i], lower_[i], upper_[i]);
  for (std::size_t i : fixed_) x[i] = fixed_value_[i];
  for (const auto& d : disks_) {
    x[d.ix] = u[d.ix];
    x[d.iy] = u[d.iy];
    project_onto_disk(x[d.ix], x[d.iy], d.r);
  }
}

void NativeTangential::shift(const Vec& z, const Eigen::VectorXd& nu, Vec& u) const {
  u.resize(n_);
  if (m_ == 1) {
    const double v = nu(0);
    const double* a = rows_[0];
    for (std::size_t i = 0; i < n_; ++i) u[i] = z[i] + v * a[i];
    return;
  }
  for (std::size_t i = 0; i < n_; ++i) {
    double s = z[i];
    for (std::size_t k = 0; k < m_; ++k) s += nu(static_cast<Eigen::Index>(k)) * rows_[k][i];
    u[i] = s;
  }
}

Eigen::VectorXd NativeTangential::equality_defect(const Vec& x) const {
  Eigen::VectorXd e(static_cast<Eigen::Index>(m_));
  for (std::size_t k = 0; k < m_; ++k) {
    const double* a = rows_[k];
    double s = 0.0;
    for (std::size_t i = 0; i < n_; ++i) s += a[i] * x[i];
    e(static_cast<Eigen::Index>(k)) = b_(static_cast<Eigen::Index>(k)) - s;
  }
  return e;
}

bool NativeTangential::project(const Vec& z, Vec& x, Eigen::VectorXd& nu) {
  if (m_ == 0) {
    u_last_ = z;
    project_d(z, x);
    return true;
  }
  // Dual of min 1/2|x - z|^2 - nu'(Ax - b) over D: theta(nu) = that minimum, concave, with
  // gradient e = b - A x(nu) and Hessian -A J A' (J: Jacobian of Pi_D at u = z + A'nu).
  const auto evaluate = [&](const Eigen::VectorXd& v, Vec& u, Vec& xv, Eigen::VectorXd& e) {
    shift(z, v, u);
    project_d(u, xv);
    e = equality_defect(xv);
  };
  // theta(nu_t) - theta(nu) without cancellation (theta itself may be large):
  //   sum_i (x_t - x)_i ((x_t + x)_i / 2 - u_i) + (nu_t - nu)'e_t,   u = z + A'nu.
  const auto increase = [&](const Vec& xv, const Vec& uv, const Vec& xt, const Eigen::VectorXd& dnu,
                            const Eigen::VectorXd& et) {
    double s = 0.0;
    for (std::size_t i : boxed_) s += (xt[i] - xv[i]) * (0.5 * (xt[i] + xv[i]) - uv[i]);
    for (const auto& d : disks_) {
      const std::size_t i = d.ix, j = d.iy;
      s += chord_dot(xv[i], xv[j], xt[i], xt[j], 0.5 * (xt[i] + xv[i]) - uv[i], 0.5 * (xt[j] + xv[j]) - uv[j], d.r);
    }
    return s + dnu.dot(et);
  };
  const auto within = [&](const Eigen::VectorXd& e, double rel) {
    return (e.cwiseAbs().array() <= rel * eq_scale_.array()).all();
  };
  const auto m = static_cast<Eigen::Index>(m_);
  Eigen::VectorXd e(m), e_t(m), nu_t(m);
  Eigen::MatrixXd h(m, m);
  std::vector<double> pa(m_), pb(m_);
  evaluate(nu, u_last_, x, e);
  const double delta_min = 1e-12 * rows_norm2_;
  double delta = delta_min;
  for (int it = 0; it < 100 && !within(e, 1e-13); ++it) {
    // A J A' at u (J: Jacobian of Pi_D).
    h.setZero();
    const auto add = [&](const std::vector<double>& v, double weight) {
      for (Eigen::Index k = 0; k < m; ++k)
        for (Eigen::Index l = 0; l <= k; ++l)
          h(k, l) += weight * v[static_cast<std::size_t>(k)] * v[static_cast<std::size_t>(l)];
    };
    for (std::size_t i : boxed_)
      if (u_last_[i] > lower_[i] && u_last_[i] < upper_[i]) {
        for (std::size_t k = 0; k < m_; ++k) pa[k] = rows_[k][i];
        add(pa, 1.0);
      }
    for (const auto& d : disks_) {
      const double ux = u_last_[d.ix], uy = u_last_[d.iy], norm2 = ux * ux + uy * uy;
      if (norm2 <= d.r * d.r) {
        for (std::size_t k = 0; k < m_; ++k) {
          pa[k] = rows_[k][d.ix];
          pb[k] = rows_[k][d.iy];
        }
        add(pa, 1.0);
        add(pb, 1.0);
      } else {
        const double norm = std::sqrt(norm2), tx = -uy / norm, ty = ux / norm;
        for (std::size_t k = 0; k < m_; ++k) pa[k] = rows_[k][d.ix] * tx + rows_[k][d.iy] * ty;
        add(pa, d.r / norm);
      }
    }
    h = h.selfadjointView<Eigen::Lower>();
    // Damped Newton ascent on the dual with a Levenberg-Marquardt safeguard: (A J A' + delta I)
    // step = e; delta grows on failure up to beyond the Lipschitz constant |A|^2 of the dual
    // gradient, where the step is a plain gradient ascent step that cannot fail (J may be
    // singular: everything clamped). At the round-off floor one failed Newton step ends it.
    const bool floor = within(e, 1e-10);
    bool accepted = false;
    for (; delta <= 1e3 * rows_norm2_; delta *= 100.0) {
      Eigen::MatrixXd hd = h;
      hd.diagonal().array() += delta;
      const Eigen::VectorXd step = hd.ldlt().solve(e);
      const double slope = e.dot(step);
      const double alpha_min = delta == delta_min ? 1.0 / 64.0 : 0.25;
      for (double alpha = 1.0; alpha >= alpha_min && !accepted; alpha *= 0.5) {
        nu_t = nu + alpha * step;
        evaluate(nu_t, work_u_, work_x_, e_t);
        // Armijo on the concave dual (or a halved residual at a dual value unchanged up to round-off).
        const double gain = increase(x, u_last_, work_x_, nu_t - nu, e_t);
        if (gain >= 1e-4 * alpha * slope || (e_t.norm() <= 0.5 * e.norm() && gain >= -1e-3 * alpha * slope)) {
          nu = nu_t;
          e = e_t;
          std::swap(u_last_, work_u_);
          std::swap(x, work_x_);
          accepted = true;
        }
      }
      if (accepted || floor) break;
    }
    if (!accepted) break;
    delta = std::max(delta * 1e-4, delta_min);
  }
  return within(e, 1e-10);
}

/// (b - a).v for two points a, b of the plane; when both lie on the circle of radius r the step
/// is orthogonal to a + b, and only its component along the chord is kept: the normal part
/// of b - a is round-off there, which v (O(1) along the normal) would amplify.
double chord_dot(double ax, double ay, double bx, double by, double vx, double vy, double r) {
  const double dx = bx - ax, dy = by - ay;
  const double tol = 1e-12 * r;
  if (std::abs(std::sqrt(ax * ax + ay * ay) - r) <= tol && std::abs(std::sqrt(bx * bx + by * by) - r) <= tol) {
    const double mx = -(ay + by), my = ax + bx, norm2 = mx * mx + my * my;
    if (norm2 > 0.0) return (dx * mx + dy * my) * (mx * vx + my * vy) / norm2;
  }
  return dx * vx + dy * vy;
}

double NativeTangential::step_dot(const Vec& x0, const Vec& x1, const Vec& v) const {
  double s = 0.0;
  for (std::size_t i : boxed_) s += (x1[i] - x0[i]) * v[i];
  for (const auto& d : disks_)
    s += chord_dot(x0[d.ix], x0[d.iy], x1[d.ix], x1[d.iy], v[d.ix], v[d.iy], d.r);
  return s;
}

void NativeTangential::build_face(const Vec& x, const Vec& w) {
  minv_.assign(n_, 1.0);
  for (std::size_t k = 0; k < boxed_.size(); ++k) {
    const std::size_t i = boxed_[k];
    face_.held[k] = w[i] <= lower_[i] ? 1 : (w[i] >= upper_[i] ? 2 : 0);
  }
  for (std::size_t k = 0; k < disks_.size(); ++k) {
    const auto& d = disks_[k];
    const double wx = w[d.ix], wy = w[d.iy], w_norm = std::sqrt(wx * wx + wy * wy);
    const double xx = x[d.ix], xy = x[d.iy], x_norm = std::sqrt(xx * xx + xy * xy);
    face_.slip[k] = 0;
    if (w_norm <= d.r) continue;  // the projection of w is w itself: stick
    if (x_norm >= d.r * (1.0 - 1e-9)) {
      // On the circle: linearise there (SQP); the multiplier estimate mu = -gh.n must be positive
      // (gh = x - w), else the element is released into the disk.
      const double nx = xx / x_norm, ny = xy / x_norm;
      const double mu = -((xx - wx) * nx + (xy - wy) * ny);
      if (!(mu > 0.0)) continue;
      face_.slip[k] = 1;
      face_.nx[k] = nx;
      face_.ny[k] = ny;
      face_.curv[k] = mu / d.r;
    } else {
      // Inside, but its projected-gradient point is on the circle: move it there along w/|w|.
      face_.slip[k] = 1;
      face_.nx[k] = wx / w_norm;
      face_.ny[k] = wy / w_norm;
      face_.curv[k] = std::max(w_norm - (face_.nx[k] * xx + face_.ny[k] * xy), 0.0) / d.r;
    }
    if (face_.slip[k]) minv_[d.ix] = minv_[d.iy] = 1.0 / (1.0 + face_.curv[k]);
  }
  sqrt_minv_.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) sqrt_minv_[i] = std::sqrt(minv_[i]);
}

void NativeTangential::to_face(Vec& v) const {
  for (std::size_t k = 0; k < boxed_.size(); ++k)
    if (face_.held[k]) v[boxed_[k]] = 0.0;
  for (std::size_t i : fixed_) v[i] = 0.0;
  for (std::size_t k = 0; k < disks_.size(); ++k) {
    if (!face_.slip[k]) continue;
    const auto& d = disks_[k];
    const double tx = -face_.ny[k], ty = face_.nx[k];
    const double s = tx * v[d.ix] + ty * v[d.iy];
    v[d.ix] = s * tx;
    v[d.iy] = s * ty;
  }
}

void NativeTangential::face_precondition(const Vec& v, Vec& z) const {
  z.resize(n_);
  if (!qp_.preconditioner) {
    for (std::size_t i = 0; i < n_; ++i) z[i] = minv_[i] * v[i];
    return;
  }
  pre_in_.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) pre_in_[i] = sqrt_minv_[i] * v[i];
  to_face(pre_in_);
  qp_.preconditioner->apply(pre_in_.data(), z.data());
  for (std::size_t i = 0; i < n_; ++i) z[i] *= sqrt_minv_[i];
  to_face(z);
}

void NativeTangential::add_curvature(const Vec& v, Vec& y) const {
  for (std::size_t k = 0; k < disks_.size(); ++k) {
    if (!face_.slip[k]) continue;
    const auto& d = disks_[k];
    const double tx = -face_.ny[k], ty = face_.nx[k];
    const double s = face_.curv[k] * (tx * v[d.ix] + ty * v[d.iy]);
    y[d.ix] += s * tx;
    y[d.iy] += s * ty;
  }
}

void NativeTangential::null_space_precondition(Vec& r, Vec& rho) const {
  // Gould, Hribar & Nocedal (2001): the residual itself is updated, r <- r - A_F'y with
  // y = (A_F M^-1 A_F')^+ A_F M^-1 r, so that it stays small; projecting a residual with a large
  // range(A') part (the multiplier term of g) makes the projected CG unstable.
  const auto m = static_cast<Eigen::Index>(m_);
  Eigen::VectorXd t(m);
  for (int pass = 0; pass < (m_ == 0 ? 0 : 2); ++pass) {  // a second pass: iterative refinement
    for (Eigen::Index k = 0; k < m; ++k) t(k) = dot(a_face_minv_[static_cast<std::size_t>(k)], r);
    const Eigen::VectorXd coef = gram_pinv_ * t;
    for (Eigen::Index k = 0; k < m; ++k) {
      const auto& a = a_face_[static_cast<std::size_t>(k)];
      const double ck = coef(k);
      for (std::size_t i = 0; i < n_; ++i) r[i] -= ck * a[i];
    }
  }
  face_precondition(r, rho);
}

void NativeTangential::solve(SolveOutcome& out) {
  if (!invalid_.empty()) {
    out.message = "native tangential: invalid program: " + invalid_;
    return;
  }
  out.equality_multipliers.assign(m_, 0.0);
  if (n_ == 0) {
    out.success = true;
    out.message = "native tangential: empty program";
    return;
  }
  const int max_outer = std::max(options_.max_iter, 1);
  const long long max_applies = 20LL * max_outer;
  // Stopping is relative to the size of the solution (the larger of x and its projected
  // gradient step, at most the largest radius): an absolute test stops at x = 0 when the load
  // is tiny against the friction bound (full stick, huge mu).
  double tol_x = options_.tol * scale_;
  const auto m = static_cast<Eigen::Index>(m_);

  // Every entry of these is written before it is read (resize keeps the last solve's values).
  Vec &x = work_.x, &g = work_.g, &z = work_.z, &y = work_.y, &w = work_.w, &d0 = work_.d0, &hd0 = work_.hd0,
      &dt = work_.dt, &r = work_.r, &rho = work_.rho, &p = work_.p, &q = work_.q, &xt = work_.xt, &gt = work_.gt,
      &gh = work_.gh, &ght = work_.ght;
  for (Vec* v : {&x, &g, &z, &y, &w, &d0, &hd0, &dt, &r, &rho, &p, &q, &xt, &gt, &gh, &ght}) v->resize(n_);
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m), nu_t(m);
  if (qp_.x0.size() == n_) z = qp_.x0;
  else std::fill(z.begin(), z.end(), 0.0);
  if (!project(z, x, lambda)) {
    out.x = x;
    out.message = "native tangential: the equality rows could not be met inside the disks and bounds (infeasible program)";
    return;
  }
  lambda.setZero();
  gradient(x, g);
  double f = objective(x, g);
  double lipschitz = 1.0;  // Q has unit diagonal: lambda_max >= 1
  double res = kInf, eq_res = kInf, level = scale_;
  int outer = 0, newton_steps = 0, gradient_steps = 0, cg_total = 0;
  Vec& history = work_.history;  // residual per outer iteration
  history.clear();
  std::string status;
  bool converged = false;

  for (;; ++outer) {
    throw_if_interrupted();
    // Residual and multipliers: y = Pi_C(x - g) = Pi_D(x - g + A'lambda).
    for (std::size_t i = 0; i < n_; ++i) z[i] = x[i] - g[i];
    if (!project(z, y, lambda)) {
      status = "the projection onto the equality rows failed";
      break;
    }
    w = u_last_;
    res = 0.0;
    for (std::size_t i = 0; i < n_; ++i) res = std::max(res, std::abs(x[i] - y[i]));
    level = std::min(scale_, std::max(max_abs(x), max_abs(y)));
    tol_x = options_.tol * level;
    eq_res = equality_residual(x);
    history.push_back(res);
    if (options_.progress) options_.progress({applies_, f, res, tol_x});
    if (res <= tol_x && equalities_met(x)) {
      converged = true;
      break;
    }
    if (outer >= max_outer || applies_ + 2 > max_applies) {
      status = "iteration limit reached";
      break;
    }

    // Stagnation (Newton steps accepted without progress): a gradient step instead.
    const bool stalled = history.size() > 4 && res > 0.5 * history[history.size() - 5];
    bool accepted = false;
    if (!stalled) {
      build_face(x, w);
      // Fixed part of the step: held box variables to their bound, slipping disks onto the circle.
      std::fill(d0.begin(), d0.end(), 0.0);
      for (std::size_t k = 0; k < boxed_.size(); ++k)
        if (face_.held[k]) {
          const std::size_t i = boxed_[k];
          d0[i] = (face_.held[k] == 1 ? lower_[i] : upper_[i]) - x[i];
        }
      for (std::size_t k = 0; k < disks_.size(); ++k)
        if (face_.slip[k]) {
          const auto& d = disks_[k];
          const double s = d.r - (face_.nx[k] * x[d.ix] + face_.ny[k] * x[d.iy]);
          d0[d.ix] = s * face_.nx[k];
          d0[d.iy] = s * face_.ny[k];
        }
      // Equality rows on the face: a particular solution of A_F d = b - A(x + d0).
      if (m_ > 0) {
        a_face_.resize(m_);
        for (std::size_t k = 0; k < m_; ++k) {
          a_face_[k].assign(rows_[k], rows_[k] + n_);
          to_face(a_face_[k]);
        }
        Eigen::MatrixXd gram(m, m);
        a_face_minv_.resize(m_);
        auto& ma = a_face_minv_;
        for (std::size_t k = 0; k < m_; ++k) face_precondition(a_face_[k], ma[k]);
        for (Eigen::Index k = 0; k < m; ++k)
          for (Eigen::Index l = 0; l < m; ++l)
            gram(k, l) = dot(a_face_[static_cast<std::size_t>(k)], ma[static_cast<std::size_t>(l)]);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(gram);
        const Eigen::VectorXd ev = eig.eigenvalues();
        const double cut = 1e-12 * std::max(ev.cwiseAbs().maxCoeff(), 1e-300);
        Eigen::VectorXd inv(m);
        for (Eigen::Index k = 0; k < m; ++k) inv(k) = ev(k) > cut ? 1.0 / ev(k) : 0.0;
        gram_pinv_ = eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
        for (std::size_t i = 0; i < n_; ++i) xt[i] = x[i] + d0[i];
        const Eigen::VectorXd coef = gram_pinv_ * equality_defect(xt);
        for (std::size_t k = 0; k < m_; ++k)
          for (std::size_t i = 0; i < n_; ++i) d0[i] += coef(static_cast<Eigen::Index>(k)) * ma[k][i];
      }
      // Gradient of the model 1/2 d'(Q + D)d + g'd at d0 (the apply is skipped when d0 is negligible).
      std::fill(hd0.begin(), hd0.end(), 0.0);
      if (max_abs(d0) > 1e-3 * tol_x) {
        apply(d0, hd0);
        add_curvature(d0, hd0);
      }
      for (std::size_t i = 0; i < n_; ++i) r[i] = g[i] + hd0[i];
      to_face(r);
      null_space_precondition(r, rho);
      // Projected preconditioned CG on the face, stopped at a relative decrease min(0.1, res).
      std::fill(dt.begin(), dt.end(), 0.0);
      const double rho0 = max_abs(rho);
      const double target = std::max(std::min(0.1, res / scale_) * rho0, 0.1 * tol_x);
      double rz = dot(r, rho);
      for (std::size_t i = 0; i < n_; ++i) p[i] = -rho[i];
      const long long cg_cap = max_applies - applies_ - 1;
      for (long long it = 0; it < cg_cap && max_abs(rho) > target; ++it) {
        apply(p, q);
        ++cg_total;
        to_face(q);
        add_curvature(p, q);
        const double pq = dot(p, q);
        if (!(pq > 0.0)) break;
        const double alpha = rz / pq;
        for (std::size_t i = 0; i < n_; ++i) {
          dt[i] += alpha * p[i];
          r[i] += alpha * q[i];
        }
        null_space_precondition(r, rho);
        const double rz_new = dot(r, rho);
        const double beta = rz_new / rz;
        rz = rz_new;
        for (std::size_t i = 0; i < n_; ++i) p[i] = -rho[i] + beta * p[i];
      }
      // Trial points on the projection arc x(alpha) = Pi_C(x + alpha dx): alpha = 1, then at most
      // two backtracks by quadratic interpolation of the objective along the arc.
      double alpha = 1.0;
      for (int trial = 0; trial < 3 && !accepted && applies_ < max_applies; ++trial) {
        for (std::size_t i = 0; i < n_; ++i) z[i] = x[i] + alpha * (d0[i] + dt[i]);
        nu_t.setZero();  // x + dx meets the rows already: the projection barely moves it
        if (!project(z, xt, nu_t)) break;
        gradient(xt, gt);
        // With g - A'lambda in place of g (the same, as A(xt - x) = 0): the multiplier would
        // amplify the round-off of A(xt - x) = 0 into the decrease.
        shift(g, -lambda, gh);
        shift(gt, -lambda, ght);
        const double df = 0.5 * (step_dot(x, xt, gh) + step_dot(x, xt, ght)), slope = step_dot(x, xt, gh);
        double step = 0.0;
        for (std::size_t i = 0; i < n_; ++i) step = std::max(step, std::abs(xt[i] - x[i]));
        if (step > 0.0 && df <= 1e-4 * slope) {
          std::swap(x, xt);
          std::swap(g, gt);
          accepted = true;
          ++newton_steps;
        } else if (slope < 0.0 && df > slope) {
          alpha *= std::clamp(-slope / (2.0 * (df - slope)), 0.1, 0.5);
        } else {
          break;  // not a descent direction: leave it to the gradient step
        }
      }
    }
    if (!accepted) {
      // Projected gradient with backtracking on the Lipschitz constant: always a decrease.
      bool moved = false;
      for (int k = 0; k < 60 && applies_ < max_applies; ++k) {
        for (std::size_t i = 0; i < n_; ++i) z[i] = x[i] - g[i] / lipschitz;
        nu_t = lambda / lipschitz;
        if (!project(z, xt, nu_t)) {
          status = "the projection onto the equality rows failed";
          break;
        }
        gradient(xt, gt);
        double dd = 0.0, dqd = 0.0;
        for (std::size_t i = 0; i < n_; ++i) {
          const double di = xt[i] - x[i];
          dd += di * di;
          dqd += di * (gt[i] - g[i]);
        }
        if (dd == 0.0) break;
        if (dqd <= lipschitz * dd * (1.0 + 1e-10)) {
          std::swap(x, xt);
          std::swap(g, gt);
          moved = true;
          ++gradient_steps;
          break;
        }
        lipschitz *= 2.0;
      }
      if (!moved && applies_ >= max_applies) {
        status = "iteration limit reached";
        break;
      }
      if (!moved) {
        if (status.empty()) status = "no descent from the projected gradient (round-off floor)";
        break;
      }
      history.clear();  // a fresh start for the stagnation test
    }
    f = objective(x, g);
  }

  out.x = x;
  out.objective = objective(x, g);
  out.iterations = applies_;
  for (Eigen::Index k = 0; k < m; ++k) out.equality_multipliers[static_cast<std::size_t>(k)] = lambda(k);
  out.success = converged;
  // The message written into out's own storage (no temporaries: a solve per dynamic step).
  char effort[256];
  std::snprintf(effort, sizeof effort,
                " after %d outer iterations (%d Newton, %d gradient steps, %d CG), iterations = %lld operator "
                "applies; residual %.3g, equality residual %.3g",
                outer, newton_steps, gradient_steps, cg_total, static_cast<long long>(applies_),
                level > 0.0 ? res / level : res, eq_res);
  out.message.assign("native tangential: ");
  out.message.append(converged ? "converged" : status.c_str());
  out.message.append(effort);
}

}  // namespace

SolveOutcome solve_tangential_native(const QuadraticProgram& qp, const SolveOptions& options,
                                     NativeTangentialWorkspace& workspace) {
  SolveOutcome out;
  solve_tangential_native(qp, options, workspace, out);
  return out;
}

void solve_tangential_native(const QuadraticProgram& qp, const SolveOptions& options,
                             NativeTangentialWorkspace& workspace, SolveOutcome& out) {
  NativeTangential solver(qp, options, *workspace.storage_);
  solver.solve(out);
}

SolveOutcome solve_tangential_native(const QuadraticProgram& qp, const SolveOptions& options) {
  NativeTangentialWorkspace workspace;
  return solve_tangential_native(qp, options, workspace);
}

}  // namespace dc
