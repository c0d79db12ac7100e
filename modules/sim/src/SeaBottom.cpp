#include "pm/sim/SeaBottom.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

#include "pm/core/Error.h"
#include "pm/sim/Noise.h"

namespace pm::sim {

namespace {

//! The smooth fields of the sea bottom at (x, y) mm: sand, rocks, ripple warp, caustic field.
struct Fields
{
  float sand, rock, warp, caustic;
};

Fields fieldsAt(double x, double y, std::uint64_t s)
{
  Fields f;
  f.sand = static_cast<float>(fbm(x / 90.0, y / 90.0, s, 5));
  f.rock = static_cast<float>(std::clamp((fbm(x / 60.0 + 17, y / 60.0 - 5, s + 1, 4) - 0.55) * 6.0, 0.0, 1.0));
  f.warp = static_cast<float>(8.0 * fbm(x / 40.0, y / 40.0, s + 2, 3));
  f.caustic = static_cast<float>(fbm(x / 22.0 + 3 * fbm(x / 50.0, y / 50.0, s + 3, 2), y / 22.0, s + 4, 3));
  return f;
}

std::shared_ptr<const Texture> generate(const SeaBottomParams &p)
{
  auto t = std::make_shared<Texture>();
  t->width = static_cast<int>(std::ceil(p.widthMm / p.texelMm));
  t->height = static_cast<int>(std::ceil(p.heightMm / p.texelMm));
  t->rgb.resize(3 * static_cast<std::size_t>(t->width) * t->height);
  const std::uint64_t s = p.seed;
  // The smooth fields on a coarse grid (every 2.4 mm), interpolated; the fine detail per texel.
  const double coarseMm = 2.4;
  const int cw = static_cast<int>(std::ceil(p.widthMm / coarseMm)) + 2, ch = static_cast<int>(std::ceil(p.heightMm / coarseMm)) + 2;
  std::vector<Fields> coarse(static_cast<std::size_t>(cw) * ch);
#pragma omp parallel for schedule(dynamic, 4)
  for (int j = 0; j < ch; ++j)
    for (int i = 0; i < cw; ++i)
      coarse[static_cast<std::size_t>(j) * cw + i] = fieldsAt(i * coarseMm, j * coarseMm, s);
#pragma omp parallel for schedule(dynamic, 16)
  for (int j = 0; j < t->height; ++j)
    for (int i = 0; i < t->width; ++i) {
      const double x = i * p.texelMm, y = j * p.texelMm; // mm
      const double gx = x / coarseMm, gy = y / coarseMm;
      const int ci = static_cast<int>(gx), cj = static_cast<int>(gy);
      const float a = static_cast<float>(gx - ci), b = static_cast<float>(gy - cj);
      const Fields &f00 = coarse[static_cast<std::size_t>(cj) * cw + ci], &f10 = coarse[static_cast<std::size_t>(cj) * cw + ci + 1];
      const Fields &f01 = coarse[static_cast<std::size_t>(cj + 1) * cw + ci], &f11 = coarse[static_cast<std::size_t>(cj + 1) * cw + ci + 1];
      auto lerp2 = [&](float Fields::*m) {
        const float top = f00.*m + a * (f10.*m - f00.*m), bot = f01.*m + a * (f11.*m - f01.*m);
        return static_cast<double>(top + b * (bot - top));
      };
      const double sand = lerp2(&Fields::sand), rock = lerp2(&Fields::rock);
      const double ripple = 0.5 + 0.5 * std::sin((y * 0.9 + x * 0.25) / 6.0 + lerp2(&Fields::warp));
      const double caustic = std::exp(-std::pow((lerp2(&Fields::caustic) - 0.5) * 28.0, 2.0)); // thin bright lines
      const double grain = valueNoise(x / 1.2, y / 1.2, s + 5);
      const double shade = 1.05 - 0.35 * (y / p.heightMm); // light from the surface above
      double v = (0.42 + 0.22 * sand + 0.06 * ripple + 0.05 * grain) * (1.0 - 0.35 * rock) * shade + 0.22 * caustic;
      const double hue = 208.0 + 14.0 * (sand - 0.5) - 10.0 * rock + 6.0 * caustic; // teal to deep blue
      const double sat = std::clamp(0.78 - 0.25 * caustic + 0.1 * rock - 0.08 * grain, 0.3, 1.0);
      v = std::clamp(v, 0.0, 1.0);
      const double h = hue / 60.0;
      const int k = static_cast<int>(std::floor(h)) % 6;
      const double fr = h - std::floor(h), pp = v * (1 - sat), q = v * (1 - sat * fr), tt = v * (1 - sat * (1 - fr));
      const double tab[6][3] = {{v, tt, pp}, {q, v, pp}, {pp, v, tt}, {pp, q, v}, {tt, pp, v}, {v, pp, q}};
      std::uint8_t *o = &t->rgb[3 * (static_cast<std::size_t>(j) * t->width + i)];
      for (int c = 0; c < 3; ++c)
        o[c] = static_cast<std::uint8_t>(std::lround(tab[k][c] * 255));
    }
  return t;
}

} // namespace

std::shared_ptr<const Texture> makeSeaBottomTexture(const SeaBottomParams &p)
{
  if (!(p.widthMm > 0 && p.heightMm > 0 && p.texelMm > 0.05) || p.widthMm / p.texelMm * p.heightMm / p.texelMm > 4e7)
    throw core::Error("sea bottom: size and texel must be positive, and the texture at most 40 million texels");
  // One texture per parameter set is shared by every scene of the process (it is immutable).
  static std::mutex mutex;
  static std::map<std::tuple<double, double, double, std::uint64_t>, std::weak_ptr<const Texture>> cache;
  const auto key = std::make_tuple(p.widthMm, p.heightMm, p.texelMm, p.seed);
  std::lock_guard<std::mutex> lock(mutex);
  if (auto t = cache[key].lock())
    return t;
  auto t = generate(p);
  cache[key] = t;
  return t;
}

Mesh makeBackdropMesh(std::shared_ptr<const Texture> texture, const SeaBottomParams &p, double zMm)
{
  // A grid of quads rather than one: triangles that reach behind a camera are skipped whole by
  // the rasterizer, so small ones keep the rest of the panel when it is seen at a grazing angle.
  const int nx = 32, ny = 24;
  Mesh m;
  const double w = p.widthMm * 1e-3, h = p.heightMm * 1e-3;
  const float z = static_cast<float>(zMm * 1e-3);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double fx = static_cast<double>(i) / nx, fy = static_cast<double>(j) / ny;
      m.vertices.push_back({static_cast<float>((fx - 0.5) * w), static_cast<float>((fy - 0.5) * h), z, 0, 0, -1,
                            static_cast<float>(fx * (texture->width - 1)), static_cast<float>(fy * (texture->height - 1)), -1});
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const auto a = static_cast<std::uint32_t>(j * (nx + 1) + i), b = a + 1, d = a + static_cast<std::uint32_t>(nx + 1), c = d + 1;
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  m.texture = std::move(texture);
  return m;
}

} // namespace pm::sim
