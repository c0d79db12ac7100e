#pragma once
/*!
  \file StereoPhotoModelBuilder.h
  The stereo photo-model: the rig's own two cameras take the photos (the backdrop alone, then
  the target on it, from one hand pose), and every model point gets its relief.

  1. The target region in each view, as buildPhotoModel() finds it (the left view's S_in and
     S_out are sampled as in the flat model). A target missing from one view, or a background
     pair that does not match the photo pair, is an error.
  2. The backdrop's depth: OpenCV's semi-global matcher (cv::StereoSGBM) on the rectified
     background pair (cv::stereoRectify), the median over the target's surroundings; or given.
  3. The photo pair, rectified, is matched by cv::StereoSGBM with the disparity search bounded
     by the backdrop (from \e behindBackdropMm behind it to \e maxReliefMm in front), with
     OpenCV's uniqueness and left-right checks. Each S_in point takes the disparity where its
     pixel lands in the rectified left image (bilinear over valid neighbours whose spread is
     under \e maxDisparitySpreadPx): its 3-D position is on its own pixel's ray at that depth.
     Points without a reliable match, or whose depth lies more than \e maxLocalDeviationMm off
     the median of the matched pixels around them, are dropped and counted.
  4. Each S_out point lies on its pixel's ray at the depth of the silhouette next to it: where the
     surface turns away from the camera, the farthest of the matched region pixels within
     \e silhouetteRadiusPx (plus the strip's width) of it (their 90th percentile of depth).
  5. The model frame: origin at the 3-D centroid of S_in, axes those of the hand frame at the
     photo pose (so hMm = translation(origin) at that pose).

  A target with too little texture to match (under \e minMatchedFraction of S_in matched) is
  refused, not faked: a flat model at a guessed depth is what the stereo model replaces, and the
  user can still choose it knowingly (buildPhotoModel; pm-make-model --background --photo --distance-mm).

  \code
      const pm::model::StereoPhotoModelBuild b = pm::model::buildStereoPhotoModel(rig, bgL, bgR, L, R);
      pm::io::savePhotoModel(b.model, "model.json");            // version 2: z per point
      std::cout << "origin in the hand frame " << b.hMm.getTranslationVector().t() << "\n";
  \endcode
*/
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/model/PhotoModelBuilder.h"
#include "pm/core/StereoRig.h"

namespace pm::model {

//! Parameters of buildStereoPhotoModel() (the steps of the file's description); validate() checks them.
struct StereoModelParams
{
  PhotoModelParams photo;            //!< region and sampling, as the flat model
  double backdropMm = 0;             //!< the backdrop's depth along the left camera's axis (mm; 0: measured)
  double maxReliefMm = 200;          //!< search this far in front of the backdrop (mm)
  double behindBackdropMm = 20;      //!< ... and this far behind it (mm)
  int blockPx = 5;                   //!< SGBM block size (odd)
  int uniquenessPercent = 5;         //!< SGBM uniqueness ratio
  double maxDisparitySpreadPx = 1.5; //!< a point's neighbouring disparities must agree within this (px)
  double localRadiusPx = 8;          //!< a point's depth is checked against the matched pixels this close (px) ...
  double maxLocalDeviationMm = 8;    //!< ... and dropped beyond this from their median (a wrong match)
  double silhouetteRadiusPx = 12;    //!< S_out takes the depth of region pixels this close (px; plus the strip's gap and width)
  double minMatchedFraction = 0.5;   //!< fewer S_in points matched: refused (too little texture)
  double maxRegionFraction = 0.5;    //!< a larger region means the background pair does not match
  double maxBackgroundChange = 12;   //!< ... and so does a median change over this (grey levels) outside the target
  bool rightView = false;            //!< add the right camera's own view (S_in, S_out sampled in its photo; measured, off: README)

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

/*!
  What buildStereoPhotoModel() returns: the model and, for reports and pictures, what the build
  found in the (first) photo pair.
*/
struct StereoPhotoModelBuild
{
  core::PhotoModel model;                    //!< points in the model frame, z included
  //! The target region in the left photo (255 inside, 0 elsewhere).
  vpImage<unsigned char> regionLeft, regionRight; //!< the same in the right photo
  vpImage<float> depthLeft;            //!< hand-frame z (mm) of each matched region pixel of the left photo, NaN elsewhere
  vpHomogeneousMatrix hMm;             //!< the model frame in the hand frame at the photo pose (metres)
  double backdropMm = 0;               //!< backdrop depth used (left camera's z, mm)
  bool backdropMeasured = false;       //!< measured from the background pair (else given)
  int nOutFallback = 0;                //!< S_out points with no matched region pixel near them (median depth used)
  std::vector<core::ModelPoint> dropped;     //!< the S_in points dropped (u, v, hue as sampled), for pictures
};

/*!
  Builds the stereo model from the background pair (\e bgL, \e bgR) and the photo pair (\e L,
  \e R), all taken by \e rig from one hand pose. Throws pm::core::Error with what to do for: images
  whose size differs from the rig's cameras, a background pair that does not match the photo
  pair, the target missing from (or cut by) one view, a backdrop that cannot be matched (give
  \e backdropMm), too little texture to match.
  A rig whose cameras have lens distortion: the four photos are undistorted first (UndistortMap),
  and regionLeft, regionRight and depthLeft are those of the left camera's ideal (undistorted) image.

  \code
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/model/StereoPhotoModelBuilder.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  // From one hand pose: the backdrop alone, then the target on it.
  const vpImage<vpRGBa> bgL = pm::io::readColorImage("background_left.png");
  const vpImage<vpRGBa> bgR = pm::io::readColorImage("background_right.png");
  const vpImage<vpRGBa> L = pm::io::readColorImage("left.png");
  const vpImage<vpRGBa> R = pm::io::readColorImage("right.png");
  pm::model::StereoModelParams params;
  params.backdropMm = 700; // a plain backdrop, too smooth to match: its depth given (mm)
  const pm::model::StereoPhotoModelBuild b = pm::model::buildStereoPhotoModel(rig, bgL, bgR, L, R, params);
  pm::io::savePhotoModel(b.model, "model.json");
  std::cout << b.model.inner.size() << " S_in points, " << b.model.nInDropped << " dropped\n";
}
  \endcode
*/
StereoPhotoModelBuild buildStereoPhotoModel(const core::StereoRig &rig, const vpImage<vpRGBa> &bgL,
                                            const vpImage<vpRGBa> &bgR, const vpImage<vpRGBa> &L,
                                            const vpImage<vpRGBa> &R, const StereoModelParams &params = StereoModelParams());

/*!
  A further pair of photos of the same target for a multi-view model, taken after a known motion
  of the target or of the hand (a turntable, the robot holding the target, or the arm's own
  kinematics): its background pair, its photo pair and \e hMh0, which takes a point fixed to the
  target from the first pair's hand frame into this pair's (metres). For a target turned in front
  of a still hand from pose hMo0 to hMo: hMh0 = hMo * hMo0^-1; for a hand moved around a still
  target: hMh0 = (h0Mh)^-1 with h0Mh the hand's motion.
*/
struct StereoViewPair
{
  //! \var backgroundLeft
  //! The left camera's photo of the backdrop alone.
  //! \var backgroundRight
  //! The right camera's photo of the backdrop alone.
  //! \var left
  //! The left camera's photo of the target on it.
  vpImage<vpRGBa> backgroundLeft, backgroundRight, left, right; //!< the right camera's photo of the target on it
  vpHomogeneousMatrix hMh0; //!< the first pair's hand frame into this pair's, for points fixed to the target (metres)
};

/*!
  The multi-view stereo model: the model of the first pair (its frame is the model's), and each
  further pair built the same way, its views (left and right) moved into the model frame by its
  known motion. Each camera is then scored with the view whose camera looked from the direction
  nearest its own (StereoFitness). Throws pm::core::Error as the one-pair build, naming the pair.
  The build's regions, depth map, dropped points and counts are those of the first pair.

  \code
      std::vector<pm::model::StereoViewPair> more(1);
      more[0] = {bgL, bgR, turnedL, turnedR, hMo_turned * hMo.inverse()};
      const pm::model::StereoPhotoModelBuild b = pm::model::buildStereoPhotoModel(rig, bgL, bgR, L, R, more);
  \endcode
*/
StereoPhotoModelBuild buildStereoPhotoModel(const core::StereoRig &rig, const vpImage<vpRGBa> &bgL,
                                            const vpImage<vpRGBa> &bgR, const vpImage<vpRGBa> &L,
                                            const vpImage<vpRGBa> &R, const std::vector<StereoViewPair> &more,
                                            const StereoModelParams &params = StereoModelParams());

} // namespace pm::model
