#pragma once
/*!
  \file Overlay.h
  Pictures of photo-models for people: the sampled points drawn on the photo, and the model
  alone (S_in in its hues, S_out in white) on grey, like Fig. 4 (c), (d) of the paper.
  Also the model's points as they scored at a pose (drawPointScores), the relief a stereo model
  measured (drawDepth), and two helpers: a text label in an image and two images side by side.
  Every function returns a new image and leaves its inputs unchanged, except drawLabel() and
  drawCorrespondenceLines(), which draw into the image they are given. Point coordinates are pixels: u the column, v the row.
*/
#include <string>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/CameraImages.h"
#include "pm/core/StereoFitness.h"
#include "pm/precise/CorrespondenceLines.h"

namespace pm::report {

/*!
  The photo with the region outline (yellow), S_in (green), S_out (red) and the origin (cross).
  Each point is drawn where it was sampled (ModelPoint::u, v), the white cross at the region's
  centroid (PhotoModel::centroidU, centroidV), and the point counts are written in the top-left
  corner. \e region is the target mask (non-zero inside), of the photo's size; a mask of another
  size draws no outline.
*/
vpImage<vpRGBa> drawModelOnPhoto(const vpImage<vpRGBa> &photo, const vpImage<unsigned char> &region, const core::PhotoModel &m);
/*!
  The model alone: S_in points in their own hue, S_out points white, on dark grey.
  The image has the photo's size (PhotoModel::photoWidth x photoHeight px), each point drawn where
  it was sampled (u, v), with a caption in the top-left corner.
*/
vpImage<vpRGBa> drawModel(const core::PhotoModel &m);
/*!
  The model projected at a pose, each point coloured by how it scored (Eqs. 8, 9): S_in on the
  target green, on background yellow, elsewhere light grey; S_out on background light blue,
  elsewhere (on the target, or on a pixel without hue) red.
  Draws each PointScore at its (u, v) on a copy of \e image, leaving out the points of class
  PointScore::Off, and writes \e label in white in the top-left corner. The scores' (u, v) are in
  the raw (distorted) image of their camera, so \e image is that camera's image as taken.
  \code
  pm::core::StereoFitness fitness(rig, model);        // rig, model: pm/io/RigFile.h, pm/io/PhotoModelFile.h
  fitness.setImages(IL, IR);                    // the stereo pair, vpImage<vpRGBa>
  const vpImage<vpRGBa> both = pm::report::sideBySide(
      pm::report::drawPointScores(IL, fitness.pointScores(phi, 0), "model at phi, left"),
      pm::report::drawPointScores(IR, fitness.pointScores(phi, 1), "right"));
  pm::io::writeImage(both, "scores.png");       // pm/io/ImageFile.h
  \endcode
*/
vpImage<vpRGBa> drawPointScores(const vpImage<vpRGBa> &image, const std::vector<core::PointScore> &scores,
                                const std::string &label);
/*!
  The relief the rig measured: the photo in grey, each matched region pixel coloured by its depth
  in the hand frame (\e depthMm, NaN where unmatched; red near, blue far over [near, far]), the
  S_in points kept (white) and dropped (black), and a colour bar with the depths in mm.
  \e depthMm must have the photo's size (else no pixel is coloured); every finite pixel of it is
  coloured, a depth outside [\e nearMm, \e farMm] (mm) with the colour of the nearer end (a span
  of 1 mm when \e farMm <= \e nearMm). \e dropped are the S_in points left out of \e m (drawn at
  their u, v in the photo). The result is 40 px taller than the photo: the colour bar, labelled
  with \e nearMm and \e farMm, is in that strip under the photo.
*/
vpImage<vpRGBa> drawDepth(const vpImage<vpRGBa> &photo, const vpImage<float> &depthMm, const core::PhotoModel &m,
                          const std::vector<core::ModelPoint> &dropped, double nearMm, double farMm);
/*!
  Writes \e text at (row, col) with ViSP's font, in \e color.
  Draws into \e I itself, in ViSP's 16 px monospace font (vpFont), over a black shadow one pixel
  down and right; (row, col) in pixels is the position given to vpFont::drawText.
*/
void drawLabel(vpImage<vpRGBa> &I, const std::string &text, int row, int col, const vpRGBa &color);
/*!
  The precise stage's correspondence lines of one camera as last measured (precise::CorrespondenceLines),
  drawn into \e I: each kept line as a short cyan stroke along its normal through the outline it
  found, each line found hidden (precise::StereoOcclusion) as a longer magenta stroke through its
  centre. The lines' pixels are of the ideal (undistorted) image: on a camera with a lens, a few
  pixels off the raw image near its edges.
  \code
  const pm::precise::PreciseStage &stage = *tracker.preciseStage();
  vpImage<vpRGBa> left = IL;
  pm::report::drawCorrespondenceLines(left, stage.lines(0));
  \endcode
*/
void drawCorrespondenceLines(vpImage<vpRGBa> &I, const precise::CorrespondenceLines &lines);
/*!
  Places \e b to the right of \e a.
  The result is as wide as both and as high as the higher; the part under the lower one is black.
*/
vpImage<vpRGBa> sideBySide(const vpImage<vpRGBa> &a, const vpImage<vpRGBa> &b);

/*!
  A rig's images side by side, each with its points drawn (drawPointScores; \e scores[k] on image k,
  none past the end) and its label (\e labels[k], none past the end).
  \code
  const vpImage<vpRGBa> all = pm::report::drawCameras(pm::core::CameraImages::of(images),
                                                      {fitness.pointScores(phi, 0)}, pm::report::cameraLabels(images.size(), "found, "));
  \endcode
*/
vpImage<vpRGBa> drawCameras(const core::CameraImages &images, const std::vector<std::vector<core::PointScore>> &scores,
                            const std::vector<std::string> &labels);
//! The labels of \e n cameras' images: a pair's \e prefix + "left", "right"; otherwise \e prefix + "camera 0", "camera 1", ...
std::vector<std::string> cameraLabels(std::size_t n, const std::string &prefix);

} // namespace pm::report
