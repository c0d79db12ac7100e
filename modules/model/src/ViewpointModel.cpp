#include "pm/model/ViewpointModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/core/Rounding.h"
#include "pm/model/AllAroundModelBuilder.h"

namespace pm::model {

using hull::Vec3;

void depthBuffer(const core::PinholeCamera::Projection &cam, const std::vector<Vec3> &pts, int radius, std::vector<float> &zbuf)
{
  zbuf.assign(static_cast<std::size_t>(cam.w) * static_cast<std::size_t>(cam.h), std::numeric_limits<float>::infinity());
  for (const Vec3 &p : pts) {
    double u, v, z;
    if (!cam.project(p, u, v, z))
      continue;
    const int ui = static_cast<int>(core::roundHalfAway(u)), vi = static_cast<int>(core::roundHalfAway(v));
    for (int dv = -radius; dv <= radius; ++dv)
      for (int du = -radius; du <= radius; ++du) {
        const int x = ui + du, y = vi + dv;
        if (x < 0 || y < 0 || x >= cam.w || y >= cam.h)
          continue;
        float &d = zbuf[static_cast<std::size_t>(y) * static_cast<std::size_t>(cam.w) + static_cast<std::size_t>(x)];
        d = std::min(d, static_cast<float>(z));
      }
  }
}

namespace {

//! The bounding box of \e mask's non-zero pixels grown by \e margin, within the image (empty when none is).
cv::Rect roiAround(const cv::Mat &mask, int margin)
{
  const cv::Rect b = cv::boundingRect(mask);
  if (b.area() == 0)
    return b;
  return cv::Rect(b.x - margin, b.y - margin, b.width + 2 * margin, b.height + 2 * margin) & cv::Rect(0, 0, mask.cols, mask.rows);
}

} // namespace

std::vector<core::ContourPoint> meshOutline(const core::PinholeCamera::Projection &cam, const HullMesh &mesh, const std::vector<unsigned char> &mask, int n)
{
  ViewpointScratch scratch;
  return meshOutline(cam, mesh, mask.data(), n, scratch);
}

std::vector<core::ContourPoint> meshOutline(const core::PinholeCamera::Projection &cam, const HullMesh &mesh, const unsigned char *mask, int n,
                                            ViewpointScratch &scratch, std::vector<OutlineOrigin> *origins)
{
  if (origins)
    origins->clear();
  auto inMask = [&](double u, double v) {
    const int x = static_cast<int>(core::roundHalfAway(u)), y = static_cast<int>(core::roundHalfAway(v));
    return x >= 0 && y >= 0 && x < cam.w && y < cam.h && mask[static_cast<std::size_t>(y) * static_cast<std::size_t>(cam.w) + static_cast<std::size_t>(x)];
  };
  struct Segment
  {
    Vec3 a, b;
    double ua, va, ub, vb, nu, nv, len;
    std::uint32_t ia, ib;
  };
  std::vector<Segment> segs;
  double total = 0;
  std::vector<unsigned char> &facing = scratch.facing; // each face once, not once per edge around it
  facing.resize(mesh.triangles.size());
  for (std::size_t f = 0; f < facing.size(); ++f)
    facing[f] = mesh.facing(f, cam.centre) ? 1 : 0;
  for (const MeshEdge &e : mesh.edges) {
    if (e.f1 < 0)
      continue;
    const bool fa = facing[static_cast<std::size_t>(e.f0)] != 0, fb = facing[static_cast<std::size_t>(e.f1)] != 0;
    if (fa == fb)
      continue;
    const std::size_t front = static_cast<std::size_t>(fa ? e.f0 : e.f1);
    Segment s;
    s.a = mesh.vertices[e.a], s.b = mesh.vertices[e.b];
    s.ia = e.a, s.ib = e.b;
    double za, zb, u3, v3, z3;
    if (!cam.project(s.a, s.ua, s.va, za) || !cam.project(s.b, s.ub, s.vb, zb))
      continue;
    std::uint32_t third = mesh.triangles[front][0];
    for (std::uint32_t v : mesh.triangles[front])
      if (v != e.a && v != e.b)
        third = v;
    if (!cam.project(mesh.vertices[third], u3, v3, z3))
      continue;
    s.len = std::hypot(s.ub - s.ua, s.vb - s.va);
    if (!(s.len > 1e-6))
      continue;
    s.nu = (s.vb - s.va) / s.len, s.nv = -(s.ub - s.ua) / s.len;
    const double mu = 0.5 * (s.ua + s.ub), mv = 0.5 * (s.va + s.vb);
    if (s.nu * (mu - u3) + s.nv * (mv - v3) < 0)
      s.nu = -s.nu, s.nv = -s.nv;
    // On the silhouette's boundary: the background just outside.
    if (inMask(mu + 1.5 * s.nu, mv + 1.5 * s.nv) || !inMask(mu - 1.0 * s.nu, mv - 1.0 * s.nv))
      continue;
    segs.push_back(s);
    total += s.len;
  }
  std::vector<core::ContourPoint> out;
  if (segs.empty() || n <= 0)
    return out;
  // The outline's normal from the coverage, blurred: a contour edge of the mesh zigzags across its
  // triangles, its own perpendicular is not the outline's.
  // Blurred only over the coverage's box and the kernel's reach around it, and kept there: beyond
  // it the image is background, 0 blurred or not, and the box's margin of 0s wider than the
  // kernel's half makes its border (a reflection) read what the whole image holds there.
  cv::Mat &cover = scratch.cover;
  const cv::Mat maskMat(cam.h, cam.w, CV_8U, const_cast<unsigned char *>(mask));
  constexpr double kSigma = 1.5;
  const int reach = static_cast<int>(std::ceil(4 * kSigma)) + 1; // OpenCV's kernel for a float image: 4 sigma a side
  const cv::Rect box = roiAround(maskMat, reach);
  if (box.area() > 0) {
    cv::Mat(maskMat(box) != 0).convertTo(cover, CV_32F, 1.0 / 255.0); // 1 on the coverage, 0 off it
    cv::GaussianBlur(cover, cover, cv::Size(0, 0), kSigma);
  }
  auto coverPx = [&](int x, int y) { return box.contains({x, y}) ? cover.at<float>(y - box.y, x - box.x) : 0.f; };
  auto coverAt = [&](double u, double v) {
    const int x = std::clamp(static_cast<int>(std::floor(u)), 0, cam.w - 2), y = std::clamp(static_cast<int>(std::floor(v)), 0, cam.h - 2);
    const double fu = std::clamp(u - x, 0.0, 1.0), fv = std::clamp(v - y, 0.0, 1.0);
    return (1 - fv) * ((1 - fu) * coverPx(x, y) + fu * coverPx(x + 1, y)) + fv * ((1 - fu) * coverPx(x, y + 1) + fu * coverPx(x + 1, y + 1));
  };
  const double step = total / n;
  double next = 0.5 * step, walked = 0;
  auto run = [&](double u, double v, double nu, double nv, double from, bool wantInside) {
    int k = 0;
    for (; k < 60; ++k)
      if (inMask(u + (from + k) * nu, v + (from + k) * nv) != wantInside)
        break;
    return from + k;
  };
  for (const Segment &s : segs) {
    while (next < walked + s.len && static_cast<int>(out.size()) < n) {
      const double t = (next - walked) / s.len;
      const Vec3 X{s.a[0] + t * (s.b[0] - s.a[0]), s.a[1] + t * (s.b[1] - s.a[1]), s.a[2] + t * (s.b[2] - s.a[2])};
      const double u = s.ua + t * (s.ub - s.ua), v = s.va + t * (s.vb - s.va);
      double uu = u, vv = v, z = 0;
      cam.project(X, uu, vv, z);
      double gu = coverAt(u - 1, v) - coverAt(u + 1, v), gv = coverAt(u, v - 1) - coverAt(u, v + 1);
      const double gn = std::hypot(gu, gv);
      next += step;
      if (!(gn > 0.05)) // no clear outline here (a thin part, a corner)
        continue;
      gu /= gn, gv /= gn;
      const Vec3 ax = cam.axis(0), ay = cam.axis(1);
      const Vec3 n3 = hull::unit({gu * ax[0] + gv * ay[0], gu * ax[1] + gv * ay[1], gu * ax[2] + gv * ay[2]});
      core::ContourPoint c;
      c.x = static_cast<float>(X[0]), c.y = static_cast<float>(X[1]), c.z = static_cast<float>(X[2]);
      c.nx = static_cast<float>(n3[0]), c.ny = static_cast<float>(n3[1]), c.nz = static_cast<float>(n3[2]);
      const double mmPerPx = z / cam.px;
      c.insideMm = static_cast<float>(run(u, v, -gu, -gv, 1.0, true) * mmPerPx);
      c.outsideMm = static_cast<float>(run(u, v, gu, gv, 1.0, false) * mmPerPx);
      out.push_back(c);
      if (origins)
        origins->push_back({s.ia, s.ib, t, uu, vv, z});
    }
    walked += s.len;
  }
  return out;
}

namespace {

//! The hull's exact coverage in the view's image (255 where its surface is), from its depth map \e zbuf, into \e mask.
void coverageMask(const core::PinholeCamera::Projection &cam, const std::vector<float> &zbuf, cv::Mat &mask)
{
  mask.create(cam.h, cam.w, CV_8U);
  for (int y = 0; y < cam.h; ++y) {
    const float *z = zbuf.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(cam.w);
    unsigned char *m = mask.ptr<unsigned char>(y);
    for (int x = 0; x < cam.w; ++x)
      m[x] = z[x] < std::numeric_limits<float>::infinity() ? 255 : 0; // finite: the depth map holds +inf or a depth, never NaN
  }
}

/*!
  S_in: visible points with a hue at least minInsidePx inside the outline (at the outline a pixel
  mixes target and background), one per cell of a grid over the image, thinned evenly to nIn.
*/
std::vector<core::ModelPoint> sampleInner(const core::PinholeCamera::Projection &cam, const std::vector<SurfacePoint> &surface,
                                          const std::vector<Vec3> &mpts, const std::vector<HullMesh::Projected> &projected,
                                          const AllAroundParams &p, const cv::Mat &mask, const std::vector<float> &zbuf, cv::Mat &inside)
{
  // The distance to the background only over the hull's box and a pixel of background around it:
  // the background nearest a pixel in the box is never farther than its projection on the box's
  // border, which is background, so the distances are those of the whole image.
  const cv::Rect box = roiAround(mask, 1);
  if (box.area() > 0)
    cv::distanceTransform(mask(box), inside, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  auto insidePx = [&](int x, int y) { return box.contains({x, y}) ? inside.at<float>(y - box.y, x - box.x) : 0.f; };
  const double area = box.area() > 0 ? cv::countNonZero(mask(box)) : 0;
  const double step = std::max(1.0, std::sqrt(area / p.viewpoints.nIn));
  // One point a cell of a step x step grid over the image: the nearest to the cell's centre, of
  // equal distances (points that project to the same place) the first in the surface's order. A
  // kept point's pixel lies in the image, so its u in [-0.5, w - 0.5): its cell from -1 on.
  struct Pick
  {
    double d2 = 0;
    std::size_t i = 0;
    float u = 0, v = 0;
    bool taken = false;
  };
  const long cols = static_cast<long>(std::floor((cam.w - 0.5) / step)) + 2, rows = static_cast<long>(std::floor((cam.h - 0.5) / step)) + 2;
  std::vector<Pick> cells(static_cast<std::size_t>(cols * rows));
  for (std::size_t i = 0; i < mpts.size(); ++i) {
    const HullMesh::Projected &q = projected[i]; // as the depth map projected it
    if (!surface[i].hasHue || !q.ok)
      continue;
    const double u = q.u, v = q.v, z = q.z;
    const int ui = static_cast<int>(core::roundHalfAway(u)), vv = static_cast<int>(core::roundHalfAway(v));
    if (ui < 0 || vv < 0 || ui >= cam.w || vv >= cam.h)
      continue;
    if (z > zbuf[static_cast<std::size_t>(vv) * static_cast<std::size_t>(cam.w) + static_cast<std::size_t>(ui)] + p.surface.visibilityTolMm)
      continue;
    if (hull::dot(hull::unit(hull::sub(cam.centre, mpts[i])), {surface[i].nx, surface[i].ny, surface[i].nz}) < 0.2)
      continue;
    if (insidePx(ui, vv) < p.viewpoints.inMinInsidePx)
      continue;
    const long cx = static_cast<long>(std::floor(u / step)), cy = static_cast<long>(std::floor(v / step));
    const double ddx = u - (static_cast<double>(cx) + 0.5) * step, ddy = v - (static_cast<double>(cy) + 0.5) * step;
    const double d2 = ddx * ddx + ddy * ddy;
    Pick &c = cells[static_cast<std::size_t>((cy + 1) * cols + (cx + 1))];
    if (!c.taken || d2 < c.d2)
      c = {d2, i, static_cast<float>(u), static_cast<float>(v), true};
  }
  std::vector<core::ModelPoint> inner; // the cells row by row
  for (const Pick &c : cells)
    if (c.taken) {
      const SurfacePoint &s = surface[c.i];
      inner.push_back({s.x, s.y, s.z, s.hue, c.u, c.v, s.r, s.g, s.b});
    }
  const std::size_t n = static_cast<std::size_t>(p.viewpoints.nIn);
  if (inner.size() <= n)
    return inner;
  std::vector<core::ModelPoint> thinned; // every (size / n)-th
  const double r = static_cast<double>(inner.size()) / static_cast<double>(n);
  for (std::size_t j = 0; j < n; ++j)
    thinned.push_back(inner[static_cast<std::size_t>(static_cast<double>(j) * r)]);
  return thinned;
}

/*!
  S_out: along the mask's contours (every part of the outline, evenly), offset outward, at the
  outline's depth, where the strip falls off the target.
*/
std::vector<core::ModelPoint> sampleOuter(const core::PinholeCamera::Projection &cam, float bgHue, const AllAroundParams &p,
                                          const cv::Mat &mask, const std::vector<float> &zbuf)
{
  std::vector<core::ModelPoint> outer;
  std::vector<std::vector<cv::Point>> contours;
  // Over the coverage's box and a pixel around it (findContours takes an image's border for 0s): the
  // same contours, in the same order, as over the whole image.
  const cv::Rect box = roiAround(mask, 1);
  if (box.area() > 0)
    cv::findContours(mask(box), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE, box.tl());
  double total = 0;
  for (const auto &c : contours)
    total += static_cast<double>(c.size());
  const int perRow = std::max(1, p.viewpoints.nOut / p.viewpoints.stripRows);
  for (const auto &c : contours) {
    const int n = static_cast<int>(c.size());
    if (n < 8)
      continue;
    const int count = std::max(1, static_cast<int>(std::lround(perRow * n / total)));
    for (int j = 0; j < count; ++j) {
      const int a = static_cast<int>(static_cast<long>(j) * n / count);
      const cv::Point P = c[static_cast<std::size_t>(a)], A = c[static_cast<std::size_t>((a + n - 3) % n)],
                      B = c[static_cast<std::size_t>((a + 3) % n)];
      double nx = B.y - A.y, ny = -(B.x - A.x);
      const double nn = std::hypot(nx, ny);
      if (nn <= 0)
        continue;
      nx /= nn, ny /= nn;
      if (cv::pointPolygonTest(c, cv::Point2f(static_cast<float>(P.x + 2 * nx), static_cast<float>(P.y + 2 * ny)), false) > 0)
        nx = -nx, ny = -ny;
      // The outline's depth: the nearest depth under the outline pixel and its neighbours.
      float depth = std::numeric_limits<float>::infinity();
      for (int dv = -2; dv <= 2; ++dv)
        for (int du = -2; du <= 2; ++du) {
          const int x = P.x + du, y = P.y + dv;
          if (x >= 0 && y >= 0 && x < cam.w && y < cam.h)
            depth = std::min(depth, zbuf[static_cast<std::size_t>(y) * static_cast<std::size_t>(cam.w) + static_cast<std::size_t>(x)]);
        }
      if (!std::isfinite(depth))
        continue;
      for (int row = 0; row < p.viewpoints.stripRows; ++row) {
        // From the contour pixel (the last one on the target) to the outline is half a pixel.
        const double off = 0.5 + p.viewpoints.stripGapPx + (p.viewpoints.stripRows > 1 ? p.viewpoints.stripWidthPx * row / (p.viewpoints.stripRows - 1) : 0.0);
        const double su = P.x + off * nx, sv = P.y + off * ny;
        const int ui = static_cast<int>(core::roundHalfAway(su)), vv = static_cast<int>(core::roundHalfAway(sv));
        if (ui >= 0 && vv >= 0 && ui < cam.w && vv < cam.h && mask.at<unsigned char>(vv, ui))
          continue; // in a concavity, on the target
        const Vec3 w = cam.backProject(su, sv, depth);
        outer.push_back({static_cast<float>(w[0]), static_cast<float>(w[1]), static_cast<float>(w[2]), bgHue, static_cast<float>(su),
                         static_cast<float>(sv)});
      }
    }
  }
  return outer;
}

} // namespace

core::ModelView sampleViewpoint(const core::PinholeCamera::Projection &cam, const std::vector<SurfacePoint> &surface, const HullMesh &mesh,
                                float bgHue, const AllAroundParams &p, ViewpointScratch &scratch)
{
  if (surface.size() != mesh.vertices.size())
    throw core::Error("all-around model: a viewpoint's surface holds " + std::to_string(surface.size()) + " points, its mesh " +
                      std::to_string(mesh.vertices.size()) + " vertices (one point a vertex)");
  std::vector<float> &zbuf = scratch.zbuf;
  mesh.depthMap(cam, zbuf, scratch.vertices); // the hull's exact coverage and depth
  cv::Mat &mask = scratch.mask;
  coverageMask(cam, zbuf, mask);
  core::ModelView view;
  for (int k = 0; k < 3; ++k)
    view.cameraMm[k] = cam.centre[static_cast<std::size_t>(k)];
  view.inner = sampleInner(cam, surface, mesh.vertices, scratch.vertices, p, mask, zbuf, scratch.inside);
  // The outline: the mesh's contour edges on the silhouette's boundary.
  view.contour = meshOutline(cam, mesh, mask.ptr<unsigned char>(), p.viewpoints.nContour, scratch);
  view.outer = sampleOuter(cam, bgHue, p, mask, zbuf);
  return view;
}

} // namespace pm::model
