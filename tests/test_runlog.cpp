// RunLog: the online figures of a closed-loop run equal those computed from the whole record,
// and its memory does not grow with the run.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "pm/robot/Pa10Model.h"
#include "pm/lab/RunLog.h"
#include "pm/lab/RunSummary.h"

#include <nlohmann/json.hpp>

namespace {

using pm::lab::LoopFrame;

//! A synthetic run: errors large for \e settle frames, then small with rare spikes; moving in blocks.
std::vector<LoopFrame> syntheticRun(long n, long settle, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<LoopFrame> run;
  for (long k = 0; k < n; ++k) {
    LoopFrame f;
    f.t = static_cast<double>(k) / 30.0;
    f.moving = (k / 45) % 2 == 1;
    const bool spike = u(rng) < 0.01;
    f.translationErrorMm = k < settle ? 20 + 30 * u(rng) : (spike ? 12 + 40 * u(rng) : 8 * u(rng));
    f.rotationErrorDeg = k < settle ? 3 + 5 * u(rng) : (spike ? 2.5 : 1.5 * u(rng));
    f.q = pm::robot::Pa10Model().restJoints();
    f.qdot.resize(7);
    for (unsigned i = 0; i < 7; ++i)
      f.qdot[i] = 0.5 * (u(rng) - 0.5);
    f.track.computeMs = 1 + u(rng);
    run.push_back(f);
  }
  return run;
}

//! The batch rule: the first frame from which 30 frames in a row (1 s) stay within 10 mm and 2 deg.
long batchConvergence(const std::vector<LoopFrame> &run)
{
  for (std::size_t k = 0; k < run.size(); ++k) {
    bool ok = true;
    for (std::size_t j = k; j < std::min(run.size(), k + 30) && ok; ++j)
      ok = run[j].translationErrorMm <= 10 && run[j].rotationErrorDeg <= 2;
    if (ok)
      return static_cast<long>(k);
  }
  return -1;
}

} // namespace

TEST(RunLog, OnlineFiguresEqualTheBatchOnes)
{
  const pm::robot::Pa10Model robot;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const std::vector<LoopFrame> run = syntheticRun(3000, 100 * seed, seed);
    pm::lab::RunLog log(static_cast<long>(run.size()), 30, robot, 500);
    for (const auto &f : run)
      log.add(f);
    log.finish();

    const long c = batchConvergence(run);
    ASSERT_GE(c, 0) << "seed " << seed;
    ASSERT_TRUE(log.converged());
    EXPECT_DOUBLE_EQ(log.convergedAfterS(), run[static_cast<std::size_t>(c)].t) << "seed " << seed;
    double s2 = 0, mx = 0, r2 = 0, rmx = 0, sumMs = 0;
    std::size_t n = 0;
    for (std::size_t k = static_cast<std::size_t>(c); k < run.size(); ++k)
      if (run[k].moving) {
        s2 += run[k].translationErrorMm * run[k].translationErrorMm;
        mx = std::max(mx, run[k].translationErrorMm);
        r2 += run[k].rotationErrorDeg * run[k].rotationErrorDeg;
        rmx = std::max(rmx, run[k].rotationErrorDeg);
        ++n;
      }
    for (const auto &f : run)
      sumMs += f.track.computeMs;
    EXPECT_EQ(log.moving().frames, n);
    EXPECT_NEAR(log.moving().rmsMm(), std::sqrt(s2 / static_cast<double>(n)), 1e-9);
    EXPECT_DOUBLE_EQ(log.moving().maxMm, mx);
    EXPECT_NEAR(log.moving().rmsDeg(), std::sqrt(r2 / static_cast<double>(n)), 1e-9);
    EXPECT_DOUBLE_EQ(log.moving().maxDeg, rmx);
    EXPECT_EQ(log.atRest().frames + log.moving().frames, run.size() - static_cast<std::size_t>(c));
    EXPECT_NEAR(log.meanComputeMs(), sumMs / static_cast<double>(run.size()), 1e-9);
    std::size_t inTenths = 0;
    for (const auto &t : log.tenths()) {
      EXPECT_EQ(t.frames, run.size() / 10);
      inTenths += t.frames;
    }
    EXPECT_EQ(inTenths, run.size());
    EXPECT_EQ(log.jointLimitViolations(), 0);
    EXPECT_LE(log.maxJointSpeedFraction(), 0.25 / robot.speedLimits().getMinValue() + 1e-12);
  }
}

TEST(RunLog, TheNearestTheTargetCameAndHowWellItWasSeenThere)
{
  // A grasp approach: 500 mm to 300 mm in 200 frames, then held 60; the estimate 0.5 mm off while
  // farther than 310 mm, 1.5 mm and 0.8 deg nearer, and one frame searching at 300 mm 40 mm off.
  const pm::robot::Pa10Model robot;
  pm::lab::RunLog log(261, 30, robot, 500);
  for (long k = 0; k < 261; ++k) {
    LoopFrame f;
    f.t = static_cast<double>(k) / 30.0;
    f.q = robot.restJoints();
    f.qdot.resize(7, 0.0);
    const double z = std::max(300.0, 500.0 - static_cast<double>(k));
    f.hMmTrue = vpHomogeneousMatrix(0, 0, 1e-3 * z, 0, 0, 0);
    f.track.state = k == 250 ? pm::tracker::TrackState::Searching : pm::tracker::TrackState::Tracking;
    f.estimateErrorMm = k == 250 ? 40 : (z >= 310 ? 0.5 : 1.5);
    f.estimateErrorDeg = z >= 310 ? 0.2 : 0.8;
    log.add(f);
  }
  log.finish();
  EXPECT_DOUBLE_EQ(log.nearestMm(), 300);
  const pm::lab::ErrorStats e = log.estimateNearest();
  EXPECT_EQ(e.frames, 60u + 10u - 1u); // held at 300 (the searching frame left out) and 309..301 on the way
  EXPECT_DOUBLE_EQ(e.maxMm, 1.5);
  EXPECT_DOUBLE_EQ(e.maxDeg, 0.8);
  EXPECT_EQ(log.estimateNearest(30).frames, e.frames + 20u); // 329..310 too
  EXPECT_DOUBLE_EQ(log.estimateNearest(30).maxMm, 1.5);
}

TEST(RunLog, NeverConvergedMeansTheWholeRun)
{
  const pm::robot::Pa10Model robot;
  std::vector<LoopFrame> run = syntheticRun(300, 300, 7); // never within the bounds
  pm::lab::RunLog log(300, 30, robot);
  for (const auto &f : run)
    log.add(f);
  log.finish();
  EXPECT_FALSE(log.converged());
  EXPECT_EQ(log.atRest().frames + log.moving().frames, run.size());
  // The tracker's estimate is measured from convergence on: none here, and the summary says so
  // rather than print an error of 0.00 mm, which would read as perfect.
  EXPECT_EQ(log.estimate().frames, 0u);
  const std::string text = pm::lab::runSummaryText(log, pm::lab::RunInfo());
  EXPECT_NE(text.find("the tracker's estimate: not measured"), std::string::npos) << text;
  EXPECT_EQ(text.find("the tracker's estimate: rms"), std::string::npos) << text;
  EXPECT_EQ(nlohmann::json::parse(pm::lab::runSummaryJson(log, pm::lab::RunInfo()))["estimate_error"]["frames"], 0);
}

TEST(RunLog, AConvergedRunSummarisesItsEstimate)
{
  const pm::robot::Pa10Model robot;
  std::vector<LoopFrame> run = syntheticRun(300, 30, 7);
  for (LoopFrame &f : run) {
    f.track.state = pm::tracker::TrackState::Tracking;
    f.estimateErrorMm = 0.5;
    f.estimateErrorDeg = 0.25;
  }
  pm::lab::RunLog log(300, 30, robot);
  for (const auto &f : run)
    log.add(f);
  log.finish();
  ASSERT_TRUE(log.converged());
  const std::string text = pm::lab::runSummaryText(log, pm::lab::RunInfo());
  EXPECT_NE(text.find("the tracker's estimate: rms 0.50 mm and 0.25 deg, max 0.50 mm and 0.25 deg"), std::string::npos) << text;
  const nlohmann::json j = nlohmann::json::parse(pm::lab::runSummaryJson(log, pm::lab::RunInfo()));
  EXPECT_GT(j["estimate_error"]["frames"].get<long>(), 0);
  EXPECT_LT(j["estimate_error"]["frames"].get<long>(), 300); // from convergence on, not the settling frames
}

TEST(RunLog, SamplesStayBoundedAndKeepThePeaks)
{
  const pm::robot::Pa10Model robot;
  const std::vector<LoopFrame> run = syntheticRun(100000, 50, 3);
  const double peak = std::max_element(run.begin(), run.end(), [](const LoopFrame &a, const LoopFrame &b) {
                        return a.translationErrorMm < b.translationErrorMm;
                      })->translationErrorMm;
  // As expected: 100,000 frames in at most 1,000 samples of 100 frames.
  pm::lab::RunLog log(100000, 30, robot, 1000);
  // Longer than announced: 100 times the expected frames still fit in twice the samples.
  pm::lab::RunLog longer(1000, 30, robot, 1000);
  for (const auto &f : run) {
    log.add(f);
    longer.add(f);
  }
  log.finish();
  longer.finish();
  EXPECT_EQ(log.samples().size(), 1000u);
  EXPECT_EQ(log.framesPerSample(), 100);
  EXPECT_LE(longer.samples().size(), 2000u);
  EXPECT_GE(longer.samples().size(), 500u);
  for (const auto *l : {&log, &longer}) {
    double sampledPeak = 0;
    for (const auto &s : l->samples())
      sampledPeak = std::max(sampledPeak, s.translationErrorMm);
    EXPECT_DOUBLE_EQ(sampledPeak, peak);
    EXPECT_DOUBLE_EQ(l->samples().front().t, 0.0);
    EXPECT_LT(l->samples().back().t, run.back().t + 1e-9);
  }
  EXPECT_EQ(longer.tenths()[9].frames, run.size() - 900);
}
