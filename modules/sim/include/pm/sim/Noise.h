#pragma once
/*!
  \file Noise.h
  Deterministic noise for procedural textures and sensor noise: everything is a pure
  function of (seed, coordinates), so images are reproducible and can be made in parallel.
*/
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace pm::sim {

//! SplitMix64 finaliser: a well-mixed 64-bit hash.
inline std::uint64_t hash64(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

//! Uniform in [0, 1) from a hash.
inline double unitFromHash(std::uint64_t h) { return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0); }

//! Uniform in [0, 1) at integer lattice point (i, j) for \e seed.
inline double latticeValue(std::int64_t i, std::int64_t j, std::uint64_t seed)
{
  return unitFromHash(hash64(seed ^ hash64(static_cast<std::uint64_t>(i) * 0x632be59bd9b4e019ULL ^
                                           static_cast<std::uint64_t>(j) * 0x85ebca6bULL)));
}

//! Smooth value noise in [0, 1] (quintic interpolation of lattice values).
double valueNoise(double x, double y, std::uint64_t seed);
//! Fractal sum of \e octaves value noises (each twice the frequency, half the amplitude), in [0, 1].
double fbm(double x, double y, std::uint64_t seed, int octaves);
//! Standard normal sample, a pure function of (seed, index) (Box-Muller: exact but slow).
double gaussianFromHash(std::uint64_t seed, std::uint64_t index);
/*!
  Three standard normal samples (one per colour channel of pixel \e index), a pure function of
  (seed, index): a hash of (seed, 3 index + channel) picks each from a fixed table of 65536
  normal samples. Fast, for per-pixel sensor noise.
*/
void fastGaussian3(std::uint64_t seed, std::uint64_t index, float out[3]);
/*!
  fastGaussian3 of pixels \e first + k, k = 0 .. n - 1, into out[stride k + channel] (stride >= 3):
  the same draws, in one tight loop.
*/
void fastGaussian3Run(std::uint64_t seed, std::uint64_t first, std::size_t n, float *out, std::size_t stride = 3);

} // namespace pm::sim
