#include "pm/lab/TargetRendering.h"

#include <chrono>
#include <numeric>

#include <nlohmann/json.hpp>

#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/report/Overlay.h"

namespace pm::lab {

namespace {

//! Half the size, each pixel the mean of four.
vpImage<vpRGBa> halfSize(const vpImage<vpRGBa> &I)
{
  vpImage<vpRGBa> o(I.getHeight() / 2, I.getWidth() / 2);
  for (unsigned v = 0; v < o.getHeight(); ++v)
    for (unsigned u = 0; u < o.getWidth(); ++u) {
      unsigned s[3] = {0, 0, 0};
      for (unsigned j = 0; j < 2; ++j)
        for (unsigned i = 0; i < 2; ++i) {
          const vpRGBa &p = I[2 * v + j][2 * u + i];
          s[0] += p.R, s[1] += p.G, s[2] += p.B;
        }
      o[v][u] = vpRGBa(static_cast<unsigned char>(s[0] / 4), static_cast<unsigned char>(s[1] / 4),
                       static_cast<unsigned char>(s[2] / 4));
    }
  return o;
}

const vpRGBa white(255, 255, 255);

} // namespace

RenderedTarget renderTarget(const sim::Scene &scene, const sim::TargetShape &shape, const core::CameraRig &rig, const core::Phi &phi,
                            int repeat, const std::function<void(std::size_t)> &step)
{
  if (repeat < 1)
    throw core::Error("renderTarget: repeat must be at least 1, not " + std::to_string(repeat));
  RenderedTarget t;
  t.code = shape.info.code;
  t.name = shape.info.name;
  for (const core::PinholeCamera &c : rig.cameras)
    t.cameras.push_back(c.name);
  const vpHomogeneousMatrix hMo = core::toHomogeneousMatrix(phi);
  double ms = 0;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    t.views = scene.renderRig(rig, hMo, static_cast<std::uint64_t>(r));
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (step)
      step(1);
  }
  t.renderStereoMs = ms / repeat;
  // The relief seen from three sides: turned about y by -0.3, 0, +0.3 (quaternion vector).
  sim::Rasterizer raster;
  for (int k = 0; k < 3; ++k) {
    core::Phi p = phi;
    p.e2 = (k - 1) * 0.3;
    scene.render(raster, rig[0], core::toHomogeneousMatrix(p), 0, 0, t.turned[k]);
  }
  if (step)
    step(2);
  t.nominalSizeMm[0] = shape.info.widthMm;
  t.nominalSizeMm[1] = shape.info.heightMm;
  t.nominalSizeMm[2] = shape.info.depthMm;
  shape.measuredExtent(t.measuredOutlineMm[0], t.measuredOutlineMm[1]);
  t.triangles = scene.targetTriangles();
  return t;
}

double writeRenderedTargets(const std::string &dir, const std::vector<RenderedTarget> &targets, const core::Phi &phi,
                            const sim::SceneParams &sp, bool gallery)
{
  if (targets.empty())
    throw core::Error("writeRenderedTargets: no target");
  io::StagedFiles files(dir);
  nlohmann::json list = nlohmann::json::array();
  std::vector<vpImage<vpRGBa>> thumbs;
  double sumMs = 0;
  for (const RenderedTarget &t : targets) {
    const std::string &c = t.code;
    vpImage<vpRGBa> all;
    for (std::size_t k = 0; k < t.views.size(); ++k) {
      io::writeImage(t.views[k], files.stage(c + "_" + t.cameras[k] + ".png"));
      vpImage<vpRGBa> labelled = t.views[k];
      report::drawLabel(labelled, k == 0 ? c + " " + t.name + " - " + t.cameras[k] : t.cameras[k], 8, 8, white);
      all = k == 0 ? labelled : report::sideBySide(all, labelled);
    }
    io::writeImage(all, files.stage(c + (t.views.size() == 2 ? "_stereo.png" : "_views.png")));
    vpImage<vpRGBa> rel =
        report::sideBySide(report::sideBySide(halfSize(t.turned[0]), halfSize(t.turned[1])), halfSize(t.turned[2]));
    report::drawLabel(rel, c + " turned eps2 = -0.3, 0, +0.3 (" + t.cameras[0] + " camera)", 6, 6, white);
    io::writeImage(rel, files.stage(c + "_relief.png"));
    list.push_back({{"code", c},
                    {"name", t.name},
                    {"nominal_size_mm", {t.nominalSizeMm[0], t.nominalSizeMm[1], t.nominalSizeMm[2]}},
                    {"measured_outline_mm", {t.measuredOutlineMm[0], t.measuredOutlineMm[1]}},
                    {"triangles", t.triangles},
                    {"render_stereo_ms", t.renderStereoMs}});
    vpImage<vpRGBa> th = halfSize(t.views[0]);
    report::drawLabel(th, c + " " + t.name, 4, 4, white);
    thumbs.push_back(th);
    sumMs += t.renderStereoMs;
  }
  if (gallery) {
    const unsigned tw = thumbs[0].getWidth(), th = thumbs[0].getHeight();
    const unsigned rows = static_cast<unsigned>((thumbs.size() + 3) / 4);
    vpImage<vpRGBa> g(rows * th, 4 * tw);
    for (std::size_t i = 0; i < thumbs.size(); ++i)
      g.insert(thumbs[i], vpImagePoint(static_cast<double>((i / 4) * th), static_cast<double>((i % 4) * tw)));
    io::writeImage(g, files.stage("gallery.png"));
  }
  const double meanMs = sumMs / static_cast<double>(targets.size());
  const nlohmann::json summary{{"pose", {phi.x, phi.y, phi.z, phi.e1, phi.e2, phi.e3}},
                               {"supersampling", sp.supersampling},
                               {"noise_sigma", sp.noiseSigma},
                               {"exposure", sp.exposure},
                               {"occluder", sp.occluder},
                               {"sweeping_bar", sp.sweepingBar},
                               {"still_backdrop", sp.stillBackdrop},
                               {"clutter", sp.clutter},
                               {"gripper", sp.gripper},
                               {"render_stereo_ms_mean", meanMs},
                               {"targets", list}};
  io::writeTextFile(files.stage("summary.json"), summary.dump(2) + "\n");
  files.commit();
  return meanMs;
}

} // namespace pm::lab
