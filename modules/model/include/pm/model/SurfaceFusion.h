#pragma once
/*!
  \file SurfaceFusion.h
  The all-around model's surface where the silhouettes cannot carve it (AllAroundModelBuilder.h,
  step 3): a hull carved from a cap of directions bulges in front of every flat or concave face
  (R1's printed front: 13 mm on average) and reaches behind the target, where no camera looks.
  Each view's stereo pair says where the surface is: its left camera's depth from the pair
  (StereoDepth.h: rectified, semi-global matching) inside the silhouette, and the backdrop's depth
  from the pair taken without the target.
  - The surface's evidence is a truncated signed distance averaged over the views (as in depth-map
    fusion): for a point X, each view whose depth there is valid gives its depth minus X's, clamped
    to +-truncationMm; their mean is positive where X lies in front of the measured surface (free
    space). A view that sees X hidden behind its surface votes for the inside: one wrong match
    cannot carve what the other views see behind their surface.
    A view's weight ramps from 0 at its eroded silhouette's edge to 1 \e edgeRampPx inside: near
    the outline it sees the surface at a grazing angle, where matching is biased, and the
    silhouettes know the outline better. It also falls with the angle at which the view sees the
    surface there (from its depth map's slope): grazing, the matcher's blocks straddle a steep slope.
  - The backdrop bounds the back the cameras never see: a point behind the backdrop (by over
    \e backdropMarginMm) in at least two views is outside: the target rests on it. Against a plain
    backdrop (no texture, no background pass) there is no such bound: the back stays the hull's.
  The hull's field and this evidence make one field (the least of them, in mm), carved and meshed
  as the hull alone was (HullMesh.h).

  \code
      // views: the pass's cameras (hull::HullView); cams: pointers to those used
      const pm::model::DepthEvidence ev = pm::model::measureStereo(idealRig, views, masks, backgrounds, used, false, hull, params);
      const long removed = ev.carve(hull, cams);
  \endcode
*/
#include <algorithm>
#include <vector>

#include <opencv2/core.hpp>

#include "pm/core/StereoRig.h"
#include "pm/model/HullGeometry.h"
#include "pm/model/VisualHull.h"

namespace pm::model {

//! How the surface is fused from the views' stereo pairs (SurfaceFusion.h).
struct FusionParams
{
  bool enabled = true;          //!< measure the views' depth and fuse it with the hull (false: the silhouettes alone)
  double truncationMm = 4;      //!< the truncated distance's band (mm)
  double backdropMarginMm = 3;  //!< a point this far behind the backdrop is outside (mm)
  int blockPx = 5;              //!< the matcher's block (odd px)
  double maxDisparitySpreadPx = 1.0; //!< a pixel's neighbouring disparities must agree within this (px)
  int erodePx = 3;              //!< the silhouette is eroded by this before matching (its edge mixes target and backdrop)
  double edgeRampPx = 10;       //!< a view's depth counts fully this far inside its eroded silhouette, less nearer its edge (px)
  double outlineMarginPx = 4;   //!< the depths carve nothing that projects within this of any silhouette's edge (fieldInside(); px)
  double grazingCos = 0.3;      //!< a depth whose surface faces the view at a cosine under this counts nothing (full weight half way to 1)
  double backdropSearchMm = 300; //!< the backdrop is searched this far behind the hull (mm)
  bool fastMatching = true;     //!< the matcher's three-path mode (StereoDepth.h), about 3 times faster than eight paths
  double minTexture = 1.5;      //!< pixels with less texture across the epipolar lines are not matched (StereoDepth.h)
  int uniquenessPercent = 10;   //!< the matcher's uniqueness ratio
  void validate() const;        //!< throws pm::core::Error naming the first value out of range
};

/*!
  The views' measured depths (see SurfaceFusion.h): for each view's left camera, the depth of the
  target inside its silhouette and of the backdrop around and behind it (mm, NaN where unmatched).
  \code
  const pm::model::DepthEvidence ev = pm::model::measureStereo(idealRig, cams, masks, backgrounds, used, false, hull, params);
  const double f = ev.field({0, 0, 500});   // mm: > 0 behind the measured surface, < 0 in front, +inf: no evidence
  \endcode
*/
class DepthEvidence
{
public:
  //! One camera's measured depths.
  struct View
  {
    core::PinholeCamera::Projection cam; //!< where it was (the pass's world frame)
    cv::Mat target;    //!< CV_32F, the target's depth (camera z, mm), NaN elsewhere
    cv::Mat backdrop;  //!< CV_32F, the backdrop's depth, NaN elsewhere (empty: none)
    cv::Mat silhouette; //!< CV_32F, its silhouette's signed distance (px, HullView::signedDist)
    cv::Mat weight;    //!< CV_32F, each depth's weight, from how squarely the view sees the surface there
    int view = -1;     //!< the pass view it belongs to (HullView::view)
  };
  FusionParams params; //!< the fusion's parameters
  std::vector<View> views; //!< the cameras with their depths

  //! This evidence with the views of \e used only (used[HullView::view]: a model built without some of the pass's views).
  DepthEvidence only(const std::vector<bool> &used) const;

  /*!
    The evidence's field at \e X (mm, as the hull's: positive inside): the least of the surface's
    (minus the mean truncated distance) and the backdrop's (how far in front of it, the second view's).
    +inf where no view says anything.
  */
  double field(const hull::Vec3 &X) const;
  /*!
    The evidence's field at \e X where the silhouettes' field there is \e silhouettePx (VisualHull.h:
    how far inside every silhouette X projects, px): within outlineMarginPx of a silhouette's edge
    the evidence is raised until, at the edge, it cannot carve. The outline the pass's views saw is
    the silhouettes', which know it to a fraction of a pixel; the depths carve behind it.
  */
  double fieldInside(const hull::Vec3 &X, double silhouettePx) const { return raisedNearOutline(field(X), silhouettePx); }
  //! fieldInside() from the evidence's field \e f at the point: never below \e f.
  double raisedNearOutline(double f, double silhouettePx) const
  {
    return f + params.truncationMm * std::max(0.0, 1.0 - silhouettePx / params.outlineMarginPx);
  }
  //! Empties the occupied cells of \e hull whose centre the evidence puts outside (fieldInside() with \e cams' silhouettes); returns how many.
  long carve(VisualHull &hull, const std::vector<const hull::HullView *> &cams) const;
  //! Pixels with a measured depth: target and backdrop, over every view.
  void counts(long &target, long &backdrop) const;
};

/*!
  Measures the depths of the used views (see SurfaceFusion.h): \e cams and \e masks as the
  builder made them (left, right of each view in turn), \e backgrounds the photos without the
  target (the photos themselves against a plain backdrop: \e plainBackdrop), \e idealRig the rig
  without its lens (the photos are ideal). The depth search spans the carved \e hull's box (and
  backdropSearchMm behind it for the backdrop).
*/
DepthEvidence measureStereo(const core::StereoRig &idealRig, const std::vector<hull::HullView> &cams,
                            const std::vector<vpImage<unsigned char>> &masks, const std::vector<vpImage<vpRGBa>> &backgrounds,
                            const std::vector<bool> &used, bool plainBackdrop, const VisualHull &hull, const FusionParams &params);

} // namespace pm::model
