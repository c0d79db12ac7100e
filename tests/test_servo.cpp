// The servo module's own tests: PoseFilter (the alpha-beta filter of the estimate in the base
// frame, with the twist the feed-forward uses). SafeCommand and PbvsServo are exercised in
// test_robot.cpp with the PA-10.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <visp3/core/vpThetaUVector.h>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/servo/PoseFilter.h"

namespace {

double angleDeg(const vpRotationMatrix &R)
{
  const vpThetaUVector tu(R);
  return std::sqrt(tu.sumSquare()) * 180.0 / M_PI;
}

double distanceMm(const vpHomogeneousMatrix &a, const vpHomogeneousMatrix &b)
{
  return 1e3 * std::sqrt((a.getTranslationVector() - b.getTranslationVector()).sumSquare());
}

//! The pose at time t of a body moving at constant velocity v (m/s) and turning at w (rad/s), fixed frame.
vpHomogeneousMatrix movingPose(double t, const double v[3], const double w[3])
{
  const vpHomogeneousMatrix start(0.1, -0.05, 0.6, 0.2, -0.1, 0.3);
  const vpRotationMatrix R = vpRotationMatrix(vpThetaUVector(w[0] * t, w[1] * t, w[2] * t)) * start.getRotationMatrix();
  vpTranslationVector p = start.getTranslationVector();
  for (unsigned i = 0; i < 3; ++i)
    p[i] += v[i] * t;
  return vpHomogeneousMatrix(p, R);
}

} // namespace

TEST(PoseFilter, FollowsAConstantMotionWithoutLagAndMeasuresItsTwist)
{
  // Exact measurements of a body moving at 0.1 m/s and turning at 0.3 rad/s: a constant-velocity
  // filter ends on the pose itself (no lag, unlike a low-pass) and its twist is the motion's.
  const double v[3] = {0.1, -0.04, 0.02}, w[3] = {0.0, 0.1, 0.3}, dt = 1.0 / 30;
  pm::servo::PoseFilter f;
  for (int k = 0; k <= 300; ++k)
    f.update(movingPose(k * dt, v, w), dt);
  const vpHomogeneousMatrix truth = movingPose(300 * dt, v, w);
  EXPECT_LT(distanceMm(f.pose(), truth), 0.01);
  EXPECT_LT(angleDeg(f.pose().getRotationMatrix() * truth.getRotationMatrix().t()), 0.01);
  const vpColVector tw = f.twist();
  for (unsigned i = 0; i < 3; ++i) {
    EXPECT_NEAR(tw[i], v[i], 1e-4) << i;
    EXPECT_NEAR(tw[3 + i], w[i], 1e-3) << i;
  }
}

TEST(PoseFilter, SmoothsTheNoiseOfAStillPose)
{
  // A still pose measured with 2 mm and 1 deg of noise (seeded): the filtered poses scatter less
  // than the measurements, in position and in rotation.
  const vpHomogeneousMatrix truth(0.02, 0.01, 0.5, 0.1, 0.2, -0.1);
  std::mt19937 rng(7);
  std::normal_distribution<double> mm(0.0, 0.002), rad(0.0, M_PI / 180);
  pm::servo::PoseFilter f;
  double measured[2] = {0, 0}, filtered[2] = {0, 0};
  int n = 0;
  for (int k = 0; k < 600; ++k) {
    const vpHomogeneousMatrix noise(mm(rng), mm(rng), mm(rng), rad(rng), rad(rng), rad(rng));
    const vpHomogeneousMatrix z = truth * noise;
    const vpHomogeneousMatrix &p = f.update(z, 1.0 / 30);
    if (k < 60)
      continue; // the filter's start
    measured[0] += std::pow(distanceMm(z, truth), 2);
    measured[1] += std::pow(angleDeg(z.getRotationMatrix() * truth.getRotationMatrix().t()), 2);
    filtered[0] += std::pow(distanceMm(p, truth), 2);
    filtered[1] += std::pow(angleDeg(p.getRotationMatrix() * truth.getRotationMatrix().t()), 2);
    ++n;
  }
  for (int i = 0; i < 2; ++i) {
    const double ratio = std::sqrt(filtered[i] / measured[i]);
    std::cout << (i ? "rotation" : "position") << " rms filtered / measured: " << ratio << "\n";
    EXPECT_LT(ratio, 0.9) << i;
  }
  // The rotation gains are the smaller ones (the estimate's tilt is its noisiest part).
  EXPECT_LT(std::sqrt(filtered[1] / measured[1]), std::sqrt(filtered[0] / measured[0]));
}

TEST(PoseFilter, StartsOnItsFirstMeasurementAndAgainAfterAReset)
{
  pm::servo::PoseFilter f;
  EXPECT_FALSE(f.initialised());
  const vpHomogeneousMatrix a(0.1, 0.2, 0.7, 0.3, 0, 0), b(-0.2, 0.1, 0.4, 0, 0.5, 0);
  EXPECT_LT(distanceMm(f.update(a, 0.03), a), 1e-9);
  EXPECT_TRUE(f.initialised());
  f.update(a, 0.03);
  EXPECT_GT(distanceMm(f.update(b, 0.03), b), 10.0); // a jump is smoothed ...
  f.reset();
  EXPECT_LT(distanceMm(f.update(b, 0.03), b), 1e-9); // ... unless the filter is told to start again
  EXPECT_LT(std::sqrt(f.twist().sumSquare()), 1e-12);
}

TEST(PoseFilter, GainsOutOfRangeAreRefused)
{
  for (auto set : std::vector<void (*)(pm::servo::PoseFilterParams &)>{[](pm::servo::PoseFilterParams &p) { p.alphaT = 0; },
                                                                [](pm::servo::PoseFilterParams &p) { p.alphaR = 1.5; },
                                                                [](pm::servo::PoseFilterParams &p) { p.betaT = 2; },
                                                                [](pm::servo::PoseFilterParams &p) { p.betaR = -0.1; }}) {
    pm::servo::PoseFilterParams p;
    set(p);
    EXPECT_THROW(pm::servo::PoseFilter{p}, pm::core::Error);
  }
  EXPECT_NO_THROW(pm::servo::PoseFilter{pm::servo::PoseFilterParams()});
}
