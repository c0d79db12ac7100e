#include "pm/model/OutlineRefinement.h"

#include <algorithm>
#include <cmath>

#include "pm/core/Error.h"
#include "pm/model/ViewpointModel.h"

namespace pm::model {

using hull::Vec3;

void OutlineRefinementParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("outline refinement: ") + what);
  };
  check(rounds >= 0 && rounds <= 20, "rounds must lie in [0, 20]");
  check(maxResidualPx > 0 && maxResidualPx <= 10, "the largest residual must lie in (0, 10] px");
  check(gain > 0 && gain <= 1, "the gain must lie in (0, 1]");
  check(maxStepMm > 0 && maxStepMm <= 5, "the largest step must lie in (0, 5] mm");
  check(smoothness >= 0 && smoothness <= 100, "the smoothness must lie in [0, 100]");
  check(stay > 0 && stay <= 100, "the weight of staying must lie in (0, 100]");
  check(smoothIterations >= 0 && smoothIterations <= 200, "the smoothing must lie in [0, 200] sweeps");
}

namespace {

//! Per vertex: the sum of the moves its cameras ask (mm, along its normal) and how many ask.
struct Asks
{
  std::vector<double> sumMm;
  std::vector<double> count; //!< weights: an outline point shares itself between its edge's two vertices
  double sumPx = 0, sum2Px = 0;
  long samples = 0;
};

//! The outline of \e mesh in each camera (ViewpointModel.h's meshOutline) and what each camera's silhouette asks of its edges' vertices.
Asks measure(const HullMesh &mesh, const std::vector<const hull::HullView *> &cams, double maxResidualPx, ViewpointScratch &scratch,
             std::vector<unsigned char> &mask, std::vector<OutlineOrigin> &origins)
{
  constexpr int kPointsPerCamera = 1500; // a third of a pixel apart on a toy's outline at the pass's distance
  Asks a;
  a.sumMm.assign(mesh.vertices.size(), 0.0);
  a.count.assign(mesh.vertices.size(), 0.0);
  for (const hull::HullView *vc : cams) {
    mesh.depthMap(vc->cam, scratch.zbuf, scratch.vertices);
    mask.resize(scratch.zbuf.size());
    for (std::size_t i = 0; i < mask.size(); ++i)
      mask[i] = std::isfinite(scratch.zbuf[i]) ? 255 : 0;
    (void)meshOutline(vc->cam, mesh, mask.data(), kPointsPerCamera, scratch, &origins);
    for (const OutlineOrigin &o : origins) {
      const double r = vc->sdSmooth(o.u, o.v);
      if (std::fabs(r) > maxResidualPx)
        continue; // far from this view's outline: a part the silhouettes cannot tell
      const double mm = r * o.z / vc->cam.px;
      a.sumMm[o.a] += (1 - o.t) * mm, a.count[o.a] += 1 - o.t;
      a.sumMm[o.b] += o.t * mm, a.count[o.b] += o.t;
      a.sumPx += r, a.sum2Px += r * r;
      ++a.samples;
    }
  }
  return a;
}

//! The vertices' neighbours (every edge both ways), as offsets into one list.
void neighbours(const HullMesh &mesh, std::vector<std::uint32_t> &first, std::vector<std::uint32_t> &list)
{
  first.assign(mesh.vertices.size() + 1, 0);
  for (const MeshEdge &e : mesh.edges)
    ++first[e.a + 1], ++first[e.b + 1];
  for (std::size_t i = 1; i < first.size(); ++i)
    first[i] += first[i - 1];
  list.resize(first.back());
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for (const MeshEdge &e : mesh.edges)
    list[fill[e.a]++] = e.b, list[fill[e.b]++] = e.a;
}

} // namespace

OutlineRefinementStats refineOutlines(HullMesh &mesh, const std::vector<const hull::HullView *> &cams, const OutlineRefinementParams &p)
{
  p.validate();
  OutlineRefinementStats st;
  ViewpointScratch scratch;
  std::vector<unsigned char> mask;
  std::vector<OutlineOrigin> origins;
  std::vector<std::uint32_t> first, list;
  neighbours(mesh, first, list);
  const std::size_t n = mesh.vertices.size();
  std::vector<double> ask(n), move(n), next(n);
  for (int round = 0; round <= p.rounds; ++round) {
    const Asks a = measure(mesh, cams, p.maxResidualPx, scratch, mask, origins);
    const double mean = a.samples ? a.sumPx / static_cast<double>(a.samples) : 0.0;
    const double rms = a.samples ? std::sqrt(a.sum2Px / static_cast<double>(a.samples)) : 0.0;
    if (round == 0)
      st.meanBeforePx = mean, st.rmsBeforePx = rms;
    st.meanAfterPx = mean, st.rmsAfterPx = rms, st.samples = a.samples;
    if (round == p.rounds)
      break;
    // The moves: each vertex's ask (weighted by how many outline points asked) against its
    // neighbours' moves (a smooth surface) and against staying (where nobody asks), by Jacobi sweeps.
    for (std::size_t i = 0; i < n; ++i) {
      ask[i] = a.count[i] > 0 ? std::clamp(p.gain * a.sumMm[i] / a.count[i], -p.maxStepMm, p.maxStepMm) : 0.0;
      move[i] = ask[i];
    }
    for (int it = 0; it < p.smoothIterations; ++it) {
      for (std::size_t i = 0; i < n; ++i) {
        double s = 0;
        for (std::uint32_t k = first[i]; k < first[i + 1]; ++k)
          s += move[list[k]];
        const double deg = first[i + 1] - first[i];
        next[i] = (a.count[i] * ask[i] + p.smoothness * s) / (a.count[i] + p.smoothness * deg + p.stay);
      }
      move.swap(next);
    }
    for (std::size_t i = 0; i < n; ++i)
      mesh.vertices[i] = hull::add(mesh.vertices[i], hull::scaled(mesh.normals[i], move[i]));
    mesh.update();
  }
  return st;
}

} // namespace pm::model
