//! pm-bench: the precise stage alone, and a tracked frame of the all-around model with and without it.
#include <benchmark/benchmark.h>

#include <array>
#include <map>
#include <string>

#include "pm/io/RigFile.h"
#include "pm/lab/LabModel.h"
#include "pm/precise/PreciseStage.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/PhotoModelTracker.h"

#include "BenchSetup.h"

namespace {

using pm::bench::setup;

//! The crab's all-around model (the lab's pass: about 6 s), its pair at a tilted pose and the truth, made on first use.
struct AllAround
{
  pm::sim::Scene scene{pm::sim::makeTarget("C12")};
  pm::sim::SimulatedPhotoModel model = pm::lab::makeLabModel(scene, setup().rig, pm::lab::LabModelChoice());
  vpHomogeneousMatrix hMo = vpHomogeneousMatrix(0.01, -0.005, 0.51, vpMath::rad(15), vpMath::rad(-10), 0);
  pm::sim::StereoImages images = scene.renderStereo(setup().rig, hMo, 0);
  pm::core::Phi truth = model.truth(hMo);
};
const AllAround &allAround()
{
  static const AllAround a;
  return a;
}

/*!
  PreciseStage::refine() from 1 mm and 1 deg off the truth (a tracked frame's start), on the crab's
  all-around model: the outline's lines in both cameras with the interior term, and without it (its peer).
*/
void preciseRefine(benchmark::State &state, bool interior)
{
  const AllAround &a = allAround();
  pm::precise::PreciseParams p;
  if (!interior)
    p.interiorPoints = 0;
  pm::precise::PreciseStage precise(setup().rig, a.model.build.model, p);
  precise.setImages({a.images.left, a.images.right});
  const double twist[6] = {0.6, -0.5, 0.6, 0.01, -0.01, 0.008};
  const pm::core::Phi start = pm::core::applyTwist(a.truth, twist);
  std::size_t lines = 0;
  for (auto _ : state) {
    const pm::precise::PreciseResult r = precise.refine(start);
    lines = r.totalLines();
    benchmark::DoNotOptimize(r.phi);
  }
  state.counters["lines"] = static_cast<double>(lines);
}
void Precise_Refine(benchmark::State &s) { preciseRefine(s, true); }
//! Its peer: the outline alone (PreciseParams::interiorPoints 0).
void Precise_Refine_OutlineOnly(benchmark::State &s) { preciseRefine(s, false); }

/*!
  PreciseStage::learnColours() at the truth (a trusted frame's apply step): the colours along the
  outline's lines of both cameras counted (up to 20 px on either side of each line), and the
  histograms blended.
*/
void Precise_LearnColours(benchmark::State &state)
{
  const AllAround &a = allAround();
  pm::precise::PreciseStage precise(setup().rig, a.model.build.model);
  precise.setImages({a.images.left, a.images.right});
  for (auto _ : state)
    precise.learnColours(a.truth);
  benchmark::DoNotOptimize(precise.colours().separation());
}

/*!
  A new frame's refine() through a lens (OpenCV's k1 -0.25 on both cameras, the images rendered
  through it): setImages() and refine(), which resamples the ideal image where the stage reads
  (IdealImage.h); its peer the same through the pinhole rig.
*/
void preciseRefineNewFrame(benchmark::State &state, bool lens)
{
  const AllAround &a = allAround();
  pm::core::StereoRig rig = setup().rig;
  if (lens)
    rig.left.distortion = rig.right.distortion = pm::core::LensDistortion{{-0.25, 0.08, 0.001, -0.0005, 0}};
  static std::map<bool, pm::sim::StereoImages> images;
  if (!images.count(lens))
    images[lens] = a.scene.renderStereo(rig, a.hMo, 0);
  pm::precise::PreciseStage precise(rig, a.model.build.model);
  const double twist[6] = {0.6, -0.5, 0.6, 0.01, -0.01, 0.008};
  const pm::core::Phi start = pm::core::applyTwist(a.truth, twist);
  for (auto _ : state) {
    precise.setImages({images[lens].left, images[lens].right});
    const pm::precise::PreciseResult r = precise.refine(start);
    benchmark::DoNotOptimize(r.phi);
  }
}
void Precise_Refine_NewFrame_Pinhole(benchmark::State &s) { preciseRefineNewFrame(s, false); }
void Precise_Refine_NewFrame_Lens(benchmark::State &s) { preciseRefineNewFrame(s, true); }

//! Adds \e r's steps' times to \e sum.
void addSteps(const pm::tracker::TrackResult &r, std::array<double, pm::tracker::StepTimes::kCount> &sum)
{
  const auto v = r.steps.values();
  for (std::size_t k = 0; k < v.size(); ++k)
    sum[k] += v[k];
}

//! Each step's mean time per frame (ms) as the benchmark's counters plan_ms ... apply_ms (the tracker's own clock: frames.csv's step_*_ms).
void stepCounters(benchmark::State &state, const std::array<double, pm::tracker::StepTimes::kCount> &sum)
{
  for (std::size_t k = 0; k < sum.size(); ++k)
    state.counters[std::string(pm::tracker::StepTimes::names()[k]) + "_ms"] = benchmark::Counter(sum[k], benchmark::Counter::kAvgIterations);
}

/*!
  A steady tracked frame of the all-around model (the tracker's defaults), with the precise stage, and
  its peers: without it, and without the background's learning (a trusted frame's S_out hues read).
  Each step's mean time per frame is a counter (plan_ms ... apply_ms): the parts of the frame, in the
  same run.
*/
void allAroundFrame(benchmark::State &state, bool precise, bool learnBackground = true, bool oneCamera = false)
{
  const AllAround &a = allAround();
  pm::tracker::TrackerParams p;
  p.refinement.precise.enabled = precise;
  p.background.learn = learnBackground;
  const pm::core::CameraRig rig = oneCamera ? pm::core::CameraRig(std::vector<pm::core::PinholeCamera>{setup().rig.left}) : pm::core::CameraRig(setup().rig);
  const pm::core::CameraImages images = oneCamera ? pm::core::CameraImages(a.images.left) : pm::core::CameraImages(a.images.left, a.images.right);
  pm::tracker::PhotoModelTracker tracker(rig, a.model.build.model, p);
  tracker.initFromPose(pm::core::toHomogeneousMatrix(a.truth));
  for (int k = 0; k < 5; ++k) // a few frames: steady
    tracker.track(images);
  std::array<double, pm::tracker::StepTimes::kCount> sum{};
  for (auto _ : state) {
    const pm::tracker::TrackResult r = tracker.track(images);
    addSteps(r, sum);
    benchmark::DoNotOptimize(r.fitness);
  }
  stepCounters(state, sum);
}

/*!
  A frame with the whole budget: the all-around tracker searching from scratch (initialize() before
  each, not timed), RM-GA's whole budget and the judgement of what it found; per step as above.
*/
void Tracker_Frame_WholeBudget_AllAround(benchmark::State &state)
{
  const AllAround &a = allAround();
  pm::tracker::PhotoModelTracker tracker(setup().rig, a.model.build.model);
  const pm::core::CameraImages images(a.images.left, a.images.right);
  std::array<double, pm::tracker::StepTimes::kCount> sum{};
  for (auto _ : state) {
    state.PauseTiming();
    tracker.initialize();
    state.ResumeTiming();
    const pm::tracker::TrackResult r = tracker.track(images);
    addSteps(r, sum);
    benchmark::DoNotOptimize(r.fitness);
  }
  stepCounters(state, sum);
}
void Tracker_Frame_Steady_AllAround(benchmark::State &s) { allAroundFrame(s, true); }
void Tracker_Frame_Steady_AllAround_NoPrecise(benchmark::State &s) { allAroundFrame(s, false); }
void Tracker_Frame_Steady_AllAround_NoBackgroundLearning(benchmark::State &s) { allAroundFrame(s, true, false); }
//! The same frame through the left camera alone (a one-camera rig, issue 58): its peer is Tracker_Frame_Steady_AllAround.
void Tracker_Frame_Steady_AllAround_OneCamera(benchmark::State &s) { allAroundFrame(s, true, true, true); }

} // namespace

BENCHMARK(Precise_Refine)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(Precise_Refine_OutlineOnly)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(Precise_LearnColours)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(Precise_Refine_NewFrame_Pinhole)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(Precise_Refine_NewFrame_Lens)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady_AllAround)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady_AllAround_NoPrecise)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady_AllAround_NoBackgroundLearning)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady_AllAround_OneCamera)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_WholeBudget_AllAround)->Unit(benchmark::kMillisecond)->UseRealTime();
