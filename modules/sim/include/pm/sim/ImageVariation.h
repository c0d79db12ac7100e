#pragma once
/*!
  \file ImageVariation.h
  The lab's images varied as real cameras vary them (so that trust is tested outside our renderer): the
  optics (defocus, motion blur, vignetting) before the sensor's noise, then a signal-dependent
  (shot) noise, and what the camera's processing does after it (white balance, gamma, JPEG). The
  renderer's own images are one camera; these are others. Scene::render() applies
  SceneParams::variation; each named preset (imageVariationNames()) is one kind, "camera" a mild
  mix of them all.
*/
#include <cstdint>
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::sim {

//! How a camera varies the images (all off by default); validate() checks the ranges.
struct ImageVariation
{
  double defocusSigmaPx = 0;      //!< defocus: a Gaussian blur of this sigma (px)
  double motionBlurPx = 0;        //!< motion blur: a line of this length (px) ...
  double motionBlurAngleDeg = 0;  //!< ... at this angle from the image's x axis (deg)
  double vignetting = 0;          //!< the corners darkened by this fraction (a cos^4-like fall-off)
  double shotNoise = 0;           //!< sensor noise that grows with the signal: sigma = shotNoise * sqrt(level) (grey levels)
  double whiteBalance[3] = {1, 1, 1}; //!< the red, green and blue gains of a white balance set for another light
  double gamma = 1;               //!< a tone curve: out = 255 (in / 255)^(1 / gamma)
  int jpegQuality = 0;            //!< encoded and decoded as JPEG at this quality (1-100; 0: not)

  //! True if anything varies (otherwise Scene::render() gives the renderer's images, bit for bit).
  bool any() const;
  //! True if the optics blur or darken (applied before the sensor's noise).
  bool optics() const { return defocusSigmaPx > 0 || motionBlurPx > 0 || vignetting > 0; }
  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
  //! The optics: defocus, motion blur, vignetting (before the noise).
  void applyOptics(vpImage<vpRGBa> &image) const;
  //! After the sensor's own noise: the shot noise (its draws a function of \e seed), white balance, gamma, JPEG.
  void applyAfterSensor(vpImage<vpRGBa> &image, std::uint64_t seed) const;
};

/*!
  The preset \e name: defocus, motion-blur, vignetting, shot-noise, white-balance, gamma, jpeg, or
  camera (a mild mix of them all). Several names, comma-separated, combine (each sets its own
  parameters). Throws pm::core::Error for an unknown name.
  \code
  pm::sim::SceneParams sp;
  sp.variation = pm::sim::imageVariation("defocus,jpeg"); // a soft lens and a compressed stream
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"), sp);
  \endcode
*/
ImageVariation imageVariation(const std::string &names);
//! The presets' names, in order.
const std::vector<std::string> &imageVariationNames();

} // namespace pm::sim
