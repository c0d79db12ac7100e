// PoseUncertainty: the pose's 1-sigma per axis from the precise stage's information, and its
// calibration (pm-uncertainty): a fit that makes about 68 % of the true errors fall within 1 sigma.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>
#include <algorithm>

#include "pm/compare/UncertaintyCalibration.h"
#include "pm/core/Error.h"
#include "pm/precise/ModelErrorFloor.h"
#include "pm/precise/PoseUncertainty.h"

namespace {

//! A diagonal information whose inverse has these sigmas (mm, then rad).
std::array<double, 36> diagonalInformation(const std::array<double, 6> &sigma)
{
  std::array<double, 36> I{};
  for (std::size_t i = 0; i < 6; ++i)
    I[7 * i] = 1.0 / (sigma[i] * sigma[i]);
  return I;
}

//! Samples whose errors are Gaussian with sigma = trueScale * residual * line sigma (and no floor).
std::vector<pm::compare::UncertaintySample> gaussianSamples(double trueScale, std::size_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> lineSigma(0.05, 0.5), residual(0.5, 2.0);
  std::vector<pm::compare::UncertaintySample> out(n);
  for (auto &s : out) {
    s.residualPx = residual(rng);
    for (std::size_t a = 0; a < 6; ++a) {
      s.lineSigma[a] = lineSigma(rng);
      s.error[a] = trueScale * s.residualPx * s.lineSigma[a] * unit(rng);
    }
  }
  return out;
}

} // namespace

TEST(PoseUncertainty, TheLinesSigmasAreTheRootsOfTheInverseInformationsDiagonalInMmAndDeg)
{
  const std::array<double, 6> s = pm::precise::lineSigmas(diagonalInformation({0.5, 0.25, 2.0, 0.01, 0.002, 0.004}));
  EXPECT_NEAR(s[0], 0.5, 1e-9);
  EXPECT_NEAR(s[1], 0.25, 1e-9);
  EXPECT_NEAR(s[2], 2.0, 1e-9);
  EXPECT_NEAR(s[3], 0.01 * 180 / M_PI, 1e-9);
  EXPECT_NEAR(s[5], 0.004 * 180 / M_PI, 1e-9);
  // A correlated pair: the marginal sigma is that of the inverse, not 1 / sqrt of the diagonal.
  std::array<double, 36> I = diagonalInformation({1, 1, 1, 1, 1, 1});
  I[1] = I[6] = 0.5; // x and y information coupled
  EXPECT_NEAR(pm::precise::lineSigmas(I)[0], std::sqrt(1.0 / 0.75), 1e-9);
}

TEST(PoseUncertainty, IsUnknownWhenTheLinesDoNotPinEveryDegreeOfFreedom)
{
  std::array<double, 36> I = diagonalInformation({1, 1, 1, 0.01, 0.01, 0.01});
  I[35] = 0; // nothing about the rotation about z (a circle seen face-on)
  const pm::precise::UncertaintyModel m;
  EXPECT_FALSE(m.uncertainty(I, 1.0).known);
  EXPECT_TRUE(std::isinf(pm::precise::lineSigmas(I)[5]));
  I[35] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(m.uncertainty(I, 1.0).known);
  EXPECT_FALSE(m.uncertainty(diagonalInformation({1, 1, 1, 1, 1, 1}), -1.0).known); // no residual
}

TEST(PoseUncertainty, ScalesTheLinesSigmaByTheResidualAndAddsTheFloorInQuadrature)
{
  pm::precise::UncertaintyModel m;
  m.scale = {2, 2, 2, 3, 3, 3};
  m.floor = {0.3, 0, 0, 0, 0.4, 0};
  const pm::precise::PoseUncertainty u = m.uncertainty(diagonalInformation({0.2, 0.2, 0.2, 0.001, 0.001, 0.001}), 1.5);
  ASSERT_TRUE(u.known);
  EXPECT_NEAR(u.sigmaMm[0], std::hypot(2 * 1.5 * 0.2, 0.3), 1e-9);
  EXPECT_NEAR(u.sigmaMm[1], 2 * 1.5 * 0.2, 1e-9);
  EXPECT_NEAR(u.sigmaDeg[1], std::hypot(3 * 1.5 * 0.001 * 180 / M_PI, 0.4), 1e-9);
  EXPECT_NEAR(u.maxMm(), u.sigmaMm[0], 1e-12);
  EXPECT_NEAR(u.maxDeg(), u.sigmaDeg[1], 1e-12);
}

TEST(PoseUncertainty, AScaleThatIsNotPositiveOrAFloorThatIsNegativeIsRefused)
{
  EXPECT_NO_THROW(pm::precise::UncertaintyModel().validate());
  pm::precise::UncertaintyModel m;
  m.scale[2] = 0;
  EXPECT_THROW(m.validate(), pm::core::Error);
  m = pm::precise::UncertaintyModel();
  m.floor[4] = -0.1;
  EXPECT_THROW(m.validate(), pm::core::Error);
  m = pm::precise::UncertaintyModel();
  m.scale[0] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(m.validate(), pm::core::Error);
}

TEST(PoseUncertainty, TheModelsOwnErrorIsAddedInQuadratureTimesItsGain)
{
  pm::precise::UncertaintyModel m;
  m.scale = {1, 1, 1, 1, 1, 1};
  m.floor = {0, 0, 0, 0, 0, 0};
  m.modelErrorGain = 2;
  const std::array<double, 6> lines{0.3, 0.3, 0.3, 0.2, 0.2, 0.2}, model{0.4, 0, 0, 0, 0.1, 0};
  const pm::precise::PoseUncertainty u = m.uncertainty(lines, 1.0, model);
  EXPECT_NEAR(u.sigmaMm[0], std::hypot(0.3, 0.8), 1e-12);
  EXPECT_NEAR(u.sigmaMm[1], 0.3, 1e-12);
  EXPECT_NEAR(u.sigmaDeg[1], std::hypot(0.2, 0.2), 1e-12);
  m.modelErrorGain = -1;
  EXPECT_THROW(m.validate(), pm::core::Error);
  m.modelErrorGain = 1;
  m.modelErrorWidthDeg = 0;
  EXPECT_THROW(m.validate(), pm::core::Error);
}

TEST(ModelErrorFloor, IsTheRmsOfTheNearPassViewsOffsetsInTheHandsAxes)
{
  // Two pass views: one straight behind the model (camera at -z), one 90 deg away (camera at +x).
  pm::core::PassLanding a, b;
  a.cameraMm[2] = -500;
  a.offsetMm[0] = 0.4;
  a.offsetDeg[1] = 0.3;
  b.cameraMm[0] = 500;
  b.offsetMm[2] = -0.6;
  b.offsetDeg[0] = 0.5;
  const vpHomogeneousMatrix hMc; // the camera at the hand's origin
  const pm::precise::ModelErrorFloor floor({a, b}, hMc, 10);
  ASSERT_FALSE(floor.empty());
  // Looking along view a (the model 0.5 m ahead, axes as the hand's): a's offsets, b's weight nil.
  std::array<double, 6> f = floor.at(pm::core::Phi{0, 0, 500, 0, 0, 0});
  EXPECT_NEAR(f[0], 0.4, 1e-9);
  EXPECT_NEAR(f[2], 0.0, 1e-9);
  EXPECT_NEAR(f[4], 0.3, 1e-9);
  EXPECT_NEAR(f[3], 0.0, 1e-9);
  // The hand turned 90 deg about its z axis: the model's x is the hand's y.
  f = floor.at(pm::core::fromHomogeneousMatrix(vpHomogeneousMatrix(0, 0, 0.5, 0, 0, M_PI / 2)));
  EXPECT_NEAR(f[0], 0.0, 1e-9);
  EXPECT_NEAR(f[1], 0.4, 1e-9);
  EXPECT_NEAR(f[3], 0.3, 1e-9); // the model's y turned onto the hand's -x
  // Half way between the two views (45 deg from each): equal weights, the rms of both.
  const vpHomogeneousMatrix between(0, 0, 0.5, 0, M_PI / 4, 0); // the camera seen from the model at 45 deg between -z and +x
  const vpHomogeneousMatrix mMc = between.inverse();
  ASSERT_NEAR(mMc[0][3], -mMc[2][3], 1e-9);
  ASSERT_GT(mMc[0][3], 0);
  f = floor.at(pm::core::fromHomogeneousMatrix(between));
  const vpRotationMatrix R = between.getRotationMatrix();
  const double x2 = 0.5 * (vpMath::sqr(R[0][0] * 0.4) + vpMath::sqr(R[0][2] * 0.6));
  EXPECT_NEAR(f[0], std::sqrt(x2), 1e-9);
  // Far from every view (the camera at the model's -x: 90 deg from a, 180 from b): the nearest view's, a's.
  f = floor.at(pm::core::fromHomogeneousMatrix(vpHomogeneousMatrix(0, 0, 0.5, 0, -M_PI / 2, 0)));
  EXPECT_NEAR(f[4], 0.3, 1e-9);
  EXPECT_NEAR(f[3], 0.0, 1e-9);
  // A camera off the hand's origin: at (0.5, 0, 0.5) m it sees the model (0.5 m ahead, axes as the
  // hand's) from its +x side, view b's direction: b's offsets, a's weight nil.
  const pm::precise::ModelErrorFloor beside({a, b}, vpHomogeneousMatrix(0.5, 0, 0.5, 0, 0, 0), 10);
  f = beside.at(pm::core::Phi{0, 0, 500, 0, 0, 0});
  EXPECT_NEAR(f[2], 0.6, 1e-9);
  EXPECT_NEAR(f[3], 0.5, 1e-9);
  EXPECT_NEAR(f[0], 0.0, 1e-9);
  // No landings: no floor; a width that is not positive is refused.
  EXPECT_TRUE(pm::precise::ModelErrorFloor({}, hMc).empty());
  EXPECT_EQ(pm::precise::ModelErrorFloor({}, hMc).at(pm::core::Phi{0, 0, 500, 0, 0, 0})[4], 0.0);
  EXPECT_THROW(pm::precise::ModelErrorFloor({a}, hMc, 0), pm::core::Error);
}

TEST(UncertaintyCalibration, TheFitFindsTheTrueScaleOfGaussianErrorsAndPuts68PercentWithinOneSigma)
{
  const auto a = gaussianSamples(2.5, 3000, 1), b = gaussianSamples(2.5, 3000, 2), held = gaussianSamples(2.5, 3000, 3);
  const pm::precise::UncertaintyModel m = pm::compare::fitUncertainty({a, b});
  for (std::size_t axis = 0; axis < 6; ++axis) {
    // Scale and floor trade off a little on a finite sample (the fit matches shares, not the
    // parameters); the sigmas it gives are the true ones within 10 % on the median frame.
    std::vector<double> ratio;
    for (const auto &s : held)
      ratio.push_back(m.sigma(axis, s.lineSigma[axis], s.residualPx) / (2.5 * s.residualPx * s.lineSigma[axis]));
    std::nth_element(ratio.begin(), ratio.begin() + static_cast<long>(ratio.size() / 2), ratio.end());
    EXPECT_NEAR(ratio[ratio.size() / 2], 1.0, 0.1) << axis;
  }
  const auto w1 = pm::compare::shareWithin(held, m, 1.0), w2 = pm::compare::shareWithin(held, m, 2.0);
  for (std::size_t axis = 0; axis < 6; ++axis) {
    EXPECT_NEAR(w1[axis], 0.683, 0.03) << axis; // on samples the fit did not see
    EXPECT_NEAR(w2[axis], 0.954, 0.02) << axis;
  }
  // The lines' own sigma (scale 1) is over-confident here: far fewer errors within it.
  pm::precise::UncertaintyModel raw;
  raw.scale.fill(1.0);
  raw.floor.fill(0.0);
  EXPECT_LT(pm::compare::shareWithin(held, raw, 1.0)[0], 0.4);
  EXPECT_THROW(pm::compare::fitUncertainty({a, {}}), pm::core::Error);
}
