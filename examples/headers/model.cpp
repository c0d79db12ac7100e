// The usage examples of pm::model's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/AllAroundParams.h"
#include "pm/model/BackgroundSubtraction.h"
#include "pm/model/HullMesh.h"
#include "pm/model/PassLandings.h"
#include "pm/model/PhotoModelBuilder.h"
#include "pm/model/StereoDepth.h"
#include "pm/model/StereoPhotoModelBuilder.h"
#include "pm/model/SurfaceFusion.h"
#include "pm/model/VisualHull.h"

#include <iostream>
#include "pm/io/PhotoModelFile.h"
#include "pm/io/ViewsFolder.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/BilinearColour.h"
#include "pm/model/EdgeBlur.h"
#include "pm/model/HullGeometry.h"
#include "pm/model/OutlineRefinement.h"
#include "pm/model/PassPlanner.h"
#include "pm/model/PassRig.h"
#include "pm/io/RigFile.h"
#include "pm/model/PassView.h"
#include "pm/model/Silhouette.h"
#include "pm/model/StereoPhotoModelBuilder.h"
#include "pm/model/SubpixelOutline.h"
#include "pm/model/ViewpointModel.h"
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

// AllAroundModelBuilder.h
void exampleAllAroundModelBuilder(const pm::core::StereoRig &rig)
{
  const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder("views", rig, 6);
  const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass);
  pm::io::savePhotoModel(b.model, "model.json");
  std::cout << b.surface.size() << " surface points, hull " << b.hullVolumeCm3 << " cm3\n";
}

// AllAroundParams.h
void exampleAllAroundParams()
{
  pm::model::AllAroundParams p;
  p.viewpoints.count = 120;       // a lighter model: half the viewpoints
  p.surface.refineOutlines = true; // the outlines to a fraction of a pixel
  p.validate();                   // throws pm::core::Error naming the first value out of range
}

// BilinearColour.h
void exampleBilinearColour(const vpImage<vpRGBa> &photo)
{
  const std::array<double, 3> rgb = pm::model::bilinearColour(photo, 120.25, 64.5);
}

// EdgeBlur.h
void exampleEdgeBlur(const vpImage<unsigned char> &mask, const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background)
{
  const pm::model::EdgeWidth w = pm::model::edgeWidth(mask, photo, &background);
  if (w.samples >= 50) std::cout << "the outline rises over " << w.widthPx << " px\n";
}

// HullGeometry.h
void exampleHullGeometry(const vpHomogeneousMatrix &wMc, const pm::core::StereoRig &rig, const vpImage<unsigned char> &mask)
{
  pm::model::hull::HullView v;
  v.cam = pm::core::PinholeCamera::Projection(wMc, rig.left.cam, 640, 480); // wMc in metres
  v.signedDist = pm::model::hull::signedDistance(mask);
  double u, z, w;
  if (v.cam.project({0, 0, 500}, u, w, z) && v.sd(u, w) > 0) std::cout << "inside the silhouette\n";
}

// HullMesh.h
void exampleHullMeshFile(const pm::model::VisualHull &hull, const std::vector<const pm::model::hull::HullView *> &cams)
{
  const pm::model::HullMesh mesh = pm::model::meshVisualHull(hull, cams);
  std::cout << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles\n";
}

// OutlineRefinement.h
void exampleOutlineRefinement(pm::model::HullMesh &mesh, const std::vector<const pm::model::hull::HullView *> &usedCams)
{
  pm::model::OutlineRefinementStats st = pm::model::refineOutlines(mesh, usedCams, pm::model::OutlineRefinementParams());
  std::cout << "outline residual " << st.meanBeforePx << " -> " << st.meanAfterPx << " px\n";
}

// PassPlanner.h
void examplePassRig()
{
  const pm::core::CameraRig mono = pm::io::loadCameraRig("data/rig/pa10_mono.json");
  const pm::core::StereoRig pair = pm::model::passRig(mono);  // the camera and its side step
  const vpHomogeneousMatrix step = pm::model::sideStep(mono); // the hand's motion to the second image
  std::cout << pair.right.hMc.getTranslationVector().t() << "\n" << step << "\n";
}

void examplePassPlanner()
{
  const std::vector<vpHomogeneousMatrix> h0Mh = pm::model::planPass(pm::model::PassPlan());  // 16 poses
  // a robot: fMh_k = fMh0 * h0Mh[k], reached (and refused if not) by its own kinematics
}

// PassView.h
void examplePassView(const pm::core::StereoRig &rig)
{
  std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder("views", rig);
  std::cout << pass.size() << " views, the first from " << pass[0].fMh.getTranslationVector().t() << "\n";
}

// Silhouette.h
void exampleSilhouette(const pm::model::PassView &view)
{
  pm::model::SilhouetteStats st;
  const vpImage<unsigned char> mask = pm::model::silhouette(view.left, view.backgroundLeft, pm::model::SilhouetteParams(), &st);
  std::cout << st.shadowPx << " shadow pixels dropped\n";
}

// StereoDepth.h
void exampleStereoDepthFile(const pm::core::StereoRig &rig, const vpImage<vpRGBa> &L, const vpImage<vpRGBa> &R, const vpImage<unsigned char> &region)
{
  const pm::model::stereo::Rectification rect(rig);                  // once per rig (pinhole cameras)
  const cv::Mat z = pm::model::stereo::leftDepth(rect, L, R, region, 400, 600, pm::model::stereo::MatchParams());
}

// StereoPhotoModelBuilder.h
void exampleStereoPhotoModelBuilder(const pm::core::StereoRig &rig, const vpImage<vpRGBa> &bgL, const vpImage<vpRGBa> &bgR, const vpImage<vpRGBa> &L, const vpImage<vpRGBa> &R)
{
  const pm::model::StereoPhotoModelBuild b = pm::model::buildStereoPhotoModel(rig, bgL, bgR, L, R);
  pm::io::savePhotoModel(b.model, "model.json");            // version 2: z per point
  std::cout << "origin in the hand frame " << b.hMm.getTranslationVector().t() << "\n";
}

// StereoPhotoModelBuilder.h
void exampleStereoPhotoModelBuilder3(const pm::core::StereoRig &rig, const vpImage<vpRGBa> &bgL, const vpImage<vpRGBa> &bgR, const vpImage<vpRGBa> &L, const vpImage<vpRGBa> &R, const vpImage<vpRGBa> &turnedL, const vpImage<vpRGBa> &turnedR,
                                     const vpHomogeneousMatrix &hMo_turned, const vpHomogeneousMatrix &hMo)
{
  std::vector<pm::model::StereoViewPair> more(1);
  more[0] = {bgL, bgR, turnedL, turnedR, hMo_turned * hMo.inverse()};
  const pm::model::StereoPhotoModelBuild b = pm::model::buildStereoPhotoModel(rig, bgL, bgR, L, R, more);
}

// SubpixelOutline.h
void exampleSubpixelOutline(const vpImage<unsigned char> &mask, const pm::model::PassView &view)
{
  cv::Mat sd = pm::model::hull::subpixelSignedDistance(mask, view.left, &view.backgroundLeft);
  // sd(y, x): px, positive inside; its zero level is the photo's outline, to a tenth of a pixel
}

// SurfaceFusion.h
void exampleSurfaceFusionFile(const pm::core::StereoRig &idealRig, const std::vector<pm::model::hull::HullView> &views,
                              const std::vector<const pm::model::hull::HullView *> &cams, const std::vector<vpImage<unsigned char>> &masks,
                              const std::vector<vpImage<vpRGBa>> &backgrounds, const std::vector<bool> &used, pm::model::VisualHull &hull,
                              const pm::model::FusionParams &params)
{
  // views: the pass's cameras (hull::HullView); cams: pointers to those used
  const pm::model::DepthEvidence ev = pm::model::measureStereo(idealRig, views, masks, backgrounds, used, false, hull, params);
  const long removed = ev.carve(hull, cams);
}

// ViewpointModel.h
void exampleViewpointModel(const pm::core::PinholeCamera::Projection &cam, const std::vector<pm::model::SurfacePoint> &surface,
                           const pm::model::HullMesh &mesh, float bgHue, const pm::model::AllAroundParams &params)
{
  pm::model::ViewpointScratch scratch; // kept from one viewpoint to the next
  const pm::core::ModelView v = pm::model::sampleViewpoint(cam, surface, mesh, bgHue, params, scratch);
}

// VisualHull.h
void exampleVisualHullFile(const std::vector<pm::model::hull::HullView> &views, const std::vector<vpImage<unsigned char>> &masks, double radiusMm)
{
  // views: the pass's cameras (hull::HullView), masks: their silhouettes
  const pm::model::hull::Vec3 c = pm::model::hull::silhouettesMeet(views, masks);
  std::vector<const pm::model::hull::HullView *> cams;
  for (const pm::model::hull::HullView &v : views)
    cams.push_back(&v);
  pm::model::VisualHull hull = pm::model::hullGrid(c, radiusMm, 1.0);
  pm::model::carveVisualHull(cams, hull, 16.0);
  std::cout << hull.volumeCm3() << " cm3\n";
}


} // namespace pm_examples
