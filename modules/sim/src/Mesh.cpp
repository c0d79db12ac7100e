#include "pm/sim/Mesh.h"

#include <algorithm>

#include "pm/sim/Noise.h"

namespace pm::sim {

std::shared_ptr<Texture> speckledTexture(int width, int height, std::uint64_t seed, double lo, double amp,
                                         const std::function<std::array<double, 3>(int i, int j)> &colourAt)
{
  auto tex = std::make_shared<Texture>();
  tex->width = width;
  tex->height = height;
  tex->rgb.resize(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const double n = lo + amp * latticeValue(i, j, seed);
      const std::array<double, 3> c = colourAt(i, j);
      std::uint8_t *o = &tex->rgb[3 * static_cast<std::size_t>(j * width + i)];
      for (int k = 0; k < 3; ++k)
        o[k] = static_cast<std::uint8_t>(std::min(255.0, c[static_cast<std::size_t>(k)] * n));
    }
  return tex;
}

} // namespace pm::sim
