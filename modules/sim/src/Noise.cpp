#include "pm/sim/Noise.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#endif

namespace pm::sim {

namespace {
constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL; //!< the step between consecutive draws' hash inputs

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
    out[k] = table.v[hash64(seed + (3 * index + k) * kGolden) & 0xffff];
}

namespace {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PM_NOISE_AVX512 1
/*!
  hash64 of x + q kGolden for q = 0 .. count - 1, each picking table[hash & 0xffff] into out[q], 8 at
  a time (AVX-512 with its 64-bit multiply): the same integer operations as hash64, so the same
  draws. Returns the number done (a multiple of 8); the caller draws the rest one at a time.
*/
__attribute__((target("avx512f,avx512dq"))) std::size_t drawRunAvx512(const float *table, std::uint64_t x, std::size_t count,
                                                                     float *out)
{
  const __m512i golden = _mm512_set1_epi64(static_cast<long long>(kGolden));
  const __m512i c1 = _mm512_set1_epi64(static_cast<long long>(0xbf58476d1ce4e5b9ULL));
  const __m512i c2 = _mm512_set1_epi64(static_cast<long long>(0x94d049bb133111ebULL));
  const __m512i step = _mm512_set1_epi64(static_cast<long long>(8 * kGolden));
  const __m512i low16 = _mm512_set1_epi64(0xffff);
  const __mmask8 all = 0xff;
  // hash64 adds kGolden first: lane q starts at x + (q + 1) kGolden.
  __m512i h0 = _mm512_add_epi64(_mm512_set1_epi64(static_cast<long long>(x)),
                                _mm512_mullo_epi64(_mm512_setr_epi64(1, 2, 3, 4, 5, 6, 7, 8), golden));
  std::size_t done = 0;
  for (; done + 8 <= count; done += 8, h0 = _mm512_add_epi64(h0, step)) {
    // (The zero-masked shifts and the masked gather: GCC 12's plain ones warn of an undefined source.)
    __m512i h = _mm512_mullo_epi64(_mm512_xor_si512(h0, _mm512_maskz_srli_epi64(all, h0, 30)), c1);
    h = _mm512_mullo_epi64(_mm512_xor_si512(h, _mm512_maskz_srli_epi64(all, h, 27)), c2);
    h = _mm512_and_si512(_mm512_xor_si512(h, _mm512_maskz_srli_epi64(all, h, 31)), low16);
    _mm256_storeu_ps(out + done, _mm512_mask_i64gather_ps(_mm256_setzero_ps(), all, h, table, 4));
  }
  return done;
}

bool avx512Available()
{
  static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
  return has;
}
#else
#define PM_NOISE_AVX512 0
#endif
} // namespace

void fastGaussian3Run(std::uint64_t seed, std::uint64_t first, std::size_t n, float *out, std::size_t stride)
{
  const GaussianTable &table = gaussianTable();
  // The channels' indices step by one: 3 first + 3 k + c.
  std::uint64_t x = seed + 3 * first * kGolden;
#if PM_NOISE_AVX512
  if (stride == 3 && avx512Available()) { // the draws are consecutive in memory: 8 at a time
    const std::size_t done = drawRunAvx512(table.v, x, 3 * n, out);
    for (std::size_t q = done; q < 3 * n; ++q)
      out[q] = table.v[hash64(x + q * kGolden) & 0xffff];
    return;
  }
#endif
  for (std::size_t k = 0; k < n; ++k, out += stride)
    for (std::size_t c = 0; c < 3; ++c, x += kGolden)
      out[c] = table.v[hash64(x) & 0xffff];
}

} // namespace pm::sim
