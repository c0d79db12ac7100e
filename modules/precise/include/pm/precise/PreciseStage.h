#pragma once
/*!
  \file PreciseStage.h
  The precise last stage of a frame: from RM-GA's best pose (or the last frame's), Gauss-Newton
  steps on a smooth objective of the outline in every camera of the rig at once, coarse to fine, after the
  region-based trackers (SRT3D, DLR's M3T). The hue fitness of Eqs. (8)-(11) finds the target with
  no initial pose but is flat in rotation near its peak (a turn of 2 deg moves the image by 1.5 px
  and costs nothing); this objective moves with every pixel the outline moves.

  Each iteration: the correspondence lines of each camera are measured at the current pose
  (CorrespondenceLines.h: where along each outline normal the colours turn from target to
  background), then \e updatesPerScale Gauss-Newton steps with a Tikhonov regularisation
  (the step's prior: no motion) move the pose toward the outline's measured positions. The lines'
  segments shrink from the first scale to the last (pixels per segment), their search range with
  them. The colour posteriors come from the model's photos (PhotoModel::foregroundHistogram) and
  follow the scene: learnColours() blends in each frame's colours along the outline.

  \code
      pm::precise::PreciseStage precise(rig, model);           // the model must carry outlines (version 5)
      precise.setImages({IL, IR});                    // the frame, one image per camera (kept by pointer until the next)
      const pm::precise::PreciseResult r = precise.refine(rmgaBest);
      if (r.ok) { phi = r.phi; precise.learnColours(phi); }
  \endcode
*/
#include <array>
#include <memory>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/PhotoModel.h"
#include "pm/core/Pose.h"
#include "pm/core/CameraImages.h"
#include "pm/core/CameraRig.h"
#include "pm/core/UndistortMap.h"
#include "pm/precise/ColourHistograms.h"
#include "pm/precise/CorrespondenceLines.h"
#include "pm/precise/InteriorTerm.h"
#include "pm/precise/IdealImage.h"
#include "pm/precise/OutlineViews.h"
#include "pm/precise/StereoOcclusion.h"

namespace pm::precise {

/*!
  The precise stage's parameters (PreciseStage.h), with measured defaults; validate() checks them.
*/
struct PreciseParams
{
  std::size_t lines = 150;               //!< correspondence lines per camera (at most; the viewpoint's contour points)
  std::vector<int> scales{5, 2, 1, 1};   //!< pixels per segment, one measurement each, coarse to fine
  std::vector<double> sigmasPx{12, 4, 1.5, 1.5}; //!< per scale: the lines' weight is the least variance over this squared (px)
  std::vector<int> nearScales{2, 1, 1};  //!< the scales from a start known to be near (refine(start, true): the last frame's pose)
  std::vector<double> nearSigmasPx{4, 1.5, 1.5}; //!< their sigmas
  int interiorMaxScale = 16;             //!< the interior term joins from this scale down (px per segment; 16: at every scale)
  int updatesPerScale = 2;               //!< Gauss-Newton steps per measurement
  LineShape shape;                       //!< the smoothed step and the distribution's length (segments)
  double minContinuous = 3;              //!< a line needs this many segments of target and of background
  double regularisationRotation = 1000;  //!< Tikhonov weight of a turn (per rad^2)
  double regularisationTranslation = 0.03; //!< Tikhonov weight of a shift (per mm^2)
  double learningRate = 0.2;             //!< how much of a frame's colours learnColours() blends in
  double histogramSkipPx = 0.5;          //!< colours are learnt from this far off the outline ...
  double histogramMaxPx = 20;            //!< ... to this far (px)
  std::size_t minLines = 24;             //!< fewer lines in all the cameras together: no result (PreciseResult::ok false)
  std::size_t interiorPoints = 200;      //!< the interior term's points per camera (InteriorTerm.h; 0: off, the outline alone)
  double interiorSigma = 0.05;           //!< the chromaticity's noise the interior term assumes
  double interiorWeight = 1.0;           //!< the interior term's weight beside the outline's
  StereoOcclusionParams occlusion;       //!< the lines hidden in one camera and seen by its partner leave the stage (StereoOcclusion.h; one camera: off)

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

//! What PreciseStage::refine() found.
struct PreciseResult
{
  core::Phi phi;                     //!< the refined pose (the start when !ok)
  bool ok = false;             //!< enough lines were measured in the last iteration
  std::size_t cameras = 0;     //!< the rig's cameras: the arrays' entries that count
  std::array<std::size_t, core::CameraRig::kMaxCameras> lines{}; //!< lines measured in each camera at the finest scale
  std::array<std::size_t, core::CameraRig::kMaxCameras> hiddenLines{}; //!< lines found hidden in each camera at the finest scale and left out (StereoOcclusion.h)
  /*!
    The Gauss-Newton information of the finest scale's lines at phi: sum over lines of J^T J /
    variance, J the line position's derivative (px) with respect to the twist (mm, then rad; hand
    frame, about the model's origin). Its inverse is the pose's covariance under the lines' model.
  */
  std::array<double, 36> information{};
  double residualPx = 0;       //!< rms distance between the outline found on each line and the model's (finest scale, px)
  std::array<double, core::CameraRig::kMaxCameras> residualPxPerCamera{}; //!< the same in each camera alone (0 where a camera has no line)
  //! All the cameras' lines.
  std::size_t totalLines() const
  {
    std::size_t n = 0;
    for (std::size_t k = 0; k < cameras; ++k)
      n += lines[k];
    return n;
  }
  double separation = 0;       //!< mean over lines of how sharply target and background split along them, in [0, 1]
  int iterations = 0;          //!< Gauss-Newton steps taken
};

/*!
  The precise stage (see PreciseStage.h). Copies what it needs of the rig and the model; holds the
  colour histograms from frame to frame. refine() allocates nothing. Not thread-safe.
  \code
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/precise/PreciseStage.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json"); // an all-around model
  pm::precise::PreciseStage precise(rig, model);
  const vpImage<vpRGBa> IL = pm::io::readColorImage("left.png"), IR = pm::io::readColorImage("right.png");
  precise.setImages({IL, IR});            // one image per camera of the rig
  pm::core::Phi phi;                      // a pose within a few degrees and millimetres
  phi.z = 500;
  const pm::precise::PreciseResult r = precise.refine(phi);
  std::cout << r.phi.toString() << " from " << r.totalLines() << " lines\n";
}
  \endcode
*/
class PreciseStage
{
public:
  //! Throws pm::core::Error for an invalid rig (one camera or more) or parameters, or a model without outlines.
  PreciseStage(const core::CameraRig &rig, const core::PhotoModel &model, const PreciseParams &params = PreciseParams());
  PreciseStage(const PreciseStage &) = delete;            //!< its lines keep pointers to its cameras
  PreciseStage &operator=(const PreciseStage &) = delete; //!< its lines keep pointers to its cameras
  /*!
    The frame's images (raw, as the cameras gave them), one per camera: kept by pointer, they must
    live until the last refine() or learnColours() on them. Throws pm::core::Error if their number
    is not the rig's or a size is not its camera's.
  */
  void setImages(const core::CameraImages &images);
  //! The rig's number of cameras.
  std::size_t cameraCount() const { return m_nCams; }
  //! The background's hue its hidden lines compare with (deg, [0, 360)): the model's until set (tracker::BackgroundLearning).
  void setBackgroundHue(double deg)
  {
    if (m_occlusion)
      m_occlusion->setBackgroundHue(deg);
  }
  /*!
    Refines \e start on the images (see PreciseStage.h): with every scale, or, \e near (a start known
    to lie within a few pixels, e.g. the last frame's pose while tracking), with nearScales only;
    \e lookForHidden false: every line and interior point counts this time, even with
    PreciseParams::occlusion on (the tracker looks only where the fitness found part of the target
    hidden). Throws pm::core::Error for no images or an invalid start.
  */
  PreciseResult refine(const core::Phi &start, bool near = false, bool lookForHidden = true);
  /*!
    The stage's objective at \e phi, what its steps drive down: the lines measured at \e phi at the
    finest scale, the mean of (offset / its standard deviation)^2 of the outline each finds from the
    model's, plus, with the interior term, the mean of (chromaticity residual / interiorSigma)^2 (0 at a
    perfect fit; smooth in the pose). For plots (pm-fitness-map --profiles). Throws pm::core::Error for no
    images or an invalid pose; NaN when too few lines are measured.
  */
  double objective(const core::Phi &phi);
  /*!
    Blends this frame's colours along the outline at \e phi into the histograms (learningRate; the
    whole of them when the model gave none and none were learnt yet); along the lines not hidden
    (PreciseParams::occlusion), unless \e lookForHidden is false (refine()'s).
  */
  void learnColours(const core::Phi &phi, bool lookForHidden = true);
  /*!
    The same as learnColours(), into colours kept aside (from the ones in use at the first such
    call): the stage measures with the colours in use until takeColoursLearntAside(). For frames of
    a pose not yet known right (a new lock awaiting its verification), kept once it is known right.
  */
  void learnColoursAside(const core::Phi &phi, bool lookForHidden = true);
  //! The colours learnt aside, if any, become the ones in use.
  void takeColoursLearntAside();
  //! The colours learnt aside, if any, are forgotten.
  void dropColoursLearntAside() { m_aside = false; }
  bool hasColoursLearntAside() const { return m_aside; } //!< learnColoursAside() since the last take or drop
  //! Back to the model's colour histograms (or none); the colours learnt aside forgotten.
  void resetColours();
  const ColourHistograms &colours() const { return m_colours; }                    //!< the colour statistics
  const CorrespondenceLines &lines(int camera) const { return *m_lines[static_cast<std::size_t>(camera)]; } //!< the last measurement
  const LineCamera &camera(int camera) const { return m_cams[static_cast<std::size_t>(camera)]; }           //!< a camera as the lines see it
  const OutlineViews &outlines() const { return m_outlines; }                       //!< the model's outlines
  const PreciseParams &params() const { return m_params; }                          //!< the parameters

private:
  //! Camera \e k's interior samples at \e phi (its lines' viewpoint), without those \e occlusion finds hidden (null: all).
  std::size_t measureInterior(std::size_t k, const core::Phi &phi, int scale, const StereoOcclusion *occlusion);
  //! A one-camera rig's Gauss-Newton sums at \e phi (lines and interior) into \e g and \e H, on two cores.
  void accumulateOneCamera(const core::Phi &phi, int scale, double weight, double g[6], double H[36]);
  PreciseParams m_params;
  OutlineViews m_outlines;
  //! The camera whose view tells camera \e k's hidden lines (the next one; the last: the one before), or null alone.
  const LineCamera *partner(std::size_t k) const;
  //! The lines of each camera look for hidden ones with \e occlusion (null: every line counts).
  void useOcclusion(const StereoOcclusion *occlusion);
  static constexpr std::size_t kMax = core::CameraRig::kMaxCameras;
  std::size_t m_nCams = 0;
  core::CameraRig m_rig; //!< the rig, for its images' sizes
  std::array<LineCamera, kMax> m_cams;
  std::array<std::shared_ptr<const core::UndistortMap>, kMax> m_undistort;
  std::array<std::unique_ptr<IdealImage>, kMax> m_ideal; //!< through a lens: what the stage reads (null: a pinhole, the image itself)
  //! Through a lens: each camera's ideal image resampled where the stage reads at \e phi (the outline's box and the lines' reach).
  void coverAround(const core::Phi &phi);
  std::array<std::unique_ptr<CorrespondenceLines>, kMax> m_lines;
  std::unique_ptr<StereoOcclusion> m_occlusion; //!< null: every line counts
  std::unique_ptr<InteriorTerm> m_interior; //!< null: off, or a model without colours
  std::array<InteriorSamples, kMax> m_samples;  //!< each camera's interior samples of the last measurement (one camera's refine: [0] and [1], its points' two halves)
  ColourHistograms m_colours;
  ColourHistograms m_asideColours; //!< learnColoursAside()'s, while m_aside
  bool m_aside = false;
  std::vector<float> m_modelF, m_modelB;
  bool m_hasImages = false;
};

} // namespace pm::precise
