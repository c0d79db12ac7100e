#include "pm/sim/SimulatedPhotoModel.h"

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

} // namespace pm::sim
