#include "pm/rmga/SearchSpace.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"

namespace pm::rmga {

void SearchSpace::validate() const
{
  for (std::size_t i = 0; i < 6; ++i)
    if (!std::isfinite(lo[i]) || !std::isfinite(hi[i]) || !(hi[i] > lo[i]))
      throw core::Error("search space: the range of variable " + std::to_string(i) + " must be finite and increasing");
  for (std::size_t i = 3; i < 6; ++i)
    if (lo[i] < -1 || hi[i] > 1)
      throw core::Error("search space: the ranges of eps must lie in [-1, 1]");
}

core::Phi SearchSpace::clamp(const core::Phi &p) const
{
  core::Phi q = p;
  for (std::size_t i = 0; i < 6; ++i)
    q[i] = std::min(hi[i], std::max(lo[i], p[i]));
  return q;
}

bool SearchSpace::contains(const core::Phi &p) const
{
  for (std::size_t i = 0; i < 6; ++i)
    if (!(p[i] >= lo[i] && p[i] <= hi[i]))
      return false;
  return true;
}

core::Phi decode(const Genome &g, const SearchSpace &s)
{
  core::Phi p;
  for (std::size_t i = 0; i < 6; ++i)
    p[i] = s.lo[i] + (s.hi[i] - s.lo[i]) * g.gene[i] / static_cast<double>(Genome::kMax);
  const double n2 = p.epsNorm2();
  if (n2 > 0.999 * 0.999) {
    const double k = 0.999 / std::sqrt(n2);
    p.e1 *= k;
    p.e2 *= k;
    p.e3 *= k;
  }
  return p;
}

Genome encode(const core::Phi &p, const SearchSpace &s)
{
  Genome g;
  for (std::size_t i = 0; i < 6; ++i) {
    const double t = (p[i] - s.lo[i]) / (s.hi[i] - s.lo[i]);
    const double v = std::isfinite(t) ? std::min(1.0, std::max(0.0, t)) : 0.5;
    g.gene[i] = static_cast<std::uint16_t>(std::lround(v * Genome::kMax));
  }
  return g;
}

Genome crossover(const Genome &a, const Genome &b, int cut)
{
  Genome c;
  const int whole = cut / Genome::kBits, part = cut % Genome::kBits;
  for (int i = 0; i < 6; ++i) {
    if (i < whole)
      c.gene[static_cast<std::size_t>(i)] = a.gene[static_cast<std::size_t>(i)];
    else if (i > whole || part == 0)
      c.gene[static_cast<std::size_t>(i)] = b.gene[static_cast<std::size_t>(i)];
    else {
      const std::uint16_t high = static_cast<std::uint16_t>(((1u << part) - 1) << (Genome::kBits - part));
      c.gene[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>((a.gene[static_cast<std::size_t>(i)] & high) |
                                                                      (b.gene[static_cast<std::size_t>(i)] & ~high & Genome::kMax));
    }
  }
  return c;
}

} // namespace pm::rmga
