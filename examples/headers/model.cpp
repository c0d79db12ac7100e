// The usage examples of pm::model's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/BackgroundSubtraction.h"
#include "pm/model/HullMesh.h"
#include "pm/model/PassLandings.h"
#include "pm/model/PhotoModelBuilder.h"
#include "pm/model/StereoDepth.h"
#include "pm/model/StereoPhotoModelBuilder.h"
#include "pm/model/SurfaceFusion.h"
#include "pm/model/VisualHull.h"

#include <iostream>
namespace pm_examples {

// What an example leaves to its reader (declared, never defined: this file is compiled, never linked).
bool facesCamera(const pm::model::HullMesh &mesh, std::int32_t face, const pm::model::hull::Vec3 &C);
void use(const pm::model::MeshEdge &e);
void use(const pm::model::hull::Vec3 &X);

// BackgroundSubtraction.h
void exampleBackgroundSubtraction(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background)
{
  int shadow = 0;
  const cv::Mat target = pm::model::subtractBackground(photo, background, pm::model::BackgroundParams(), &shadow);
  std::cout << cv::countNonZero(target) << " target pixels, " << shadow << " shadow pixels\n";
}

// HullMesh.h
void exampleHullMesh(const pm::model::VisualHull &hull, const std::vector<const pm::model::hull::HullView *> &cams, const pm::model::hull::Vec3 &C)
{
  const pm::model::HullMesh mesh = pm::model::meshVisualHull(hull, cams);
  for (const pm::model::MeshEdge &e : mesh.edges)
    if (e.f1 >= 0 && facesCamera(mesh, e.f0, C) != facesCamera(mesh, e.f1, C)) use(e); // on the outline
}

// PassLandings.h
void examplePassLandings(const pm::core::StereoRig &rig, const std::vector<pm::model::PassView> &pass)
{
  const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass); // measures them (AllAroundParams::passLandings)
  for (const pm::core::PassLanding &l : b.model.passLandings)
    std::cout << l.offsetDeg[0] << " " << l.offsetDeg[1] << " " << l.offsetDeg[2] << " deg\n";
}

// StereoDepth.h
void exampleStereoDepth(const pm::core::StereoRig &rig, const vpImage<vpRGBa> &L)
{
  const pm::model::stereo::Rectification rect(rig);
  const cv::Mat left = rect.remap(pm::model::stereo::toBgr(L), 0);   // the rectified left image
  std::cout << "500 mm lies at a disparity of " << rect.disparityAt(500) << " px\n";
}

// SurfaceFusion.h
void exampleSurfaceFusion(const pm::core::StereoRig &idealRig, const std::vector<pm::model::hull::HullView> &cams,
                          const std::vector<vpImage<unsigned char>> &masks, const std::vector<vpImage<vpRGBa>> &backgrounds,
                          const std::vector<bool> &used, const pm::model::VisualHull &hull, const pm::model::FusionParams &params)
{
  const pm::model::DepthEvidence ev = pm::model::measureStereo(idealRig, cams, masks, backgrounds, used, false, hull, params);
  const double f = ev.field({0, 0, 500});   // mm: > 0 behind the measured surface, < 0 in front, +inf: no evidence
}

// VisualHull.h
void exampleVisualHull(const std::vector<const pm::model::hull::HullView *> &cams, const pm::model::hull::Vec3 &centre)
{
  pm::model::VisualHull hull = pm::model::hullGrid(centre, 120, 1.0);
  pm::model::carveVisualHull(cams, hull, 16.0);
  for (int z = 0; z < hull.n; ++z) // the occupied cells' centres
    for (int y = 0; y < hull.n; ++y)
      for (int x = 0; x < hull.n; ++x)
        if (hull.at(x, y, z)) use(hull.centre(x, y, z));
}

} // namespace pm_examples
