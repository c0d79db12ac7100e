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
#include "pm/precise/InteriorTerm.h"
#include "pm/precise/OutlineViews.h"
#include "pm/precise/IdealImage.h"
namespace pm_examples {

// What an example leaves to its reader (declared, never defined: this file is compiled, never linked).
void use(const pm::core::ContourPoint &p);

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
void exampleModelErrorFloor(const pm::core::PhotoModel &model, const pm::core::StereoRig &rig, const pm::core::Phi &phi)
{
  const pm::precise::ModelErrorFloor floor(model.passLandings, rig.left.hMc); // 10 deg wide
  if (!floor.empty()) {
    const std::array<double, 6> f = floor.at(phi);  // the model at phi: mm along x, y, z; deg about them (hand frame)
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

// ColourHistograms.h
void exampleColourHistogramsFile(const pm::core::PhotoModel &model)
{
  pm::precise::ColourHistograms h;
  h.start(model.foregroundHistogram, model.backgroundHistogram);   // the model's photos
  h.addForeground(vpRGBa(200, 40, 30)); h.addBackground(vpRGBa(30, 60, 200));
  h.update(0.2, 0.2);                                               // a frame's colours blended in
  const float pf = h.posterior(vpRGBa(190, 50, 30));               // near 1: the target's colour
}

// CorrespondenceLines.h
void exampleCorrespondenceLines(const pm::precise::LineCamera &camera, const pm::precise::OutlineViews &outlines, const pm::core::Phi &phi,
                                const pm::precise::LineShape &shape, const pm::precise::ColourHistograms &colours, double weight)
{
  pm::precise::CorrespondenceLines lines(200, 19, 6);
  lines.measure(camera, outlines, phi, shape, colours, 2, 150, 3.0);
  double g[6] = {0}, H[36] = {0};
  lines.accumulate(camera, phi, weight, g, H, nullptr);
}

// InteriorTerm.h
void exampleInteriorTermFile(const pm::core::PhotoModel &model, const pm::precise::LineCamera &camera, std::size_t view, const pm::core::Phi &phi,
                             pm::precise::InteriorSamples &samples, double g[6], double H[36])
{
  pm::precise::InteriorTerm interior(model, 200);
  interior.measure(camera, view, phi, 1.0, samples);          // at each step
  pm::precise::InteriorTerm::accumulate(camera, phi, samples, 0.05, 1.0, g, H, nullptr); // each step
}

// OutlineViews.h
void exampleOutlineViewsFile(const pm::core::PhotoModel &model, const double cameraInModelMm[3])
{
  const pm::precise::OutlineViews outlines(model);             // throws unless model.hasContours()
  const std::size_t k = outlines.nearest(cameraInModelMm);
  for (std::size_t i = outlines.view(k).begin; i < outlines.view(k).end; ++i) use(outlines.point(i));
}

// PreciseStage.h
void examplePreciseStageFile(const pm::core::StereoRig &rig, const pm::core::PhotoModel &model, const vpImage<vpRGBa> &IL, const vpImage<vpRGBa> &IR,
                             const pm::core::Phi &rmgaBest, pm::core::Phi &phi)
{
  pm::precise::PreciseStage precise(rig, model);           // the model must carry outlines (version 5)
  precise.setImages({IL, IR});                    // the frame, one image per camera (kept by pointer until the next)
  const pm::precise::PreciseResult r = precise.refine(rmgaBest);
  if (r.ok) { phi = r.phi; precise.learnColours(phi); }
}

// StereoOcclusion.h
void exampleStereoOcclusionFile(const pm::core::PhotoModel &model, const pm::precise::LineCamera &left, const pm::precise::ModelInCamera &leftPose,
                                const double leftCentre[3], const pm::precise::LineCamera &right, const pm::precise::ModelInCamera &rightPose,
                                const pm::core::ContourPoint &contourPoint, double pxPerMm)
{
  pm::precise::StereoOcclusion occlusion(model, pm::precise::StereoOcclusionParams());
  const bool h = occlusion.hidden(left, leftPose, leftCentre, right, rightPose, contourPoint, pxPerMm);
}

// IdealImage.h
void exampleIdealImage(const pm::core::PinholeCamera &camera, const vpImage<vpRGBa> &raw)
{
  pm::precise::IdealImage ideal(std::make_shared<pm::core::UndistortMap>(camera));
  ideal.setRaw(raw);                                 // each frame: nothing resampled yet
  const vpRGBa *pixels = ideal.cover(100, 80, 420, 360); // the ideal image, right within that rectangle
}

} // namespace pm_examples
