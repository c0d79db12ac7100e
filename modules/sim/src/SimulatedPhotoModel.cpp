#include "pm/sim/SimulatedPhotoModel.h"

#include <cmath>

#include "pm/core/Error.h"

namespace pm::sim {

SimulatedPhotoModel makeSimulatedPhotoModel(const Scene &scene, const vpCameraParameters &cam, unsigned w, unsigned h,
                                            double distanceMm, const PhotoModelParams &params)
{
  SimulatedPhotoModel s;
  scene.renderPhotos(cam, w, h, distanceMm, s.background, s.photo);
  s.build = buildPhotoModel(s.background, s.photo, cam, distanceMm, params);
  const PhotoModel &m = s.build.model;
  s.oMm = vpHomogeneousMatrix((m.centroidU - m.u0) * m.distanceMm / m.px * 1e-3,
                              (m.centroidV - m.v0) * m.distanceMm / m.py * 1e-3, 0, 0, 0, 0);
  return s;
}

SimulatedPhotoModel makeSimulatedStereoPhotoModel(const Scene &scene, const StereoRig &rig, double distanceMm,
                                                  const StereoModelParams &params)
{
  if (!(distanceMm > 0) || !std::isfinite(distanceMm))
    throw Error("photo distance must be positive");
  SimulatedPhotoModel s;
  s.stereo = true;
  const vpHomogeneousMatrix hMo(0, 0, distanceMm * 1e-3, 0, 0, 0);
  Rasterizer r;
  // Streams 4 to 7: images of their own noise, apart from the tracking frames' (0, 1).
  scene.render(r, rig.left, hMo, 0, 4, s.background, false);
  scene.render(r, rig.right, hMo, 0, 5, s.backgroundRight, false);
  scene.render(r, rig.left, hMo, 0, 6, s.photo, true);
  scene.render(r, rig.right, hMo, 0, 7, s.photoRight, true);
  StereoPhotoModelBuild b = buildStereoPhotoModel(rig, s.background, s.backgroundRight, s.photo, s.photoRight, params);
  s.build.model = std::move(b.model);
  s.build.region = std::move(b.regionLeft);
  s.depth = std::move(b.depthLeft);
  s.backdropMm = b.backdropMm;
  s.nOutFallback = b.nOutFallback;
  s.dropped = std::move(b.dropped);
  s.oMm = hMo.inverse() * b.hMm;
  return s;
}

} // namespace pm::sim
