// TrackConfidence: the logistic model over the tracker's cues that says whether a frame's estimate
// can be trusted (the servo acts on trusted estimates only). Its coefficients are fitted by
// pm-confidence (test_compare.cpp runs it); here, the model itself and the shipped coefficients'
// directions, which the trust analysis relies on (docs/trust.md).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pm/core/Error.h"
#include "pm/tracker/TrackConfidence.h"

namespace {

/*!
  A frame the tracker is sure of: tracked a second, verified, fitting in both cameras (q, the worse
  camera's q, S_in on the hue, S_out on the background), above its rivals by \e margin, still.
*/
pm::tracker::ConfidenceCues goodFrame(double q = 0.8, double qMin = 0.75, double inMatch = 0.8, double outBackground = 0.9, double margin = 0.3)
{
  pm::tracker::ConfidenceCues c;
  c.quality = q;
  c.qualityMin = qMin;
  c.inMatchMin = inMatch;
  c.outBackgroundMin = outBackground;
  c.tiltDeg = 3;
  c.competitorMargin = margin;
  c.qualityDrop = 0;
  c.jumpMm = 0.5;
  c.jumpDeg = 0.2;
  c.framesTracked = 30;
  c.verified = true;
  c.tracking = true;
  return c;
}

} // namespace

TEST(TrackConfidence, TheFeaturesAreTheCuesScaledAsDocumented)
{
  pm::tracker::ConfidenceCues c = goodFrame();
  c.tiltDeg = 25;
  c.jumpMm = std::exp(2.0) - 1;
  c.jumpDeg = -3;          // a negative jump counts as none
  c.qualityDrop = -0.1;    // as does a negative drop
  c.framesTracked = 90;    // capped at 30
  const auto x = c.features();
  ASSERT_EQ(x.size(), pm::tracker::ConfidenceCues::kFeatures);
  ASSERT_EQ(pm::tracker::ConfidenceCues::featureNames().size(), pm::tracker::ConfidenceCues::kFeatures);
  EXPECT_DOUBLE_EQ(x[0], 0.8);
  EXPECT_DOUBLE_EQ(x[4], 2.5);            // tilt / 10
  EXPECT_DOUBLE_EQ(x[6], 0.0);            // max(0, drop)
  EXPECT_NEAR(x[7], 2.0, 1e-12);          // log1p(jump mm)
  EXPECT_DOUBLE_EQ(x[8], 0.0);
  EXPECT_DOUBLE_EQ(x[9], 1.0);            // min(frames, 30) / 30
  EXPECT_DOUBLE_EQ(x[10], 1.0);
  EXPECT_DOUBLE_EQ(x[11], 1.0);
  EXPECT_STREQ(pm::tracker::ConfidenceCues::featureNames()[4], "tilt_deg_10");
}

TEST(TrackConfidence, IsTheLogisticOfTheWeightedFeatures)
{
  pm::tracker::ConfidenceModel m;
  m.weights.fill(0);
  m.bias = 0;
  const pm::tracker::ConfidenceCues c = goodFrame();
  EXPECT_DOUBLE_EQ(m.confidence(c), 0.5); // no evidence either way
  m.weights[0] = 2.0;
  m.bias = -1.0;
  EXPECT_NEAR(m.confidence(c), 1.0 / (1.0 + std::exp(-(2.0 * 0.8 - 1.0))), 1e-12);
}

TEST(TrackConfidence, TheShippedModelTrustsASureFrameAndDoubtsWhatShouldBeDoubted)
{
  const pm::tracker::ConfidenceModel m;
  EXPECT_NO_THROW(m.validate());
  const double sure = m.confidence(goodFrame());
  EXPECT_GE(sure, m.threshold);
  // Each of these, alone, must lower the confidence of the same frame.
  struct Change
  {
    const char *what;
    void (*apply)(pm::tracker::ConfidenceCues &);
  };
  const Change doubts[] = {
      {"a lower fitness", [](pm::tracker::ConfidenceCues &c) { c.quality = c.qualityMin = 0.4; }},
      {"a pose that fits one camera only", [](pm::tracker::ConfidenceCues &c) { c.qualityMin = 0.2; }},
      {"S_in off the model's hue", [](pm::tracker::ConfidenceCues &c) { c.inMatchMin = 0.3; }},
      {"a competitor as good (a near-symmetric outline)", [](pm::tracker::ConfidenceCues &c) { c.competitorMargin = 0; }},
      {"a steep tilt (the flat model's relief bias)", [](pm::tracker::ConfidenceCues &c) { c.tiltDeg = 40; }},
      {"a fall of the fitness", [](pm::tracker::ConfidenceCues &c) { c.qualityDrop = 0.3; }},
      {"a jump of 50 mm", [](pm::tracker::ConfidenceCues &c) { c.jumpMm = 50; }},
      {"a jump of 20 deg", [](pm::tracker::ConfidenceCues &c) { c.jumpDeg = 20; }},
      {"a lock not yet verified", [](pm::tracker::ConfidenceCues &c) { c.verified = false; }},
      {"a lock of one frame", [](pm::tracker::ConfidenceCues &c) { c.framesTracked = 1; }},
      {"no lock at all", [](pm::tracker::ConfidenceCues &c) { c.tracking = false; }},
  };
  for (const Change &d : doubts) {
    pm::tracker::ConfidenceCues c = goodFrame();
    d.apply(c);
    EXPECT_LT(m.confidence(c), sure) << d.what;
  }
  // A frame with every doubt at once is far from trusted.
  pm::tracker::ConfidenceCues bad = goodFrame();
  for (const Change &d : doubts)
    d.apply(bad);
  EXPECT_LT(m.confidence(bad), 0.05);
}

TEST(TrackConfidence, ACoefficientThatIsNotFiniteOrAThresholdOutsideTheOpenIntervalIsRefused)
{
  pm::tracker::ConfidenceModel m;
  m.weights[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(m.validate(), pm::core::Error);
  m = pm::tracker::ConfidenceModel();
  m.bias = std::numeric_limits<double>::infinity();
  EXPECT_THROW(m.validate(), pm::core::Error);
  for (double t : {0.0, 1.0, -0.5, 2.0}) {
    m = pm::tracker::ConfidenceModel();
    m.threshold = t;
    EXPECT_THROW(m.validate(), pm::core::Error) << t;
  }
}

TEST(TrackConfidence, TheAllAroundModelTrustsASurePreciseFrameAndDoubtsWhatThePreciseStageDoubts)
{
  // The all-around model's coefficients weigh the precise stage's cues: a frame the stage pins well
  // and fits well is trusted; each doubt, alone, lowers its confidence; the tilt weighs nothing.
  const pm::tracker::ConfidenceModel m = pm::tracker::ConfidenceModel::shipped(pm::tracker::ConfidenceKind::AllAround);
  EXPECT_NO_THROW(m.validate());
  // The median cues of the crab's trusted frames in pm-confidence --all-around.
  pm::tracker::ConfidenceCues sure = goodFrame(0.975, 0.97, 0.97, 1.0, 0.39);
  sure.precise = true;
  sure.preciseResidualPx = 0.57;
  sure.preciseSigmaMm = 0.2;
  sure.preciseSigmaDeg = 0.28;
  sure.separation = 0.9;
  sure.cameraDisagreementPx = 0.12;
  const double c = m.confidence(sure);
  EXPECT_GE(c, m.threshold);
  struct Change
  {
    const char *what;
    void (*apply)(pm::tracker::ConfidenceCues &);
  };
  const Change doubts[] = {
      {"the outline found 3 px from the model's", [](pm::tracker::ConfidenceCues &x) { x.preciseResidualPx = 3; }},
      {"lines that pin the position to 3 mm only", [](pm::tracker::ConfidenceCues &x) { x.preciseSigmaMm = 3; }},
      {"colours that do not split along the lines", [](pm::tracker::ConfidenceCues &x) { x.separation = 0.3; }},
      {"S_out off the background", [](pm::tracker::ConfidenceCues &x) { x.outBackgroundMin = 0.6; }},
      {"a competitor as good", [](pm::tracker::ConfidenceCues &x) { x.competitorMargin = 0; }},
      {"a lock not yet verified", [](pm::tracker::ConfidenceCues &x) { x.verified = false; }},
  };
  for (const Change &d : doubts) {
    pm::tracker::ConfidenceCues x = sure;
    d.apply(x);
    EXPECT_LT(m.confidence(x), c) << d.what;
  }
  pm::tracker::ConfidenceCues tilted = sure;
  tilted.tiltDeg = 60;
  EXPECT_DOUBLE_EQ(m.confidence(tilted), c); // a model that knows the relief is not doubted for a tilt
}
