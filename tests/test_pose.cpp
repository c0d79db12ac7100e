// Pose parameter phi <-> hMo (Eq. 7 of the paper).
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <random>
#include <vector>

#include <visp3/core/vpQuaternionVector.h>
#include <visp3/core/vpRotationMatrix.h>
#include <visp3/core/vpThetaUVector.h>

#include "pm/core/Error.h"
#include "pm/core/Pose.h"
#include "pm/core/Quaternion.h"
#include "pm/core/Rounding.h"

namespace {

pm::core::Phi randomPhi(std::mt19937 &rng)
{
  std::uniform_real_distribution<double> pos(-180, 180), z(320, 680), axis(-1, 1), ang(0, M_PI);
  double a[3];
  double n = 0;
  do {
    for (double &c : a)
      c = axis(rng);
    n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  } while (n < 1e-3 || n > 1);
  const double s = std::sin(ang(rng) / 2);
  return {pos(rng), pos(rng), z(rng), s * a[0] / n, s * a[1] / n, s * a[2] / n};
}

} // namespace

TEST(Pose, RoundTripPhiToMatrixToPhi)
{
  std::mt19937 rng(42);
  for (int i = 0; i < 1000; ++i) {
    const pm::core::Phi p = randomPhi(rng);
    const pm::core::Phi q = pm::core::fromHomogeneousMatrix(pm::core::toHomogeneousMatrix(p));
    for (std::size_t k = 0; k < 6; ++k)
      EXPECT_NEAR(p[k], q[k], k < 3 ? 1e-9 : 1e-9) << "component " << k << " of " << p.toString();
  }
}

TEST(Pose, RoundTripMatrixToPhiToMatrix)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-M_PI, M_PI);
  for (int i = 0; i < 500; ++i) {
    const vpHomogeneousMatrix M(0.1 * u(rng), 0.1 * u(rng), 0.5 + 0.05 * u(rng), u(rng) / 2, u(rng) / 2, u(rng) / 2);
    const vpHomogeneousMatrix N = pm::core::toHomogeneousMatrix(pm::core::fromHomogeneousMatrix(M));
    for (unsigned r = 0; r < 3; ++r)
      for (unsigned c = 0; c < 4; ++c)
        EXPECT_NEAR(M[r][c], N[r][c], 1e-9);
  }
}

TEST(Pose, Equation7AgreesWithViSPQuaternion)
{
  std::mt19937 rng(3);
  for (int i = 0; i < 500; ++i) {
    const pm::core::Phi p = randomPhi(rng);
    const vpRotationMatrix R(vpQuaternionVector(p.e1, p.e2, p.e3, p.eta()));
    const pm::core::Rot3 r = pm::core::rotationOf(p);
    const vpHomogeneousMatrix M = pm::core::toHomogeneousMatrix(p);
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b) {
        EXPECT_NEAR(r[3 * a + b], R[a][b], 1e-12);
        EXPECT_NEAR(M[a][b], R[a][b], 1e-12);
      }
    EXPECT_NEAR(M[0][3], p.x * 1e-3, 1e-15);
    EXPECT_NEAR(M[2][3], p.z * 1e-3, 1e-15);
  }
}

TEST(Pose, EtaIsNonNegativeWhateverTheQuaternionSign)
{
  // The same rotation from q and -q: phi must come out with eta >= 0 both times.
  const double e[3] = {0.2, -0.3, 0.1}, w = std::sqrt(1 - 0.04 - 0.09 - 0.01);
  for (double s : {1.0, -1.0}) {
    vpHomogeneousMatrix M;
    M.insert(vpRotationMatrix(vpQuaternionVector(s * e[0], s * e[1], s * e[2], s * w)));
    const pm::core::Phi p = pm::core::fromHomogeneousMatrix(M);
    EXPECT_NEAR(p.e1, e[0], 1e-12);
    EXPECT_NEAR(p.e2, e[1], 1e-12);
    EXPECT_NEAR(p.e3, e[2], 1e-12);
    EXPECT_GE(p.eta(), 0.0);
  }
}

TEST(Pose, IdentityIsTheDesiredPose)
{
  const pm::core::Phi p{0, 0, 500, 0, 0, 0};
  const vpHomogeneousMatrix M = pm::core::toHomogeneousMatrix(p);
  EXPECT_TRUE(M.getRotationMatrix().isARotationMatrix());
  EXPECT_NEAR(M[2][3], 0.5, 1e-15);
  EXPECT_NEAR(M[0][0], 1.0, 1e-15);
}

TEST(Pose, HalfTurnHasUnitEps)
{
  vpHomogeneousMatrix M(0, 0, 0.5, 0, 0, M_PI); // 180 deg about z: eta = 0, |eps| = 1
  const pm::core::Phi p = pm::core::fromHomogeneousMatrix(M);
  EXPECT_NEAR(std::fabs(p.e3), 1.0, 1e-9);
  EXPECT_TRUE(p.isValid());
  const vpHomogeneousMatrix N = pm::core::toHomogeneousMatrix(p);
  EXPECT_NEAR(N[0][0], -1.0, 1e-9);
}

TEST(Pose, EpsLongerThanOneIsRefusedWithAClearError)
{
  const pm::core::Phi p{0, 0, 500, 0.8, 0.7, 0.0}; // |eps| = 1.06
  EXPECT_FALSE(p.isValid());
  try {
    pm::core::toHomogeneousMatrix(p);
    FAIL() << "no error for |eps| > 1";
  } catch (const pm::core::Error &e) {
    EXPECT_NE(std::string(e.what()).find("|eps| <= 1"), std::string::npos) << e.what();
  }
}

TEST(Pose, NonFiniteIsRefused)
{
  EXPECT_THROW(pm::core::toHomogeneousMatrix({NAN, 0, 500, 0, 0, 0}), pm::core::Error);
  EXPECT_THROW(pm::core::toHomogeneousMatrix({0, 0, 500, INFINITY, 0, 0}), pm::core::Error);
}

TEST(Pose, NonRigidMatrixIsRefused)
{
  vpHomogeneousMatrix M;
  M[0][0] = 2.0; // a scale, not a rotation
  EXPECT_THROW(pm::core::fromHomogeneousMatrix(M), pm::core::Error);
}

TEST(Pose, ATwistMovesTheOriginAndTurnsAboutItInTheHandFrame)
{
  // applyTwist(phi, [v, w]) is hMo' = [exp(w) R, t + v]: as ViSP composes it.
  const pm::core::Phi phi{12, -30, 480, 0.1, -0.2, 0.3};
  const double twist[6] = {1.5, -2.0, 3.0, 0.02, -0.05, 0.03};
  const pm::core::Phi moved = pm::core::applyTwist(phi, twist);
  const vpHomogeneousMatrix M = pm::core::toHomogeneousMatrix(phi);
  const vpRotationMatrix R = vpRotationMatrix(vpThetaUVector(twist[3], twist[4], twist[5])) * M.getRotationMatrix();
  const vpHomogeneousMatrix N = pm::core::toHomogeneousMatrix(moved);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j)
      EXPECT_NEAR(N[i][j], R[i][j], 1e-12) << i << j;
    EXPECT_NEAR(N[i][3] * 1e3, phi[i] + twist[i], 1e-9);
  }
  EXPECT_GE(moved.eta(), 0.0);
  // No rotation: the orientation is untouched; a half turn keeps eta >= 0.
  const double shift[6] = {1, 2, 3, 0, 0, 0};
  EXPECT_EQ(pm::core::applyTwist(phi, shift).e2, phi.e2);
  const double halfTurn[6] = {0, 0, 0, M_PI, 0, 0};
  const pm::core::Phi h = pm::core::applyTwist(phi, halfTurn);
  EXPECT_TRUE(h.isValid());
  EXPECT_NEAR(pm::core::rotationDistanceDeg(h, phi), 180.0, 1e-6);
}

TEST(Quaternion, ItsProductAngleAndRotationVectorAreViSPsMatrixProductAndThetaU)
{
  // Quaternion.h's algebra against ViSP's matrices on random poses: the product is the matrices'
  // product, withRotation() the pose of that matrix, angle() and rotationVector() the theta-u of it.
  std::mt19937 rng(11);
  for (int i = 0; i < 300; ++i) {
    const pm::core::Phi a = randomPhi(rng), b = randomPhi(rng);
    const vpHomogeneousMatrix A = pm::core::toHomogeneousMatrix(a), B = pm::core::toHomogeneousMatrix(b);
    const pm::core::Phi ab = pm::core::withRotation(a, pm::core::quaternionOf(a) * pm::core::quaternionOf(b));
    vpHomogeneousMatrix AB = A * B;
    AB[0][3] = A[0][3]; // withRotation keeps a's position
    AB[1][3] = A[1][3];
    AB[2][3] = A[2][3];
    const pm::core::Phi viaViSP = pm::core::fromHomogeneousMatrix(AB);
    for (std::size_t k = 0; k < 6; ++k)
      EXPECT_NEAR(ab[k], viaViSP[k], 1e-12) << "component " << k;
    EXPECT_GE(ab.eta(), 0.0);
    const pm::core::Quaternion d = pm::core::quaternionOf(b) * pm::core::quaternionOf(a).conjugate(); // hRb hRa^T
    const vpThetaUVector tu(vpRotationMatrix(B.getRotationMatrix() * A.getRotationMatrix().t()));
    double v[3];
    d.rotationVector(v);
    const double th = std::sqrt(tu.sumSquare());
    EXPECT_NEAR(d.angle(), th, 1e-9);
    if (th < M_PI - 1e-3) { // a half turn's axis has either sign
      for (unsigned k = 0; k < 3; ++k)
        EXPECT_NEAR(v[k], tu[k], 1e-9);
    }
    // Back from the rotation vector: the same turn.
    const pm::core::Quaternion back = pm::core::Quaternion::fromRotationVector(v[0], v[1], v[2]);
    EXPECT_NEAR(std::fabs(back.w * d.w + back.x * d.x + back.y * d.y + back.z * d.z), 1.0, 1e-12);
  }
  // About z: the matrix of ViSP's theta-u (0, 0, a); the identity's rotation vector is nil.
  const pm::core::Phi z = pm::core::withRotation(pm::core::Phi{}, pm::core::Quaternion::aboutZ(0.7));
  const vpHomogeneousMatrix Z = pm::core::toHomogeneousMatrix(z), V(0, 0, 0, 0, 0, 0.7);
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c)
      EXPECT_NEAR(Z[r][c], V[r][c], 1e-12);
  double v[3] = {1, 1, 1};
  pm::core::Quaternion().rotationVector(v);
  EXPECT_EQ(v[0] * v[0] + v[1] * v[1] + v[2] * v[2], 0.0);
}

TEST(Rounding, RoundHalfAwayIsStdLroundToTheBit)
{
  // The halves and their neighbours one bit away (where x + 0.5 as a shortcut goes wrong), whole
  // numbers, and a million values spread over 24 orders of magnitude of either sign.
  std::vector<double> xs{0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994,
                         4503599627370495.5, -4503599627370495.5, 4503599627370497.0, 9.2e18, -9.2e18};
  for (double h = 0.5; h < 1e6; h += 1.0)
    for (double x : {h, -h})
      xs.insert(xs.end(), {x, std::nextafter(x, 0.0), std::nextafter(x, 2 * x)});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-6.0, 18.0), unit(-1.0, 1.0);
  for (int i = 0; i < 1000000; ++i)
    xs.push_back(unit(rng) * std::pow(10.0, exponent(rng)));
  std::size_t wrong = 0;
  for (double x : xs)
    if (pm::core::roundHalfAway(x) != std::lround(x) && ++wrong <= 5)
      ADD_FAILURE() << std::setprecision(17) << x << ": " << pm::core::roundHalfAway(x) << ", std::lround " << std::lround(x);
  EXPECT_EQ(wrong, 0u) << "of " << xs.size();
}
