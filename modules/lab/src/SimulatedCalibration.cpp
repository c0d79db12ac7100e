#include "pm/lab/SimulatedCalibration.h"

#include <cmath>
#include <random>

#include "pm/core/Error.h"
#include "pm/core/Pose.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetShape.h"

namespace pm::lab {

StereoRig labRigWithLens(const LensDistortion &lens)
{
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(754, 754, 320, 240);
  StereoRig rig = StereoRig::symmetric(cam, 640, 480, 0.323, StereoRig::toeInFor(0.323, 0.5));
  rig.left.distortion = lens;
  rig.right.distortion = lens;
  rig.validate();
  return rig;
}

std::vector<calib::StereoImagePair> renderCalibrationPairs(const StereoRig &rig, const calib::Pattern &board, int n,
                                                           const SimulatedCalibrationParams &params,
                                                           const std::function<void()> &step)
{
  if (n < 1)
    throw Error("simulated calibration: at least one pair");
  rig.validate();
  board.validate();
  sim::SceneParams sp;
  sp.supersampling = 3;
  sp.noiseSigma = params.noiseSigma;
  sp.seed = params.seed;
  sp.shadows = sim::ShadowMode::Off;
  const sim::Scene scene(sim::flatPrint(board.render(8.0), board.widthMm(), "calibration pattern"), sp);
  std::mt19937 rng(static_cast<std::uint32_t>(params.seed));
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<calib::StereoImagePair> pairs;
  for (int k = 0; k < n; ++k) {
    // Every other pose near the middle, where both cameras see the whole board (the stereo pose);
    // the others off-centre and tilted, so that one camera's corners reach its image's edges, where
    // the lens bends most (its intrinsics).
    const double spread = k % 2 ? 1.0 : 0.3;
    const Phi p{160 * spread * u(rng), 120 * spread * u(rng), 450 + 60 * u(rng), 0.2 * u(rng), 0.2 * u(rng), 0.3 * u(rng)};
    const sim::StereoImages im = scene.renderStereo(rig, toHomogeneousMatrix(p), static_cast<std::uint64_t>(k));
    calib::StereoImagePair pair;
    pair.name = "simulated pair " + std::to_string(k);
    pair.left = im.left;
    pair.right = im.right;
    pairs.push_back(std::move(pair));
    if (step)
      step();
  }
  return pairs;
}

namespace {
double cameraMapRms(const RigCamera &est, const RigCamera &truth)
{
  std::vector<vpImagePoint> raw;
  for (unsigned v = 0; v <= truth.height; v += truth.height / 12)
    for (unsigned u = 0; u <= truth.width; u += truth.width / 16)
      raw.emplace_back(std::min<double>(v, truth.height - 1), std::min<double>(u, truth.width - 1));
  const std::vector<vpImagePoint> ideal = truth.distortion.undistort(truth.cam, raw);
  double s2 = 0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    // The ray of the true camera through this raw pixel, seen by the estimated camera.
    const double x = (ideal[i].get_u() - truth.cam.get_u0()) / truth.cam.get_px();
    const double y = (ideal[i].get_v() - truth.cam.get_v0()) / truth.cam.get_py();
    const vpImagePoint e(est.cam.get_v0() + y * est.cam.get_py(), est.cam.get_u0() + x * est.cam.get_px());
    const vpImagePoint d = est.distortion.distort(est.cam, e);
    s2 += vpImagePoint::sqrDistance(d, raw[i]);
  }
  return std::sqrt(s2 / static_cast<double>(raw.size()));
}
} // namespace

CalibrationErrors compareRigs(const StereoRig &estimated, const StereoRig &truth)
{
  CalibrationErrors e;
  const vpHomogeneousMatrix a = estimated.cLMcR(), b = truth.cLMcR();
  const vpTranslationVector ta = a.getTranslationVector(), tb = b.getTranslationVector();
  e.baselineErrorMm = (ta.frobeniusNorm() - tb.frobeniusNorm()) * 1e3;
  e.translationErrorMm = (ta - tb).frobeniusNorm() * 1e3;
  e.rotationErrorDeg = (b.inverse() * a).getThetaUVector().getTheta() * 180.0 / M_PI;
  e.reprojectionRmsPx[0] = cameraMapRms(estimated.left, truth.left);
  e.reprojectionRmsPx[1] = cameraMapRms(estimated.right, truth.right);
  return e;
}

} // namespace pm::lab
