#include "pm/tracker/StaticDetection.h"

#include <chrono>

#include "pm/rmga/RmGa.h"
#include "pm/rmga/StereoObjective.h"

namespace pm::tracker {

Detection detectStatic(PhotoModelTracker &tracker, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right,
                       const DetectionParams &params)
{
  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  Detection d;
  double bestF = -1e300;
  int sinceBest = 0;
  TrackResult last;
  while (seconds() < params.maxTimeS) {
    const TrackResult r = tracker.track(left, right);
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
  rmga::StereoObjective obj(fitness);
  rmga::RmGaParams gp;
  gp.population = 2;
  gp.elite = 1;
  gp.refineEvaluations = 5000;
  rmga::RmGa ga(space, gp);
  ga.seedAround(start, 0.0);
  return ga.evolve(obj, rmga::FrameBudget::evals(2 + gp.refineEvaluations)).best;
}

} // namespace pm::tracker
