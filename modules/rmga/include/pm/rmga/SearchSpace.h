#pragma once
/*!
  \file SearchSpace.h
  Where RM-GA looks for phi, and the 72-bit chromosome of the paper (Sec. 3.6): 12 bits per
  variable, each mapped linearly onto its range. The paper's ranges: x, y in [-180, 180] mm,
  z in [320, 680] mm, eps1..3 in [-0.37, 0.37].
*/
#include <array>
#include <cstdint>

#include "pm/core/Pose.h"

namespace pm::rmga {

/*!
  The box RM-GA searches phi in: a range [lo, hi] per variable, in the order of Phi (x, y, z in
  mm, then eps1, eps2, eps3). The defaults are the paper's ranges.
*/
struct SearchSpace
{
  std::array<double, 6> lo{-180, -180, 320, -0.37, -0.37, -0.37}; //!< lower bounds: x, y, z (mm), eps1, eps2, eps3
  std::array<double, 6> hi{180, 180, 680, 0.37, 0.37, 0.37};       //!< upper bounds, in the same order

  //! Throws pm::core::Error unless every range is finite and increasing, and those of eps lie in [-1, 1].
  void validate() const;
  //! Clamps phi into the ranges.
  core::Phi clamp(const core::Phi &p) const;
  //! True when every variable of \e p lies in its range (bounds included).
  bool contains(const core::Phi &p) const;
};

//! 6 genes of 12 bits: 72 bits in all.
struct Genome
{
  static constexpr int kBits = 12;                          //!< bits per gene
  static constexpr std::uint16_t kMax = (1u << kBits) - 1;  //!< the largest gene, 4095 (the range's upper bound)
  std::array<std::uint16_t, 6> gene{};                      //!< x, y, z, eps1, eps2, eps3, each in [0, kMax]

  //! Bit \e k of the 72-bit string (gene k / 12, most significant bit first).
  bool bit(int k) const { return (gene[static_cast<std::size_t>(k / kBits)] >> (kBits - 1 - k % kBits)) & 1u; }
  //! Flips bit \e k of the 72-bit string (numbered as in bit()).
  void flip(int k) { gene[static_cast<std::size_t>(k / kBits)] ^= static_cast<std::uint16_t>(1u << (kBits - 1 - k % kBits)); }
  //! Same genes.
  bool operator==(const Genome &o) const { return gene == o.gene; }
};

/*!
  Gene to value: lo + (hi - lo) g / 4095. A decoded phi whose |eps| would exceed 1 (only in a
  search space wider than the paper's) is repaired onto |eps| = 0.999, never left invalid.
*/
core::Phi decode(const Genome &g, const SearchSpace &s);
//! Value to the nearest gene (clamped into the ranges).
Genome encode(const core::Phi &p, const SearchSpace &s);
//! Single-point crossover of the 72-bit strings at bit \e cut (1..71): a[0, cut) + b[cut, 72).
Genome crossover(const Genome &a, const Genome &b, int cut);

} // namespace pm::rmga
