//! pm-bench: the stages of a tracked frame, and the lab's renderer.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpMeterPixelConversion.h>

#include "pm/core/BatchPool.h"
#include "pm/core/FitnessMap.h"
#include "pm/core/Hue.h"
#include "pm/core/StereoFitness.h"
#include "pm/core/UndistortMap.h"
#include "pm/lab/SimulatedCalibration.h"
#include "pm/rmga/RmGa.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/PhotoModelTracker.h"

#include <benchmark/benchmark.h>

#include "BenchSetup.h"

namespace {

using pm::bench::poses;
using pm::bench::Setup;
using pm::bench::setup;

/*!
  Stages of a tracked frame, as pm-track runs it (the tracker's defaults: 800 evaluations, 15 %
  of them on a steady frame, the default C12 model): a frame with the whole budget (hue planes of
  both images, RM-GA's generations, the smooth ascent, the confidence's cues), a steady frame, the
  same steady frame with the hue of the whole images (its peer), a frame on which a new lock is
  verified; and the budget of before issue 18 (1,900 evaluations on every frame, RM-GA's own
  refinement of 100; the tracker's other parts as now), the peer of the whole frame.
*/
void trackerFrame(benchmark::State &state, double steadyFraction, bool verifying, int hueMarginPx = -1, bool before = false,
                  bool stereoVisibility = true)
{
  pm::tracker::TrackerParams p = pm::tracker::TrackerParams();
  p.fitness.stereoVisibility = stereoVisibility;
  p.steady.budgetFraction = steadyFraction;
  if (hueMarginPx >= 0)
    p.steady.hueMarginPx = hueMarginPx;
  if (before) {
    p.search.budgetEvaluations = 1900;
    p.verifier.evaluations = 6000;
  }
  pm::tracker::PhotoModelTracker tracker(setup().rig, setup().model, p);
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(setup().truth);
  long evaluations = 0, frames = 0;
  for (auto _ : state) {
    state.PauseTiming();
    if (verifying) { // a first lock from no pose: the timed frame verifies it
      tracker.initialize();
      tracker.track(setup().images.left, setup().images.right);
    } else if (frames == 0) {
      tracker.initFromPose(hMo); // a verified lock: the timed frames track
    }
    state.ResumeTiming();
    const pm::tracker::TrackResult r = tracker.track(setup().images.left, setup().images.right);
    evaluations += r.evaluations;
    ++frames;
    benchmark::DoNotOptimize(r.fitness);
  }
  state.counters["evaluations"] = static_cast<double>(evaluations) / static_cast<double>(std::max<long>(1, frames));
}
void Tracker_Frame_Whole(benchmark::State &s) { trackerFrame(s, 1.0, false); }
void Tracker_Frame_Steady(benchmark::State &s) { trackerFrame(s, pm::tracker::TrackerParams().steady.budgetFraction, false); }
//! Its peer for the stereo visibility (issue 43): the same steady frame with the paper's fitness, each camera alone.
void Tracker_Frame_Steady_PaperFitness(benchmark::State &s)
{
  trackerFrame(s, pm::tracker::TrackerParams().steady.budgetFraction, false, -1, false, false);
}
//! Its peer: the same steady frame with the hue of the whole images (SteadyParams::hueMarginPx 0).
void Tracker_Frame_Steady_WholeImages(benchmark::State &s) { trackerFrame(s, pm::tracker::TrackerParams().steady.budgetFraction, false, 0); }
void Tracker_Frame_Verifying(benchmark::State &s) { trackerFrame(s, 1.0, true); }
//! The whole frame's peer: the budget of before issue 18 (1,900 evaluations, refinement 100), the rest as now.
void Tracker_Frame_Before_1900Evals(benchmark::State &s) { trackerFrame(s, 1.0, false, -1, true); }

//! The lab's renderer: a stereo pair of the C12 crab (supersampling 2, the default).
void Render_StereoPair(benchmark::State &state)
{
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
  std::uint64_t k = 0;
  for (auto _ : state) {
    const pm::sim::StereoImages im = scene.renderStereo(setup().rig, setup().hMo, k++);
    benchmark::DoNotOptimize(im.left.bitmap);
  }
}

} // namespace

BENCHMARK(Tracker_Frame_Whole)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady_PaperFitness)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady_WholeImages)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Verifying)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Before_1900Evals)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Render_StereoPair)->Unit(benchmark::kMillisecond)->UseRealTime();
