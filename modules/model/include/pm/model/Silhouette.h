#pragma once
/*!
  \file Silhouette.h
  The target's silhouette in one photo: where it differs from the photo of the same hand pose
  with the target removed (PassView), cleaned with OpenCV's image operations.

  A pixel differs when its chromaticity (r, g, b divided by their sum) moved by more than
  \e chromaTol, or its brightness changed by a ratio outside [\e darkRatio, \e brightRatio]. A cast
  shadow dims the backdrop and keeps its chromaticity: a pixel darker than the background by a
  ratio in [\e darkRatio, 1) with its chromaticity kept is shadow, not target. White and grey
  parts of a target differ from a coloured backdrop in chromaticity, and from a grey one in
  brightness upward (a shadow never brightens). Then opening and closing (\e cleanRadiusPx), the
  connected regions of at least \e minRegionFraction of the largest one, their holes filled.

      pm::model::SilhouetteStats st;
      const vpImage<unsigned char> mask = pm::model::silhouette(view.left, view.backgroundLeft, pm::model::SilhouetteParams(), &st);
      std::cout << st.shadowPx << " shadow pixels dropped\n";
*/
#include <string>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::model {

//! How silhouette() and silhouetteOnBackdrop() tell the target (see the file); validate() checks them.
struct SilhouetteParams
{
  double chromaTol = 0.035;       //!< chromaticity change (each of r, g over r + g + b) that marks the target
  double darkRatio = 0.35;        //!< darker than this ratio of the background: the target (a shadow keeps more light)
  double brightRatio = 1.12;      //!< brighter than this ratio: the target (no shadow brightens)
  double minBrightness = 30;      //!< a background darker than this (mean of r, g, b) has no chromaticity to compare: brightness alone decides
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
