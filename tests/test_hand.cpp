// The pass and the servo on an arm from its own cameras (pm::hand), as on a real arm: the lab's
// cameras on the arm's hand (pm::lab::ArmCameraSource) in place of the rig's.
#include <gtest/gtest.h>

#include <cmath>

#include "TestSupport.h"
#include "pm/core/Error.h"
#include "pm/hand/GraspApproach.h"
#include "pm/hand/HandLoop.h"
#include "pm/hand/HandPass.h"
#include "pm/io/RigFile.h"
#include "pm/lab/ArmCameraSource.h"
#include "pm/lab/LabPass.h"
#include "pm/robot/ArmCatalog.h"
#include "pm/robot/SteppedArm.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/sim/Trajectory.h"

using pm::test::errorOf;

namespace {

const pm::core::StereoRig &rig()
{
  static const pm::core::StereoRig r = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  return r;
}

//! Mean |difference| of the red channel over the image's central quarter.
double centreDifference(const vpImage<vpRGBa> &a, const vpImage<vpRGBa> &b)
{
  double sum = 0;
  long n = 0;
  for (unsigned i = a.getHeight() / 4; i < 3 * a.getHeight() / 4; ++i)
    for (unsigned j = a.getWidth() / 4; j < 3 * a.getWidth() / 4; ++j, ++n)
      sum += std::abs(static_cast<int>(a[i][j].R) - static_cast<int>(b[i][j].R));
  return sum / static_cast<double>(n);
}

double mm(const vpHomogeneousMatrix &e) { return 1e3 * e.getTranslationVector().frobeniusNorm(); }
double deg(const vpHomogeneousMatrix &e) { return e.getThetaUVector().getTheta() * 180 / M_PI; }

} // namespace

TEST(GraspApproach, ClosesInOnlyWhileServoedOnceSettledAndStopsAtTheGraspsDistance)
{
  pm::hand::GraspApproachParams p; // 500 to 300 mm at 25 mm/s, after 1 s servoed at 500
  const vpHomogeneousMatrix hdMo0(0.01, -0.02, 0.45, 0.1, 0, 0);
  pm::hand::GraspApproach a(p, hdMo0);
  EXPECT_DOUBLE_EQ(a.distanceMm(), 500); // the start's distance, the rest of hdMo0 kept
  EXPECT_DOUBLE_EQ(a.hdMo()[2][3], 0.5);
  EXPECT_DOUBLE_EQ(a.hdMo()[0][3], 0.01);
  EXPECT_DOUBLE_EQ(a.hdMo()[1][2], hdMo0[1][2]);
  const double dt = 0.1;
  for (int k = 0; k < 20; ++k) // held: it waits
    a.advance(false, dt);
  EXPECT_DOUBLE_EQ(a.distanceMm(), 500);
  for (int k = 0; k < 10; ++k) // servoed 1 s: settled, not yet moving
    a.advance(true, dt);
  EXPECT_NEAR(a.distanceMm(), 500, 1e-9);
  for (int k = 0; k < 10; ++k) // servoed 1 s more: 25 mm in
    a.advance(true, dt);
  EXPECT_NEAR(a.distanceMm(), 475, 1e-6);
  a.advance(false, dt); // a frame held: no step, and no new settling afterwards
  EXPECT_NEAR(a.distanceMm(), 475, 1e-6);
  a.advance(true, dt);
  EXPECT_NEAR(a.distanceMm(), 472.5, 1e-6);
  EXPECT_FALSE(a.done());
  for (int k = 0; k < 200; ++k)
    a.advance(true, dt);
  EXPECT_DOUBLE_EQ(a.distanceMm(), 300); // and no nearer
  EXPECT_DOUBLE_EQ(a.hdMo()[2][3], 0.3);
  EXPECT_TRUE(a.done());
  p.toMm = 600; // farther than the start
  EXPECT_THROW(pm::hand::GraspApproach(p, hdMo0), pm::core::Error);
  p = pm::hand::GraspApproachParams();
  p.mmPerS = 0;
  EXPECT_THROW(p.validate(), pm::core::Error);
}

TEST(HandPass, FromTheArmsOwnCamerasItStopsWhereTheLabsPassDoesTakesTheBackgroundsAndComesBack)
{
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  pm::model::PassPlan plan;
  plan.views = 8;
  plan.ringsDeg = {30};
  plan.distanceMm = 500;
  pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850")), labArm(pm::robot::makeArmModel("viper850"));
  const vpColVector q0 = arm.q();
  pm::lab::ArmCameraSource cameras(scene, rig(), arm, arm.fMh() * vpHomogeneousMatrix(0, 0, 0.5, 0, 0, 0), 30, 0);
  pm::hand::PassRecording rec;
  int asked = 0;
  rec.ask = [&](const std::string &) {
    ++asked;
    cameras.setTargetPresent(false);
  };
  const std::vector<pm::model::PassView> views = pm::hand::recordPass(arm, cameras, plan, rec);
  const pm::lab::LabPass lab = pm::lab::runLabPass(scene, rig(), plan, labArm);
  ASSERT_EQ(views.size(), lab.views.size());
  EXPECT_EQ(asked, 1);
  EXPECT_EQ(cameras.stats().pairs, static_cast<long>(2 * views.size() * (rec.settlePairs + 1)));
  for (std::size_t k = 0; k < views.size(); ++k) {
    EXPECT_EQ(views[k].name, lab.views[k].name);
    EXPECT_LT(mm(lab.views[k].fMh.inverse() * views[k].fMh), 1e-6) << k;
    EXPECT_LT(deg(lab.views[k].fMh.inverse() * views[k].fMh), 1e-6) << k;
    // The target in view, then gone from the same pose (the crab is red on a blue sea).
    EXPECT_GT(centreDifference(views[k].left, views[k].backgroundLeft), 20) << k;
    EXPECT_LT(centreDifference(lab.views[k].backgroundLeft, views[k].backgroundLeft), 10) << k;
  }
  for (unsigned i = 0; i < 6; ++i)
    EXPECT_EQ(arm.q()[i], q0[i]); // back where it started
  // Out of reach (the crab 3 m ahead of the Afma6: the ring is beyond its slides): the view and the
  // joint named before the arm moves or a pair is taken.
  pm::robot::SteppedArm afma6(pm::robot::makeArmModel("afma6"));
  pm::lab::ArmCameraSource far(scene, rig(), afma6, afma6.fMh() * vpHomogeneousMatrix(0, 0, 3, 0, 0, 0), 30, 0);
  plan.distanceMm = 3000;
  const vpColVector a0 = afma6.q();
  const std::string e = errorOf([&] { pm::hand::recordPass(afma6, far, plan, rec); });
  EXPECT_NE(e.find("view 01 of the pass"), std::string::npos) << e;
  EXPECT_NE(e.find("limits"), std::string::npos) << e;
  EXPECT_EQ(afma6.q(), a0);
  EXPECT_EQ(far.stats().pairs, 0);
  // Backgrounds asked for with no one to remove the target: refused before anything moves.
  rec.ask = nullptr;
  plan.distanceMm = 500;
  EXPECT_NE(errorOf([&] { pm::hand::recordPass(afma6, far, plan, rec); }).find("remove the target"), std::string::npos);
  EXPECT_EQ(far.stats().pairs, 0);
}

TEST(HandLoop, KeepsAMovingTargetWhereItWasFirstFoundAndHoldsTheArmUntilThen)
{
  // The Viper850's own all-around model of the crab, the crab then moving in front of the hand
  // (50 mm across, 40 mm up and 60 mm nearer, back), the arm servoed from its own cameras.
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  const pm::sim::SimulatedPhotoModel sm = pm::lab::makeSimulatedAllAroundModel(scene, rig(), pm::model::PassPlan(), "viper850");
  pm::robot::SteppedArm arm(pm::robot::makeArmModel("viper850"));
  const vpColVector q0 = arm.q();
  const vpHomogeneousMatrix fMh0 = arm.fMh();
  const pm::sim::Trajectory steps({{0, 0, 500, 0, 0, 0}, {50, 0, 500, 0, 0, 0}, {50, -40, 440, 0, 0, 0}, {0, 0, 500, 0, 0, 0}},
                                  1.5, 1.5);
  pm::lab::ArmCameraSource cameras(scene, rig(), arm, [&](double t) { return fMh0 * pm::core::toHomogeneousMatrix(steps.at(t)); },
                                   30, static_cast<long>(steps.duration() * 30) + 1);
  pm::hand::HandLoop loop(rig(), sm.build.model, pm::tracker::TrackerParams(), pm::servo::ServoParams(), pm::hand::GuardParams(), cameras, arm);
  loop.keepWhereFound();
  pm::hand::HandFrame f;
  long frames = 0, servoed = 0, found = -1;
  double travel = 0;
  vpHomogeneousMatrix hMmTrue;
  while (true) {
    hMmTrue = cameras.hMo() * sm.oMm;
    if (!loop.step(f))
      break;
    ++frames;
    if (f.tookDesired) {
      found = frames - 1;
      EXPECT_LT(mm(hMmTrue.inverse() * loop.desired()), 2.0); // kept where it truly was
      EXPECT_LT(deg(hMmTrue.inverse() * loop.desired()), 1.0);
    }
    if (found < 0) {
      EXPECT_EQ(f.command.qdot.frobeniusNorm(), 0.0) << "frame " << frames - 1 << ": moved before the target was found";
    }
    servoed += f.command.servoing ? 1 : 0;
    travel = std::max(travel, (f.q - q0).infinityNorm());
  }
  ASSERT_GE(found, 0);
  EXPECT_LT(found, 30); // within a second, with no initial pose
  EXPECT_GT(travel, 0.05); // the arm followed
  EXPECT_GT(static_cast<double>(servoed), 0.95 * static_cast<double>(frames - found));
  // The crab back and still for 1.5 s: the hand keeps it where it was found.
  EXPECT_LT(mm(loop.desired().inverse() * hMmTrue), 2.0);
  EXPECT_LT(deg(loop.desired().inverse() * hMmTrue), 1.0);
  EXPECT_EQ(arm.commanded().frobeniusNorm(), 0.0); // the cameras ended: stopped
}
