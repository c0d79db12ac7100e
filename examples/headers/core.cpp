// The usage examples of pm::core's headers, each as its header shows it: this file is compiled (not
// run), and scripts/header-examples.py checks that every example of a header is part of a file here.
// What an example takes as given (a fitness, a model) is its function's parameters.
#include <cmath>
#include <iostream>

#include <visp3/core/vpMath.h>
#include <visp3/io/vpImageIo.h>

#include "pm/core/BatchPool.h"
#include "pm/core/CameraImages.h"
#include "pm/core/CameraRig.h"
#include "pm/core/FitnessMap.h"
#include "pm/core/Hue.h"
#include "pm/core/HuePlane.h"
#include "pm/core/PhotoModel.h"
#include "pm/core/PinholeCamera.h"
#include "pm/core/Pose.h"
#include "pm/core/Quaternion.h"
#include "pm/core/Rounding.h"
#include "pm/core/Statistics.h"
#include "pm/core/StereoFitness.h"
#include "pm/core/StereoScorer.h"
#include "pm/core/HueFrame.h"
#include "pm/core/StereoRig.h"
#include "pm/core/TargetHues.h"
#include "pm/core/ViewpointIndex.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/RigFile.h"

#include "pm/core/LensDistortion.h"
#include "pm/core/UndistortMap.h"
#include "pm/core/Vec3.h"
namespace pm_examples {

// BatchPool.h
void exampleBatchPool()
{
  std::vector<double> out(20);
  pm::core::BatchPool::shared().run(out.size(), [&](std::size_t i) { out[i] = std::sqrt(static_cast<double>(i)); });
  // every out[i] is set here, whichever thread computed it
}

// FitnessMap.h
void exampleFitnessMap(const pm::core::StereoFitness &fitness, const pm::core::Phi &truth)
{
  // fitness: a pm::core::StereoFitness given its images; truth: the pm::core::Phi to map around
  const std::vector<pm::core::FitnessMapSpec> specs = pm::core::paperFitnessMaps();
  const pm::core::FitnessMap map = pm::core::computeFitnessMap(fitness, truth, specs[0]); // F over x-y, 1 mm steps
  std::cout << "peak at x = " << map.peakA << " mm, y = " << map.peakB << " mm\n";
}

// Hue.h
void exampleHue()
{
  const pm::core::Hsv c = pm::core::rgbToHsv(255, 128, 0);                  // orange: h = 30.1 deg, s = 1, v = 1
  const float d = pm::core::hueDistance(c.h, pm::core::hueDeg(vpRGBa(255, 0, 0))); // 30.1 deg from red
}

// HuePlane.h
void exampleHuePlane()
{
  vpImage<vpRGBa> I;
  vpImageIo::read(I, "left.png");
  pm::core::HuePlane plane;
  plane.compute(I, 0.1f);                        // pixels of saturation < 0.1 get kNoHue
  const std::uint16_t h = plane.at(320, 240);    // tenths of a degree
  if (h != pm::core::HuePlane::kNoHue)
    std::cout << "hue " << h / 10.0 << " deg\n";
  plane.compute(I, 0.1f, pm::core::PixelRect{100, 80, 300, 240}); // only columns [100, 300), rows [80, 240)
}

// PhotoModel.h
void examplePhotoModel()
{
  pm::core::PhotoModel m;                         // by hand: one red point, one point of background
  m.distanceMm = 500;
  m.px = m.py = 800;
  m.backgroundHue = 200;
  m.inner.push_back({0.f, 0.f, 0.f, 0.f, 320.f, 240.f});   // x, y, z (mm), hue (deg), u, v (px)
  m.outer.push_back({50.f, 0.f, 0.f, 200.f, 400.f, 240.f});
  m.validate("hand-made model");            // throws pm::core::Error if it cannot be used
  std::cout << m.size() << " points, " << (m.hasDepth() ? "3-D" : "flat") << "\n";
}

// PinholeCamera.h
void examplePinholeCamera()
{
  pm::core::PinholeCamera c;
  c.cam.initPersProjWithoutDistortion(754, 754, 320, 240); // px, py, u0, v0
  c.width = 640;
  c.height = 480;
  c.hMc.buildFrom(0.16, 0, 0, 0, -0.31, 0);                // on the hand: 160 mm to the right, toed in
  c.validate();
  const pm::core::PinholeCamera::Projection p = c.projection(); // placed in the hand frame
  double u, v, z;
  if (p.project({0, 0, 500}, u, v, z))                     // a point 500 mm ahead of the hand
    std::cout << u << " " << v << " at depth " << z << " mm\n";
}

// Pose.h
void examplePose()
{
  pm::core::Phi phi;
  phi.z = 500;                                       // 500 mm ahead of the hand
  phi.e3 = std::sin(0.5 * vpMath::rad(30));          // turned 30 deg about the hand's z axis
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(phi); // translation in metres
  const pm::core::StereoRig rig = pm::core::StereoRig::symmetric(vpCameraParameters(800, 800, 320, 240), 640, 480, 0.1, 0.0);
  const vpHomogeneousMatrix cMo = rig.left.cMh() * hMo;         // the model in the left camera
  const pm::core::Phi back = pm::core::fromHomogeneousMatrix(hMo);
  std::cout << back.toString() << ", " << pm::core::rotationDistanceDeg(phi, back) << " deg apart\n";
}

// Quaternion.h
void exampleQuaternion()
{
    const pm::core::Phi phi{0, 0, 500, 0.1, 0, 0};
    // The pose turned 90 deg about the model's own z axis (hRo Rz), its position kept:
    const pm::core::Phi turned = pm::core::withRotation(phi, pm::core::quaternionOf(phi) * pm::core::Quaternion::aboutZ(M_PI / 2));
    // The turn from phi to turned, and its angle (90 deg):
    const pm::core::Quaternion d = pm::core::quaternionOf(turned) * pm::core::quaternionOf(phi).conjugate();
    std::cout << d.angle() * 180 / M_PI << " deg\n";
}

// Rounding.h
void exampleRounding()
{
  const long a = pm::core::roundHalfAway(2.5), b = pm::core::roundHalfAway(-2.5); // 3 and -3
}

// Statistics.h
void exampleStatistics()
{
  const double p99 = pm::core::percentile({1.0, 2.0, 3.0, 4.0}, 0.99); // 4
  const double median = pm::core::percentile({1.0, 2.0, 3.0, 4.0}, 0.5); // 2
}
void exampleStatisticsMedian()
{
  const double m = pm::core::median({4.0, 1.0, 3.0, 2.0}); // 2.5
}

// StereoFitness.h
void exampleStereoFitness()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");              // pm/io/RigFile.h
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json");  // pm/io/PhotoModelFile.h
  pm::core::StereoFitness fitness(rig, model);       // the paper's parameters
  vpImage<vpRGBa> IL, IR;
  vpImageIo::read(IL, "left.png");
  vpImageIo::read(IR, "right.png");
  fitness.setImages(IL, IR);                   // a new pair: the hue planes
  pm::core::Phi phi;                                 // hMo: the model 500 mm ahead of the hand,
  phi.z = 500;                                 // its axes those of the hand
  const double F = fitness.evaluate(phi);      // the higher, the better phi fits the pair
  const pm::core::FitnessDetail d = fitness.evaluateDetail(phi);
  std::cout << "F = " << F << " (left " << d.score[0] << ", right " << d.score[1] << ")\n";
}

// StereoScorer.h
void exampleStereoScorer()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");              // pm/io/RigFile.h
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json");  // pm/io/PhotoModelFile.h
  const pm::core::StereoScorer scorer(rig, model); // the paper's parameters
  pm::core::HueFrame frame = scorer.newFrame();
  vpImage<vpRGBa> IL, IR;
  vpImageIo::read(IL, "left.png");
  vpImageIo::read(IR, "right.png");
  scorer.setImages(frame, IL, IR);                 // a new pair: the frame's hue planes
  pm::core::Phi phi;                               // hMo: the model 500 mm ahead of the hand,
  phi.z = 500;                                     // its axes those of the hand
  const double F = scorer.evaluate(frame, phi);    // the higher, the better phi fits the pair
}

// StereoScorer.h
void exampleStereoScorer2(const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame, const pm::core::Phi *children, std::size_t n,
                          double *F, double worstSurvivor, double margin, double *cost)
{
  scorer.evaluate(frame, children, n, F, worstSurvivor - margin, cost); // a GA's children
}

// StereoScorer.h
void exampleStereoScorer3(const pm::core::StereoScorer &scorer, const pm::core::HueFrame &frame, const pm::core::Phi &phi)
{
  double g[6], M[36];
  const double s = scorer.evaluateSmoothGradient(frame, phi, g, M); // climb along M^-1 g (SmoothAscent)
}

// HueFrame.h
void exampleHueFrame(const pm::core::StereoScorer &scorer, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR, const pm::core::Phi &phi)
{
  pm::core::HueFrame frame = scorer.newFrame(); // the model's background hue, no images yet
  scorer.setImages(frame, IL, IR);               // this pair's hue planes
  frame.setBackgroundHue(200);                   // a background that changed since the photos
  const double F = scorer.evaluate(frame, phi);
}

// HueFrame.h
void exampleHueFrame2(const pm::core::StereoScorer &scorer, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR)
{
  pm::core::HueFrame frame = scorer.newFrame();
  scorer.setImages(frame, IL, IR);
  std::cout << frame.plane(0).width() << " px wide, background hue " << frame.backgroundHue() << " deg\n";
}

// CameraRig.h
void exampleCameraRig()
{
  const pm::core::StereoRig stereo = pm::io::loadRig("data/rig/pa10_stereo.json");
  const pm::core::CameraRig both(stereo);                        // cameras[0] left, cameras[1] right
  const pm::core::CameraRig one(std::vector<pm::core::PinholeCamera>{stereo.left}); // the left camera alone
  one.validate();                                                // throws pm::core::Error naming what is wrong
  std::cout << one.size() << " camera, stereo: " << (one.isStereo() ? "yes" : "no") << "\n";
  const pm::core::StereoRig again = both.stereo();               // the two cameras as left and right
}

// StereoRig.h
void exampleCameraImages()
{
  vpImage<vpRGBa> IL, IR;
  const pm::core::CameraImages pair(IL, IR);        // a stereo rig's frame: 0 left, 1 right
  const pm::core::CameraImages one(IL);             // a one-camera rig's frame
  std::vector<vpImage<vpRGBa>> views(3);
  const pm::core::CameraImages three = pm::core::CameraImages::of(views); // camera k's image views[k]
  std::cout << pair.size() << " " << one.size() << " " << three.size() << "\n"; // 2 1 3
}

void exampleStereoRig()
{
  const vpCameraParameters cam(800, 800, 320, 240);            // px, py, u0, v0 (pixels)
  const double baseline = 0.1;                                 // metres
  pm::core::StereoRig rig = pm::core::StereoRig::symmetric(cam, 640, 480, baseline, pm::core::StereoRig::toeInFor(baseline, 0.5));
  rig.left.distortion.coefficients = {-0.27, 0.05, 0.001, 0.0, 0.0}; // the left lens (OpenCV's order)
  rig.validate();                                              // throws pm::core::Error naming what is wrong
  const vpHomogeneousMatrix cLMcR = rig.cLMcR();               // the right camera in the left one
}

// TargetHues.h
void exampleTargetHues(const pm::core::PhotoModel &model)
{
  const pm::core::TargetHues hues(model);
  const std::uint16_t h = pm::core::hueDeci(vpRGBa(200, 40, 30), 0.f);
  std::cout << (hues.has(h) ? "the target's" : "not the target's") << "\n";
}

// ViewpointIndex.h
void exampleViewpointIndex(const pm::core::PhotoModel &model)
{
  const pm::core::ViewpointIndex views(model);
  const double camera[3] = {0, 0, -500};          // a camera 500 mm in front of the model's origin
  const std::size_t k = views.nearest(camera);    // 0: the model's own view
}

// LensDistortion.h
void exampleLensDistortion(const vpCameraParameters &cam, const vpImagePoint &ideal)
{
  pm::core::LensDistortion d{{-0.27, 0.05, 0.001, 0.0, 0.0}};
  d.validate(cam, 640, 480, "left camera");            // throws if it folds the image
  const vpImagePoint raw = d.distort(cam, ideal);     // where an ideal pixel lands in the raw image
  const vpImagePoint back = d.undistort(cam, raw);    // and back
}

// PhotoModel.h
void examplePhotoModelFile()
{
  pm::core::PhotoModel m = pm::io::loadPhotoModel("model.json");   // version 1 (flat), 2 or 3 (depth)
  if (m.hasDepth()) std::cout << "relief " << m.depthRangeMm[0] << " to " << m.depthRangeMm[1] << " mm\n";
}

// TargetHues.h
void exampleTargetHuesFile(const pm::core::PhotoModel &model, const vpRGBa &pixel)
{
  const pm::core::TargetHues hues(model);
  if (hues.has(pm::core::hueDeci(pixel, 0.f)))
    std::cout << "a colour of the target's own\n";
}

// UndistortMap.h
void exampleUndistortMap(const pm::core::StereoRig &rig, const vpImage<vpRGBa> &rawLeft, pm::core::HuePlane &plane)
{
  const pm::core::UndistortMap map(rig.left);           // once
  vpImage<vpRGBa> ideal;
  map.undistort(rawLeft, ideal);                  // a photo for the builder
  plane.compute(rawLeft, 0.1f, map);              // the hue plane in the ideal image
}

// Vec3.h
void exampleVec3()
{
  const pm::core::Vec3 a{0, 0, 500}, b{10, 0, 500};
  const double d = std::sqrt(pm::core::dot(pm::core::sub(b, a), pm::core::sub(b, a))); // 10 mm
}

} // namespace pm_examples
