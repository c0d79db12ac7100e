#pragma once
/*!
  \file Silhouette.h
  The target's silhouette in one photo: where it differs from the photo of the same hand pose
  with the target removed (PassView; the background subtraction of BackgroundSubtraction.h), cleaned
  with OpenCV's image operations: opening and closing (\e cleanRadiusPx), the connected regions of at
  least \e minRegionFraction of the largest one, their holes filled.

  \code
      pm::model::SilhouetteStats st;
      const vpImage<unsigned char> mask = pm::model::silhouette(view.left, view.backgroundLeft, pm::model::SilhouetteParams(), &st);
      std::cout << st.shadowPx << " shadow pixels dropped\n";
  \endcode
*/
#include <string>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/model/BackgroundSubtraction.h"

namespace pm::model {

//! How silhouette() and silhouetteOnBackdrop() tell the target (see the file); validate() checks them.
struct SilhouetteParams
{
  BackgroundParams background;    //!< the background subtraction (BackgroundSubtraction.h)
  int cleanRadiusPx = 2;          //!< opening and closing radius
  double minRegionFraction = 0.2; //!< regions smaller than this fraction of the largest are dropped
  double maxImageFraction = 0.6;  //!< a silhouette over this fraction of the image: the background does not match
  // A plain backdrop of known hue instead of background images (silhouetteOnBackdrop):
  double backdropHueTolDeg = 25;   //!< a pixel this close to the backdrop's hue is backdrop
  double backdropMinSaturation = 0.2; //!< paler pixels have no hue: the target
  double backdropMinValue = 0.1;   //!< darker pixels have no hue: the target

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

//! What silhouette() and silhouetteOnBackdrop() found, besides the mask.
struct SilhouetteStats
{
  int targetPx = 0;      //!< pixels of the silhouette
  int shadowPx = 0;      //!< pixels that changed but were taken for shadow (0 on a plain backdrop)
  bool touchesBorder = false; //!< the silhouette reaches the image border (the target is cut)
};

/*!
  255 on the target, 0 elsewhere. Throws pm::core::Error (\e name says which image) for images of
  different sizes, a silhouette that is empty or covers more than maxImageFraction of the image (the
  background does not match its photo).
*/
vpImage<unsigned char> silhouette(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background,
                                  const SilhouetteParams &params = SilhouetteParams(), SilhouetteStats *stats = nullptr,
                                  const std::string &name = "the photo");

/*!
  The silhouette against a plain backdrop of hue \e backdropHueDeg, from the photo alone (no
  background image): a pixel is the target when its hue is over backdropHueTolDeg from the
  backdrop's, or when it has no hue (paler than backdropMinSaturation or darker than
  backdropMinValue). A cast shadow keeps the backdrop's hue and stays backdrop. Then the same
  cleaning and errors as silhouette().
*/
vpImage<unsigned char> silhouetteOnBackdrop(const vpImage<vpRGBa> &photo, double backdropHueDeg,
                                            const SilhouetteParams &params = SilhouetteParams(),
                                            SilhouetteStats *stats = nullptr, const std::string &name = "the photo");

} // namespace pm::model
