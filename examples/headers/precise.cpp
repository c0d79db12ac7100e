// The usage examples of pm::precise's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/precise/ColourHistograms.h"
#include "pm/precise/InteriorTerm.h"
#include "pm/precise/ModelErrorFloor.h"
#include "pm/precise/OutlineViews.h"
#include "pm/precise/PoseUncertainty.h"
#include "pm/precise/PreciseStage.h"
#include "pm/precise/StereoOcclusion.h"

#include <iostream>
#include "pm/precise/CorrespondenceLines.h"
#include "pm/tracker/PhotoModelTracker.h"
namespace pm_examples {

// ColourHistograms.h
void exampleColourHistograms(const std::vector<vpRGBa> &targetPixels, const std::vector<vpRGBa> &backgroundPixels)
{
  pm::precise::ColourHistograms h;
  for (const vpRGBa &c : targetPixels) h.addForeground(c);
  for (const vpRGBa &c : backgroundPixels) h.addBackground(c);
  h.update(1.0, 1.0);            // the first frame: taken whole
  if (h.ready()) std::cout << h.posterior(vpRGBa(255, 0, 0)) << "\n";
}

// InteriorTerm.h
void exampleInteriorTerm(const pm::core::PhotoModel &model, const pm::precise::LineCamera &camera, const pm::precise::OutlineViews &outlines,
                         const double c[3], const pm::core::Phi &phi)
{
  const pm::precise::InteriorTerm interior(model, 200);  // model.hasColours
  pm::precise::InteriorSamples s;
  interior.reserve(s);
  interior.measure(camera, outlines.nearest(c), phi, 1.0, s);
  double g[6] = {0}, H[36] = {0};
  pm::precise::InteriorTerm::accumulate(camera, phi, s, 0.05, 1.0, g, H, nullptr);
}

// ModelErrorFloor.h
void exampleModelErrorFloor(const pm::core::PhotoModel &model, const pm::core::StereoRig &rig, const vpHomogeneousMatrix &hMm)
{
  const pm::precise::ModelErrorFloor floor(model.passLandings, rig.left.hMc); // 10 deg wide
  if (!floor.empty()) {
    const std::array<double, 6> f = floor.at(hMm);  // mm along x, y, z; deg about them (hand frame)
    std::cout << "the model's own error here: " << f[4] << " deg about y\n";
  }
}

// OutlineViews.h
void exampleOutlineViews(const pm::core::PhotoModel &model)
{
  const pm::precise::OutlineViews outlines(model);
  const double c[3] = {0, 0, -500};     // a camera 500 mm in front of the model's origin
  const pm::precise::OutlineViews::View &v = outlines.view(outlines.nearest(c));
  std::cout << (v.end - v.begin) << " outline points seen from there\n";
}

// PoseUncertainty.h
void examplePoseUncertainty(pm::tracker::PhotoModelTracker &tracker, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right)
{
  const pm::tracker::TrackResult r = tracker.track(left, right);
  if (r.uncertainty.known)
    std::cout << "1-sigma " << r.uncertainty.maxMm() << " mm, " << r.uncertainty.maxDeg() << " deg\n";
}

// StereoOcclusion.h
void exampleStereoOcclusion(const pm::core::PhotoModel &model, const pm::precise::LineCamera cams[2], const pm::precise::ModelInCamera poses[2],
                            const double centre[3], std::size_t i, double depthMm)
{
  const pm::precise::StereoOcclusion occlusion(model, pm::precise::StereoOcclusionParams());
  // cams[k]: the rig's cameras as the lines see them; poses[k]: the model in each camera's frame;
  // centre: the left camera's centre in the model frame (precise::cameraInModel)
  if (occlusion.hidden(cams[0], poses[0], centre, cams[1], poses[1], model.contour[i], cams[0].px / depthMm))
    std::cout << "contour point " << i << " is hidden in the left camera\n";
}

} // namespace pm_examples
