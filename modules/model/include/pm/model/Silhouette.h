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

      pm::SilhouetteStats st;
      const vpImage<unsigned char> mask = pm::silhouette(view.left, view.backgroundLeft, pm::SilhouetteParams(), &st);
      std::cout << st.shadowPx << " shadow pixels dropped\n";
*/
#include <string>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm {

struct SilhouetteParams
{
  double chromaTol = 0.035;       //!< chromaticity change (each of r, g over r + g + b) that marks the target
  double darkRatio = 0.35;        //!< darker than this ratio of the background: the target (a shadow keeps more light)
  double brightRatio = 1.12;      //!< brighter than this ratio: the target (no shadow brightens)
  double minBrightness = 30;      //!< below this sum of r, g, b / 3 in both, chromaticity is noise: brightness alone decides
  int cleanRadiusPx = 2;          //!< opening and closing radius
  double minRegionFraction = 0.2; //!< regions smaller than this fraction of the largest are dropped
  double maxImageFraction = 0.6;  //!< a silhouette over this fraction of the image: the background does not match

  //! Throws pm::Error naming the first parameter out of range.
  void validate() const;
};

struct SilhouetteStats
{
  int targetPx = 0;      //!< pixels of the silhouette
  int shadowPx = 0;      //!< pixels that changed but were taken for shadow
  bool touchesBorder = false; //!< the silhouette reaches the image border (the target is cut)
};

/*!
  255 on the target, 0 elsewhere. Throws pm::Error (\e name says which image) for images of
  different sizes, a silhouette that is empty or covers more than maxImageFraction of the image (the
  background does not match its photo).
*/
vpImage<unsigned char> silhouette(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background,
                                  const SilhouetteParams &params = SilhouetteParams(), SilhouetteStats *stats = nullptr,
                                  const std::string &name = "the photo");

} // namespace pm
