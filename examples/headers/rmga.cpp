// The usage examples of pm::rmga's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/rmga/RmGa.h"

#include "pm/rmga/SmoothAscent.h"
#include "pm/rmga/StereoObjective.h"
namespace pm_examples {

// What an example leaves to its reader (declared, never defined: this file is compiled, never linked).
void use(const pm::core::Phi &pose);

// RmGa.h
void exampleRmGa2(pm::rmga::RmGa &ga, const pm::core::Phi &lastTrusted)
{
  ga.setAnchor(lastTrusted); // a lost target is searched for near where it was last seen too
  ga.restart(1);
}

// RmGa.h
void exampleRmGa3(pm::rmga::RmGa &ga, const pm::core::Phi &refused)
{
  ga.avoid(refused, 20, 20, 15); // not there again for half a second
  ga.scatter(0, 0);
}

// SmoothAscent.h
void exampleSmoothAscent(const pm::core::StereoFitness &fitness, const pm::core::Phi &gaBest, const pm::core::Phi &lastPose)
{
  pm::rmga::StereoObjective f(fitness);
  const pm::core::Phi starts[2] = {gaBest, lastPose};
  const pm::rmga::SmoothAscentResult r = pm::rmga::climbSmooth(f, starts, 2, pm::rmga::SmoothAscentParams());
  use(r.best); // r.score >= the best start's
}

// StereoObjective.h
void exampleStereoObjective(const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame, pm::rmga::RmGa &ga)
{
  pm::rmga::StereoObjective f(scorer, frame);                               // F on this frame, for RM-GA
  const pm::rmga::FrameResult r = ga.evolve(f, pm::rmga::FrameBudget::evals(1900));
  const pm::rmga::SmoothAscentResult a = pm::rmga::climbSmooth(f, &r.best, 1, pm::rmga::SmoothAscentParams());
}

} // namespace pm_examples
