#pragma once
// Native specialist solvers on matrix-free (FFT) operators: the fast path for large grids.
#include <memory>
#include <vector>

#include "normal_preconditioner.hpp"
#include "quadratic_program.hpp"

namespace dc {

/// The normal problem (4.7) in QP form (bounds 0 <= x <= upper, upper +inf or 0 for elements that
/// cannot touch; at most one equality sum a x = b with equal weights a on the free elements: force
/// control), solved by bound-constrained conjugate gradients on the contact set
/// (nlp/native_normal.cpp): Polonsky & Keer's active-set CG with Vollebregt's NormCG safeguards
/// (no restart when the set changes, elements enter with pressure 0). With a preconditioner (built
/// for the unscaled compliance C, Q = C / scale) the iteration counts barely grow with the grid.
/// Stops when the relative change of x falls below options.tol and the contact set is settled;
/// SolveOutcome::history holds the iterations' change and contact-set counts.
SolveOutcome solve_normal_native(const QuadraticProgram& qp, const SolveOptions& options,
                                 const NormalPreconditioner* preconditioner = nullptr, double scale = 1.0);
struct NativeNormalWorkspace;
/// The same with the caller's workspace into `out` (a default outcome or one
/// reset_keeping_storage'd): a solve repeated at every step allocates nothing once sized.
void solve_normal_native(const QuadraticProgram& qp, const SolveOptions& options,
                         const NormalPreconditioner* preconditioner, double scale, NativeNormalWorkspace& work,
                         SolveOutcome& out);

/// The normal program's structure, checked: which elements may carry load, force control and
/// its total sum x (the equality's weights a0 are equal on the free elements).
struct NormalQpForm {
  std::vector<char> free;
  std::size_t n_free = 0;
  bool force_control = false;
  double a0 = 0.0, total = 0.0;
};
NormalQpForm read_normal_qp(const QuadraticProgram& qp);
/// The same into `form` (its storage kept).
void read_normal_qp(const QuadraticProgram& qp, NormalQpForm& form);
/// Starting point: qp.x0 projected on the bounds (or 0); under force control scaled to the
/// total, or (when it carries nothing) spread evenly over the lowest tenth of the gap's range.
std::vector<double> normal_start(const QuadraticProgram& qp, const NormalQpForm& form);
/// The same into x.
void normal_start(const QuadraticProgram& qp, const NormalQpForm& form, std::vector<double>& x);

/// The native normal solver's vectors, kept between solves (NormalProblem holds one).
struct NativeNormalWorkspace {
  NormalQpForm form;
  std::vector<double> x, w, g, r, r_prev, z, v, q;
  std::vector<char> in_set;
};
/// x = the total of force control spread evenly over the free elements in the lowest tenth of
/// the gap's range (c), 0 elsewhere.
void load_lowest_elements(const QuadraticProgram& qp, const NormalQpForm& form, std::vector<double>& x);

/// The native tangential solver (cone-projected accelerated gradient on the FFT operator):
/// min 1/2 x'Qx + c'x over disks (3-D) or boxes (2-D), with up to three equality rows.
SolveOutcome solve_tangential_native(const QuadraticProgram& qp, const SolveOptions& options);

/// The native solver's work storage kept between solves by a caller that solves many programs
/// of one size (a load history: hundreds): vectors of 2N doubles reused, not reallocated.
class NativeTangentialWorkspace {
 public:
  NativeTangentialWorkspace();
  ~NativeTangentialWorkspace();
  NativeTangentialWorkspace(NativeTangentialWorkspace&&) noexcept;
  NativeTangentialWorkspace& operator=(NativeTangentialWorkspace&&) noexcept;
  struct Storage;

 private:
  std::unique_ptr<Storage> storage_;
  friend void solve_tangential_native(const QuadraticProgram&, const SolveOptions&, NativeTangentialWorkspace&,
                                      SolveOutcome&);
};
/// The same with the caller's workspace (the result does not depend on what it held).
SolveOutcome solve_tangential_native(const QuadraticProgram& qp, const SolveOptions& options,
                                     NativeTangentialWorkspace& workspace);
/// The same into `out` (a default outcome or one reset_keeping_storage'd: backend_choice.hpp),
/// whose storage it fills again.
void solve_tangential_native(const QuadraticProgram& qp, const SolveOptions& options,
                             NativeTangentialWorkspace& workspace, SolveOutcome& out);

}  // namespace dc
