#pragma once
/*!
  \file CorrespondenceLines.h
  One camera's correspondence lines, the measurement of the precise stage (PreciseStage.h), after
  the region-based trackers (SRT3D, DLR's M3T; written anew here). For the pose being refined,
  each contour point of the viewpoint nearest the camera projects into the image with its outline's
  normal; a line of pixels along that normal, centred on it, is cut into segments of \e scale pixels,
  and each segment gets the probability that it lies on the target from the colour posteriors of
  its pixels (ColourHistograms). A smoothed step (target, then background) slid along the line
  gives the probability of each position of the outline on the line; its mean and variance are the
  measurement. The objective of a pose is then, summed over the lines,

      L = - sum_i w (d_i - mu_i)^2 / (2 sigma_i^2)

  with d_i where the contour point projects along its line at that pose (pixels); its gradient and
  Gauss-Newton Hessian with respect to a small motion of the model (Pose.h's applyTwist: mm, then
  rad, in the hand frame) come from the point's projection Jacobian. Smooth in the pose, and as
  sensitive to a turn as to a shift: a turn moves the outline.

  \code
      pm::precise::CorrespondenceLines lines(200, 19, 6);
      lines.measure(camera, outlines, phi, shape, colours, 2, 150, 3.0);
      double g[6] = {0}, H[36] = {0};
      lines.accumulate(camera, phi, weight, g, H, nullptr);
  \endcode
*/
#include <array>
#include <cstdint>
#include <vector>

#include <visp3/core/vpRGBa.h>

#include "pm/core/PinholeCamera.h"
#include "pm/core/Pose.h"
#include "pm/precise/ColourHistograms.h"
#include "pm/precise/OutlineViews.h"
#include "pm/precise/StereoOcclusion.h"

namespace pm::precise {

/*!
  A camera as the lines see it: the rig's camera placed in the hand frame (core::PinholeCamera::
  Projection: cMh in mm, the intrinsics of its ideal image, its size) and its image this frame (raw;
  read through \e nearest, the UndistortMap's ideal-to-raw pixel index, when the lens has distortion).
*/
struct LineCamera : core::PinholeCamera::Projection
{
  const vpRGBa *image = nullptr;         //!< this frame's raw image (row-major w x h)
  const std::int32_t *nearest = nullptr; //!< ideal pixel -> raw pixel index (-1: off the raw image); null: a pinhole camera
};

/*!
  The shape of the lines: the smoothed step and the lengths, shared by every line (see
  PreciseParams for their meaning). prepare() fills the step's table.
*/
struct LineShape
{
  static constexpr int kMaxFunction = 16;     //!< longest smoothed step (segments)
  static constexpr int kMaxDistribution = 32; //!< longest distribution (segments)
  int functionLength = 8;      //!< segments the smoothed step spans
  /*!
    Positions of the outline considered along a line. Odd, with an even step: the line's centre (the
    contour point's projection) is then a segment boundary, one of the positions; with an even length
    an outline right at the centre would fall mid-segment, where the segment's pixels tie and the
    tie's winner moves the measure by half a segment.
  */
  int distributionLength = 13;
  double amplitude = 0.43;     //!< the step goes from 0.5 + amplitude to 0.5 - amplitude
  double slope = 0.5;          //!< its width (segments)
  std::array<float, kMaxFunction> foreground{}; //!< the step's values on the target's side (prepare())
  std::array<float, kMaxFunction> background{}; //!< the step's values on the background's side (prepare())
  double minVariance = 0.5;    //!< the least variance a measured position can have (segments^2; prepare())
  //! Fills the step's table and the least variance. Throws pm::core::Error for lengths or shapes out of range.
  void prepare();
  int segments() const { return functionLength + distributionLength - 1; } //!< a line's length in segments
};

//! One measured line: the contour point, the line in the image, and where the outline was found on it.
struct LineMeasure
{
  float X[3];        //!< the contour point in the model frame (mm)
  float cu;         //!< the line's centre, column: the point's projection when measured (px)
  float cv;         //!< the line's centre, row (px)
  float nu;         //!< the line's direction, u: the outline's outward normal in the image (unit)
  float nv;         //!< the line's direction, v
  float mean;        //!< where the outline lies along the line, from the centre (px)
  float variance;    //!< its variance (px^2)
  float separation;  //!< how sharply the line's segments split into target and background, in [0, 1]
};

/*!
  One camera's correspondence lines (see CorrespondenceLines.h). Holds its buffers: measure() and
  accumulate() allocate nothing once constructed.
*/
class CorrespondenceLines
{
public:
  //! Buffers for up to \e maxLines lines of up to \e maxSegments segments of \e maxScale pixels.
  CorrespondenceLines(std::size_t maxLines, int maxSegments, int maxScale);
  /*!
    Lines hidden in this camera (StereoOcclusion.h) leave the measurement: \e occlusion decides,
    from this camera's image and \e other's (the rig's other camera as the lines see it, its image
    read at each measure()). Both are kept by pointer and must outlive the lines; null: every line counts.
  */
  void setOcclusion(const StereoOcclusion *occlusion, const LineCamera *other)
  {
    m_occlusion = occlusion;
    m_other = occlusion ? other : nullptr;
  }
  /*!
    Measures the lines of camera \e cam at pose \e phi (hMo) on its image: at most \e maxLines
    contour points of the viewpoint nearest the camera, evenly chosen; segments of \e scale pixels.
    A line is left out when its point is behind the camera, the line leaves the image, or the target
    or the background along it is shorter than \e minContinuous segments, and when it is hidden in
    this camera (setOcclusion(); then kept apart: hiddenCount(), hiddenLine()). Returns the lines kept.
  */
  std::size_t measure(const LineCamera &cam, const OutlineViews &outlines, const core::Phi &phi, const LineShape &shape,
                      const ColourHistograms &colours, int scale, std::size_t maxLines, double minContinuous);
  /*!
    Adds \e weight times the lines' gradient of L (6, twist) to \e g and their Gauss-Newton
    information (6x6, row-major, positive) to \e H, at pose \e phi; \e residual2 (when given) gets
    the sum of the squared distances (px^2) between the outline found and the contour point's
    projection. Returns the lines in front of the camera.
  */
  std::size_t accumulate(const LineCamera &cam, const core::Phi &phi, double weight, double g[6], double H[36],
                         double *residual2) const;
  /*!
    Adds the colours of camera \e cam at pose \e phi to \e colours' counts: along each contour point's
    normal, from \e skipPx to at most \e maxPx pixels inside (target) and outside (background); not
    along the lines hidden in this camera (setOcclusion()).
  */
  void collectColours(const LineCamera &cam, const OutlineViews &outlines, const core::Phi &phi, ColourHistograms &colours,
                      std::size_t maxLines, double skipPx, double maxPx) const;
  std::size_t size() const { return m_n; }                          //!< lines kept by the last measure()
  const LineMeasure &line(std::size_t i) const { return m_lines[i]; } //!< line \e i of the last measure()
  std::size_t hiddenCount() const { return m_nHidden; }            //!< lines the last measure() found hidden and left out
  const LineMeasure &hiddenLine(std::size_t i) const { return m_hidden[i]; } //!< hidden line \e i of the last measure() (its outline as measured)
  //! The viewpoint the last measure() used.
  std::size_t viewpoint() const { return m_view; }

private:
  //! Whether contour point \e q (\e pxPerMm at its depth) is hidden in camera \e cam (the model at \e self, its centre at \e centre) and seen by m_other (at \e other).
  bool hiddenHere(const LineCamera &cam, const core::ContourPoint &q, const ModelInCamera &self, const double centre[3], const ModelInCamera &other,
                  double pxPerMm) const;
  std::vector<LineMeasure> m_lines, m_hidden;
  std::vector<float> m_segF, m_segB, m_dist;
  std::size_t m_n = 0, m_nHidden = 0, m_view = 0;
  const StereoOcclusion *m_occlusion = nullptr;
  const LineCamera *m_other = nullptr;
  int m_maxSegments, m_maxScale;
};

//! cMo of \e cam at pose \e phi: its rotation \e R (row-major) and translation \e t (mm), and the pose's rotation \e hRo.
void composeCamera(const LineCamera &cam, const core::Phi &phi, double R[9], double t[3], core::Rot3 &hRo);
//! The camera centre of \e cam (cMh) in the model frame at pose \e phi (mm).
void cameraInModel(const LineCamera &cam, const core::Phi &phi, double out[3]);

} // namespace pm::precise
