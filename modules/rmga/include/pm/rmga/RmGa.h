#pragma once
/*!
  \file RmGa.h
  RM-GA, the real-time multi-step genetic algorithm of the paper (Sec. 3.6, Fig. 7): a small
  population of poses evolved a little on every frame and carried from frame to frame.

  Per frame, evolve():
   1. (the first frame) the population is random over the search space;
   2. [option] every individual is moved by the motion predicted from the last two frames,
     except that the last frame's best also stays where it was (in place of the worst);
   3. every individual is evaluated on the new frame;
   4-7. generations until the budget is spent: parents by tournament, single-point crossover of
        the 72-bit strings, bit-flip mutation; only the children are evaluated (the others'
        fitness on this frame is known); the best N of parents and children survive (elitism);
        [option] when the best has not improved for some generations, all but the best
        restart (see restart()); the best does not breed while the new ones search;
   8. the best individual is the pose of the frame.

  It knows nothing of images: it calls a FitnessFunction. Runs are reproducible from the
  seed; with an evaluation budget they are deterministic, with a time budget they depend on the
  machine's speed.
*/
#include <cstdint>
#include <functional>
#include <array>
#include <random>
#include <vector>

#include "pm/core/Pose.h"
#include "pm/rmga/SearchSpace.h"

namespace pm::rmga {

//! What RM-GA optimises: fitness of a batch of poses (higher is better).
class FitnessFunction
{
public:
  virtual ~FitnessFunction() = default;
  //! Writes the fitness of poses[0, n) into fitness[0, n) (higher is better). RM-GA passes valid poses only.
  virtual void evaluate(const core::Phi *poses, std::size_t n, double *fitness) = 0;
  /*!
    The same, except that a pose that will score under \e rejectBelow may be given an estimate
    under \e rejectBelow instead, at a part of the work: \e cost[i] is the share of a whole
    evaluation spent on pose i (1: scored exactly). RM-GA scores every pose through this: its
    children with the worst parent's fitness (a child under it cannot survive), the others with
    -1e300 (nothing to reject). A function may also score every pose by an estimate at a part of
    the work (a coarse search), saying so in \e cost. The default scores every pose exactly.
  */
  virtual void evaluateOrReject(const core::Phi *poses, std::size_t n, double rejectBelow, double *fitness, double *cost)
  {
    (void)rejectBelow;
    evaluate(poses, n, fitness);
    for (std::size_t i = 0; i < n; ++i)
      cost[i] = 1.0;
  }
};

/*!
  RM-GA's parameters: population, genetic operators, options and seed (the paper's values where
  it gives them). validate() checks them; RmGa's constructor calls it.
*/
struct RmGaParams
{
  int population = 20;          //!< individuals (the paper: 20)
  int elite = 2;                //!< best individuals always kept (at least 1)
  int tournament = 2;           //!< tournament size of parent selection
  double crossoverRate = 0.9;   //!< probability that two parents cross over
  double mutationPerBit = 2.0 / 72; //!< probability of flipping each of the 72 bits of a child
  bool predictMotion = false;   //!< option: move the population by the predicted motion on a new frame
  int restartGenerations = 0;   //!< option: restart all but the best after this many generations without gain (0: never)
  std::uint64_t seed = 1;        //!< seed of the random generator: the same seed, the same run (with an evaluation budget)

  //! Throws pm::core::Error naming the parameter out of range.
  void validate() const;
};

//! A frame's budget: a number of evaluations (deterministic) or milliseconds of wall time.
struct FrameBudget
{
  long evaluations = 0;    //!< > 0: exactly this many evaluations at most
  double milliseconds = 0; //!< > 0 (and no evaluations): stop the generations when this time is spent
  //! A budget of \e n evaluations.
  static FrameBudget evals(long n) { return {n, 0}; }
  //! A budget of \e t milliseconds of wall time.
  static FrameBudget ms(double t) { return {0, t}; }
};

//! One member of the population: its genes, the pose they decode to and its fitness.
struct Individual
{
  Genome genome;      //!< the 72-bit chromosome
  core::Phi phi;            //!< decode(genome): the pose it stands for (mm, quaternion vector part)
  double fitness = 0; //!< fitness at its last evaluation (-1e300 before the first, or when not finite)
};

//! What RmGa::evolve() found on a frame.
struct FrameResult
{
  core::Phi best;             //!< the best individual's pose: the pose of the frame
  double fitness = 0;   //!< its fitness (the FitnessFunction's value)
  long evaluations = 0; //!< the work, in whole evaluations (a child rejected early counts its share), rounded up
  long candidates = 0;  //!< poses scored, exactly or rejected early
  int generations = 0;  //!< generations run on the frame
  bool restarted = false; //!< a stagnant search restarted during the frame (RmGaParams::restartGenerations)
};

/*!
  The RM-GA optimiser (see the file's description for the steps of a frame). It keeps copies of
  its search space and parameters, and the population from one evolve() to the next; the
  FitnessFunction is only borrowed for the call. Not thread-safe.

  \code
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
  \endcode
*/
class RmGa
{
public:
  //! Copies and checks \e space and \e params (throws pm::core::Error if invalid); the population starts random (randomize()).
  RmGa(const SearchSpace &space, const RmGaParams &params);

  //! A new random population over the search space (step 1); forgets the motion.
  void randomize();
  //! A population around \e p: the first individual is p, the others p plus uniform noise of
  //! +-spread times each range (clamped). Forgets the motion.
  void seedAround(const core::Phi &p, double spread);
  /*!
    A restart: all but the best \e keep individuals are replaced, a sixth each by random ones,
    by the best's position with a random orientation, by the best's orientation with a random
    position, by the best plus noise of +-5 % of each range, by the best with its tilt mirrored
    (e1, e2 negated) and by the best facing the cameras (e1 = e2 = 0) (all random if keep is 0). The
    kept best stays in the population but is not chosen as a parent for the next \e isolate
    generations, so the new ones search on their own instead of collapsing onto it at once: a
    lock on a wrong pose (often right in position or in orientation only) is left this way.

    With an anchor (setAnchor(): a pose known to have been right not long ago, e.g. the
    tracker's last trusted one), two more blocks come from it: its orientation with a random
    position, and the anchor plus noise of +-14 % of each position range and +-10 % of each
    orientation range (the target may have moved while unseen); the six blocks above then share
    the rest (with keep 0, half are random and half from the anchor). The restarts of a stagnant
    search (RmGaParams::restartGenerations) use it too.
  */
  void restart(int keep = 1, int isolate = 0);
  /*!
    A global restart: all but the best \e keep individuals replaced by random ones (half of them
    from the anchor's two blocks when there is one), the kept ones apart from breeding for
    \e isolate generations: for a best known to be wrong, around which restart() would search.
  */
  void scatter(int keep, int isolate);
  /*!
    The anchor of the restarts (see restart()); transform() moves it with the population.
    \code
    ga.setAnchor(lastTrusted); // a lost target is searched for near where it was last seen too
    ga.restart(1);
    \endcode
  */
  void setAnchor(const core::Phi &p);
  //! Forgets the anchor: the restarts no longer search near it.
  void clearAnchor() { m_hasAnchor = false; }
  //! True when an anchor is set (setAnchor()).
  bool hasAnchor() const { return m_hasAnchor; }
  //! The anchor, clamped into the search space; meaningful when hasAnchor().
  const core::Phi &anchor() const { return m_anchor; }
  /*!
    Moves every individual (and the remembered best poses of the last frames, for the motion
    prediction) by \e f, e.g. when the frame they are expressed in moved: the tracker compensates
    the hand's own motion this way. The fitness values are kept until the next evaluation.
  */
  void transform(const std::function<core::Phi(const core::Phi &)> &f);
  /*!
    Puts \e p (clamped into the search space) in place of the weakest individual, with \e fitness
    on the current frame: a pose found by other means (the tracker's precise stage) joins the search,
    unless it lies where the search avoids (avoid()).
  */
  void inject(const core::Phi &p, double fitness);

  /*!
    A pose to stay away from: for the next \e frames frames (evolve() on a new frame), a candidate
    within \e mm and \e deg of \e p is not scored and cannot survive (it costs nothing of the
    budget): for a best known to be wrong, whose basin the population would fall back into however
    it is scattered. At most kMaxAvoided at once (a new one replaces the one nearest its end).
    transform() moves them with the population; randomize() forgets them.
    \code
    ga.avoid(refused, 20, 20, 15); // not there again for half a second
    ga.scatter(0, 0);
    \endcode
  */
  void avoid(const core::Phi &p, double mm, double deg, int frames);
  static constexpr std::size_t kMaxAvoided = 4; //!< avoided poses kept at once
  //! The poses avoided now (avoid()), with the frames they still are.
  std::size_t avoidedCount() const;

  /*!
    Evolves the population on one frame (steps 2-8) within \e budget. Throws pm::core::Error if the
    budget is not positive. \e sameFrame: more generations on the frame of the last call (its
    fitness may have changed, e.g. scored on more of the image): no motion prediction, and the
    frame's best replaces the last one in the motion history instead of being added to it.
  */
  FrameResult evolve(FitnessFunction &f, const FrameBudget &budget, bool sameFrame = false);

  //! The current population (RmGaParams::population individuals), each with its last fitness.
  const std::vector<Individual> &population() const { return m_pop; }
  //! The search space (the copy given to the constructor).
  const SearchSpace &space() const { return m_space; }
  //! The parameters (the copy given to the constructor).
  const RmGaParams &params() const { return m_params; }

private:
  Individual make(const Genome &g) const;
  //! Scores ind[from..]; with \e rejectBelow (children), a hopeless one may be rejected early (FitnessFunction::evaluateOrReject).
  void evaluate(FitnessFunction &f, std::vector<Individual> &ind, std::size_t from, double &cost, long &candidates,
                double rejectBelow = -1e300);
  const Individual &tournament();
  void mutate(Genome &g);

  SearchSpace m_space;
  RmGaParams m_params;
  std::mt19937_64 m_rng;
  std::vector<Individual> m_pop, m_children, m_merged;
  std::vector<core::Phi> m_batch;
  std::vector<std::size_t> m_slots; //!< evaluate(): where each pose of the batch came from
  std::vector<double> m_scores, m_costs;
  bool m_havePrev = false, m_havePrev2 = false;
  core::Phi m_prev, m_prev2; //!< best of the last two frames, for the motion prediction
  Genome m_isolated;   //!< the best kept by the last restart, which does not breed ...
  int m_isolation = 0; //!< ... for this many more generations
  bool m_hasAnchor = false;
  core::Phi m_anchor;        //!< see setAnchor()
  //! A pose avoided (avoid()): its place, its radii, the frames it still is.
  struct Avoided
  {
    core::Phi pose;
    double mm = 0, deg = 0;
    int frames = 0;
  };
  std::array<Avoided, kMaxAvoided> m_avoided{};
  //! True if \e p lies within an avoided pose's radii.
  bool isAvoided(const core::Phi &p) const;
};

} // namespace pm::rmga
