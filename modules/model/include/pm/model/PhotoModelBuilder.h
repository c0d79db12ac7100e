#pragma once
/*!
  \file PhotoModelBuilder.h
  Builds a photo-model (Fig. 4 of the paper) from two photos taken by one camera at a known
  distance: (a) the background alone, (b) the target on that background.

  1. H_B is the circular mean hue of photo (a).
  2. A pixel belongs to the target when its colour in (b) differs from the same pixel in (a), by
     the model builders' one background subtraction (BackgroundSubtraction.h: chromaticity, or
     brightness beyond a shadow's). The largest connected region, cleaned by opening and closing, with its
     small holes filled (spots of a background-like hue on the target) and its large ones kept
     (background seen between legs), is the target region; its centroid is the model origin.
  3. S_in: region pixels on a grid of stepPx (aligned on the centroid) whose hue means something
     (saturation >= minSaturation, value >= minValue) and differs from H_B by more than
     minHueFromBackgroundDeg (a point of the background's hue would score as target anywhere on
     the background), each with its hue in (b).
  4. S_out: stripRows rows of points spread over [stripGapPx, stripGapPx + stripWidthPx] pixels
     outside the region boundary, sampled every stepPx along the offset outline.
*/
#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/PhotoModel.h"
#include "pm/model/BackgroundSubtraction.h"

namespace pm::model {

//! Parameters of buildPhotoModel() (the steps of the file's description); validate() checks them.
struct PhotoModelParams
{
  BackgroundParams background;   //!< how a target pixel is told from the background (BackgroundSubtraction.h)
  double minSaturation = 0.15;   //!< below this a pixel's hue is noise
  double minValue = 0.08;        //!< below this a pixel's hue is noise
  double minHueFromBackgroundDeg = 30.0; //!< S_in points need a hue this far from H_B (deg)
  int cleanRadiusPx = 1;         //!< morphological open/close radius on the region mask
  int maxHoleAreaPx = 150;       //!< holes in the region up to this area are filled (spots), larger ones kept
  double stepPx = 8.0;           //!< sampling step of S_in (grid) and along S_out (px)
  double stripGapPx = 3.0;       //!< distance of the first S_out row from the region (px)
  double stripWidthPx = 8.0;     //!< extent of the S_out strip beyond the first row (px)
  int stripRows = 2;             //!< rows of S_out points across the strip

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

//! What buildPhotoModel() returns: the model and the target region it was sampled in.
struct PhotoModelBuild
{
  core::PhotoModel model;              //!< the flat photo-model (z = 0; mm in the model frame)
  vpImage<unsigned char> region; //!< 255 inside the target region, 0 elsewhere
};

/*!
  Builds the flat model from \e background (photo (a)) and \e withTarget (photo (b)), both taken
  by the camera of intrinsics \e cam with the target at \e distanceMm (mm) from it. Throws
  pm::core::Error if the photos differ in size, a parameter is out of range, the distance or the focal
  lengths are not positive, or no target region can be told from the background (empty S_in).

  \code
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/model/PhotoModelBuilder.h>
#include <visp3/core/vpCameraParameters.h>

int main()
{
  const vpImage<vpRGBa> background = pm::io::readColorImage("background.png");
  const vpImage<vpRGBa> photo = pm::io::readColorImage("target.png"); // same camera, same place
  const vpCameraParameters cam(800, 800, 320, 240);                   // px, py, u0, v0
  pm::model::PhotoModelParams params;
  params.stepPx = 6; // a denser S_in
  const pm::model::PhotoModelBuild b = pm::model::buildPhotoModel(background, photo, cam, 500, params); // 500 mm
  pm::io::savePhotoModel(b.model, "model.json");
  std::cout << b.model.inner.size() << " S_in, " << b.model.outer.size() << " S_out points\n";
}
  \endcode
*/
PhotoModelBuild buildPhotoModel(const vpImage<vpRGBa> &background, const vpImage<vpRGBa> &withTarget,
                                const vpCameraParameters &cam, double distanceMm,
                                const PhotoModelParams &params = PhotoModelParams());

} // namespace pm::model
