// The inverse of the preconditioner's diagonal blocks (spd_inverse.hpp):
// as accurate as Eigen's Cholesky solve on the badly scaled blocks DDA makes,
// and a refusal of what is not positive definite.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "core/spd_inverse.hpp"

namespace dda::df {
namespace {

// Q diag(lambda) Q^T with eigenvalues log-uniform over `decades`, then
// scaled as D A D with D = 1 on the first half of the unknowns and 1e3 on
// the second, as a DDA block mixes translations (m) with rotations and
// strains (dimensionless) multiplied by block sizes.
template <int N>
Eigen::Matrix<double, N, N> badly_scaled_spd(std::mt19937& rng, double decades) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> exponent(0, decades);
  Eigen::Matrix<double, N, N> g;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) g(i, j) = normal(rng);
  const Eigen::Matrix<double, N, N> q = Eigen::HouseholderQR<Eigen::Matrix<double, N, N>>(g).householderQ();
  Eigen::Matrix<double, N, 1> lambda;
  for (int i = 0; i < N; ++i) lambda(i) = std::pow(10.0, exponent(rng));
  Eigen::Matrix<double, N, 1> d = Eigen::Matrix<double, N, 1>::Ones();
  d.tail(N / 2).setConstant(1e3);
  const Eigen::Matrix<double, N, N> a = d.asDiagonal() * q * lambda.asDiagonal() * q.transpose() * d.asDiagonal();
  return 0.5 * (a + a.transpose());
}

// max |A X - I|, the residual of an inverse X.
template <int N>
double residual(const Eigen::Matrix<double, N, N>& a, const Eigen::Matrix<double, N, N>& x) {
  return (a * x - Eigen::Matrix<double, N, N>::Identity()).cwiseAbs().maxCoeff();
}

template <int N>
void expect_as_accurate_as_eigen(int seed) {
  std::mt19937 rng(seed);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Matrix<double, N, N> a = badly_scaled_spd<N>(rng, 6.0);
    Eigen::Matrix<double, N, N> x;
    ASSERT_TRUE(spd_inverse<N>(a, x)) << trial;
    const Eigen::Matrix<double, N, N> reference = Eigen::LLT<Eigen::Matrix<double, N, N>>(a).solve(
        Eigen::Matrix<double, N, N>::Identity());
    // Eigen's own residual is the yardstick (cond(A) up to 1e12 here, so
    // neither is near machine epsilon); ours may be at most 10 times it,
    // plus a floor far below what the preconditioner could notice.
    EXPECT_LE(residual<N>(a, x), 10 * residual<N>(a, reference) + 1e-12) << trial;
    EXPECT_EQ(x, x.transpose()) << "the inverse is made exactly symmetric, trial " << trial;
  }
}

TEST(SpdInverse, AsAccurateAsEigensCholeskySolve6) { expect_as_accurate_as_eigen<6>(11); }
TEST(SpdInverse, AsAccurateAsEigensCholeskySolve12) { expect_as_accurate_as_eigen<12>(12); }

TEST(SpdInverse, ExactOnADiagonalMatrix) {
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  a.diagonal() << 1, 4, 16, 64, 0.25, 0.0625;  // powers of four: every root and quotient is exact
  Eigen::Matrix<double, 6, 6> x;
  ASSERT_TRUE(spd_inverse<6>(a, x));
  Eigen::Matrix<double, 6, 6> expected = Eigen::Matrix<double, 6, 6>::Zero();
  expected.diagonal() << 1, 0.25, 0.0625, 1.0 / 64, 4, 16;
  EXPECT_EQ(x, expected);
}

TEST(SpdInverse, RefusesWhatIsNotPositiveDefinite) {
  Eigen::Matrix<double, 6, 6> x;
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Identity();
  a(3, 3) = -1;  // indefinite
  EXPECT_FALSE(spd_inverse<6>(a, x));
  a(3, 3) = 0;  // singular
  EXPECT_FALSE(spd_inverse<6>(a, x));
  a = Eigen::Matrix<double, 6, 6>::Identity();
  a(2, 1) = a(1, 2) = 1;  // [[1, 1], [1, 1]] in rows 1-2: singular, pivot 0 after elimination
  EXPECT_FALSE(spd_inverse<6>(a, x));
  a = Eigen::Matrix<double, 6, 6>::Identity();
  a(5, 4) = a(4, 5) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(spd_inverse<6>(a, x));
}

}  // namespace
}  // namespace dda::df
