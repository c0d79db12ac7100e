#pragma once
/*!
  \file EdgeBlur.h
  How soft a camera's images are, read where it matters to the model: across the target's outline
  in a pass photo. Along the outline's normal the photo goes from the background's colour to the
  target's; the target's share (its colour's component along target minus background) rises from
  0 to 1 over a distance the camera's blur sets: from 25 to 75 % over 1.349 times the spread of
  what blurs it, two thirds of a pixel for a sharp camera whose pixels integrate their area (the
  pixel's box and the bilinear reading's tent: 0.5 px; the lab's renders 0.70-0.78 px), 1.75 px
  with a Gaussian defocus of 1.2 px, more along a motion. The model builder keeps its interior points farther
  inside the outline when the images are soft (ViewpointSamplingParams::blurInsideGain): a blurred outline
  mixes the background into them (docs/model-outline.md, "Blur").

  \code
      const pm::model::EdgeWidth w = pm::model::edgeWidth(mask, photo, &background);
      if (w.samples >= 50) std::cout << "the outline rises over " << w.widthPx << " px\n";
  \endcode
*/
#include <cstddef>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::model {

//! What edgeWidth() read.
struct EdgeWidth
{
  double widthPx = 0;      //!< the median distance over which the target's share rises from 25 to 75 % (px)
  std::size_t samples = 0; //!< the outline's points read (where target and background differ enough)
};

/*!
  The median 25-75 % rise of the target's share across the outline of \e mask (255 on the target)
  in \e photo, at up to \e maxSamples points of the mask's border spread along it. The background's
  colour at each point is \e background's there, or the photo's 3.5 px outside when \e background is
  null (a plain backdrop). Points where the colours 3.5 px inside and outside differ by less than
  \e minContrast (RGB distance), or whose profile does not rise through 25 and 75 %, are not read.
  Throws pm::core::Error when the images are not of one size.
*/
EdgeWidth edgeWidth(const vpImage<unsigned char> &mask, const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> *background,
                    std::size_t maxSamples = 600, double minContrast = 60);

} // namespace pm::model
