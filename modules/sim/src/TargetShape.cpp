#include "pm/sim/TargetShape.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"

namespace pm::sim {

double edgeProfile(double t, double stepFrac)
{
  if (t >= 1.0)
    return 1.0;
  if (t >= 0.0)
    return std::sqrt(1.0 - (1.0 - t) * (1.0 - t));
  const double d = std::min(1.0, std::max(1e-3, stepFrac));
  return t * std::sqrt(1.0 - (1.0 - d) * (1.0 - d)) / d;
}

float TargetShape::sampleGrid(const std::vector<float> &grid, double xMm, double yMm) const
{
  double c = xMm / texelMm + originCol, r = yMm / texelMm + originRow;
  c = std::min(std::max(c, 0.0), static_cast<double>(cols - 1));
  r = std::min(std::max(r, 0.0), static_cast<double>(rows - 1));
  const int i = std::min(static_cast<int>(c), cols - 2), j = std::min(static_cast<int>(r), rows - 2);
  const double a = c - i, b = r - j;
  auto at = [&](int ii, int jj) { return static_cast<double>(grid[static_cast<std::size_t>(jj) * cols + ii]); };
  const double top = at(i, j) + a * (at(i + 1, j) - at(i, j));
  const double bot = at(i, j + 1) + a * (at(i + 1, j + 1) - at(i, j + 1));
  return static_cast<float>(top + b * (bot - top));
}

void TargetShape::measuredExtent(double &widthMm, double &heightMm) const
{
  int c0 = cols, c1 = -1, r0 = rows, r1 = -1;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      if (sdf[static_cast<std::size_t>(r) * cols + c] < 0) {
        c0 = std::min(c0, c);
        c1 = std::max(c1, c);
        r0 = std::min(r0, r);
        r1 = std::max(r1, r);
      }
  widthMm = c1 >= c0 ? (c1 - c0 + 1) * texelMm : 0.0;
  heightMm = r1 >= r0 ? (r1 - r0 + 1) * texelMm : 0.0;
}

void TargetShape::centreOnOutline()
{
  double sc = 0, sr = 0, n = 0;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      if (sdf[static_cast<std::size_t>(r) * cols + c] < 0) {
        sc += c;
        sr += r;
        n += 1;
      }
  if (n > 0) {
    originCol = sc / n;
    originRow = sr / n;
  }
}

void TargetShape::scaleRelief(double s)
{
  if (!(s >= 0) || !std::isfinite(s))
    throw core::Error("relief scale must be a non-negative number");
  info.depthMm *= s;
  for (float &h : height)
    h *= static_cast<float>(s);
  for (float &b : base)
    b *= static_cast<float>(s);
}

Mesh buildTargetMesh(const TargetShape &shape, double stepMm, float specular)
{
  if (shape.cols < 2 || shape.rows < 2)
    throw core::Error("target '" + shape.info.code + "': empty shape grid");
  const std::size_t cells = static_cast<std::size_t>(shape.cols) * static_cast<std::size_t>(shape.rows);
  if (shape.sdf.size() != cells || shape.height.size() != cells || shape.rgb.size() != 3 * cells ||
      (!shape.base.empty() && shape.base.size() != cells))
    throw core::Error("target '" + shape.info.code + "': its grids do not match its size");
  const double x0 = -shape.originCol * shape.texelMm, y0 = -shape.originRow * shape.texelMm;
  const double x1 = (shape.cols - 1 - shape.originCol) * shape.texelMm;
  const double y1 = (shape.rows - 1 - shape.originRow) * shape.texelMm;
  const int nx = static_cast<int>(std::floor((x1 - x0) / stepMm)) + 1;
  const int ny = static_cast<int>(std::floor((y1 - y0) / stepMm)) + 1;

  Mesh mesh;
  auto tex = std::make_shared<Texture>();
  tex->width = shape.cols;
  tex->height = shape.rows;
  tex->rgb = shape.rgb;
  mesh.texture = tex;
  mesh.useMask = true;
  mesh.specular = specular;

  std::vector<std::int64_t> index(static_cast<std::size_t>(nx) * ny, -1), indexUnder;
  if (!shape.base.empty())
    indexUnder.assign(index.size(), -1);
  std::vector<float> sd(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      sd[static_cast<std::size_t>(j) * nx + i] = shape.sampleGrid(shape.sdf, x0 + i * stepMm, y0 + j * stepMm);
  // Keep the cells that touch the outline or lie inside it.
  const float keep = static_cast<float>(1.5 * stepMm);
  auto cellKept = [&](int i, int j) {
    return std::min({sd[static_cast<std::size_t>(j) * nx + i], sd[static_cast<std::size_t>(j) * nx + i + 1],
                     sd[static_cast<std::size_t>(j + 1) * nx + i], sd[static_cast<std::size_t>(j + 1) * nx + i + 1]}) < keep;
  };
  // One sheet of the body: the top (z = -height, facing the viewer, -z) or the underside
  // (z = -base, facing the backdrop, +z), on the same cells, the texture of the top on both.
  auto addSheet = [&](const std::vector<float> &grid, std::vector<std::int64_t> &ids, float facing) {
    auto vertex = [&](int i, int j) -> std::uint32_t {
      std::int64_t &id = ids[static_cast<std::size_t>(j) * nx + i];
      if (id >= 0)
        return static_cast<std::uint32_t>(id);
      const double x = x0 + i * stepMm, y = y0 + j * stepMm, e = 0.5 * stepMm;
      const double h = shape.sampleGrid(grid, x, y);
      const double hx = (shape.sampleGrid(grid, x + e, y) - shape.sampleGrid(grid, x - e, y)) / (2 * e);
      const double hy = (shape.sampleGrid(grid, x, y + e) - shape.sampleGrid(grid, x, y - e)) / (2 * e);
      const double n = std::sqrt(hx * hx + hy * hy + 1);
      MeshVertex v;
      v.x = static_cast<float>(x * 1e-3);
      v.y = static_cast<float>(y * 1e-3);
      v.z = static_cast<float>(-h * 1e-3); // the base at z = 0, the relief toward the viewer
      v.nx = static_cast<float>(facing * hx / n);
      v.ny = static_cast<float>(facing * hy / n);
      v.nz = static_cast<float>(facing / n);
      v.s = static_cast<float>(x / shape.texelMm + shape.originCol);
      v.t = static_cast<float>(y / shape.texelMm + shape.originRow);
      v.mask = sd[static_cast<std::size_t>(j) * nx + i];
      id = static_cast<std::int64_t>(mesh.vertices.size());
      mesh.vertices.push_back(v);
      return static_cast<std::uint32_t>(id);
    };
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        if (!cellKept(i, j))
          continue;
        const std::uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
        if (facing < 0) { // counter-clockwise seen from the viewer
          mesh.triangles.push_back({a, b, c});
          mesh.triangles.push_back({a, c, d});
        } else {
          mesh.triangles.push_back({a, c, b});
          mesh.triangles.push_back({a, d, c});
        }
      }
  };
  addSheet(shape.height, index, -1.f);
  if (!shape.base.empty())
    addSheet(shape.base, indexUnder, 1.f);
  return mesh;
}

TargetShape targetFromImage(const vpImage<vpRGBa> &image, double widthMm, double depthMm, const std::string &name)
{
  if (image.getSize() == 0)
    throw core::Error("target image '" + name + "' is empty");
  if (!(widthMm > 0) || !(depthMm >= 0))
    throw core::Error("target image '" + name + "': width must be positive and depth non-negative");
  TargetShape s;
  const int iw = static_cast<int>(image.getWidth()), ih = static_cast<int>(image.getHeight());
  const double mmPerPx = widthMm / iw;
  s.info = {"user", name, widthMm, ih * mmPerPx, depthMm};
  s.texelMm = mmPerPx;
  const int margin = std::max(2, static_cast<int>(std::ceil(3.0 / mmPerPx)));
  s.cols = iw + 2 * margin;
  s.rows = ih + 2 * margin;
  const std::size_t n = static_cast<std::size_t>(s.cols) * s.rows;
  s.rgb.assign(3 * n, 0);
  cv::Mat inside(s.rows, s.cols, CV_8U, cv::Scalar(0));
  bool hasAlpha = false;
  for (unsigned i = 0; i < image.getSize(); ++i)
    hasAlpha = hasAlpha || image.bitmap[i].A < 255;
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const int u = std::min(std::max(c - margin, 0), iw - 1), v = std::min(std::max(r - margin, 0), ih - 1);
      const vpRGBa &p = image[static_cast<unsigned>(v)][static_cast<unsigned>(u)];
      std::uint8_t *o = &s.rgb[3 * (static_cast<std::size_t>(r) * s.cols + c)];
      o[0] = p.R;
      o[1] = p.G;
      o[2] = p.B;
      const bool in = c >= margin && c < margin + iw && r >= margin && r < margin + ih && (!hasAlpha || p.A >= 128);
      inside.at<unsigned char>(r, c) = in ? 255 : 0;
    }
  cv::Mat outside, dIn, dOut;
  cv::bitwise_not(inside, outside);
  cv::distanceTransform(inside, dIn, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::distanceTransform(outside, dOut, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  double maxIn = 0;
  cv::minMaxLoc(dIn, nullptr, &maxIn);
  if (maxIn <= 0)
    throw core::Error("target image '" + name + "': its alpha channel leaves nothing opaque");
  const double rho = std::max(1e-6, std::min(depthMm, maxIn * mmPerPx));
  s.sdf.resize(n);
  s.height.resize(n);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const std::size_t k = static_cast<std::size_t>(r) * s.cols + c;
      const double d = (inside.at<unsigned char>(r, c) ? -(dIn.at<float>(r, c) - 0.5) : dOut.at<float>(r, c) - 0.5) * mmPerPx;
      s.sdf[k] = static_cast<float>(d);
      s.height[k] = static_cast<float>(depthMm > 0 ? depthMm * edgeProfile(-d / rho, 1.0 / rho) : 0.0);
    }
  s.originCol = margin + (iw - 1) / 2.0;
  s.originRow = margin + (ih - 1) / 2.0;
  s.centreOnOutline();
  return s;
}

TargetShape flatPrint(const vpImage<vpRGBa> &image, double widthMm, const std::string &name)
{
  TargetShape s = targetFromImage(image, widthMm, 0, name);
  s.originCol = (s.cols - 1) / 2.0;
  s.originRow = (s.rows - 1) / 2.0;
  return s;
}

} // namespace pm::sim
