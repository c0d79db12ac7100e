#include "pm/rmga/RmGa.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::rmga {

namespace {
bool lessFit(const Individual &a, const Individual &b) { return a.fitness < b.fitness; }
bool moreFit(const Individual &a, const Individual &b) { return a.fitness > b.fitness; }

//! Sorts by decreasing fitness, ties in their order (what std::stable_sort does, without its buffer).
void sortByFitness(std::vector<Individual> &v)
{
  for (std::size_t i = 1; i < v.size(); ++i)
    for (std::size_t j = i; j > 0 && v[j].fitness > v[j - 1].fitness; --j)
      std::swap(v[j], v[j - 1]);
}
} // namespace

void RmGaParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("RM-GA parameter ") + what);
  };
  check(population >= 2 && population <= 100000, "population must lie in [2, 100000]");
  check(elite >= 1 && elite < population, "elite must lie in [1, population)");
  check(tournament >= 1 && tournament <= population, "tournament size must lie in [1, population]");
  check(crossoverRate >= 0 && crossoverRate <= 1, "crossover rate must lie in [0, 1]");
  check(mutationPerBit >= 0 && mutationPerBit <= 1, "mutation rate per bit must lie in [0, 1]");
  check(restartGenerations >= 0, "restart generations must be non-negative");
}

RmGa::RmGa(const SearchSpace &space, const RmGaParams &params) : m_space(space), m_params(params), m_rng(params.seed)
{
  space.validate();
  params.validate();
  m_pop.reserve(static_cast<std::size_t>(params.population));
  m_children.reserve(static_cast<std::size_t>(params.population));
  m_merged.reserve(static_cast<std::size_t>(params.population));
  randomize();
}

Individual RmGa::make(const Genome &g) const
{
  Individual i;
  i.genome = g;
  i.phi = decode(g, m_space);
  i.fitness = -1e300;
  return i;
}

void RmGa::randomize()
{
  m_pop.clear();
  m_avoided = {};
  std::uniform_int_distribution<int> gene(0, Genome::kMax);
  for (int k = 0; k < m_params.population; ++k) {
    Genome g;
    for (auto &v : g.gene)
      v = static_cast<std::uint16_t>(gene(m_rng));
    m_pop.push_back(make(g));
  }
  m_havePrev = m_havePrev2 = false;
}

void RmGa::seedAround(const core::Phi &p, double spread)
{
  m_pop.clear();
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  m_pop.push_back(make(encode(m_space.clamp(p), m_space)));
  for (int k = 1; k < m_params.population; ++k) {
    core::Phi q = p;
    for (std::size_t i = 0; i < 6; ++i)
      q[i] += spread * (m_space.hi[i] - m_space.lo[i]) * u(m_rng);
    m_pop.push_back(make(encode(m_space.clamp(q), m_space)));
  }
  m_havePrev = m_havePrev2 = false;
}

void RmGa::setAnchor(const core::Phi &p)
{
  m_anchor = m_space.clamp(p);
  m_hasAnchor = true;
}

void RmGa::restart(int keep, int isolate)
{
  const core::Phi *anchor = m_hasAnchor ? &m_anchor : nullptr;
  std::uniform_int_distribution<int> gene(0, Genome::kMax);
  std::uniform_int_distribution<int> near(-Genome::kMax / 20, Genome::kMax / 20);
  // Near the anchor is wider: the target may have moved while it was not seen (measured on
  // pm-compare's loss scenario: 60 mm in a blank half second, a jump of 50 mm and 8 deg).
  std::uniform_int_distribution<int> nearAnchorPos(-Genome::kMax / 7, Genome::kMax / 7), nearAnchorRot(-Genome::kMax / 10, Genome::kMax / 10);
  std::sort(m_pop.begin(), m_pop.end(), moreFit);
  const std::size_t first = static_cast<std::size_t>(std::max(0, keep));
  const Genome anchorGenome = anchor ? encode(*anchor, m_space) : Genome();
  const std::size_t blocks = anchor ? 8 : 6;
  for (std::size_t k = first; k < m_pop.size(); ++k) {
    // Blocks: 0 all random; 1 the best's position; 2 the best's orientation; 3 near the best;
    // 4 the best's position with its tilt mirrored (e1, e2 negated: the other pose of a nearly
    // planar target under perspective, the classic ambiguity); 5 the best's position, facing
    // the cameras (e1 = e2 = 0). 4 and 5 keep the best's turn e3. With an anchor: 6 the
    // anchor's orientation, 7 near the anchor (+-14 % of each position range, +-10 % of each
    // orientation range).
    const std::size_t block = first > 0 ? (k - first) % blocks : (anchor ? (k % 2 == 0 ? 0 : 6 + (k / 2) % 2) : 0);
    Genome g = block >= 6 ? anchorGenome : m_pop[0].genome;
    if (block == 4 || block == 5) {
      core::Phi q = m_pop[0].phi;
      q.e1 = block == 4 ? -q.e1 : 0.0;
      q.e2 = block == 4 ? -q.e2 : 0.0;
      g = encode(m_space.clamp(q), m_space);
    }
    for (std::size_t i = 0; i < 6 && (block < 4 || block >= 6); ++i)
      if (block == 3 || block == 7)
        g.gene[i] = static_cast<std::uint16_t>(std::clamp(static_cast<int>(g.gene[i]) + (block == 3 ? near(m_rng) : i < 3 ? nearAnchorPos(m_rng) : nearAnchorRot(m_rng)), 0, static_cast<int>(Genome::kMax)));
      else if (block == 0 || (block == 1) == (i >= 3)) // 1: new orientation; 2, 6: new position
        g.gene[i] = static_cast<std::uint16_t>(gene(m_rng));
    m_pop[k] = make(g);
  }
  m_isolation = first > 0 ? std::max(0, isolate) : 0;
  if (m_isolation > 0)
    m_isolated = m_pop[0].genome;
}

void RmGa::scatter(int keep, int isolate)
{
  std::sort(m_pop.begin(), m_pop.end(), moreFit);
  const std::size_t first = static_cast<std::size_t>(std::clamp(keep, 0, m_params.population));
  const std::vector<Individual> kept(m_pop.begin(), m_pop.begin() + static_cast<std::ptrdiff_t>(first));
  restart(0); // all new: random, and from the anchor when there is one
  std::copy(kept.begin(), kept.end(), m_pop.begin());
  m_isolation = first > 0 ? std::max(0, isolate) : 0;
  if (m_isolation > 0)
    m_isolated = m_pop[0].genome;
}

void RmGa::transform(const std::function<core::Phi(const core::Phi &)> &f)
{
  for (auto &ind : m_pop) {
    const double fit = ind.fitness;
    ind = make(encode(m_space.clamp(f(ind.phi)), m_space));
    ind.fitness = fit;
  }
  if (m_hasAnchor)
    m_anchor = m_space.clamp(f(m_anchor));
  for (Avoided &a : m_avoided)
    if (a.frames > 0)
      a.pose = f(a.pose);
  if (m_havePrev)
    m_prev = f(m_prev);
  if (m_havePrev2)
    m_prev2 = f(m_prev2);
}

void RmGa::inject(const core::Phi &p, double fitness)
{
  if (m_pop.empty() || !p.isValid() || isAvoided(p))
    return;
  std::size_t weakest = 0;
  for (std::size_t i = 1; i < m_pop.size(); ++i)
    if (m_pop[i].fitness < m_pop[weakest].fitness)
      weakest = i;
  m_pop[weakest] = make(encode(m_space.clamp(p), m_space));
  m_pop[weakest].fitness = fitness;
  if (m_havePrev) // the frame's best, for the motion prediction: the injected pose when it scores as well
    m_prev = p;
}

void RmGa::avoid(const core::Phi &p, double mm, double deg, int frames)
{
  if (!p.isValid() || !(mm > 0) || !(deg > 0) || frames <= 0)
    return;
  Avoided *slot = &m_avoided[0];
  for (Avoided &a : m_avoided)
    if (a.frames < slot->frames)
      slot = &a;
  *slot = Avoided{p, mm, deg, frames};
}

std::size_t RmGa::avoidedCount() const
{
  return static_cast<std::size_t>(std::count_if(m_avoided.begin(), m_avoided.end(), [](const Avoided &a) { return a.frames > 0; }));
}

bool RmGa::isAvoided(const core::Phi &p) const
{
  for (const Avoided &a : m_avoided)
    if (a.frames > 0 && core::translationDistanceMm(p, a.pose) <= a.mm && core::rotationDistanceDeg(p, a.pose) <= a.deg)
      return true;
  return false;
}

void RmGa::evaluate(FitnessFunction &f, std::vector<Individual> &ind, std::size_t from, double &cost, long &candidates, double rejectBelow)
{
  // The avoided ones are not scored: the others go to the fitness in one batch, in their order.
  const std::size_t n = ind.size() - from;
  m_batch.resize(n);
  m_scores.resize(n);
  m_costs.resize(n);
  m_slots.resize(n);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (isAvoided(ind[from + i].phi)) {
      ind[from + i].fitness = -1e300;
      continue;
    }
    m_slots[k] = from + i;
    m_batch[k++] = ind[from + i].phi;
  }
  if (k > 0)
    f.evaluateOrReject(m_batch.data(), k, rejectBelow, m_scores.data(), m_costs.data());
  for (std::size_t j = 0; j < k; ++j) {
    ind[m_slots[j]].fitness = std::isfinite(m_scores[j]) ? m_scores[j] : -1e300;
    cost += std::clamp(m_costs[j], 0.0, 1.0);
  }
  candidates += static_cast<long>(k);
}

const Individual &RmGa::tournament()
{
  std::uniform_int_distribution<std::size_t> pick(0, m_pop.size() - 1);
  auto draw = [&]() -> const Individual & { // anyone but the isolated best, if drawn again soon enough
    const Individual *c = &m_pop[pick(m_rng)];
    for (std::size_t tries = 0; m_isolation > 0 && c->genome == m_isolated && tries < m_pop.size(); ++tries)
      c = &m_pop[pick(m_rng)];
    return *c;
  };
  const Individual *best = &draw();
  for (int k = 1; k < m_params.tournament; ++k) {
    const Individual &c = draw();
    if (c.fitness > best->fitness)
      best = &c;
  }
  return *best;
}

void RmGa::mutate(Genome &g)
{
  if (m_params.mutationPerBit <= 0)
    return;
  // Flip each bit with probability p: jump from flip to flip with geometric gaps.
  std::geometric_distribution<int> gap(m_params.mutationPerBit);
  for (int k = gap(m_rng); k < 6 * Genome::kBits; k += 1 + gap(m_rng))
    g.flip(k);
}

FrameResult RmGa::evolve(FitnessFunction &f, const FrameBudget &budget, bool sameFrame)
{
  if (!(budget.evaluations > 0) && !(budget.milliseconds > 0))
    throw core::Error("RM-GA: the frame budget must be a positive number of evaluations or milliseconds");
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsedMs = [&] { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count(); };
  FrameResult r;

  // 2. Prediction: constant velocity of the best pose over the last two frames.
  if (m_params.predictMotion && m_havePrev && m_havePrev2 && !sameFrame) {
    core::Phi v;
    for (std::size_t i = 0; i < 6; ++i)
      v[i] = m_prev[i] - m_prev2[i];
    // The prediction is a guess: the best of the last frame also stays where it was, in place of
    // the worst, so that a wrong velocity (after a jump of the estimate) cannot carry it away.
    const Individual stay = *std::max_element(m_pop.begin(), m_pop.end(), lessFit);
    const auto worst = std::min_element(m_pop.begin(), m_pop.end(), lessFit) - m_pop.begin();
    for (auto &ind : m_pop) {
      core::Phi q = ind.phi;
      for (std::size_t i = 0; i < 6; ++i)
        q[i] += v[i];
      ind = make(encode(m_space.clamp(q), m_space));
    }
    m_pop[static_cast<std::size_t>(worst)] = stay;
  }
  // 3. Evaluate everyone on the new frame.
  double evals = 0; // the work, in whole evaluations
  long candidates = 0;
  evaluate(f, m_pop, 0, evals, candidates);
  const bool byEvals = budget.evaluations > 0;
  const double gaEvals = byEvals ? static_cast<double>(budget.evaluations) : 0.0;
  const double gaMs = byEvals ? 0.0 : budget.milliseconds;
  const int n = m_params.population, lambda = n - m_params.elite;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::uniform_int_distribution<int> cut(1, 6 * Genome::kBits - 1);
  double bestSoFar = -1e300;
  int stagnant = 0;
  for (const auto &i : m_pop)
    bestSoFar = std::max(bestSoFar, i.fitness);
  // 4-7. Generations.
  while (byEvals ? evals + lambda <= gaEvals : elapsedMs() < gaMs) { // (a generation's children cost at most lambda)
    m_children.clear();
    while (static_cast<int>(m_children.size()) < lambda) {
      const Individual &a = tournament(), &b = tournament();
      Genome c1 = a.genome, c2 = b.genome;
      if (u01(m_rng) < m_params.crossoverRate) {
        const int k = cut(m_rng);
        c1 = crossover(a.genome, b.genome, k);
        c2 = crossover(b.genome, a.genome, k);
      }
      mutate(c1);
      mutate(c2);
      m_children.push_back(make(c1));
      if (static_cast<int>(m_children.size()) < lambda)
        m_children.push_back(make(c2));
    }
    // A child under the worst parent cannot survive: it need not be scored exactly.
    const double worst = std::min_element(m_pop.begin(), m_pop.end(), lessFit)->fitness;
    evaluate(f, m_children, 0, evals, candidates, worst);
    // The best n of parents and children survive (on a tie, a parent before a child, and each in its order).
    sortByFitness(m_pop);
    sortByFitness(m_children);
    m_merged.clear();
    for (std::size_t i = 0, j = 0; m_merged.size() < static_cast<std::size_t>(n);)
      m_merged.push_back(j == m_children.size() || (i < m_pop.size() && m_pop[i].fitness >= m_children[j].fitness) ? m_pop[i++] : m_children[j++]);
    m_pop.swap(m_merged);
    ++r.generations;
    if (m_isolation > 0)
      --m_isolation;
    if (m_pop[0].fitness > bestSoFar) {
      bestSoFar = m_pop[0].fitness;
      stagnant = 0;
    } else if (m_params.restartGenerations > 0 && ++stagnant >= m_params.restartGenerations) {
      restart(1, m_params.restartGenerations);
      evaluate(f, m_pop, 1, evals, candidates);
      stagnant = 0;
      r.restarted = true;
    }
  }
  // 8. The best is the frame's pose.
  const auto best = std::max_element(m_pop.begin(), m_pop.end(), lessFit);
  r.best = best->phi;
  r.fitness = best->fitness;
  r.evaluations = static_cast<long>(std::ceil(evals - 1e-9));
  r.candidates = candidates;
  if (!sameFrame) // one frame less for each avoided pose
    for (Avoided &a : m_avoided)
      a.frames = std::max(0, a.frames - 1);
  if (!sameFrame || !m_havePrev) {
    m_prev2 = m_prev;
    m_havePrev2 = m_havePrev;
  }
  m_prev = r.best;
  m_havePrev = true;
  return r;
}

} // namespace pm::rmga
