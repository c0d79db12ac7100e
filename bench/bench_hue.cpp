//! pm-bench: hue planes (ours against ViSP's RGBaToHSV, as tracked, through a lens) and projecting through a lens.
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

//! Hue planes of a stereo pair: ours against ViSP's vpImageConvert::RGBaToHSV (double precision).
void Hue_StereoPair_Ours(benchmark::State &state)
{
  pm::core::HuePlane a, b;
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
  grown by the default margin, SteadyParams::hueMarginPx).
*/
void hueAsTracked(benchmark::State &state, bool windows, bool fromMemory = false)
{
  // fromMemory: a new frame each time, as a camera delivers them (40 copies, more than the caches hold).
  std::vector<pm::sim::StereoImages> frames(fromMemory ? 40 : 1, setup().images);
  pm::core::StereoFitness fit(setup().rig, setup().model);
  const int margin = pm::tracker::TrackerParams().steady.hueMarginPx;
  std::array<pm::core::PixelRect, 2> w;
  long pixels = 0;
  for (int cam = 0; cam < 2; ++cam) {
    const pm::core::PinholeCamera::Projection &c = fit.camera(cam);
    w[static_cast<std::size_t>(cam)] = windows ? fit.footprint(setup().truth, cam).grown(margin, c.w, c.h) : pm::core::PixelRect{0, 0, c.w, c.h};
    const pm::core::PixelRect &r = w[static_cast<std::size_t>(cam)];
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
      acc += pm::core::hueDeci(I.bitmap[(k * 2654435761u) % (640 * 480)], 0.f);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * 1000);
}

//! Hue planes of a stereo pair read through a lens: the raw planes, then one gather per pixel through the UndistortMap.
void Hue_StereoPair_Lens(benchmark::State &state)
{
  const pm::core::StereoRig rig = pm::lab::labRigWithLens(pm::core::LensDistortion{{-0.25, 0.08, 0.001, -0.0005, 0}});
  const pm::core::UndistortMap ml(rig.left), mr(rig.right);
  pm::core::HuePlane a, b;
  for (auto _ : state) {
    a.compute(setup().images.left, 0.f, ml);
    b.compute(setup().images.right, 0.f, mr);
    benchmark::DoNotOptimize(a.data());
    benchmark::DoNotOptimize(b.data());
  }
  state.SetItemsProcessed(state.iterations() * 2 * 640 * 480);
}

//! One camera's image resampled bilinearly through its lens into the ideal image (UndistortMap::undistort, cv::remap): what the precise stage reads.
void Undistort_Image_Lens(benchmark::State &state)
{
  const pm::core::StereoRig rig = pm::lab::labRigWithLens(pm::core::LensDistortion{{-0.25, 0.08, 0.001, -0.0005, 0}});
  const pm::core::UndistortMap ml(rig.left);
  vpImage<vpRGBa> ideal;
  for (auto _ : state) {
    ml.undistort(setup().images.left, ideal);
    benchmark::DoNotOptimize(ideal.bitmap);
  }
  state.SetItemsProcessed(state.iterations() * 640 * 480);
}

/*!
  The other way to honour a lens: distort every projected point in the kernels. Measured here on
  1,000 points (projection and pixel index, the part of an evaluation the lens would change), with
  and without OpenCV's five-coefficient model, scalar code the compiler vectorises alike.
*/
template <bool kLens>
void projectPoints(benchmark::State &state)
{
  const pm::core::PhotoModel &m = setup().model1000;
  std::vector<float> x, y, z;
  for (const auto *set : {&m.inner, &m.outer})
    for (const pm::core::ModelPoint &p : *set) {
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

} // namespace

BENCHMARK(Hue_StereoPair_Ours)->Unit(benchmark::kMillisecond);
BENCHMARK(Hue_StereoPair_ViSP)->Unit(benchmark::kMillisecond);
BENCHMARK(Hue_StereoPair_AsTracked_WholeImages)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hue_StereoPair_AsTracked_SteadyWindows)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hue_StereoPair_AsTracked_WholeImages_NewFrames)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hue_StereoPair_AsTracked_SteadyWindows_NewFrames)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hue_PerSample);
BENCHMARK(Hue_StereoPair_Lens)->Unit(benchmark::kMillisecond);
BENCHMARK(Undistort_Image_Lens)->Unit(benchmark::kMillisecond);
BENCHMARK(Distortion_Project1000Points_Pinhole);
BENCHMARK(Distortion_Project1000Points_Lens);
