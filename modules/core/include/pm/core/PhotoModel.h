#pragma once
/*!
  \file PhotoModel.h
  The photo-model of the paper (Sec. 3.2, Fig. 4): points sampled inside the target's
  outline (S_in, each with the photo's hue there) and a strip of points enveloping it
  (S_out), all on the model plane z = 0 of the model frame M.

  A point sampled at pixel (u, v) of a photo taken at distance d by a camera of focal
  lengths px, py becomes M_r = ((u - cu) d / px, (v - cv) d / py, 0) in millimetres, where
  (cu, cv) is the centroid of the target region: the model frame's origin is the region's
  centroid (our choice, SPEC.md section 3).

  The stereo photo-model (buildStereoPhotoModel) gives every point its relief instead: z is
  measured by the rig when the photos are taken, the origin is the 3-D centroid of S_in and the
  axes are those of the hand frame at the photo pose. Both kinds share this type; hasDepth()
  tells them apart, and the fitness projects (x, y, z) either way.

  A stereo model can hold further views (ModelView): the points each camera sampled in its own
  photo, placed in the same model frame, with the camera's centre. The fitness scores each
  camera's projection with the view taken from the direction nearest to that camera's (the toy's
  outline and sides as that camera sees them), like the view-based models of DLR's trackers.

  \code
      pm::core::PhotoModel m = pm::io::loadPhotoModel("model.json");   // version 1 (flat), 2 or 3 (depth)
      if (m.hasDepth()) std::cout << "relief " << m.depthRangeMm[0] << " to " << m.depthRangeMm[1] << " mm\n";
  \endcode
*/
#include <string>
#include <array>
#include <vector>

#include "pm/core/TrustCalibration.h"

namespace pm::core {

/*!
  One point of a photo-model: its position in the model frame M, its hue, and where it was sampled.
*/
struct ModelPoint
{
  /*! \var ModelPoint::x
      \brief x of the position in the model frame (mm)
      \var ModelPoint::y
      \brief y of the position in the model frame (mm) */
  float x = 0, y = 0, z = 0; //!< z of the position in the model frame (mm); 0 on a flat model
  float hue = 0;             //!< photo hue in degrees (S_in); background hue for S_out
  /*! \var ModelPoint::u
      \brief column where it was sampled in the photo (px) */
  float u = 0, v = 0;        //!< row where it was sampled in the photo (px)
  /*! \var ModelPoint::r
      \brief the surface's red there (S_in of a model with colours, PhotoModel::hasColours)
      \var ModelPoint::g
      \brief its green */
  unsigned char r = 0, g = 0, b = 0; //!< its blue
};

/*!
  One point of a view's outline, as the precise stage reads it (pm/precise/PreciseStage.h): where the
  target's outline seen from the view's camera passes, on the surface (the contour generator), the
  outline's outward normal (perpendicular to the viewing direction), and how far the target and the
  background stretch from it along that normal in the view's image, for the correspondence lines.
*/
struct ContourPoint
{
  /*! \var ContourPoint::x
      \brief x of the point on the outline, in the model frame (mm)
      \var ContourPoint::y
      \brief y of the point (mm) */
  float x = 0, y = 0, z = 0;    //!< z of the point (mm)
  /*! \var ContourPoint::nx
      \brief x of the outline's outward unit normal, in the model frame
      \var ContourPoint::ny
      \brief y of the normal */
  float nx = 0, ny = 0, nz = 0; //!< z of the normal
  float insideMm = 0;           //!< along -normal, how far the target stays unbroken in the view (mm, at the point's depth)
  float outsideMm = 0;          //!< along +normal, how far the background stays unbroken (mm)
};

/*!
  One further view of a stereo model: S_in and S_out sampled in the photo of one camera, in the
  model frame (mm), and where that camera's centre was in the model frame when it took the photo.
  An all-around model's views also hold their outline (the precise stage's contour points).
*/
struct ModelView
{
  double cameraMm[3] = {0, 0, 0}; //!< the camera's centre in the model frame (mm)
  std::vector<ModelPoint> inner;  //!< S_in of this view (u, v: pixels of its own photo)
  std::vector<ModelPoint> outer;  //!< S_out of this view
  std::vector<ContourPoint> contour; //!< the outline seen from this view (empty: the model has none)
};

/*!
  Where the precise stage lands on one of the pass's own views, whose pose is known (the hand's, from
  the arm): how far the model's own outline and colours put the pose off at that view, the model's
  error there. An all-around model holds one per view of its pass (AllAroundModelBuilder.h); the
  tracker's uncertainty takes those near the camera's direction as its floor (ModelErrorFloor.h).
*/
struct PassLanding
{
  double cameraMm[3] = {0, 0, 0}; //!< the left camera's centre in the model frame at that view (mm)
  double offsetMm[3] = {0, 0, 0}; //!< where the stage put the model's origin less where it is, in the model frame's axes (mm)
  double offsetDeg[3] = {0, 0, 0};//!< the stage's rotation less the true one (rotation vector, model frame's axes, deg)
};

//! The root mean square of \e landings' offsets per axis of the model frame: mm along x, y, z, then deg about them (zeros for none).
std::array<double, 6> rmsOffsets(const std::vector<PassLanding> &landings);

/*!
  A photo-model: the target as the fitness looks for it (see PhotoModel.h). StereoFitness copies
  the points it needs, so a model may go once the fitness is built.
  \code
  pm::core::PhotoModel m;                         // by hand: one red point, one point of background
  m.distanceMm = 500;
  m.px = m.py = 800;
  m.backgroundHue = 200;
  m.inner.push_back({0.f, 0.f, 0.f, 0.f, 320.f, 240.f});   // x, y, z (mm), hue (deg), u, v (px)
  m.outer.push_back({50.f, 0.f, 0.f, 200.f, 400.f, 240.f});
  m.validate("hand-made model");            // throws pm::core::Error if it cannot be used
  std::cout << m.size() << " points, " << (m.hasDepth() ? "3-D" : "flat") << "\n";
  \endcode
*/
struct PhotoModel
{
  double distanceMm = 0;           //!< photo distance d (mm)
  /*! \var PhotoModel::px
      \brief photo camera focal length along u (px) */
  double px = 0, py = 0;           //!< photo camera focal length along v (px)
  /*! \var PhotoModel::u0
      \brief photo camera principal point, column (px) */
  double u0 = 0, v0 = 0;           //!< photo camera principal point, row (px)
  /*! \var PhotoModel::photoWidth
      \brief width of the photo (px) */
  unsigned photoWidth = 0, photoHeight = 0; //!< height of the photo (px)
  /*! \var PhotoModel::centroidU
      \brief column of the target region's centroid in the photo (px): the model origin */
  double centroidU = 0, centroidV = 0; //!< row of the target region's centroid in the photo (px): the model origin
  float backgroundHue = 0;         //!< H_B, circular mean hue of the background photo (deg)
  float targetHue = 0;             //!< circular mean hue of S_in (deg), for reports
  std::vector<ModelPoint> inner;   //!< S_in
  std::vector<ModelPoint> outer;   //!< S_out
  // Stereo models only (reports; the fitness needs the points alone):
  double originInHandMm[3] = {0, 0, 0}; //!< the model origin in the hand frame at the photo pose (mm)
  double depthRangeMm[2] = {0, 0};      //!< nearest and farthest S_in point along the hand's z (mm)
  int nInDropped = 0;                   //!< S_in points dropped for want of a reliable stereo match
  // Multi-view stereo models only (no views: one view, the points above, for both cameras):
  double cameraMm[3] = {0, 0, 0};       //!< the centre of the camera that sampled S_in and S_out, in the model frame (mm)
  std::vector<ModelView> views;         //!< further views; each camera is scored with the view nearest its direction
  // All-around models (version 5) only: what the precise stage needs.
  std::vector<ContourPoint> contour;    //!< the outline seen from cameraMm (the model's own view), as ModelView::contour
  /*!
    Colour histograms of the target (its surface in the photos) and of what surrounded it (the
    backgrounds next to its outline): kColourBins^3 bins over RGB (red slowest), each summing to 1,
    or empty. The precise stage starts its colour posteriors from them (ColourHistograms.h).
  */
  std::vector<float> foregroundHistogram; //!< the target's colour histogram (see above)
  std::vector<float> backgroundHistogram; //!< the surroundings' colour histogram
  static constexpr int kColourBins = 16; //!< bins per colour channel of the histograms
  bool hasColours = false;              //!< the S_in points carry the surface's colour (ModelPoint::r, g, b), for the precise stage's interior term
  std::vector<PassLanding> passLandings; //!< the precise stage on the pass's own views (all-around models; empty: not measured)
  TrustCalibration trust;               //!< what the pass taught the confidence and the uncertainty (all-around models; pm::trust)

  //! True when every view (the model's own included) carries its outline: the precise stage can run.
  bool hasContours() const;

  //! Number of points of S_in and S_out (those of the further views not counted).
  std::size_t size() const { return inner.size() + outer.size(); }
  //! True for a model of many viewing directions (more than 16 views: an all-around model, AllAroundModelBuilder.h).
  bool isAllAround() const { return views.size() > 16; }
  //! True when some point lies off the plane z = 0 (a stereo model).
  bool hasDepth() const;
  /*!
    Throws pm::core::Error if the model cannot be used: S_in empty, a non-finite coordinate or
    hue outside [0, 360), a non-positive distance or focal length, views on a flat model or a view
    without S_in or camera centre, a pass landing not finite or over 50 mm / 45 deg off. \e source names the file or the origin for the message.
  */
  void validate(const std::string &source) const;
};

} // namespace pm::core
