// Any arm (issue 38): ViSP's Viper850 and Afma6 and our PA-10 behind one ArmModel / Arm, their
// Jacobians against their own forward kinematics, inverse kinematics, the stepped drive, the
// lab's pass on each arm and the views folder it writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <random>

#include <visp3/core/vpTime.h>
#include <visp3/core/vpVelocityTwistMatrix.h>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/io/RigFile.h"
#include "pm/hand/HandLoop.h"
#include "pm/io/ViewsFolder.h"
#include "pm/lab/ArmCameraSource.h"
#include "pm/lab/LabPass.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/ArmPassPlan.h"
#include "pm/robot/InverseKinematics.h"
#include "pm/robot/SteppedArm.h"
#include "pm/robot/ViSPRobotArm.h"
#include "pm/robot/ViSPSimulatedArm.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"

#include <nlohmann/json.hpp>

using pm::test::errorOf;

namespace {

//! Random joints inside the limits (less 5 % of each range at each end).
vpColVector randomJoints(const pm::robot::ArmModel &arm, std::mt19937 &rng)
{
  const vpColVector lo = arm.jointMin(), hi = arm.jointMax();
  vpColVector q(arm.dof());
  for (unsigned i = 0; i < arm.dof(); ++i) {
    const double m = 0.05 * (hi[i] - lo[i]);
    q[i] = std::uniform_real_distribution<double>(lo[i] + m, hi[i] - m)(rng);
  }
  return q;
}

//! The twist (base frame: the origin's velocity, the angular velocity) of B relative to A over dt.
vpColVector twistBetween(const vpHomogeneousMatrix &A, const vpHomogeneousMatrix &B, double dt)
{
  vpColVector v(6);
  const vpThetaUVector w(B.getRotationMatrix() * A.getRotationMatrix().t());
  for (unsigned k = 0; k < 3; ++k) {
    v[k] = (B[k][3] - A[k][3]) / dt;
    v[3 + k] = w[k] / dt;
  }
  return v;
}

const pm::core::StereoRig &rig()
{
  static const pm::core::StereoRig r = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  return r;
}

} // namespace

TEST(ArmModel, EachArmsJacobianIsTheDerivativeOfItsOwnForwardKinematics)
{
  std::mt19937 rng(38);
  for (const std::string &name : pm::robot::armNames()) {
    const auto arm = pm::robot::makeArmModel(name);
    EXPECT_EQ(arm->name(), name);
    for (int trial = 0; trial < 6; ++trial) {
      const vpColVector q = trial == 0 ? arm->restJoints() : randomJoints(*arm, rng);
      const vpMatrix fJe = arm->fJe(q);
      ASSERT_EQ(fJe.getRows(), 6u);
      ASSERT_EQ(fJe.getCols(), arm->dof());
      for (unsigned i = 0; i < arm->dof(); ++i) {
        const double h = 1e-6;
        vpColVector qp = q, qm = q;
        qp[i] += h;
        qm[i] -= h;
        const vpColVector fd = twistBetween(arm->fMe(qm), arm->fMe(qp), 2 * h);
        for (unsigned k = 0; k < 6; ++k)
          EXPECT_NEAR(fJe[k][i], fd[k], 1e-6) << name << " joint " << i + 1 << " row " << k << " trial " << trial;
      }
      // eJe is fJe seen from the flange.
      const vpRotationMatrix eRf = arm->fMe(q).getRotationMatrix().t();
      const vpMatrix eJe = arm->eJe(q);
      for (unsigned c = 0; c < arm->dof(); ++c)
        for (unsigned blk = 0; blk < 2; ++blk)
          for (unsigned r = 0; r < 3; ++r) {
            double s = 0;
            for (unsigned k = 0; k < 3; ++k)
              s += eRf[r][k] * fJe[3 * blk + k][c];
            EXPECT_NEAR(eJe[3 * blk + r][c], s, 1e-9) << name;
          }
    }
  }
  EXPECT_NE(errorOf([] { pm::robot::makeArmModel("ur5"); }).find("pa10, viper850, afma6"), std::string::npos);
  EXPECT_NE(errorOf([] { pm::robot::makeArmModel("viper850")->fMe(vpColVector(7, 0.0)); }).find("6 joint values expected, got 7"),
            std::string::npos);
}

TEST(ArmModel, EachRestLooksAlongItsFlangeAxisWithinItsLimits)
{
  for (const std::string &name : pm::robot::armNames()) {
    const auto arm = pm::robot::makeArmModel(name);
    const vpColVector q = arm->restJoints(), lo = arm->jointMin(), hi = arm->jointMax();
    for (unsigned i = 0; i < arm->dof(); ++i) {
      EXPECT_GT(q[i], lo[i]) << name << " joint " << i + 1;
      EXPECT_LT(q[i], hi[i]) << name << " joint " << i + 1;
    }
    // Away from singularities: the Jacobian's smallest singular value is not small.
    vpColVector sv;
    vpMatrix J = arm->fJe(q), V;
    J.svd(sv, V);
    EXPECT_GT(sv[sv.size() - 1], 0.05) << name;
  }
}

TEST(InverseKinematics, ReachesPosesOfEachArmWithinItsLimitsAndNamesTheJointInTheWay)
{
  std::mt19937 rng(7);
  for (const std::string &name : pm::robot::armNames()) {
    const auto arm = pm::robot::makeArmModel(name);
    int reached = 0;
    for (int trial = 0; trial < 10; ++trial) {
      // A goal reached by joints near the rest ones (within 20 deg or 50 mm): the solver must find one.
      vpColVector q = arm->restJoints();
      for (unsigned i = 0; i < arm->dof(); ++i)
        q[i] += std::uniform_real_distribution<double>(-1, 1)(rng) * (arm->prismatic(i) ? 0.05 : 0.35);
      const vpHomogeneousMatrix goal = arm->fMe(q);
      const pm::robot::IkResult ik = pm::robot::inverseKinematics(*arm, goal, arm->restJoints());
      if (!ik.reached)
        continue;
      ++reached;
      const vpHomogeneousMatrix got = arm->fMe(ik.q);
      EXPECT_LT((got.getTranslationVector() - goal.getTranslationVector()).frobeniusNorm(), 1e-4) << name;
      for (unsigned i = 0; i < arm->dof(); ++i) {
        EXPECT_GE(ik.q[i], arm->jointMin()[i]) << name;
        EXPECT_LE(ik.q[i], arm->jointMax()[i]) << name;
      }
    }
    EXPECT_GE(reached, 9) << name;
    // 3 m away: out of reach, and no joint to blame.
    const pm::robot::IkResult far = pm::robot::inverseKinematics(*arm, vpHomogeneousMatrix(3, 0, 3, 0, 0, 0), arm->restJoints());
    EXPECT_FALSE(far.reached) << name;
  }
  // The Afma6's last joint turns +-91 deg: a pose turned 150 deg about the flange's axis is blocked by it.
  const auto afma6 = pm::robot::makeArmModel("afma6");
  const vpHomogeneousMatrix turned = afma6->fMe(afma6->restJoints()) * vpHomogeneousMatrix(0, 0, 0, 0, 0, 150 * M_PI / 180);
  const pm::robot::IkResult ik = pm::robot::inverseKinematics(*afma6, turned, afma6->restJoints());
  ASSERT_FALSE(ik.reached);
  ASSERT_GE(ik.blockingJoint, 0);
  EXPECT_NE(afma6->describeJoint(static_cast<unsigned>(ik.blockingJoint), ik.q).find("limits"), std::string::npos);
}

TEST(SteppedArm, IntegratesScalesToTheSpeedLimitsAndStopsOnALimit)
{
  pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850"));
  const vpColVector q0 = arm.q(), vmax = arm.model().speedLimits();
  EXPECT_EQ(q0, arm.model().restJoints());
  vpColVector qd(6, 0.0);
  qd[0] = 0.1;
  qd[3] = -0.2;
  arm.setJointVelocity(qd);
  arm.advance(0.5);
  EXPECT_NEAR(arm.q()[0] - q0[0], 0.05, 1e-12);
  EXPECT_NEAR(arm.q()[3] - q0[3], -0.1, 1e-12);
  // Ten times joint 6's speed limit on joint 6, a fifth of that on joint 1 (joint 6 is the tighter):
  // scaled as a whole, the direction kept.
  qd = 0;
  qd[5] = 10 * vmax[5];
  qd[0] = 0.2 * qd[5];
  ASSERT_LT(qd[0] / vmax[0], qd[5] / vmax[5]);
  arm.setJointVelocity(qd);
  EXPECT_NEAR(arm.commanded()[5], vmax[5], 1e-12);
  EXPECT_NEAR(arm.commanded()[0] / arm.commanded()[5], 0.2, 1e-12);
  // Joint 5 driven into its limit stops there, counted.
  qd = 0;
  qd[4] = vmax[4];
  arm.setJointVelocity(qd);
  arm.advance(3.0);
  EXPECT_NEAR(arm.q()[4], arm.model().jointMax()[4], 1e-12);
  EXPECT_EQ(arm.limitHits(), 1);
  EXPECT_EQ(arm.commanded()[4], 0.0);
  // Bad commands: an error, and the arm stopped.
  qd = 0;
  qd[1] = 0.1;
  arm.setJointVelocity(qd);
  qd[2] = NAN;
  EXPECT_NE(errorOf([&] { arm.setJointVelocity(qd); }).find("joint 3 is not finite"), std::string::npos);
  EXPECT_EQ(arm.commanded().frobeniusNorm(), 0.0);
  EXPECT_NE(errorOf([&] { arm.setJointVelocity(vpColVector(7, 0.0)); }).find("6 joint velocities expected"), std::string::npos);
  vpColVector beyond = arm.model().restJoints();
  beyond[1] = arm.model().jointMax()[1] + 0.1;
  EXPECT_NE(errorOf([&] { arm.moveTo(beyond); }).find("joint 2"), std::string::npos);
}

TEST(Arm, TheHandJacobianMovesTheRigMountedOffTheFlangeAsCommanded)
{
  // The rig 80 mm along the flange's z and turned 90 deg about it: hJe q' is the hand's own twist.
  const vpHomogeneousMatrix eMh(0, 0, 0.08, 0, 0, M_PI / 2);
  for (const std::string &name : pm::robot::armNames()) {
    pm::robot::SteppedArm arm(pm::robot::makeArmModel(name), eMh);
    const vpColVector q = arm.q();
    vpColVector qd(arm.model().dof(), 0.0);
    for (unsigned i = 0; i < qd.size(); ++i)
      qd[i] = (arm.model().prismatic(i) ? 0.01 : 0.05) * (i % 2 ? -1 : 1);
    const vpColVector v = arm.hJe(q) * qd; // in the hand frame
    const double dt = 1e-6;
    vpColVector q2 = q;
    for (unsigned i = 0; i < qd.size(); ++i)
      q2[i] += qd[i] * dt;
    const vpHomogeneousMatrix h1Mh2 = arm.fMh(q).inverse() * arm.fMh(q2);
    const vpThetaUVector w(h1Mh2.getRotationMatrix());
    for (unsigned k = 0; k < 3; ++k) {
      EXPECT_NEAR(v[k], h1Mh2[k][3] / dt, 1e-5) << name;
      EXPECT_NEAR(v[3 + k], w[k] / dt, 1e-5) << name;
    }
  }
}

TEST(ArmPassPlan, AnOuterRingOutOfReachIsLeftOutAndSaid)
{
  // The PA-10 at 500 mm reaches 20 and 40 deg all around but not the whole 55-deg ring: the views
  // it cannot reach are left out (their directions said), the rest made as planned.
  const auto arm = pm::robot::makeArmModel("pa10");
  pm::model::PassPlan plan;
  plan.views = 24;
  plan.ringsDeg = {20, 40, 55};
  std::vector<pm::model::PassDirection> leftOut;
  const std::vector<pm::robot::ArmPassView> views = pm::robot::planArmPass(*arm, arm->restJoints(), vpHomogeneousMatrix(), plan, 500, &leftOut);
  ASSERT_FALSE(leftOut.empty());
  EXPECT_EQ(views.size() + leftOut.size(), 24u);
  for (const pm::model::PassDirection &d : leftOut)
    EXPECT_EQ(d.tiltDeg, 55.0);
  const std::vector<pm::model::PassDirection> planned = pm::model::passDirections(plan);
  const vpHomogeneousMatrix fMe0 = arm->fMe(arm->restJoints());
  for (const pm::robot::ArmPassView &v : views) {
    const int k = std::stoi(v.name.substr(5)); // "view NN": the plan's number
    ASSERT_LT(k, 24);
    EXPECT_LE(v.direction.tiltDeg, planned[k].tiltDeg) << v.name;
    const vpHomogeneousMatrix want = fMe0 * pm::model::passPose(v.direction, 500);
    EXPECT_LT((arm->fMe(v.q).getTranslationVector() - want.getTranslationVector()).frobeniusNorm(), 1e-4) << v.name;
  }
  EXPECT_NE(pm::robot::describeLeftOut(leftOut.front(), arm->title()).find("deg: out of the PA-10's reach, left out of the pass"),
            std::string::npos);
  // Its innermost ring out of reach is still an error: a pass without it would not be a pass.
  plan.ringsDeg = {55};
  EXPECT_NE(errorOf([&] { pm::robot::planArmPass(*arm, arm->restJoints(), vpHomogeneousMatrix(), plan, 500); }).find("out of the PA-10's reach"),
            std::string::npos);
}

TEST(LabPass, EachArmReachesThePassAndItsViewsFolderMakesTheSameModel)
{
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  pm::model::PassPlan plan;
  plan.views = 8; // the rest view and a ring of 7
  plan.ringsDeg = {30};
  for (const std::string name : {"viper850", "afma6"}) {
    pm::robot::SteppedArm arm(pm::robot::makeArmModel(name));
    const pm::lab::LabPass pass = pm::lab::runLabPass(scene, rig(), plan, arm);
    ASSERT_EQ(pass.views.size(), 8u) << name;
    double tiltSum = 0;
    for (std::size_t k = 0; k < pass.views.size(); ++k) {
      // Each view where it was asked: the hand's pose from the arm's joints is the planned one.
      const vpHomogeneousMatrix want = pass.fMh0 * pm::model::passPose(pass.directions[k], 500);
      const vpHomogeneousMatrix got = arm.fMh(pass.joints[k]);
      EXPECT_LT((got.getTranslationVector() - want.getTranslationVector()).frobeniusNorm(), 1e-4) << name << " view " << k;
      // Tilted as planned, or less where out of reach, down to half (the Viper850 in the limits of ViSP's simulator).
      EXPECT_LE(pass.directions[k].tiltDeg, k == 0 ? 0 : 30) << name << " view " << k;
      EXPECT_GE(pass.directions[k].tiltDeg, k == 0 ? 0 : 15) << name << " view " << k;
      tiltSum += pass.directions[k].tiltDeg;
      for (unsigned i = 0; i < arm.model().dof(); ++i) {
        EXPECT_GE(pass.joints[k][i], arm.model().jointMin()[i]);
        EXPECT_LE(pass.joints[k][i], arm.model().jointMax()[i]);
      }
    }
    if (name == "afma6") {
      EXPECT_EQ(tiltSum, 7 * 30.0); // the gantry reaches every view of this plan
    }
    // The views folder the arm's pass writes makes the same model as the pass itself.
    pm::test::TempDir d(std::string("arm-views-") + name);
    pm::io::saveViewsFolder(pass.views, d.file("views"));
    const std::vector<pm::model::PassView> back = pm::io::loadViewsFolder(d.file("views"), rig());
    pm::model::AllAroundParams p;
    p.viewpoints.count = 1; // the front view's S_in is compared: the other viewpoints (the build's last step) are not made
    const pm::model::AllAroundBuild a = pm::model::buildAllAroundModel(rig(), pass.views, p), b = pm::model::buildAllAroundModel(rig(), back, p);
    ASSERT_EQ(a.model.inner.size(), b.model.inner.size()) << name;
    double worst = 0;
    for (std::size_t i = 0; i < a.model.inner.size(); ++i)
      worst = std::max(worst, static_cast<double>(std::fabs(a.model.inner[i].x - b.model.inner[i].x) + std::fabs(a.model.inner[i].z - b.model.inner[i].z)));
    EXPECT_LT(worst, 1e-6) << name;
  }
  // An arm that cannot make the pass: an error naming the view and the joint in the way. The toy
  // 3 m away: the ring's views, 30 deg around it (15 deg at least), are 0.78 m or more aside,
  // beyond the Afma6's slides (-0.65..0.7 m and -0.6..0.52 m).
  pm::robot::SteppedArm afma6(pm::robot::makeArmModel("afma6"));
  const std::string e = errorOf([&] { pm::lab::runLabPass(scene, rig(), plan, afma6, vpHomogeneousMatrix(0, 0, 3, 0, 0, 0)); });
  EXPECT_NE(e.find("view 01 of the pass (30 deg toward 0 deg) is out of the Afma6's reach"), std::string::npos) << e;
  EXPECT_NE(e.find(" mm, limits "), std::string::npos) << e; // a slide is in the way
}

namespace {

//! A vpRobot of six joints that integrates its velocity command when advanced by hand, and can be told to stop answering.
class FakeRobot : public vpRobot
{
public:
  vpColVector q = vpColVector(6, 0.0), qdot = vpColVector(6, 0.0);
  bool nanJoints = false, frozen = false, stopped = false;
  double clockedGain = 0;  //!< > 0: moves by itself in real time, at this share of the command (a sluggish or eager controller)
  std::function<double()> clockMs = [] { return vpTime::measureTimeMs(); }; //!< its controller's clock (ms)
  double lastReadMs = -1;
  double fastestShare = 0; //!< the largest |qdot_i| / limit_i commanded, against \e limits
  vpColVector limits;
  void get_eJe(vpMatrix &) override {}
  void get_fJe(vpMatrix &) override {}
  void getDisplacement(const vpRobot::vpControlFrameType, vpColVector &d) override { d.resize(6, true); }
  void getPosition(const vpRobot::vpControlFrameType, vpColVector &out) override
  {
    const double now = clockMs();
    if (clockedGain > 0 && lastReadMs >= 0)
      run(clockedGain * 1e-3 * (now - lastReadMs));
    lastReadMs = now;
    out = q;
    if (nanJoints)
      out[2] = NAN;
  }
  void init() override {}
  void setPosition(const vpRobot::vpControlFrameType, const vpColVector &goal) override { q = goal; }
  void setVelocity(const vpRobot::vpControlFrameType, const vpColVector &v) override
  {
    qdot = v;
    stopped = v.frobeniusNorm() == 0;
    for (unsigned i = 0; i < limits.size(); ++i)
      fastestShare = std::max(fastestShare, std::fabs(v[i]) / limits[i]);
  }
  vpRobot::vpRobotStateType setRobotState(const vpRobot::vpRobotStateType s) override
  {
    if (s == vpRobot::STATE_STOP)
      stopped = true;
    return vpRobot::setRobotState(s);
  }
  //! The motion of \e dt seconds under the last command (what a real robot's controller does meanwhile).
  void run(double dt)
  {
    if (!frozen)
      q += qdot * dt;
  }
};

} // namespace

TEST(ViSPRobotArm, ARobotThatStopsAnsweringStopsTheArmWithAClearError)
{
  FakeRobot robot;
  pm::robot::ViSPRobotArm arm(robot, pm::robot::makeArmModel("viper850"));
  arm.moveTo(arm.model().restJoints());
  EXPECT_EQ(arm.q(), arm.model().restJoints());
  vpColVector qd(6, 0.0);
  qd[0] = 0.2;
  arm.setJointVelocity(qd);
  EXPECT_EQ(robot.getRobotState(), vpRobot::STATE_VELOCITY_CONTROL);
  EXPECT_EQ(robot.qdot, qd);
  robot.run(0.05);
  arm.advance(0.05);
  EXPECT_NEAR(arm.q()[0] - arm.model().restJoints()[0], 0.01, 1e-12);
  // Joints that read as NaN: an error saying the robot does not answer, and the robot told to stop.
  robot.nanJoints = true;
  const std::string e = errorOf([&] { arm.advance(0.01); });
  EXPECT_NE(e.find("does not answer"), std::string::npos) << e;
  EXPECT_NE(e.find("joint 3"), std::string::npos) << e;
  EXPECT_TRUE(robot.stopped);
  EXPECT_EQ(robot.qdot.frobeniusNorm(), 0.0);
  // Joints that no longer move under a command: the same after ViSPRobotArmParams::stallS.
  robot.nanJoints = false;
  robot.frozen = true;
  arm.setJointVelocity(qd);
  EXPECT_FALSE(robot.stopped);
  std::string stall;
  for (int k = 0; k < 40 && stall.empty(); ++k)
    stall = errorOf([&] { arm.advance(1.0 / 30); });
  EXPECT_NE(stall.find("have not moved for"), std::string::npos) << stall;
  EXPECT_TRUE(robot.stopped);
  // Out of the model's limits: refused before the robot moves.
  vpColVector beyond = arm.model().restJoints();
  beyond[0] = arm.model().jointMax()[0] + 0.01;
  const vpColVector before = robot.q;
  EXPECT_NE(errorOf([&] { arm.moveTo(beyond); }).find("joint 1"), std::string::npos);
  EXPECT_EQ(robot.q, before);
}

TEST(ViSPRobotArm, ARobotStoppedWithAJointOnItsLimitSaysWhichJoint)
{
  // ViSP's simulators stop the arm when a joint reaches its limit: the error names it.
  FakeRobot robot;
  pm::robot::ViSPRobotArm arm(robot, pm::robot::makeArmModel("viper850"));
  robot.q = arm.model().restJoints();
  robot.q[2] = arm.model().jointMax()[2];
  robot.frozen = true;
  vpColVector qd(6, 0.0);
  qd[2] = 0.1;
  arm.setJointVelocity(qd);
  std::string e;
  for (int k = 0; k < 40 && e.empty(); ++k)
    e = errorOf([&] { arm.advance(1.0 / 30); });
  EXPECT_NE(e.find("joint 3 (215.0 deg, limits -29.0..215.0 deg) is on its limit"), std::string::npos) << e;
  EXPECT_TRUE(robot.stopped);
}

TEST(ViSPRobotArm, ACommandThatLastsLongerThanMeantStopsShortOfAJointsLimit)
{
  // A velocity command lasts until the next: a frame late by most of the horizon (a program
  // descheduled on a loaded machine) must not carry a joint onto its limit, where ViSP's
  // simulators stop the arm. Away from the limit, and on the other joints, the command is sent as asked.
  FakeRobot robot;
  pm::robot::ViSPRobotArmParams params;
  pm::robot::ViSPRobotArm arm(robot, pm::robot::makeArmModel("viper850"), vpHomogeneousMatrix(), params);
  const vpColVector hi = arm.model().jointMax(), lo = arm.model().jointMin();
  robot.q = arm.model().restJoints();
  robot.q[2] = hi[2] - 0.1;
  robot.q[1] = lo[1] + 0.05;
  vpColVector qd(6, 0.0);
  qd[2] = 1.0;  // toward joint 3's upper limit: there in 0.1 s unbounded
  qd[1] = 0.3;  // away from joint 2's lower limit
  qd[0] = -0.2; // joint 1, far from its limits
  arm.setJointVelocity(qd);
  EXPECT_NEAR(robot.qdot[2], 0.1 / params.limitHorizonS, 1e-12);
  EXPECT_EQ(robot.qdot[1], 0.3);
  EXPECT_EQ(robot.qdot[0], -0.2);
  EXPECT_EQ(arm.commanded(), robot.qdot); // what was sent
  robot.run(0.9 * params.limitHorizonS);
  EXPECT_LT(robot.q[2], hi[2]);
  EXPECT_GT(robot.q[2], hi[2] - 0.1); // it does move toward it
  // Toward joint 2's lower limit, 0.05 rad away: bounded the same way.
  qd = 0.0;
  qd[1] = -2.0;
  robot.q[1] = lo[1] + 0.05;
  arm.setJointVelocity(qd);
  EXPECT_NEAR(robot.qdot[1], -0.05 / params.limitHorizonS, 1e-12);
  // On the limit: nothing toward it.
  robot.q[2] = hi[2];
  qd = 0.0;
  qd[2] = 0.5;
  arm.setJointVelocity(qd);
  EXPECT_EQ(robot.qdot[2], 0.0);
}

TEST(ViSPRobotArm, MovesByVelocityOntoTheGoalWithinItsSpeedLimitsWhateverTheControllersGain)
{
  // ViSPRobotArmParams::moveByVelocity (what ViSP's simulators need): a closed loop, so a robot
  // that moves at 60 % or 150 % of what it is told still lands on the goal, and at most at the
  // model's speed limits.
  pm::robot::ViSPRobotArmParams params;
  params.moveByVelocity = true;
  for (const double gain : {0.6, 1.5}) {
    FakeRobot robot;
    pm::robot::ViSPRobotArm arm(robot, pm::robot::makeArmModel("viper850"), vpHomogeneousMatrix(), params);
    robot.limits = arm.model().speedLimits();
    robot.clockedGain = gain;
    robot.q = arm.model().restJoints();
    vpColVector goal = robot.q;
    goal[0] += 0.4;
    goal[3] -= 0.3;
    arm.moveTo(goal);
    EXPECT_TRUE(robot.stopped);
    for (unsigned i = 0; i < 6; ++i)
      EXPECT_NEAR(robot.q[i], goal[i], params.positionTolerance) << "joint " << i + 1 << ", gain " << gain;
    EXPECT_GT(robot.fastestShare, 0.5) << gain; // it does hurry
    EXPECT_LE(robot.fastestShare, 1.0) << gain;
    // A robot that does not move: the stall error, not a wait for ever.
    robot.frozen = true;
    const std::string e = errorOf([&] { arm.moveTo(arm.model().restJoints()); });
    EXPECT_NE(e.find("have not moved"), std::string::npos) << e;
  }
}

TEST(HandLoop, ARobotThatStopsAnsweringMidServoEndsTheLoopWithAClearErrorAndTheArmStopped)
{
  // A vpRobot that moves in real time as told, servoed from the lab's cameras on its hand to bring
  // the crab 50 mm nearer; then its joints freeze.
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  const pm::sim::SimulatedPhotoModel sm = pm::sim::makeSimulatedStereoPhotoModel(scene, rig());
  FakeRobot robot;
  pm::robot::ViSPRobotArm arm(robot, pm::robot::makeArmModel("viper850"));
  robot.q = arm.model().restJoints();
  robot.clockedGain = 1;
  // Its clock runs a frame's time per step of the loop, however slow the machine (a sanitizer's build
  // runs the loop at a third of real time: the wall clock would move the robot three frames a frame).
  double simulatedMs = 0;
  robot.clockMs = [&simulatedMs] { return simulatedMs; };
  pm::lab::ArmCameraSource cameras(scene, rig(), arm, arm.fMh() * vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), 30, 0);
  pm::servo::ServoParams sp;
  sp.hdMo = sm.photoHMo * sm.oMm * vpHomogeneousMatrix(0, 0, -0.05, 0, 0, 0); // the model's frame, 50 mm nearer
  pm::tracker::TrackerParams tp;
  tp.search.budgetEvaluations = 800; // frames of the same work whatever the machine's load: the lock comes as soon
  pm::hand::HandLoop loop(rig(), sm.build.model, tp, sp, pm::hand::GuardParams(), cameras, arm);
  pm::hand::HandFrame f;
  // Until it has servoed a second (30 frames).
  long servoed = 0;
  for (int k = 0; k < 150 && servoed < 30; ++k) { // at most 5 s
    ASSERT_TRUE(loop.step(f));
    simulatedMs += 1000.0 / 30;
    servoed += f.command.servoing ? 1 : 0;
  }
  ASSERT_EQ(servoed, 30);
  ASSERT_GT(arm.commanded().frobeniusNorm(), 1e-3);
  robot.frozen = true;
  std::string e;
  for (int k = 0; k < 90 && e.empty(); ++k) {
    e = errorOf([&] { loop.step(f); });
    simulatedMs += 1000.0 / 30;
  }
  EXPECT_NE(e.find("does not answer"), std::string::npos) << e;
  EXPECT_NE(e.find("the arm was told to stop"), std::string::npos) << e;
  EXPECT_TRUE(robot.stopped);
  EXPECT_EQ(robot.qdot.frobeniusNorm(), 0.0);
}

TEST(ArmProgram, YourArmsProgramRefusesBadInputClearlyAndWritesNothing)
{
  // examples/own-arm: ViSP's simulated Viper850 handed to pm::program::runArmProgram.
  pm::test::TempDir d("my-arm");
  const std::string rigFile = pm::test::dataPath("rig/pa10_stereo.json");
  EXPECT_EQ(pm::test::runProgram("my-arm", "").status, 2); // a subcommand is needed
  const auto help = pm::test::runProgram("my-arm", "pass --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--views"), std::string::npos);
  EXPECT_EQ(pm::test::runProgram("my-arm", "pass --rig " + rigFile + " --simulate C12").status, 2); // no --views
  EXPECT_EQ(pm::test::runProgram("my-arm", "pass --rig " + rigFile + " --views " + d.file("v")).status, 2); // no cameras
  // Out of the arm's reach: the view and the joint, nothing written.
  const auto far = pm::test::runProgram("my-arm", "pass --rig " + rigFile + " --simulate C12 --distance-mm 2500 --views " + d.file("far"));
  EXPECT_EQ(far.status, 1);
  EXPECT_NE(far.err.find("error: view 01 of the pass"), std::string::npos) << far.err;
  EXPECT_NE(far.err.find("joint 2"), std::string::npos) << far.err;
  EXPECT_FALSE(std::filesystem::exists(d.file("far")));
  // Live cameras and backgrounds with no terminal to answer: refused before the cameras open.
  const auto live = pm::test::runProgram("my-arm", "pass --rig " + rigFile + " --left 0 --right 1 --views " + d.file("live"));
  EXPECT_EQ(live.status, 1);
  EXPECT_NE(live.err.find("terminal"), std::string::npos) << live.err;
  const auto noModel = pm::test::runProgram("my-arm", "servo --rig " + rigFile + " --simulate C12 --model " + d.file("none.json"));
  EXPECT_EQ(noModel.status, 1);
  EXPECT_NE(noModel.err.find("error: "), std::string::npos) << noModel.err;
}

TEST(ViSPSimulatedArm, ViSPsThreadedSimulatorsMoveAsCommandedInRealTime)
{
  for (const std::string name : {"viper850", "afma6"}) {
    pm::robot::ViSPSimulatedArm arm(name); // at rest
    const vpColVector q0 = arm.q(), rest = arm.model().restJoints();
    for (unsigned i = 0; i < 6; ++i)
      EXPECT_NEAR(q0[i], rest[i], 1e-3) << name;
    vpColVector qd(6, 0.0);
    qd[0] = arm.model().prismatic(0) ? 0.05 : 0.2;
    qd[5] = 0.2;
    arm.setJointVelocity(qd);
    for (int k = 0; k < 15; ++k)
      arm.advance(1.0 / 30); // 0.5 s
    arm.stop();
    const vpColVector q1 = arm.q();
    // Real time: the simulator's thread integrates every 10 ms, so within 20 % of the commanded motion.
    EXPECT_NEAR((q1[0] - q0[0]) / (0.5 * qd[0]), 1.0, 0.2) << name;
    EXPECT_NEAR((q1[5] - q0[5]) / (0.5 * qd[5]), 1.0, 0.2) << name;
    EXPECT_NEAR(q1[2], q0[2], 1e-9) << name;
  }
  EXPECT_NE(errorOf([] { pm::robot::ViSPSimulatedArm arm("pa10"); }).find("no ViSP simulator"), std::string::npos);
}

TEST(MainJob, OnViSPsViper850AndAfma6TheArmKeepsTheCrabWithinGoalsAndNeverActsOnAWrongPose)
{
  // The main job on each of ViSP's arms, stepped in our loop: the arm's own pass makes the
  // all-around model of C12, then the first 4 steps of Table 2.
  pm::test::TempDir d("mainjob-arms");
  for (const std::string name : {"viper850", "afma6"}) {
    const std::string out = d.file(name);
    const auto r = pm::test::runProgram("pm-servo", "--robot " + name + " --steps 4 --no-video --overlay-every 0 --quiet --out " + out);
    ASSERT_EQ(r.status, 0) << name << ": " << r.err;
    const auto sj = nlohmann::json::parse(pm::test::readText(out + "/summary.json"));
    EXPECT_EQ(sj.at("robot").get<std::string>(), pm::robot::makeArmModel(name)->title());
    EXPECT_LT(sj.at("rms_error_mm").at("at_rest").get<double>(), 2.0) << name;
    EXPECT_LT(sj.at("rms_rotation_error_deg").at("at_rest").get<double>(), 1.0) << name;
    EXPECT_EQ(sj.at("frames_servoed_on_wrong_pose").get<long>(), 0) << name;
    EXPECT_EQ(sj.at("joint_limit_violations").get<long>(), 0) << name;
    ASSERT_TRUE(sj.at("converged_after_s").is_number()) << name; // found with no initial pose, and kept
    EXPECT_LT(sj.at("converged_after_s").get<double>(), 2.0) << name;
  }
  const auto bad = pm::test::runProgram("pm-servo", "--robot ur5 --steps 1 --out " + d.file("bad"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--robot"), std::string::npos) << bad.err;
}

TEST(LabPass, ThroughViSPsThreadedSimulatorAsThroughAnyVpRobotTheViewsAreTheSteppedOnes)
{
  // The pass made through vpRobot (ViSP's simulator of the Afma6, real time) lands on the views
  // the stepped model plans: one interface for the lab and a real arm.
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  pm::model::PassPlan plan;
  plan.views = 4;
  plan.ringsDeg = {25};
  pm::robot::SteppedArm stepped(pm::robot::makeArmModel("afma6"));
  pm::robot::ViSPSimulatedArm viaViSP("afma6");
  const pm::lab::LabPass a = pm::lab::runLabPass(scene, rig(), plan, stepped, vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), false);
  const pm::lab::LabPass b = pm::lab::runLabPass(scene, rig(), plan, viaViSP, vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), false);
  ASSERT_EQ(a.views.size(), b.views.size());
  for (std::size_t k = 0; k < a.views.size(); ++k) {
    EXPECT_EQ(a.directions[k].tiltDeg, b.directions[k].tiltDeg);
    const vpHomogeneousMatrix d = a.views[k].fMh.inverse() * b.views[k].fMh;
    EXPECT_LT(d.getTranslationVector().frobeniusNorm(), 1e-3) << "view " << k; // moveTo's tolerance, 1 mrad or 1 mm a joint
    EXPECT_LT(d.getThetaUVector().getTheta(), 5e-3) << "view " << k;
  }
}
