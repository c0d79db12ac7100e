#include "pm/lab/SimulatedCalibration.h"

#include <cmath>
#include <random>

#include "pm/core/Error.h"
#include "pm/core/Pose.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/Scene.h"
#include "pm/sim/TargetShape.h"

namespace pm::lab {

namespace {

//! The board printed flat, seen without shadows, with the params' sensor noise and seed.
sim::Scene boardScene(const calib::Pattern &board, const SimulatedCalibrationParams &params)
{
  sim::SceneParams sp;
  sp.supersampling = 3;
  sp.noiseSigma = params.noiseSigma;
  sp.seed = params.seed;
  sp.shadows = sim::ShadowMode::Off;
  return sim::Scene(sim::flatPrint(board.render(8.0), board.widthMm(), "calibration pattern"), sp);
}

} // namespace

core::StereoRig labRigWithLens(const core::LensDistortion &lens)
{
  vpCameraParameters cam;
  cam.initPersProjWithoutDistortion(754, 754, 320, 240);
  core::StereoRig rig = core::StereoRig::symmetric(cam, 640, 480, 0.323, core::StereoRig::toeInFor(0.323, 0.5));
  rig.left.distortion = lens;
  rig.right.distortion = lens;
  rig.validate();
  return rig;
}

std::vector<calib::StereoImagePair> renderCalibrationPairs(const core::StereoRig &rig, const calib::Pattern &board, int n,
                                                           const SimulatedCalibrationParams &params,
                                                           const std::function<void()> &step)
{
  if (n < 1)
    throw core::Error("simulated calibration: at least one pair");
  rig.validate();
  board.validate();
  const sim::Scene scene = boardScene(board, params);
  std::mt19937 rng(static_cast<std::uint32_t>(params.seed));
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<calib::StereoImagePair> pairs;
  for (int k = 0; k < n; ++k) {
    // Every other pose near the middle, where both cameras see the whole board (the stereo pose);
    // the others off-centre and tilted, so that one camera's corners reach its image's edges, where
    // the lens bends most (its intrinsics).
    const double spread = k % 2 ? 1.0 : 0.3;
    const core::Phi p{160 * spread * u(rng), 120 * spread * u(rng), 450 + 60 * u(rng), 0.2 * u(rng), 0.2 * u(rng), 0.3 * u(rng)};
    const sim::StereoImages im = scene.renderStereo(rig, core::toHomogeneousMatrix(p), static_cast<std::uint64_t>(k));
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

CalibrationPass renderCalibrationViews(const core::PinholeCamera &camera, const calib::Pattern &board, int n,
                                       const SimulatedCalibrationParams &params, const std::function<void()> &step)
{
  if (n < 1)
    throw core::Error("simulated calibration: at least one view");
  camera.validate();
  board.validate();
  const sim::Scene scene = boardScene(board, params);
  std::mt19937 rng(static_cast<std::uint32_t>(params.seed));
  std::uniform_real_distribution<double> u(-1, 1);
  sim::Rasterizer raster;
  CalibrationPass pass;
  for (int k = 0; k < n; ++k) {
    // The board in the camera, the whole of it in view (a camera alone has no partner to use a
    // view that cuts it); the world is the
    // board's frame, so the hand sits at the inverse of the board's pose in the hand.
    const double spread = k % 2 ? 1.0 : 0.3;
    const core::Phi p{60 * spread * u(rng), 45 * spread * u(rng), 420 + 50 * u(rng), 0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)};
    const vpHomogeneousMatrix hMo = camera.hMc * core::toHomogeneousMatrix(p);
    calib::CalibrationView v;
    v.name = "simulated view " + std::to_string(k);
    scene.render(raster, camera, hMo, static_cast<std::uint64_t>(k), 0, v.image);
    pass.views.push_back(std::move(v));
    pass.fMh.push_back(hMo.inverse());
    if (step)
      step();
  }
  return pass;
}

} // namespace pm::lab
