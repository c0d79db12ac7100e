#pragma once
/*!
  \file AllAroundModelBuilder.h
  The all-around photo-model: from a pass of the hand around the target (PassView: a stereo pair
  with the target, the same pair without it, and the hand's pose in a world frame, for a dozen or
  more hand poses), the target's shape carved from its silhouettes, coloured from the photos, and
  a sparse viewpoint model for the fitness: for each of K viewing directions, the S_in points the
  camera sees there (3-D, with their hue) and the S_out points just outside the outline it sees,
  at the outline's depth. StereoFitness scores each camera with the viewpoint nearest its own
  direction, so the model has the right outline at every orientation the pass covers.

  The build runs eight stages, in this order (AllAroundModelBuilder.cpp, build()):
  1. Silhouettes (pm::model::silhouette, or pm::model::silhouetteOnBackdrop with backdropHueDeg) of
     both cameras of every view, in the ideal (undistorted) images; a silhouette cut by the image
     border is an error naming the view.
  2. The box: a cube around the target (where the silhouettes meet); a view whose silhouettes alone
     carve away more than outlierCarveFraction of what the others keep disagrees with them: it is
     named and left out. Fewer than minViews views left: an error.
  3. The hull and its surface: cells carved coarse to fine (coarsestMm down to finestMm) against each
     silhouette's signed distance (a cell wholly outside one silhouette carved, wholly inside all
     kept, otherwise split); then, with fusion (the default), carved again by the views' stereo
     depths and the backdrop (SurfaceFusion.h); the surface as a mesh of the hull's field (HullMesh.h),
     moved onto every view's outline when refineOutlines.
  4. Which cameras see each surface point: a depth buffer of the mesh, the normal facing the camera.
  5. Colours and the model frame: each point takes the median hue of the views that see it
     (samples brighter and paler than its others are highlights, left out; a point whose views
     disagree over maxHueSpreadDeg is marked, not used as S_in); the background's hue around the
     silhouettes. The model frame: origin at the hull's centroid, axes those of the hand at the first
     view used, so a tracker starting near that view's pose sees the model turned by little.
  6. K viewpoints over the directions within capDeg of the first view's (a Fibonacci lattice), at
     the pass's distance: the surface points the virtual camera sees (nIn, spread over the image,
     at least inMinInsidePx inside the outline, farther for a soft camera), nOut points of the
     outline offset outward by the strip (S_out), and nContour outline points for the precise stage.
  7. The colours of the target and around it (histograms for the precise stage's posteriors).
  8. With passLandings: the precise stage from each pass view's known pose, the model's own error
     there (PassLandings.h; the tracker's uncertainty floor).

  \code
      const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder("views", rig, 6);
      const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass);
      pm::io::savePhotoModel(b.model, "model.json");
      std::cout << b.surface.size() << " surface points, hull " << b.hullVolumeCm3 << " cm3\n";
  \endcode
*/
#include <memory>
#include <string>
#include <vector>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/StereoRig.h"
#include "pm/model/AllAroundParams.h"
#include "pm/model/PassView.h"
#include "pm/model/HullMesh.h"
#include "pm/model/OutlineRefinement.h"
#include "pm/model/Silhouette.h"
#include "pm/model/SurfaceFusion.h"

namespace pm::model {

//! A point of the hull's surface, in the model frame.
struct SurfacePoint
{
  //! \var x
  //! Position in the model frame: x (mm).
  //! \var y
  //! Position in the model frame: y (mm).
  float x, y, z;          //!< position in the model frame: z (mm)
  //! \var nx
  //! Outward unit normal: x.
  //! \var ny
  //! Outward unit normal: y.
  float nx, ny, nz;       //!< outward unit normal: z
  float hue;              //!< median hue of the views that see it (deg; meaningful when hasHue)
  //! \var r
  //! Median colour: red (for model.ply).
  //! \var g
  //! Median colour: green.
  unsigned char r, g, b;  //!< median colour: blue
  std::uint8_t nSeen;     //!< cameras that see it
  bool hasHue;            //!< saturated enough, seen, views agree, hue far enough from H_B: may be S_in
  bool highlight;         //!< views disagreed (marked, not used as S_in)
};

//! What buildAllAroundModel() returns: the model, and what the build found on the way (for reports and pictures).
struct AllAroundBuild
{
  core::PhotoModel model;                 //!< views: the K viewpoints (view 0 in inner/outer)
  vpHomogeneousMatrix fMm;          //!< the model frame in the world frame of the poses (metres)
  std::vector<SurfacePoint> surface; //!< the surface's points (the mesh's vertices), in the model frame
  HullMesh mesh;                    //!< the surface as triangles, in the model frame (vertex i is surface point i)
  std::vector<vpImage<unsigned char>> silhouettes; //!< left and right of each view: 2k, 2k + 1
  std::vector<std::string> leftOut; //!< views left out (their silhouettes disagree), with why
  //! Views in the pass.
  std::size_t nViews = 0, nViewsUsed = 0; //!< views used (not left out)
  double hullVolumeCm3 = 0;         //!< volume of the carved hull (cm^3)
  double surfaceVolumeCm3 = 0;      //!< volume inside the final surface (the hull's mesh, refined; cm^3)
  double cellMm = 0;                //!< the finest cell size used
  long fusionCarvedCells = 0;       //!< hull cells the views' depths put outside
  long matchedTargetPx = 0;         //!< pixels of the target given a depth by stereo, over the views
  long matchedBackdropPx = 0;       //!< pixels of the backdrop given a depth, over the views
  double outlineResidualBeforePx = 0; //!< refineOutlines: the mesh's outlines inside the views' before the refinement (mean, px)
  double outlineResidualPx = 0;     //!< ... after it (mean, px; 0 without refineOutlines)
  double outlineResidualRmsPx = 0;  //!< ... after it (rms, px)
  int nHighlight = 0;               //!< surface points marked (views disagree)
  int nHighlightSamples = 0;        //!< colour samples left out as highlights
  long shadowPx = 0;                //!< changed pixels taken for shadow over all silhouettes
  double edgeWidthPx = 0;           //!< the first view's outline's 25-75 % rise, mean of its cameras (px; 0: not read; EdgeBlur.h)
  double minInsidePx = 0;           //!< S_in's distance inside the outline used (AllAroundParams::viewpoints.inMinInsidePx, raised for blur)
  double buildS = 0;                //!< wall time of the build (s)
};

/*!
  Builds the all-around model of the target seen in \e pass by \e rig. Throws pm::core::Error (one line,
  naming the view) for: fewer than minViews views, images of another size than the rig's, a view
  whose silhouette is cut by the image border, a background that does not match its photo, poses
  that carve the hull to nothing, too few usable views after leaving out the disagreeing ones.
  A rig whose cameras have lens distortion: the photos are undistorted first.

  \code
#include <iostream>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/io/ViewsFolder.h>
#include <pm/model/AllAroundModelBuilder.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder("views", rig, 6); // at least 6 views
  pm::model::AllAroundParams params;
  params.viewpoints.count = 120; // a lighter model: half the viewpoints
  const pm::model::AllAroundBuild b = pm::model::buildAllAroundModel(rig, pass, params);
  for (const std::string &why : b.leftOut)
    std::cout << "left out: " << why << "\n";
  pm::io::savePhotoModel(b.model, "model.json");
  std::cout << b.nViewsUsed << " of " << b.nViews << " views, hull " << b.hullVolumeCm3 << " cm3\n";
}
  \endcode
*/
AllAroundBuild buildAllAroundModel(const core::StereoRig &rig, const std::vector<PassView> &pass,
                                   const AllAroundParams &params = AllAroundParams());

/*!
  What buildAllAroundModel() measured of each view of a pass, whatever views a model is built from:
  the silhouettes, the ideal photos and backgrounds, the views' stereo depths. A model built again
  without some of the views (buildAllAroundModelWithout()) reuses them instead of measuring them again:
  pm::trust's held-out models, at two fifths of a build each. Shared and immutable (a copy is cheap).
*/
class PassMeasurements
{
public:
  struct Data; //!< what was measured (AllAroundModelBuilder.cpp)
  //! True when nothing was measured (a default-constructed one).
  bool empty() const { return !m_data; }
  //! What was measured (null when empty()).
  const std::shared_ptr<const Data> &data() const { return m_data; }
  //! Holds \e d.
  explicit PassMeasurements(std::shared_ptr<const Data> d = nullptr) : m_data(std::move(d)) {}

private:
  std::shared_ptr<const Data> m_data;
};

//! buildAllAroundModel(), and what it measured of each view into \e measured (for buildAllAroundModelWithout()).
AllAroundBuild buildAllAroundModel(const core::StereoRig &rig, const std::vector<PassView> &pass, const AllAroundParams &params,
                                   PassMeasurements &measured);

/*!
  The all-around model of \e pass without its views \e heldOut (indices into \e pass; the first view
  cannot be held out: the model's frame and viewpoints come from it), from what \e measured holds of
  the views (measured by buildAllAroundModel() on the same \e pass with the same \e params): the same
  model as buildAllAroundModel() of the other views, but that the stereo depths' search spans the whole
  pass's hull. Throws pm::core::Error for an empty \e measured, a held-out first view or index out of
  range, and as buildAllAroundModel() (too few views left, ...).
*/
AllAroundBuild buildAllAroundModelWithout(const core::StereoRig &rig, const std::vector<PassView> &pass, const AllAroundParams &params,
                                          const PassMeasurements &measured, const std::vector<std::size_t> &heldOut);

} // namespace pm::model
