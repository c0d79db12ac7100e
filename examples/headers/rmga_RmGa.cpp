// The usage example of modules/rmga/include/pm/rmga/RmGa.h, a whole program (compiled, never linked).
#include <cmath>
#include <iostream>
#include <pm/rmga/RmGa.h>

// A stand-in for the stereo fitness (pm::rmga::StereoObjective): the nearer (10, -20, 500) mm, the better.
class Toy : public pm::rmga::FitnessFunction
{
public:
  void evaluate(const pm::core::Phi *poses, std::size_t n, double *fitness) override
  {
    for (std::size_t i = 0; i < n; ++i)
      fitness[i] = -(std::abs(poses[i].x - 10) + std::abs(poses[i].y + 20) + std::abs(poses[i].z - 500));
  }
};

int main()
{
  pm::rmga::RmGaParams params;
  params.predictMotion = true;      // options off by default
  params.restartGenerations = 30;
  pm::rmga::RmGa ga(pm::rmga::SearchSpace(), params); // the paper's search space; a random population
  Toy toy;
  for (int frame = 0; frame < 10; ++frame) {
    const pm::rmga::FrameResult r = ga.evolve(toy, pm::rmga::FrameBudget::evals(800));
    std::cout << r.best.toString() << " F " << r.fitness << " in " << r.generations << " generations\n";
  }
}
