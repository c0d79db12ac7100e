//! pm-bench: speed of the hot path, with Google Benchmark, against ViSP doing the same work in the same process.
#include <array>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpMeterPixelConversion.h>

#include "pm/app/App.h"
#include "pm/app/Options.h"
#include "pm/core/BatchPool.h"
#include "pm/core/FitnessMap.h"
#include "pm/core/Hue.h"
#include "pm/core/StereoFitness.h"
#include "pm/core/UndistortMap.h"
#include "pm/rmga/RmGa.h"
#include "pm/io/RigFile.h"
#include "pm/lab/SimulatedCalibration.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/sim/TargetCatalog.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace {

//! The C12 crab at the true pose, its photo-model and the stereo pair, made once.
struct Setup
{
  pm::StereoRig rig;
  pm::PhotoModel model, model1000, model1000Depth;
  pm::sim::StereoImages images;
  pm::Phi truth;        //!< the model's pose (what the tracker estimates) ...
  vpHomogeneousMatrix hMo; //!< ... of the toy at this pose

  Setup()
  {
    rig = pm::io::loadRig(pm::app::dataPath("rig/pa10_stereo.json"));
    const pm::sim::Scene scene(pm::sim::makeTarget("C12"));
    hMo = pm::toHomogeneousMatrix({0, 0, 500, 0, 0, 0});
    const auto sm = pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, 640, 480, 500);
    model = sm.build.model;
    truth = sm.truth(hMo);
    // A 1,000-point model: the crab sampled more densely, thinned to exactly 1,000 points.
    pm::PhotoModelParams dense;
    dense.stepPx = 5;
    const pm::PhotoModel d = pm::sim::makeSimulatedPhotoModel(scene, rig.left.cam, 640, 480, 500, dense).build.model;
    model1000 = d;
    const std::size_t nIn = 1000 * d.inner.size() / d.size(), nOut = 1000 - nIn;
    model1000.inner.clear();
    model1000.outer.clear();
    for (std::size_t i = 0; i < nIn; ++i)
      model1000.inner.push_back(d.inner[i * d.inner.size() / nIn]);
    for (std::size_t i = 0; i < nOut; ++i)
      model1000.outer.push_back(d.outer[i * d.outer.size() / nOut]);
    // The same 1,000 points with a relief (a dome 30 mm high): the 3-D kernel, same point count.
    model1000Depth = model1000;
    for (auto *set : {&model1000Depth.inner, &model1000Depth.outer})
      for (pm::ModelPoint &p : *set)
        p.z = -30.f * std::max(0.05f, 1.f - (p.x * p.x + p.y * p.y) / (90.f * 90.f));
    images = scene.renderStereo(rig, hMo, 0);
  }
};

const Setup &setup()
{
  static const Setup s;
  return s;
}

//! Poses around the truth, as a GA population sees them.
std::vector<pm::Phi> poses(std::size_t n)
{
  std::vector<pm::Phi> v;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = static_cast<double>(i);
    v.push_back({10 * std::sin(k), 10 * std::cos(1.3 * k), 500 + 20 * std::sin(0.7 * k), 0.05 * std::sin(2.1 * k),
                 0.05 * std::cos(1.7 * k), 0.05 * std::sin(0.3 * k)});
  }
  return v;
}

void runFitness(benchmark::State &state, const pm::PhotoModel &model, bool scalar, bool smooth = false)
{
  pm::StereoFitness::forceScalar(scalar);
  pm::StereoFitness fit(setup().rig, model);
  fit.setImages(setup().images.left, setup().images.right);
  const auto ps = poses(256);
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    sink += smooth ? fit.evaluateSmooth(ps[i++ & 255]) : fit.evaluate(ps[i++ & 255]);
    benchmark::DoNotOptimize(sink);
  }
  pm::StereoFitness::forceScalar(false);
  state.SetItemsProcessed(state.iterations());
  state.counters["points"] = static_cast<double>(model.size());
  state.counters["stereo_evals_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["ns_per_point"] = benchmark::Counter(static_cast<double>(state.iterations() * model.size() * 2),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(smooth ? "smooth (bilinear, scalar)" : scalar ? "scalar" : pm::StereoFitness::kernelName());
}

void Fitness_DefaultModel(benchmark::State &s) { runFitness(s, setup().model, false); }

//! One RM-GA generation's batch (18 children) of the default model, on two cores through
//! pm::BatchPool as the tracker runs it; wall time, to compare with 18 x Fitness_DefaultModel.
void Fitness_DefaultModel_GenerationBatch(benchmark::State &state)
{
  pm::StereoFitness fit(setup().rig, setup().model);
  fit.setImages(setup().images.left, setup().images.right);
  const auto ps = poses(18);
  std::vector<double> out(ps.size());
  for (auto _ : state) {
    fit.evaluate(ps.data(), ps.size(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(ps.size()));
  state.counters["stereo_evals_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations() * static_cast<long>(ps.size())), benchmark::Counter::kIsRate);
  state.SetLabel(pm::BatchPool::shared().hasHelper() ? "two cores" : "one core");
}
/*!
  The same batch scored on the first quarter of the model's points only (StereoFitness::evaluate
  with an unreachable threshold: every pose rejected after its first share), as the coarse search
  and early rejection score a pose; compare with Fitness_DefaultModel_GenerationBatch.
*/
void Fitness_DefaultModel_GenerationBatch_Coarse(benchmark::State &state)
{
  pm::StereoFitness fit(setup().rig, setup().model);
  fit.setImages(setup().images.left, setup().images.right);
  const auto ps = poses(18);
  std::vector<double> out(ps.size()), cost(ps.size());
  for (auto _ : state) {
    fit.evaluate(ps.data(), ps.size(), out.data(), 1e300, cost.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(ps.size()));
  state.counters["cost_per_pose"] = cost[0];
}
//! RM-GA's own work per scored pose (selection, crossover, mutation, decoding, survival), on a fitness that costs nothing.
void RmGa_OwnWork(benchmark::State &state)
{
  struct Free : pm::FitnessFunction
  {
    void evaluate(const pm::Phi *p, std::size_t n, double *f) override
    {
      for (std::size_t i = 0; i < n; ++i)
        f[i] = -std::fabs(p[i].x) - std::fabs(p[i].z - 500);
    }
  } f;
  pm::RmGa ga{pm::SearchSpace(), pm::RmGaParams()};
  long poses = 0;
  for (auto _ : state)
    poses += ga.evolve(f, pm::FrameBudget::evals(1000)).candidates;
  state.SetItemsProcessed(poses);
  state.counters["ns_per_pose"] = benchmark::Counter(static_cast<double>(poses), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
//! The smooth ascent's evaluation of the default model: the smooth score and its gradient (two cores), with and without the metric.
void smoothGradient(benchmark::State &state, bool metric)
{
  pm::StereoFitness fit(setup().rig, setup().model);
  fit.setImages(setup().images.left, setup().images.right);
  const auto ps = poses(256);
  std::size_t i = 0;
  double g[6], M[36], sink = 0;
  for (auto _ : state) {
    sink += fit.evaluateSmoothGradient(ps[i++ & 255], g, metric ? M : nullptr);
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(state.iterations());
}
void Fitness_DefaultModel_SmoothGradient(benchmark::State &s) { smoothGradient(s, false); }
void Fitness_DefaultModel_SmoothGradient_Metric(benchmark::State &s) { smoothGradient(s, true); }
void Fitness_1000Points(benchmark::State &s) { runFitness(s, setup().model1000, false); }
void Fitness_1000Points_Scalar(benchmark::State &s) { runFitness(s, setup().model1000, true); }
//! The same 1,000 points with depth (the stereo model's kernel): compare with Fitness_1000Points.
void Fitness_1000Points_Depth(benchmark::State &s) { runFitness(s, setup().model1000Depth, false); }
void Fitness_1000Points_Depth_Scalar(benchmark::State &s) { runFitness(s, setup().model1000Depth, true); }
//! The smooth score of the local refinement (StereoFitness::evaluateSmooth): its cost against F's.
void Fitness_1000Points_Depth_Smooth(benchmark::State &s) { runFitness(s, setup().model1000Depth, true, true); }

/*!
  The peer: the same stereo fitness of the 1,000-point model written with ViSP's own types, as a
  ViSP user would first write it (vpHomogeneousMatrix poses, vpColVector points,
  vpMeterPixelConversion), on the same hue planes and with the same scores.
*/
void Fitness_1000Points_ViSPTypes(benchmark::State &state)
{
  const Setup &S = setup();
  const pm::PhotoModel &m = S.model1000;
  pm::StereoFitness fit(S.rig, m); // for its hue planes only
  fit.setImages(S.images.left, S.images.right);
  const vpHomogeneousMatrix cMh[2] = {S.rig.left.cMh(), S.rig.right.cMh()};
  const vpCameraParameters cams[2] = {S.rig.left.cam, S.rig.right.cam};
  const auto ps = poses(256);
  const float hB = m.backgroundHue;
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const pm::Phi &phi = ps[i++ & 255];
    vpHomogeneousMatrix hMo = pm::toHomogeneousMatrix(phi);
    double F = 0;
    for (int c = 0; c < 2; ++c) {
      const vpHomogeneousMatrix cMo = cMh[c] * hMo;
      const pm::HuePlane &plane = fit.huePlane(c);
      double sum = 0;
      for (std::size_t k = 0; k < m.size(); ++k) {
        const pm::ModelPoint &p = k < m.inner.size() ? m.inner[k] : m.outer[k - m.inner.size()];
        vpColVector X(4);
        X[0] = p.x * 1e-3;
        X[1] = p.y * 1e-3;
        X[2] = 0;
        X[3] = 1;
        const vpColVector Xc = cMo * X;
        double u = 0, v = 0;
        vpMeterPixelConversion::convertPoint(cams[c], Xc[0] / Xc[2], Xc[1] / Xc[2], u, v);
        const long ui = std::lround(u), vi = std::lround(v);
        if (Xc[2] <= 0 || ui < 0 || vi < 0 || ui >= 640 || vi >= 480)
          continue;
        const float h = plane.at(static_cast<unsigned>(ui), static_cast<unsigned>(vi)) / 10.f;
        if (k < m.inner.size())
          sum += pm::hueDistance(h, p.hue) <= 30 ? 2.0 : (pm::hueDistance(h, hB) <= 30 ? -0.005 : 0.0);
        else
          sum += pm::hueDistance(h, hB) <= 20 ? 0.1 : -0.5;
      }
      F += 0.5 * sum / static_cast<double>(m.size());
    }
    sink += F;
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["points"] = static_cast<double>(m.size());
  state.counters["stereo_evals_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.SetLabel("ViSP types");
}

//! Hue planes of a stereo pair: ours against ViSP's vpImageConvert::RGBaToHSV (double precision).
void Hue_StereoPair_Ours(benchmark::State &state)
{
  pm::HuePlane a, b;
  for (auto _ : state) {
    a.compute(setup().images.left);
    b.compute(setup().images.right);
    benchmark::DoNotOptimize(a.data());
    benchmark::DoNotOptimize(b.data());
  }
  state.SetItemsProcessed(state.iterations() * 2 * 640 * 480);
}

void Hue_StereoPair_ViSP(benchmark::State &state)
{
  std::vector<double> h(640 * 480), s(640 * 480), v(640 * 480);
  for (auto _ : state) {
    for (const auto *I : {&setup().images.left, &setup().images.right}) {
      vpImageConvert::RGBaToHSV(reinterpret_cast<const unsigned char *>(I->bitmap), h.data(), s.data(), v.data(),
                                640 * 480);
      benchmark::DoNotOptimize(h.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * 2 * 640 * 480);
}

/*!
  The hue planes as the tracker computes them (StereoFitness::setImages, both cameras on two
  cores): of the whole images, and of a steady frame's windows (the model's footprint at the pose
  grown by the default margin, TrackerParams::steadyHueMarginPx).
*/
void hueAsTracked(benchmark::State &state, bool windows, bool fromMemory = false)
{
  // fromMemory: a new frame each time, as a camera delivers them (40 copies, more than the caches hold).
  std::vector<pm::sim::StereoImages> frames(fromMemory ? 40 : 1, setup().images);
  pm::StereoFitness fit(setup().rig, setup().model);
  const int margin = pm::TrackerParams().steadyHueMarginPx;
  std::array<pm::PixelRect, 2> w;
  long pixels = 0;
  for (int cam = 0; cam < 2; ++cam) {
    const pm::StereoFitness::Camera &c = fit.camera(cam);
    w[static_cast<std::size_t>(cam)] = windows ? fit.footprint(setup().truth, cam).grown(margin, c.width, c.height) : pm::PixelRect{0, 0, c.width, c.height};
    const pm::PixelRect &r = w[static_cast<std::size_t>(cam)];
    pixels += static_cast<long>(r.u1 - r.u0) * (r.v1 - r.v0);
  }
  std::size_t k = 0;
  for (auto _ : state) {
    const pm::sim::StereoImages &im = frames[k++ % frames.size()];
    fit.setImages(im.left, im.right, w);
    benchmark::DoNotOptimize(fit.huePlane(0).data());
  }
  state.SetItemsProcessed(state.iterations() * pixels);
  state.counters["pixels"] = static_cast<double>(pixels);
}
void Hue_StereoPair_AsTracked_WholeImages(benchmark::State &s) { hueAsTracked(s, false); }
void Hue_StereoPair_AsTracked_SteadyWindows(benchmark::State &s) { hueAsTracked(s, true); }
void Hue_StereoPair_AsTracked_SteadyWindows_NewFrames(benchmark::State &s) { hueAsTracked(s, true, true); }
void Hue_StereoPair_AsTracked_WholeImages_NewFrames(benchmark::State &s) { hueAsTracked(s, false, true); }

//! Hue computed at each sampled point instead of a plane: the cost per sample, to compare.
void Hue_PerSample(benchmark::State &state)
{
  const vpImage<vpRGBa> &I = setup().images.left;
  std::uint64_t k = 0;
  unsigned acc = 0;
  for (auto _ : state) {
    for (int j = 0; j < 1000; ++j, ++k)
      acc += pm::hueDeci(I.bitmap[(k * 2654435761u) % (640 * 480)], 0.f);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * 1000);
}

//! Hue planes of a stereo pair read through a lens: the raw planes, then one gather per pixel through the UndistortMap.
void Hue_StereoPair_Lens(benchmark::State &state)
{
  const pm::StereoRig rig = pm::lab::labRigWithLens(pm::LensDistortion{{-0.25, 0.08, 0.001, -0.0005, 0}});
  const pm::UndistortMap ml(rig.left), mr(rig.right);
  pm::HuePlane a, b;
  for (auto _ : state) {
    a.compute(setup().images.left, 0.f, ml);
    b.compute(setup().images.right, 0.f, mr);
    benchmark::DoNotOptimize(a.data());
    benchmark::DoNotOptimize(b.data());
  }
  state.SetItemsProcessed(state.iterations() * 2 * 640 * 480);
}

/*!
  The other way to honour a lens: distort every projected point in the kernels. Measured here on
  1,000 points (projection and pixel index, the part of an evaluation the lens would change), with
  and without OpenCV's five-coefficient model, scalar code the compiler vectorises alike.
*/
template <bool kLens>
void projectPoints(benchmark::State &state)
{
  const pm::PhotoModel &m = setup().model1000;
  std::vector<float> x, y, z;
  for (const auto *set : {&m.inner, &m.outer})
    for (const pm::ModelPoint &p : *set) {
      x.push_back(p.x);
      y.push_back(p.y);
      z.push_back(500.f + p.z);
    }
  const std::size_t n = x.size();
  std::vector<std::int32_t> idx(n);
  const float k1 = -0.25f, k2 = 0.08f, p1 = 0.001f, p2 = -0.0005f, k3 = 0.f, f = 754.f, u0 = 320.f, v0 = 240.f;
  for (auto _ : state) {
#pragma omp simd
    for (std::size_t i = 0; i < n; ++i) {
      float xn = x[i] / z[i], yn = y[i] / z[i];
      if (kLens) {
        const float r2 = xn * xn + yn * yn, rad = 1.f + r2 * (k1 + r2 * (k2 + r2 * k3));
        const float xd = xn * rad + 2.f * p1 * xn * yn + p2 * (r2 + 2.f * xn * xn);
        const float yd = yn * rad + p1 * (r2 + 2.f * yn * yn) + 2.f * p2 * xn * yn;
        xn = xd;
        yn = yd;
      }
      idx[i] = static_cast<std::int32_t>(f * yn + v0 + 0.5f) * 640 + static_cast<std::int32_t>(f * xn + u0 + 0.5f);
    }
    benchmark::DoNotOptimize(idx.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}
void Distortion_Project1000Points_Pinhole(benchmark::State &s) { projectPoints<false>(s); }
void Distortion_Project1000Points_Lens(benchmark::State &s) { projectPoints<true>(s); }

//! The paper's four fitness maps (x-y, y-z, eps1-eps2, eps2-eps3) of the default model, on all cores.
void FitnessMaps_FourGrids(benchmark::State &state)
{
  pm::StereoFitness fit(setup().rig, setup().model);
  fit.setImages(setup().images.left, setup().images.right);
  std::size_t evals = 0;
  for (auto _ : state)
    for (const auto &spec : pm::paperFitnessMaps()) {
      const pm::FitnessMap m = pm::computeFitnessMap(fit, setup().truth, spec);
      evals += m.values.size();
      benchmark::DoNotOptimize(m.maxFitness);
    }
  state.counters["evaluations"] = static_cast<double>(evals / state.iterations());
}

/*!
  Stages of a tracked frame, as pm-track runs it (the tracker's defaults: 800 evaluations, 15 %
  of them on a steady frame, the default C12 model): a frame with the whole budget (hue planes of
  both images, RM-GA's generations, the smooth ascent, the confidence's cues), a steady frame, the
  same steady frame with the hue of the whole images (its peer), a frame on which a new lock is
  verified; and the budget of before issue 18 (1,900 evaluations on every frame, RM-GA's own
  refinement of 100; the tracker's other parts as now), the peer of the whole frame.
*/
void trackerFrame(benchmark::State &state, double steadyFraction, bool verifying, int hueMarginPx = -1, bool before = false)
{
  pm::TrackerParams p = pm::TrackerParams();
  p.steadyBudgetFraction = steadyFraction;
  if (hueMarginPx >= 0)
    p.steadyHueMarginPx = hueMarginPx;
  if (before) {
    p.budgetEvaluations = 1900;
    p.ga.refineEvaluations = 100;
    p.verifyEvaluations = 6000;
  }
  pm::PhotoModelTracker tracker(setup().rig, setup().model, p);
  const vpHomogeneousMatrix hMo = pm::toHomogeneousMatrix(setup().truth);
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
    const pm::TrackResult r = tracker.track(setup().images.left, setup().images.right);
    evaluations += r.evaluations;
    ++frames;
    benchmark::DoNotOptimize(r.fitness);
  }
  state.counters["evaluations"] = static_cast<double>(evaluations) / static_cast<double>(std::max<long>(1, frames));
}
void Tracker_Frame_Whole(benchmark::State &s) { trackerFrame(s, 1.0, false); }
void Tracker_Frame_Steady(benchmark::State &s) { trackerFrame(s, pm::TrackerParams().steadyBudgetFraction, false); }
//! Its peer: the same steady frame with the hue of the whole images (TrackerParams::steadyHueMarginPx 0).
void Tracker_Frame_Steady_WholeImages(benchmark::State &s) { trackerFrame(s, pm::TrackerParams().steadyBudgetFraction, false, 0); }
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

BENCHMARK(Fitness_DefaultModel);
BENCHMARK(Fitness_DefaultModel_GenerationBatch)->UseRealTime();
BENCHMARK(Fitness_DefaultModel_GenerationBatch_Coarse)->UseRealTime();
BENCHMARK(RmGa_OwnWork);
BENCHMARK(Fitness_DefaultModel_SmoothGradient)->UseRealTime();
BENCHMARK(Fitness_DefaultModel_SmoothGradient_Metric)->UseRealTime();
BENCHMARK(Fitness_1000Points);
BENCHMARK(Fitness_1000Points_Scalar);
BENCHMARK(Fitness_1000Points_Depth);
BENCHMARK(Fitness_1000Points_Depth_Scalar);
BENCHMARK(Fitness_1000Points_Depth_Smooth);
BENCHMARK(Fitness_1000Points_ViSPTypes);
BENCHMARK(Hue_StereoPair_Ours)->Unit(benchmark::kMillisecond);
BENCHMARK(Hue_StereoPair_ViSP)->Unit(benchmark::kMillisecond);
BENCHMARK(Hue_StereoPair_AsTracked_WholeImages)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hue_StereoPair_AsTracked_SteadyWindows)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hue_StereoPair_AsTracked_WholeImages_NewFrames)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hue_StereoPair_AsTracked_SteadyWindows_NewFrames)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hue_PerSample);
BENCHMARK(Hue_StereoPair_Lens)->Unit(benchmark::kMillisecond);
BENCHMARK(Distortion_Project1000Points_Pinhole);
BENCHMARK(Distortion_Project1000Points_Lens);
BENCHMARK(FitnessMaps_FourGrids)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(Tracker_Frame_Whole)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Steady_WholeImages)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Verifying)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Tracker_Frame_Before_1900Evals)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Render_StereoPair)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char **argv)
{
  // pm-bench [suite] [Google Benchmark flags]; the suite "fitness" runs the fitness and hue benchmarks.
  std::vector<char *> args{argv[0]};
  std::string filter = "--benchmark_filter=.";
  std::string format = "--benchmark_format=json";
  int i = 1;
  if (argc > 1 && argv[1][0] != '-') {
    const std::string suite = argv[1];
    if (suite == "fitness")
      filter = "--benchmark_filter=^(Fitness|Hue)";
    else {
      std::cerr << "pm-bench: usage error: unknown suite '" << suite << "' (known: fitness) (see --help)" << std::endl;
      return 2;
    }
    i = 2;
  }
  for (int k = 1; k < argc; ++k)
    if (!std::strcmp(argv[k], "--help") || !std::strcmp(argv[k], "-h")) {
      std::cout << "usage: pm-bench [fitness] [Google Benchmark flags, e.g. --benchmark_filter=REGEX "
                   "--benchmark_repetitions=N]\n"
                   "Prints JSON (Google Benchmark's format) on stdout: stereo fitness evaluations per second on one core "
                   "for the default C12 model and a 1,000-point model (AVX2 and scalar kernels, and the same fitness "
                   "written with ViSP's types as the peer), hue planes against vpImageConvert::RGBaToHSV, the four "
                   "fitness maps on all cores, the stages of a tracked frame (hue planes as tracked, a generation of "
                   "evaluations exact and coarse, the smooth ascent's gradient, RM-GA's own work; whole, steady, steady on "
                   "the whole images as the peer of the steady frame's hue windows, verifying a lock, and the 1,900 "
                   "evaluations of before issue 18 as the whole frame's peer) and the lab's renderer (a stereo pair).\n";
      return 0;
    }
  args.push_back(filter.data());
  args.push_back(format.data());
  for (; i < argc; ++i)
    args.push_back(argv[i]);
  int n = static_cast<int>(args.size());
  try {
    benchmark::Initialize(&n, args.data());
    if (benchmark::ReportUnrecognizedArguments(n, args.data()))
      return 2;
    setup(); // build the scene before timing; errors surface here
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
  } catch (const std::exception &e) {
    std::cerr << "error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
