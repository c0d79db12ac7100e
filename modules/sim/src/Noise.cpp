#include "pm/sim/Noise.h"

namespace pm::sim {

namespace {
inline double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
} // namespace

double valueNoise(double x, double y, std::uint64_t seed)
{
  const double fx = std::floor(x), fy = std::floor(y);
  const auto i = static_cast<std::int64_t>(fx), j = static_cast<std::int64_t>(fy);
  const double tx = fade(x - fx), ty = fade(y - fy);
  const double a = latticeValue(i, j, seed), b = latticeValue(i + 1, j, seed);
  const double c = latticeValue(i, j + 1, seed), d = latticeValue(i + 1, j + 1, seed);
  return (a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty;
}

double fbm(double x, double y, std::uint64_t seed, int octaves)
{
  double sum = 0, amp = 1, norm = 0, f = 1;
  for (int o = 0; o < octaves; ++o) {
    sum += amp * valueNoise(x * f, y * f, seed + static_cast<std::uint64_t>(o) * 1013);
    norm += amp;
    amp *= 0.5;
    f *= 2.0;
  }
  return sum / norm;
}

double gaussianFromHash(std::uint64_t seed, std::uint64_t index)
{
  const std::uint64_t h = hash64(seed ^ hash64(index));
  const double u1 = (static_cast<double>(h >> 40) + 0.5) * (1.0 / 16777216.0);
  const double u2 = static_cast<double>(h & 0xffffffULL) * (1.0 / 16777216.0);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

namespace {
struct GaussianTable
{
  float v[65536];
  GaussianTable()
  {
    for (int i = 0; i < 65536; ++i)
      v[i] = static_cast<float>(gaussianFromHash(0x5eed, static_cast<std::uint64_t>(i)));
  }
};
} // namespace

namespace {
const GaussianTable &gaussianTable()
{
  static const GaussianTable table;
  return table;
}
} // namespace

void fastGaussian3(std::uint64_t seed, std::uint64_t index, float out[3])
{
  const GaussianTable &table = gaussianTable();
  for (std::uint64_t k = 0; k < 3; ++k)
    out[k] = table.v[hash64(seed + (3 * index + k) * 0x9e3779b97f4a7c15ULL) & 0xffff];
}

void fastGaussian3Run(std::uint64_t seed, std::uint64_t first, std::size_t n, float *out, std::size_t stride)
{
  const GaussianTable &table = gaussianTable();
  // The channels' indices step by one: 3 first + 3 k + c.
  std::uint64_t x = seed + 3 * first * 0x9e3779b97f4a7c15ULL;
  for (std::size_t k = 0; k < n; ++k, out += stride)
    for (std::size_t c = 0; c < 3; ++c, x += 0x9e3779b97f4a7c15ULL)
      out[c] = table.v[hash64(x) & 0xffff];
}

} // namespace pm::sim
