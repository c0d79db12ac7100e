// sim: the trajectory of the TC-robot's steps (Table 2's motion): holds, quintic moves with
// zero speed and acceleration at both ends, the peak speed of a quintic, and its errors. (The
// renderer, the scene and the targets: test_render.cpp; the PA-10 and the TC-robot: test_robot.cpp.)
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "pm/io/PoseTableFile.h"
#include "pm/sim/Trajectory.h"

using pm::test::errorOf;

TEST(Trajectory, HoldsThenMovesOnAQuinticWithZeroSpeedAndAccelerationAtTheEnds)
{
  const pm::core::Phi a{0, 0, 500, 0, 0, 0}, b{60, -30, 540, 0.1, 0, -0.05};
  const pm::sim::Trajectory tr({a, b, a}, 1.5, 1.0);
  EXPECT_DOUBLE_EQ(tr.duration(), 3 * 1.5 + 2 * 1.0);
  // Holds: exactly the waypoint, not moving.
  for (double t : {0.0, 0.7, 1.5}) {
    EXPECT_EQ(tr.at(t).x, a.x) << t;
    EXPECT_FALSE(tr.moving(t)) << t;
  }
  for (double t : {2.5, 3.2, 4.0})
    EXPECT_EQ(tr.at(t).toString(), b.toString()) << t;
  EXPECT_EQ(tr.at(100).toString(), a.toString()); // held at the end
  EXPECT_EQ(tr.at(-1).toString(), a.toString());  // and before the start
  EXPECT_EQ(tr.stepAt(0.2), 0);
  EXPECT_EQ(tr.stepAt(2.6), 1);
  EXPECT_EQ(tr.stepAt(100), 2);
  // The move: halfway at its middle (a quintic is symmetric), moving, monotonic.
  EXPECT_TRUE(tr.moving(2.0));
  EXPECT_NEAR(tr.at(2.0).x, 30, 1e-12);
  EXPECT_NEAR(tr.at(2.0).z, 520, 1e-12);
  double last = -1;
  for (double t = 1.5; t <= 2.5; t += 0.01) {
    EXPECT_GE(tr.at(t).x, last - 1e-12);
    last = tr.at(t).x;
  }
  // Speed and acceleration by finite differences: zero at both ends of the move, and the peak
  // speed of a quintic, 15/8 of the mean (60 mm in 1 s: 112.5 mm/s at the middle).
  const double h = 1e-4;
  auto speed = [&](double t) { return (tr.at(t + h).x - tr.at(t - h).x) / (2 * h); };
  auto accel = [&](double t) { return (tr.at(t + h).x - 2 * tr.at(t).x + tr.at(t - h).x) / (h * h); };
  EXPECT_NEAR(speed(1.5 + 2 * h), 0, 1e-3);
  EXPECT_NEAR(speed(2.5 - 2 * h), 0, 1e-3);
  EXPECT_NEAR(speed(2.0), 112.5, 1e-3);
  double peak = 0;
  for (double t = 1.5; t <= 2.5; t += 0.001)
    peak = std::max(peak, std::fabs(speed(t)));
  EXPECT_NEAR(peak, 112.5, 1e-2);
  // Acceleration: the quintic's peak, 10 / sqrt(3) D / T^2 (346.4 mm/s^2), and nearly none at the ends.
  double peakAccel = 0;
  for (double t = 1.5 + 0.01; t <= 2.5 - 0.01; t += 0.001)
    peakAccel = std::max(peakAccel, std::fabs(accel(t)));
  EXPECT_NEAR(peakAccel, 10 / std::sqrt(3.0) * 60, 0.5);
  EXPECT_LT(std::fabs(accel(1.5 + 2 * h)), 0.005 * peakAccel);
  EXPECT_LT(std::fabs(accel(2.5 - 2 * h)), 0.005 * peakAccel);
}

TEST(Trajectory, Table2HasTwentyValidStepsAndBadTrajectoriesAreRefused)
{
  const std::vector<pm::core::Phi> w = pm::io::readWaypoints(pm::test::dataPath("trajectories/table2.csv"));
  ASSERT_EQ(w.size(), 20u);
  EXPECT_EQ(pm::io::readWaypoints(pm::test::dataPath("trajectories/table2.csv"), 3).size(), 3u);
  const pm::sim::Trajectory tr(w, 1.5, 1.0);
  EXPECT_DOUBLE_EQ(tr.duration(), 20 * 1.5 + 19 * 1.0);
  EXPECT_NE(errorOf([] { pm::sim::Trajectory({}, 1, 1); }).find("no waypoint"), std::string::npos);
  EXPECT_NE(errorOf([] { pm::sim::Trajectory({{0, 0, 500, 0, 0, 0}}, 1, 0); }).find("move time"), std::string::npos);
  EXPECT_NE(errorOf([] { pm::sim::Trajectory({{0, 0, 500, 0, 0, 0}}, -1, 1); }).find("hold time"), std::string::npos);
  EXPECT_NE(errorOf([] { pm::sim::Trajectory({{0, 0, 500, 0.9, 0.9, 0}}, 1, 1); }).find("invalid waypoint"), std::string::npos);
}
