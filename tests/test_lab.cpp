// The lab's runners: one convergence rule, the tracking report against hand-computed figures,
// the simulator as a source of stereo pairs, the sine fit of the frequency response and the
// closed loop's table; pm-render's pictures of targets; and the one percentile every program reports.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "pm/robot/Pa10Model.h"
#include "pm/core/Error.h"
#include "pm/core/Statistics.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"
#include "pm/lab/Convergence.h"
#include "pm/lab/FrequencyResponse.h"
#include "pm/lab/LabSequence.h"
#include "pm/lab/LoopTable.h"
#include "pm/lab/TargetRendering.h"
#include "pm/lab/TrackingReport.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetCatalog.h"

using pm::test::errorOf;
using pm::test::TempDir;

TEST(Statistics, MedianIsTheMiddleOrTheMeanOfTheTwoMiddleValues)
{
  EXPECT_EQ(pm::core::median({5, 1, 4, 2, 3}), 3);
  EXPECT_EQ(pm::core::median({4, 1, 3, 2}), 2.5);
  EXPECT_EQ(pm::core::median({-7}), -7);
  EXPECT_EQ(pm::core::median({}), 0);
}

TEST(Statistics, PercentileIsTheNearestRank)
{
  const std::vector<double> v{5, 1, 4, 2, 3};
  EXPECT_EQ(pm::core::percentile(v, 0.99), 5);
  EXPECT_EQ(pm::core::percentile(v, 1.0), 5);
  EXPECT_EQ(pm::core::percentile(v, 0.5), 3); // ceil(2.5) = 3rd smallest
  EXPECT_EQ(pm::core::percentile(v, 0.2), 1);
  EXPECT_EQ(pm::core::percentile(v, 0.21), 2);
  std::vector<double> hundred;
  for (int i = 100; i >= 1; --i)
    hundred.push_back(i);
  EXPECT_EQ(pm::core::percentile(hundred, 0.99), 99); // the p99 of 1..100
  EXPECT_EQ(pm::core::percentile({}, 0.99), 0);
  EXPECT_NE(errorOf([] { pm::core::percentile({1.0}, 0.0); }).find("(0, 1]"), std::string::npos);
  EXPECT_NE(errorOf([] { pm::core::percentile({1.0}, 1.5); }).find("(0, 1]"), std::string::npos);
}

TEST(Convergence, TheFirstFrameOfAFullRunWithinTheBounds)
{
  // window 3: a run of two is not enough; the run from frame 4 is.
  const bool within[] = {false, true, true, false, true, true, true, false, true};
  pm::lab::Convergence c(3);
  std::vector<long> starts;
  for (long k = 0; k < 9; ++k)
    if (c.add(k, 0.5 * static_cast<double>(k), within[k]))
      starts.push_back(k);
  c.finish();
  EXPECT_TRUE(c.converged());
  EXPECT_EQ(c.frame(), 4);
  EXPECT_DOUBLE_EQ(c.time(), 2.0);
  EXPECT_EQ(starts, (std::vector<long>{1, 4})); // runs start there; after convergence nothing does

  pm::lab::Convergence end(5); // a run that reaches the end of the record counts
  for (long k = 0; k < 4; ++k)
    end.add(k, static_cast<double>(k), k >= 2);
  EXPECT_FALSE(end.converged());
  end.finish();
  EXPECT_EQ(end.frame(), 2);

  pm::lab::Convergence never(2);
  for (long k = 0; k < 10; ++k)
    never.add(k, static_cast<double>(k), k % 2 == 0);
  never.finish();
  EXPECT_FALSE(never.converged());
  EXPECT_EQ(never.frame(), -1);
  EXPECT_LT(never.time(), 0);
  EXPECT_NE(errorOf([] { pm::lab::Convergence(0); }).find("at least one frame"), std::string::npos);
}

namespace {

pm::lab::TrackedFrame frameAt(double t, const pm::core::Phi &truth, const pm::core::Phi &estimate, bool moving)
{
  pm::lab::TrackedFrame f;
  f.t = t;
  f.haveTruth = true;
  f.truth = truth;
  f.moving = moving;
  f.result.phi = estimate;
  f.result.state = pm::tracker::TrackState::Tracking;
  f.result.computeMs = 1.0;
  f.result.evaluations = 800;
  return f;
}

} // namespace

TEST(TrackingReport, FiguresAfterConvergenceAsComputedByHand)
{
  // 60 frames at 30 fps: 10 frames 100 mm off (searching), then x off by 1 mm at rest and 3 mm
  // while moving (frames 30..44), and one frame turned 3 deg (beyond 2 deg) before convergence.
  std::vector<pm::lab::TrackedFrame> frames;
  const pm::core::Phi truth{0, 0, 500, 0, 0, 0};
  for (int k = 0; k < 60; ++k) {
    const double t = k / 30.0;
    const bool moving = k >= 30 && k < 45;
    pm::core::Phi est = truth;
    if (k < 10)
      est.x = 100;
    else
      est.x = moving ? 3 : 1;
    if (k == 12)
      est.e1 = std::sin(1.5 * M_PI / 180); // a 3 deg turn about x
    frames.push_back(frameAt(t, truth, est, moving));
    if (k < 10)
      frames.back().result.state = pm::tracker::TrackState::Searching;
    frames.back().result.computeMs = k == 59 ? 9.0 : 1.0;
  }
  const pm::lab::TrackingReport r = pm::lab::reportTracking(frames, 30.0, pm::lab::table2Goals());
  EXPECT_EQ(r.convergedFrame, 13); // frames 10, 11 start a run that frame 12 breaks
  EXPECT_DOUBLE_EQ(r.convergedS, 13 / 30.0);
  ASSERT_TRUE(r.haveTruth);
  const pm::lab::AxisErrors &x = r.errors[0];
  EXPECT_EQ(x.frames, 47u);
  EXPECT_NEAR(x.rms, std::sqrt((32 * 1.0 + 15 * 9.0) / 47), 1e-12);
  EXPECT_DOUBLE_EQ(x.max, 3);
  EXPECT_DOUBLE_EQ(x.maxMoving, 3);
  EXPECT_DOUBLE_EQ(x.maxAtRest, 1);
  EXPECT_DOUBLE_EQ(x.goal, 5);
  EXPECT_DOUBLE_EQ(r.errors[1].max, 0);
  EXPECT_TRUE(r.goalsMet);
  EXPECT_DOUBLE_EQ(r.meanMs, (59 * 1.0 + 9.0) / 60);
  EXPECT_DOUBLE_EQ(r.p99Ms, 9.0);
  EXPECT_DOUBLE_EQ(r.meanEvaluations, 800);
  EXPECT_EQ(r.states.at("searching"), 10);
  EXPECT_EQ(r.states.at("tracking"), 50);
  EXPECT_EQ(r.trustedFrames, 0);
  EXPECT_DOUBLE_EQ(r.trustedMaxMm, 0); // none trusted: nothing acted on
  {
    // Trusted from frame 10 on: the worst of them 3 mm off (moving) and 3 deg off (frame 12), each its own maximum;
    // the searching frames 100 mm off, untrusted, do not count.
    std::vector<pm::lab::TrackedFrame> some = frames;
    for (std::size_t k = 10; k < some.size(); ++k)
      some[k].result.trusted = true;
    const pm::lab::TrackingReport t = pm::lab::reportTracking(some, 30.0, pm::lab::table2Goals());
    EXPECT_NEAR(t.trustedMaxMm, 3.0, 1e-9);
    EXPECT_NEAR(t.trustedMaxDeg, 3.0, 1e-6);
    EXPECT_EQ(t.wrongTrusted, 0);
  }

  // A goal missed; and a run without truth converges on the tracker's state alone.
  std::array<double, 6> tight = pm::lab::table2Goals();
  tight[0] = 2;
  EXPECT_FALSE(pm::lab::reportTracking(frames, 30.0, tight).goalsMet);
  for (auto &f : frames)
    f.haveTruth = false;
  const pm::lab::TrackingReport blind = pm::lab::reportTracking(frames, 30.0, pm::lab::table2Goals());
  EXPECT_EQ(blind.convergedFrame, 10);
  EXPECT_FALSE(blind.haveTruth);
  EXPECT_FALSE(blind.goalsMet); // nothing to meet them with
  EXPECT_NE(errorOf([] { pm::lab::reportTracking({}, 30.0, pm::lab::table2Goals()); }).find("no frame"), std::string::npos);

  std::ostringstream csv;
  pm::lab::writeFramesCsv(csv, {frames.front()});
  const std::string text = csv.str();
  EXPECT_EQ(text.rfind("t,true_x,", 0), 0u);
  EXPECT_NE(text.find("\n0,nan,nan,nan,nan,nan,nan,100,0,500,0,0,0,nan,"), std::string::npos) << text;
  EXPECT_NE(text.find(",searching,800,"), std::string::npos) << text;
}

TEST(LabSequence, FramesAreTheSimulatorsAlongTheTrajectoryWithTheirTruth)
{
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  pm::sim::SceneParams sp;
  sp.supersampling = 1;
  const pm::sim::Scene scene(pm::sim::makeTarget("C05"), sp);
  const pm::sim::Trajectory trajectory({{0, 0, 500, 0, 0, 0}, {30, -20, 520, 0.05, 0, 0}}, 0.1, 0.2);
  const vpHomogeneousMatrix oMm(0.004, -0.002, 0.01, 0, 0, 0.1);
  pm::lab::LabSequence seq(scene, rig, trajectory, oMm, 10.0, 4);
  EXPECT_EQ(seq.length(), 4);
  EXPECT_NE(seq.describe().find("C05"), std::string::npos);
  pm::capture::StereoFrame f;
  for (long k = 0; k < 4; ++k) {
    ASSERT_TRUE(seq.next(f));
    EXPECT_EQ(f.index, k);
    EXPECT_DOUBLE_EQ(f.timeS, 0.1 * static_cast<double>(k));
    const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(trajectory.at(f.timeS));
    const pm::core::Phi expected = pm::core::fromHomogeneousMatrix(hMo * oMm);
    for (std::size_t i = 0; i < 6; ++i)
      EXPECT_NEAR(seq.truth(k)[i], expected[i], 1e-12) << k << " " << i;
    EXPECT_EQ(seq.moving(k), trajectory.moving(f.timeS));
    if (k == 2) { // the images are the scene's at that pose, with noise seed k
      const pm::sim::StereoImages im = scene.renderStereo(rig, hMo, 2);
      EXPECT_TRUE(f.left == im.left);
      EXPECT_TRUE(f.right == im.right);
    }
  }
  EXPECT_TRUE(seq.moving(2));
  EXPECT_FALSE(seq.moving(0));
  EXPECT_FALSE(seq.next(f));
  EXPECT_EQ(seq.stats().pairs, 4);
  EXPECT_NE(errorOf([&] { pm::lab::LabSequence(scene, rig, trajectory, oMm, 0.0, 4); }).find("frame rate"), std::string::npos);
}

TEST(FrequencyResponse, TheSineFitRecoversAmplitudeAndPhase)
{
  std::vector<double> t, y;
  for (int k = 0; k < 300; ++k) {
    t.push_back(k / 30.0);
    y.push_back(3.0 * std::sin(2 * M_PI * 0.5 * t.back() + 0.7) + 1.5 + 0.2 * std::sin(2 * M_PI * 2.0 * t.back()));
  }
  const auto [amplitude, phase] = pm::lab::sinusoidFit(t, y, 0.5);
  EXPECT_NEAR(amplitude, 3.0, 1e-3); // the 2 Hz component and the offset are not the 0.5 Hz one
  EXPECT_NEAR(phase, 0.7, 1e-3);
}

TEST(LoopTable, EveryRowHasTheHeadersColumns)
{
  std::ostringstream csv;
  pm::lab::writeLoopCsvHeader(csv);
  pm::lab::LoopFrame f;
  f.t = 0.5;
  f.q = pm::robot::Pa10Model().restJoints();
  f.qdot.resize(7);
  f.translationErrorMm = 1.25;
  pm::lab::writeLoopCsvRow(csv, f, true);
  std::istringstream lines(csv.str());
  std::string header, row;
  std::getline(lines, header);
  std::getline(lines, row);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), std::count(row.begin(), row.end(), ','));
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), 74); // 75 columns: 30, 6 sigmas, 18 cues, 7 steps' times and 14 joints
  EXPECT_NE(row.find(",1.25,"), std::string::npos) << row;
  EXPECT_NE(row.find(",oracle,"), std::string::npos) << row;
  EXPECT_NE(row.find(",,,,,,"), std::string::npos) << row; // an unknown uncertainty: six empty cells
  // A known uncertainty: its six sigmas under their headers.
  f.track.uncertainty.known = true;
  f.track.uncertainty.sigmaMm = {0.125, 0.25, 0.5};
  f.track.uncertainty.sigmaDeg = {0.375, 0.625, 0.875};
  std::ostringstream known;
  pm::lab::writeLoopCsvRow(known, f, true);
  const std::string k = known.str();
  const auto col = [&](const std::string &name) {
    const auto at = header.find(name);
    return at == std::string::npos ? -1 : static_cast<int>(std::count(header.begin(), header.begin() + static_cast<long>(at), ','));
  };
  const auto cell = [&](int c) {
    std::size_t b = 0;
    for (int i = 0; i < c; ++i)
      b = k.find(',', b) + 1;
    return k.substr(b, k.find(',', b) - b);
  };
  EXPECT_EQ(cell(col("sigma_x_mm")), "0.125");
  EXPECT_EQ(cell(col("sigma_rz_deg")), "0.875");
  f.track.visibleShare = 0.75; // the share of the model not hidden, under its header
  std::ostringstream seen;
  pm::lab::writeLoopCsvRow(seen, f, true);
  const std::string vs = seen.str();
  std::size_t b = 0;
  for (int i = 0; i < col("visible_share"); ++i)
    b = vs.find(',', b) + 1;
  EXPECT_EQ(vs.substr(b, vs.find(',', b) - b), "0.75");
  f.track.backgroundHueDeg = 212.5; // the background's hue the frame was scored with, under its header
  std::ostringstream hue;
  pm::lab::writeLoopCsvRow(hue, f, true);
  const std::string hs = hue.str();
  b = 0;
  for (int i = 0; i < col("background_hue_deg"); ++i)
    b = hs.find(',', b) + 1;
  EXPECT_EQ(hs.substr(b, hs.find(',', b) - b), "212.5");
  // Why the arm was held, and the cue's reading, under their headers.
  f.heldBy = "precise_residual_px";
  f.track.cues.precise = true;
  f.track.cues.preciseResidualPx = 1.75;
  std::ostringstream held;
  pm::lab::writeLoopCsvRow(held, f, true);
  const std::string hb = held.str();
  const auto cellOf = [&](const std::string &line, int c) {
    std::size_t at = 0;
    for (int i = 0; i < c; ++i)
      at = line.find(',', at) + 1;
    return line.substr(at, line.find(',', at) - at);
  };
  EXPECT_EQ(cellOf(hb, col(",held_by") + 1), "precise_residual_px");
  EXPECT_EQ(cellOf(hb, col(",cue_precise_residual_px") + 1), "1.75");
  // A 6-joint arm (ViSP's Viper850 and Afma6): 12 joint columns, and a row of its 6 joints fits them.
  std::ostringstream six;
  pm::lab::writeLoopCsvHeader(six, 6);
  f.q.resize(6);
  f.qdot.resize(6);
  pm::lab::writeLoopCsvRow(six, f, true);
  std::istringstream sixLines(six.str());
  std::getline(sixLines, header);
  std::getline(sixLines, row);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), 72);
  EXPECT_EQ(std::count(row.begin(), row.end(), ','), 72);
  EXPECT_EQ(header.find(",q7"), std::string::npos);
}

TEST(TargetRendering, TheReliefTurnsTheTimeIsTheMeanAndTheGalleryHoldsEveryTarget)
{
  const pm::core::StereoRig rig = pm::io::loadRig(pm::test::dataPath("rig/pa10_stereo.json"));
  const pm::core::Phi phi{0, 0, 500, 0, 0, 0};
  std::vector<pm::lab::RenderedTarget> targets;
  std::size_t steps = 0;
  for (const char *code : {"R2", "C01", "C12", "R1", "C05"}) {
    const pm::sim::TargetShape shape = pm::sim::makeTarget(code);
    targets.push_back(pm::lab::renderTarget(pm::sim::Scene(shape, pm::sim::SceneParams()), shape, rig, phi, 2, [&](std::size_t n) { steps += n; }));
  }
  EXPECT_EQ(steps, 5u * (2 + 2));
  const pm::lab::RenderedTarget &head = targets[0];
  EXPECT_EQ(head.code, "R2");
  EXPECT_GT(head.triangles, 0u);
  EXPECT_GT(head.renderStereoMs, 0.0);
  // The view at eps2 = 0 is the pose's own left view; turned either way, the toy looks different.
  const auto differing = [](const vpImage<vpRGBa> &a, const vpImage<vpRGBa> &b) {
    std::size_t n = 0;
    for (unsigned i = 0; i < a.getSize(); ++i)
      n += a.bitmap[i].R != b.bitmap[i].R || a.bitmap[i].G != b.bitmap[i].G || a.bitmap[i].B != b.bitmap[i].B ? 1 : 0;
    return n;
  };
  EXPECT_GT(differing(head.turned[0], head.turned[2]), 2000u);
  EXPECT_GT(differing(head.turned[0], head.turned[1]), 1000u);

  TempDir d("render");
  const double mean = pm::lab::writeRenderedTargets(d.file("r"), targets, phi, pm::sim::SceneParams(), true);
  double sum = 0;
  for (const auto &t : targets)
    sum += t.renderStereoMs;
  EXPECT_DOUBLE_EQ(mean, sum / 5);
  const vpImage<vpRGBa> gallery = pm::io::readColorImage(d.file("r/gallery.png"));
  EXPECT_EQ(gallery.getWidth(), 4 * (rig.left.width / 2));
  EXPECT_EQ(gallery.getHeight(), 2 * (rig.left.height / 2)); // five targets: two rows of four
  for (const char *f : {"R2_left.png", "C05_relief.png", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(d.file("r/") + f)) << f;
  EXPECT_THROW(pm::lab::writeRenderedTargets(d.file("none"), {}, phi, pm::sim::SceneParams(), false), pm::core::Error);
  EXPECT_FALSE(std::filesystem::exists(d.file("none")));
}
