#include "pm/sim/SimulatedPhotoModel.h"

#include <cmath>
#include <limits>

#include <visp3/core/vpThetaUVector.h>

#include "pm/core/Error.h"

namespace pm::sim {

SimulatedPhotoModel makeSimulatedPhotoModel(const Scene &inScene, const vpCameraParameters &cam, unsigned w, unsigned h,
                                            double distanceMm, const model::PhotoModelParams &params)
{
  const Scene scene = inScene.targetAlone();
  SimulatedPhotoModel s;
  scene.renderPhotos(cam, w, h, distanceMm, s.background, s.photo);
  s.build = model::buildPhotoModel(s.background, s.photo, cam, distanceMm, params);
  const core::PhotoModel &m = s.build.model;
  s.oMm = vpHomogeneousMatrix((m.centroidU - m.u0) * m.distanceMm / m.px * 1e-3,
                              (m.centroidV - m.v0) * m.distanceMm / m.py * 1e-3, 0, 0, 0, 0);
  return s;
}

SimulatedPhotoModel makeSimulatedStereoPhotoModel(const Scene &inScene, const core::StereoRig &rig, double distanceMm,
                                                  const model::StereoModelParams &params, double viewTurnDeg)
{
  const Scene scene = inScene.targetAlone();
  if (!(distanceMm > 0) || !std::isfinite(distanceMm))
    throw core::Error("photo distance must be positive");
  if (!(viewTurnDeg >= 0 && viewTurnDeg <= 45))
    throw core::Error("the further views' turn must lie in [0, 45] deg");
  SimulatedPhotoModel s;
  s.stereo = true;
  s.photoHMo = vpHomogeneousMatrix(0, 0, distanceMm * 1e-3, 0, 0, 0);
  const vpHomogeneousMatrix hMo(0, 0, distanceMm * 1e-3, 0, 0, 0);
  Rasterizer r;
  // Streams 4 to 7: images of their own noise, apart from the tracking frames' (0, 1).
  scene.render(r, rig.left, hMo, 0, 4, s.background, false);
  scene.render(r, rig.right, hMo, 0, 5, s.backgroundRight, false);
  scene.render(r, rig.left, hMo, 0, 6, s.photo, true);
  if (!rig.left.distortion.isNone()) {
    // The model's pixels are the ideal image's: the true depth of that image (a pinhole render).
    core::PinholeCamera ideal = rig.left;
    ideal.distortion = core::LensDistortion();
    vpImage<vpRGBa> unused;
    scene.render(r, ideal, hMo, 0, 6, unused, true);
  }
  // The toy's true depth at each left pixel, from the renderer's depth buffer (id 2: the toy).
  const vpHomogeneousMatrix hMc = rig.left.hMc;
  const vpCameraParameters &c = rig.left.cam;
  s.trueDepth.resize(rig.left.height, rig.left.width, std::numeric_limits<float>::quiet_NaN());
  for (unsigned v = 0; v < rig.left.height; ++v)
    for (unsigned u = 0; u < rig.left.width; ++u) {
      const double z = r.depthAt(u, v, 2);
      if (std::isfinite(z)) {
        const double x = (u - c.get_u0()) / c.get_px() * z, y = (v - c.get_v0()) / c.get_py() * z;
        s.trueDepth[v][u] = static_cast<float>(1e3 * (hMc[2][0] * x + hMc[2][1] * y + hMc[2][2] * z + hMc[2][3]));
      }
    }
  scene.render(r, rig.right, hMo, 0, 7, s.photoRight, true);
  // Further views: the hand moved around the scene (toy, backdrop and light turned together about
  // the toy's origin) by +-viewTurnDeg about the hand's x and y axes.
  std::vector<model::StereoViewPair> more;
  if (viewTurnDeg > 0) {
    const double a = viewTurnDeg * M_PI / 180.0;
    const double axes[4][3] = {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}};
    for (int k = 0; k < 4; ++k) {
      const vpHomogeneousMatrix turn(vpTranslationVector(0, 0, 0), vpThetaUVector(axes[k][0], axes[k][1], axes[k][2]));
      const vpHomogeneousMatrix hMoK = turn * hMo; // turned about the hand's axes through the toy's origin
      const vpHomogeneousMatrix hMoT(hMo.getTranslationVector(), hMoK.getRotationMatrix());
      model::StereoViewPair pr;
      const std::uint64_t frame = static_cast<std::uint64_t>(k + 1);
      scene.render(r, rig.left, hMoT, frame, 4, pr.backgroundLeft, false);
      scene.render(r, rig.right, hMoT, frame, 5, pr.backgroundRight, false);
      scene.render(r, rig.left, hMoT, frame, 6, pr.left, true);
      scene.render(r, rig.right, hMoT, frame, 7, pr.right, true);
      pr.hMh0 = hMoT * hMo.inverse();
      more.push_back(std::move(pr));
    }
  }
  model::StereoPhotoModelBuild b = model::buildStereoPhotoModel(rig, s.background, s.backgroundRight, s.photo, s.photoRight, more, params);
  s.build.model = std::move(b.model);
  s.build.region = std::move(b.regionLeft);
  s.depth = std::move(b.depthLeft);
  s.backdropMm = b.backdropMm;
  s.nOutFallback = b.nOutFallback;
  s.dropped = std::move(b.dropped);
  s.oMm = hMo.inverse() * b.hMm;
  return s;
}

std::vector<double> SimulatedPhotoModel::inDepthErrorsMm() const
{
  std::vector<double> e;
  if (!stereo)
    return e;
  const core::PhotoModel &m = build.model;
  const vpHomogeneousMatrix hMm = photoHMo * oMm;
  for (const core::ModelPoint &p : m.inner) {
    const long u = std::lround(p.u), v = std::lround(p.v);
    float t = std::numeric_limits<float>::quiet_NaN();
    if (u >= 0 && v >= 0 && u < static_cast<long>(trueDepth.getWidth()) && v < static_cast<long>(trueDepth.getHeight()))
      t = trueDepth[static_cast<unsigned>(v)][static_cast<unsigned>(u)];
    const double z = 1e3 * (hMm[2][0] * p.x * 1e-3 + hMm[2][1] * p.y * 1e-3 + hMm[2][2] * p.z * 1e-3 + hMm[2][3]);
    e.push_back(z - static_cast<double>(t));
  }
  return e;
}

} // namespace pm::sim
