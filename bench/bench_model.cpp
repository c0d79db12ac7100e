//! pm-bench: the all-around model's builder, a viewpoint's depth map of its surface (each of the 240 viewpoints draws one).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/AllAroundParams.h"
#include "pm/model/HullMesh.h"
#include "pm/model/ViewpointModel.h"
#include "pm/model/VisualHull.h"

namespace {

//! A bumpy ellipsoid (80 x 60 x 40 mm half-axes) as surface nets on a 1 mm grid: about the crab's hull's size and faces.
pm::model::HullMesh bumpyEllipsoid()
{
  pm::model::VisualHull g = pm::model::hullGrid({0, 0, 0}, 90, 1.0);
  g.occ.assign(static_cast<std::size_t>(g.n) * g.n * g.n, 0);
  auto field = [&](const pm::model::hull::Vec3 &X) {
    const double r = std::sqrt(X[0] * X[0] / 6400 + X[1] * X[1] / 3600 + X[2] * X[2] / 1600);
    return 40 * (1 - r) + 2 * std::sin(X[0] / 7) * std::cos(X[1] / 5);
  };
  for (int z = 0; z < g.n; ++z)
    for (int y = 0; y < g.n; ++y)
      for (int x = 0; x < g.n; ++x)
        g.occ[g.idx(x, y, z)] = field(g.centre(x, y, z)) > 0 ? 1 : 0;
  return pm::model::meshField(g, [&](int x, int y, int z) { return field(g.corner(x, y, z)); });
}

/*!
  HullMesh::depthMap() of the mesh from 500 mm, 640 x 480 (the model's viewpoints): its time per
  face is the builder's largest part (counter: faces).
*/
void Model_DepthMap(benchmark::State &state)
{
  static const pm::model::HullMesh mesh = bumpyEllipsoid();
  vpCameraParameters cam(800, 800, 320, 240);
  const pm::core::PinholeCamera::Projection view = pm::core::PinholeCamera::Projection::lookingAtOrigin({120, -90, 480}, cam, 640, 480);
  std::vector<float> zbuf;
  std::vector<pm::model::HullMesh::Projected> scratch;
  for (auto _ : state) {
    mesh.depthMap(view, zbuf, scratch);
    benchmark::DoNotOptimize(zbuf.data());
  }
  state.counters["faces"] = static_cast<double>(mesh.triangles.size());
}

/*!
  sampleViewpoint() of the same mesh, every vertex a surface point with a hue: the depth map, the
  coverage, S_in, the outline and S_out of one of a model's 240 viewpoints (counter: the outline's points).
*/
void Model_Viewpoint(benchmark::State &state)
{
  static const pm::model::HullMesh mesh = bumpyEllipsoid();
  std::vector<pm::model::SurfacePoint> surface(mesh.vertices.size());
  for (std::size_t i = 0; i < surface.size(); ++i) {
    pm::model::SurfacePoint &s = surface[i];
    s.x = static_cast<float>(mesh.vertices[i][0]), s.y = static_cast<float>(mesh.vertices[i][1]), s.z = static_cast<float>(mesh.vertices[i][2]);
    s.nx = static_cast<float>(mesh.normals[i][0]), s.ny = static_cast<float>(mesh.normals[i][1]), s.nz = static_cast<float>(mesh.normals[i][2]);
    s.hue = static_cast<float>(i % 360), s.r = 200, s.g = 100, s.b = 50, s.nSeen = 2, s.hasHue = true, s.highlight = false;
  }
  vpCameraParameters cam(800, 800, 320, 240);
  const pm::core::PinholeCamera::Projection view = pm::core::PinholeCamera::Projection::lookingAtOrigin({120, -90, 480}, cam, 640, 480);
  const pm::model::AllAroundParams params;
  pm::model::ViewpointScratch scratch;
  std::size_t contour = 0;
  for (auto _ : state) {
    const pm::core::ModelView v = pm::model::sampleViewpoint(view, surface, mesh, 120.f, params, scratch);
    contour = v.contour.size();
    benchmark::DoNotOptimize(v.inner.data());
  }
  state.counters["outline"] = static_cast<double>(contour);
}

} // namespace

BENCHMARK(Model_DepthMap)->Unit(benchmark::kMillisecond);
BENCHMARK(Model_Viewpoint)->Unit(benchmark::kMillisecond);
