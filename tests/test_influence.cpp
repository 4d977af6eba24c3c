// Influence coefficients (Boussinesq-Cerruti on rectangles / strips) and the operators that
// apply them: closed forms, reciprocity, far field, dense = FFT.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "influence.hpp"
#include "linear_operator.hpp"
#include "solver_support.hpp"

namespace dc {
namespace {

MaterialPair identical_steel() { return {Elastic::from_E_nu(2.1e11, 0.3), Elastic::from_E_nu(2.1e11, 0.3)}; }

TEST(Influence, CentreOfUniformlyLoadedSquareMatchesLove) {
  // Johnson (3.5): the centre of a square of side s under uniform p sinks by
  // (1 - nu^2)/E * p * s * 4 ln(1 + sqrt 2) / pi; two bodies: 1/E*.
  const auto m = test::steel_on_aluminium();
  const Grid g = Grid::make(3, 5, 5, -1e-3, 1e-3, -1e-3, 1e-3);
  const KernelTable t = influence_table(g, m, kZ, kZ);
  const double expected = g.dx * 4.0 * std::log(1.0 + std::sqrt(2.0)) / (std::numbers::pi * m.E_star());
  EXPECT_NEAR(t.at(0, 0), expected, 1e-12 * expected);
}

TEST(Influence, RectangleCornerSumMatchesQuadrature) {
  // Midpoint quadrature of each point kernel over an element away from the field point.
  const auto m = test::steel_on_aluminium();
  const Grid g = Grid::make(3, 8, 6, 0.0, 8e-3, 0.0, 9e-3);
  const int di = 3, dj = -2;
  const int q = 400;
  for (Axis out : {kX, kY, kZ})
    for (Axis in : {kX, kY, kZ}) {
      const KernelTable t = influence_table(g, m, out, in);
      double sum = 0.0;
      for (int a = 0; a < q; ++a)
        for (int b = 0; b < q; ++b) {
          const double x = di * g.dx + ((a + 0.5) / q - 0.5) * g.dx;
          const double y = dj * g.dy + ((b + 0.5) / q - 0.5) * g.dy;
          sum += point_load_kernel(3, m, out, in, x, y, 1.0);
        }
      sum *= g.dx * g.dy / (q * q);
      EXPECT_NEAR(t.at(di, dj), sum, 1e-5 * std::abs(sum))
          << "component " << out << in;
    }
}

TEST(Influence, FarFieldApproachesPointLoad) {
  const auto m = test::steel_on_aluminium();
  const Grid g = Grid::make(3, 64, 64, 0.0, 64e-3, 0.0, 64e-3);
  for (Axis out : {kX, kY, kZ})
    for (Axis in : {kX, kY, kZ}) {
      const KernelTable t = influence_table(g, m, out, in);
      const int di = 40, dj = 25;
      const double point = point_load_kernel(3, m, out, in, di * g.dx, dj * g.dy, 1.0) * g.dx * g.dy;
      EXPECT_NEAR(t.at(di, dj), point, 1e-3 * std::abs(point)) << "component " << out << in;
    }
}

TEST(Influence, TwoDimensionalStripsMatchLineLoads) {
  const auto m = test::steel_on_aluminium();
  const Grid g = Grid::make(2, 100, 1, -5e-3, 5e-3, 0, 0);
  const double L = g.nx * g.dx;
  for (auto [out, in] : {std::pair{kZ, kZ}, {kX, kX}, {kX, kZ}, {kZ, kX}}) {
    const KernelTable t = influence_table(g, m, out, in);
    const int di = 60;
    const double line = point_load_kernel(2, m, out, in, di * g.dx, 0.0, L) * g.dx;
    EXPECT_NEAR(t.at(di, 0), line, 1e-4 * std::abs(line) + 1e-20) << out << in;
    // Antisymmetric cross terms, symmetric direct terms.
    const double sign = (out == in) ? 1.0 : -1.0;
    EXPECT_DOUBLE_EQ(t.at(-di, 0), sign * t.at(di, 0));
  }
  // The log kernel vanishes at the reference distance: a strip centred there, far from the
  // load, carries about zero displacement.
  const KernelTable zz = influence_table(g, m, kZ, kZ, {.reference_length = 30 * g.dx});
  EXPECT_NEAR(zz.at(30, 0), 0.0, 1e-3 * zz.at(0, 0));
}

TEST(Influence, FullOperatorIsSymmetricPositiveDefinite) {
  // Betti: the 3x3-block compliance of (tau_x, tau_y, p) is symmetric, and the elastic
  // energy t.Ct is positive; the kappa cross terms make the blocks couple.
  const auto m = test::steel_on_aluminium();
  ASSERT_GT(std::abs(m.kappa()), 0.0);
  const Grid g = Grid::make(3, 6, 5, -1e-3, 1e-3, -1e-3, 1.5e-3);
  std::vector<KernelTable> blocks;
  for (Axis out : {kX, kY, kZ})
    for (Axis in : {kX, kY, kZ}) blocks.push_back(influence_table(g, m, out, in));
  const auto op = make_convolution_operator(g, blocks, 3, 3, OperatorKind::dense);
  const Eigen::MatrixXd C = op->to_dense();
  EXPECT_LT((C - C.transpose()).cwiseAbs().maxCoeff(), 1e-12 * C.cwiseAbs().maxCoeff());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(C);
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

TEST(Influence, IdenticalMaterialsDecoupleNormalAndTangential) {
  const auto m = identical_steel();
  EXPECT_DOUBLE_EQ(m.kappa(), 0.0);
  const Grid g = Grid::make(3, 4, 4, -1e-3, 1e-3, -1e-3, 1e-3);
  const KernelTable xz = influence_table(g, m, kX, kZ);
  for (double v : xz.values) EXPECT_EQ(v, 0.0);
}

void expect_dense_equals_fft(const Grid& g, const MaterialPair& m, int n_out, int n_in,
                             const std::vector<std::pair<Axis, Axis>>& pairs) {
  std::vector<KernelTable> blocks;
  for (auto [o, i] : pairs) blocks.push_back(influence_table(g, m, o, i));
  const auto dense = make_convolution_operator(g, blocks, n_out, n_in, OperatorKind::dense);
  const auto fft = make_convolution_operator(g, blocks, n_out, n_in, OperatorKind::fft);
  EXPECT_EQ(dense->kind(), "dense");
  EXPECT_EQ(fft->kind(), "fft");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> x(dense->cols()), yd, yf;
  for (double& v : x) v = u(rng);
  dense->apply(x, yd);
  fft->apply(x, yf);
  double scale = 0.0, diff = 0.0;
  for (std::size_t k = 0; k < yd.size(); ++k) {
    scale = std::max(scale, std::abs(yd[k]));
    diff = std::max(diff, std::abs(yd[k] - yf[k]));
  }
  EXPECT_LT(diff, 1e-12 * scale);
  for (std::size_t k = 0; k < std::min(dense->rows(), dense->cols()); k += 7)
    if (n_out == n_in) {
      EXPECT_DOUBLE_EQ(dense->diagonal(k), fft->diagonal(k));
    }
}

TEST(Operator, DenseEqualsFftNormal3d) {
  expect_dense_equals_fft(Grid::make(3, 13, 9, -1e-3, 1e-3, -2e-3, 1e-3), test::steel_on_aluminium(), 1, 1,
                          {{kZ, kZ}});
}

TEST(Operator, DenseEqualsFftTangentialBlocks) {
  expect_dense_equals_fft(Grid::make(3, 10, 7, -1e-3, 1e-3, -1e-3, 1e-3), test::steel_on_aluminium(), 2, 2,
                          {{kX, kX}, {kX, kY}, {kY, kX}, {kY, kY}});
}

TEST(Operator, DenseEqualsFftCrossTerms) {
  expect_dense_equals_fft(Grid::make(3, 8, 11, -1e-3, 1e-3, -1e-3, 1e-3), test::steel_on_aluminium(), 2, 1,
                          {{kX, kZ}, {kY, kZ}});
}

TEST(Operator, DenseEqualsFft2d) {
  expect_dense_equals_fft(Grid::make(2, 37, 1, -1e-3, 1e-3, 0, 0), test::steel_on_aluminium(), 1, 1, {{kZ, kZ}});
}

TEST(Operator, HalfSpaceBuildsEveryOperator) {
  const Grid g = Grid::make(3, 6, 6, -1e-3, 1e-3, -1e-3, 1e-3);
  const HalfSpace hs(g, test::steel_on_aluminium());
  EXPECT_EQ(hs.normal()->rows(), 36u);
  EXPECT_EQ(hs.tangential()->rows(), 72u);
  EXPECT_EQ(hs.tangential_from_normal()->rows(), 72u);
  EXPECT_EQ(hs.tangential_from_normal()->cols(), 36u);
  EXPECT_EQ(hs.normal_from_tangential()->cols(), 72u);
  // B32 is the transpose of B21 (Betti).
  const Eigen::MatrixXd b21 = hs.tangential_from_normal()->to_dense();
  const Eigen::MatrixXd b32 = hs.normal_from_tangential()->to_dense();
  EXPECT_LT((b21.transpose() - b32).cwiseAbs().maxCoeff(), 1e-14 * b21.cwiseAbs().maxCoeff());
}

/// displacement_shifted(shifts) with weights w against sum_k w_k (tangential_shifted(k) tau +
/// tangential_from_normal_shifted(k) p), the separate operators (bilinear interpolation of the
/// convected memory (3.8) in one apply): the same to round-off, for both kinds.
void expect_weighted_displacement(const Grid& g, const std::vector<std::pair<int, int>>& shifts,
                                  const std::vector<double>& weights, OperatorKind kind) {
  const HalfSpace hs(g, test::steel_on_aluminium());
  const auto op = hs.displacement_shifted(shifts, true, kind);
  op->set_weights(weights);
  const std::size_t N = g.size(), comps = g.dimension == 2 ? 1 : 2;
  ASSERT_EQ(op->rows(), comps * N);
  ASSERT_EQ(op->cols(), (comps + 1) * N);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> x(op->cols()), y;
  for (double& v : x) v = u(rng);
  op->apply(x, y);
  const std::vector<double> tau(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(comps * N)),
      p(x.begin() + static_cast<std::ptrdiff_t>(comps * N), x.end());
  std::vector<double> expected(comps * N, 0.0), a, b;
  for (std::size_t k = 0; k < shifts.size(); ++k) {
    hs.tangential_shifted(shifts[k].first, shifts[k].second, OperatorKind::dense)->apply(tau, a);
    hs.tangential_from_normal_shifted(shifts[k].first, shifts[k].second, OperatorKind::dense)->apply(p, b);
    for (std::size_t i = 0; i < expected.size(); ++i) expected[i] += weights[k] * (a[i] + b[i]);
  }
  double scale = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    scale = std::max(scale, std::abs(expected[i]));
    diff = std::max(diff, std::abs(y[i] - expected[i]));
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(diff, 1e-12 * scale) << op->kind();
  // Without the pressure (kappa = 0): the tangential blocks alone.
  const auto tangential_only = hs.displacement_shifted(shifts, false, kind);
  tangential_only->set_weights(weights);
  EXPECT_EQ(tangential_only->cols(), comps * N);
  EXPECT_THROW(tangential_only->set_weights({1.0}), std::invalid_argument) << "one weight per term";
}

TEST(Operator, WeightedShiftedDisplacementIsTheWeightedSumOfTheShiftedOperators) {
  const Grid g3 = Grid::make(3, 9, 7, -1e-3, 1e-3, -1e-3, 1e-3);
  const std::vector<std::pair<int, int>> corners{{2, -1}, {3, -1}, {2, 0}, {3, 0}};
  const double tx = 0.37, ty = 0.81;
  const std::vector<double> bilinear{(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
  expect_weighted_displacement(g3, corners, bilinear, OperatorKind::dense);
  expect_weighted_displacement(g3, corners, bilinear, OperatorKind::fft);
  expect_weighted_displacement(g3, corners, {0.0, 1.0, 0.0, 0.0}, OperatorKind::fft);  // a term of weight 0 skipped
  const Grid g2 = Grid::make(2, 23, 1, -1e-3, 1e-3, 0, 0);
  expect_weighted_displacement(g2, {{1, 0}, {2, 0}}, {0.25, 0.75}, OperatorKind::fft);
  expect_weighted_displacement(g2, {{1, 0}, {2, 0}}, {0.25, 0.75}, OperatorKind::dense);
}

TEST(Operator, DenseRefusedForLargeGrids) {
  const Grid g = Grid::make(3, 128, 128, -1e-3, 1e-3, -1e-3, 1e-3);
  EXPECT_THROW(make_convolution_operator(g, {influence_table(g, identical_steel(), kZ, kZ)}, 1, 1,
                                         OperatorKind::dense),
               std::length_error);
  const auto fft = make_convolution_operator(g, {influence_table(g, identical_steel(), kZ, kZ)}, 1, 1,
                                             OperatorKind::automatic);
  EXPECT_EQ(fft->kind(), "fft");
}

}  // namespace
}  // namespace dc
