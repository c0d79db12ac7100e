#include "pm/tracker/StaticDetection.h"

#include <chrono>

#include <cmath>
#include <cstdint>

#include "pm/rmga/RmGa.h"

namespace pm::tracker {

Detection detectStatic(PhotoModelTracker &tracker, const core::CameraImages &images, const DetectionParams &params)
{
  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  Detection d;
  double bestF = -1e300;
  int sinceBest = 0;
  TrackResult last;
  while (seconds() < params.maxTimeS) {
    const TrackResult r = tracker.track(images);
    last = r;
    ++d.frames;
    d.totalEvaluations += r.evaluations;
    if (r.fitness > bestF) {
      bestF = r.fitness;
      d.best = r;
      d.convergedS = seconds();
      d.evaluations = d.totalEvaluations;
      sinceBest = 0;
    } else if (++sinceBest >= params.patience && d.best.state == TrackState::Tracking) {
      break;
    }
  }
  // The precise stage lands on the outline's peak, which F (flat there) does not rank: once
  // converged, the last frame's pose is the detection when the stage gave it.
  if (last.state == TrackState::Tracking && last.precise)
    d.best = last;
  d.totalS = seconds();
  return d;
}

core::Phi nearestFitnessPeak(const core::StereoFitness &fitness, const core::Phi &start, const rmga::SearchSpace &space)
{
  // A pattern search on RM-GA's genes (its grid of poses): +-step on each variable, the first gain
  // taken, the step halved from 16 genes to 1 when nothing gains, 5,000 evaluations at most.
  constexpr int kEvaluations = 5000;
  auto score = [&](const rmga::Genome &g) {
    const core::Phi phi = rmga::decode(g, space);
    double F = 0;
    fitness.evaluate(&phi, 1, &F);
    return std::isfinite(F) ? F : -1e300;
  };
  rmga::Genome best = rmga::encode(space.clamp(start), space);
  double bestF = score(best);
  int used = 0;
  for (int step = 16; step >= 1 && used < kEvaluations; step /= 2) {
    bool improved = true;
    while (improved && used < kEvaluations) {
      improved = false;
      for (std::size_t i = 0; i < 6 && used < kEvaluations; ++i)
        for (int dir : {1, -1}) {
          if (used >= kEvaluations)
            break;
          rmga::Genome g = best;
          const int v = static_cast<int>(g.gene[i]) + dir * step;
          if (v < 0 || v > rmga::Genome::kMax)
            continue;
          g.gene[i] = static_cast<std::uint16_t>(v);
          const double F = score(g);
          ++used;
          if (F > bestF) {
            best = g;
            bestF = F;
            improved = true;
            break;
          }
        }
    }
  }
  return rmga::decode(best, space);
}

} // namespace pm::tracker
