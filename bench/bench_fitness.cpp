//! pm-bench: the stereo fitness (Eqs. 8-11), RM-GA's own work, the smooth gradient, the peer written with ViSP's types, the four fitness maps.
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

void runFitness(benchmark::State &state, const pm::core::PhotoModel &model, bool scalar, bool smooth = false)
{
  pm::core::StereoFitness fit(setup().rig, model);
  fit.useScalarKernel(scalar);
  fit.setImages(setup().images.left, setup().images.right);
  const auto ps = poses(256);
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    sink += smooth ? fit.evaluateSmooth(ps[i++ & 255]) : fit.evaluate(ps[i++ & 255]);
    benchmark::DoNotOptimize(sink);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["points"] = static_cast<double>(model.size());
  state.counters["stereo_evals_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["ns_per_point"] = benchmark::Counter(static_cast<double>(state.iterations() * model.size() * 2),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(smooth ? "smooth (bilinear, scalar)" : scalar ? "scalar" : fit.kernelName());
}

void Fitness_DefaultModel(benchmark::State &s) { runFitness(s, setup().model, false); }

//! One RM-GA generation's batch (18 children) of the default model, on two cores through
//! pm::core::BatchPool as the tracker runs it; wall time, to compare with 18 x Fitness_DefaultModel.
void generationBatch(benchmark::State &state, bool stereoVisibility)
{
  pm::core::FitnessParams fp;
  fp.stereoVisibility = stereoVisibility;
  pm::core::StereoFitness fit(setup().rig, setup().model, fp);
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
  state.SetLabel(pm::core::BatchPool::shared().hasHelper() ? "two cores" : "one core");
}
void Fitness_DefaultModel_GenerationBatch(benchmark::State &s) { generationBatch(s, true); }
//! Its peer: the same batch with the paper's fitness, each camera alone (no stereo visibility, issue 43).
void Fitness_DefaultModel_GenerationBatch_PaperFitness(benchmark::State &s) { generationBatch(s, false); }
/*!
  The same batch scored on the first quarter of the model's points only (StereoFitness::evaluate
  with an unreachable threshold: every pose rejected after its first share), as the coarse search
  and early rejection score a pose; compare with Fitness_DefaultModel_GenerationBatch.
*/
void Fitness_DefaultModel_GenerationBatch_Coarse(benchmark::State &state)
{
  pm::core::StereoFitness fit(setup().rig, setup().model);
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
  struct Free : pm::rmga::FitnessFunction
  {
    void evaluate(const pm::core::Phi *p, std::size_t n, double *f) override
    {
      for (std::size_t i = 0; i < n; ++i)
        f[i] = -std::fabs(p[i].x) - std::fabs(p[i].z - 500);
    }
  } f;
  pm::rmga::RmGa ga{pm::rmga::SearchSpace(), pm::rmga::RmGaParams()};
  long poses = 0;
  for (auto _ : state)
    poses += ga.evolve(f, pm::rmga::FrameBudget::evals(1000)).candidates;
  state.SetItemsProcessed(poses);
  state.counters["ns_per_pose"] = benchmark::Counter(static_cast<double>(poses), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
//! The smooth ascent's evaluation of the default model: the smooth score and its gradient (two cores), with and without the metric.
void smoothGradient(benchmark::State &state, bool metric)
{
  pm::core::StereoFitness fit(setup().rig, setup().model);
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
  const pm::core::PhotoModel &m = S.model1000;
  pm::core::StereoFitness fit(S.rig, m); // for its hue planes only
  fit.setImages(S.images.left, S.images.right);
  const vpHomogeneousMatrix cMh[2] = {S.rig.left.cMh(), S.rig.right.cMh()};
  const vpCameraParameters cams[2] = {S.rig.left.cam, S.rig.right.cam};
  const auto ps = poses(256);
  const float hB = m.backgroundHue;
  std::size_t i = 0;
  double sink = 0;
  for (auto _ : state) {
    const pm::core::Phi &phi = ps[i++ & 255];
    vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(phi);
    double F = 0;
    for (int c = 0; c < 2; ++c) {
      const vpHomogeneousMatrix cMo = cMh[c] * hMo;
      const pm::core::HuePlane &plane = fit.huePlane(c);
      double sum = 0;
      for (std::size_t k = 0; k < m.size(); ++k) {
        const pm::core::ModelPoint &p = k < m.inner.size() ? m.inner[k] : m.outer[k - m.inner.size()];
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
          sum += pm::core::hueDistance(h, p.hue) <= 30 ? 2.0 : (pm::core::hueDistance(h, hB) <= 30 ? -0.005 : 0.0);
        else
          sum += pm::core::hueDistance(h, hB) <= 20 ? 0.1 : -0.5;
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

//! The paper's four fitness maps (x-y, y-z, eps1-eps2, eps2-eps3) of the default model, on all cores.
void FitnessMaps_FourGrids(benchmark::State &state)
{
  pm::core::StereoFitness fit(setup().rig, setup().model);
  fit.setImages(setup().images.left, setup().images.right);
  std::size_t evals = 0;
  for (auto _ : state)
    for (const auto &spec : pm::core::paperFitnessMaps()) {
      const pm::core::FitnessMap m = pm::core::computeFitnessMap(fit, setup().truth, spec);
      evals += m.values.size();
      benchmark::DoNotOptimize(m.maxFitness);
    }
  state.counters["evaluations"] = static_cast<double>(evals / state.iterations());
}

} // namespace

BENCHMARK(Fitness_DefaultModel);
BENCHMARK(Fitness_DefaultModel_GenerationBatch)->UseRealTime();
BENCHMARK(Fitness_DefaultModel_GenerationBatch_PaperFitness)->UseRealTime();
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
BENCHMARK(FitnessMaps_FourGrids)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
