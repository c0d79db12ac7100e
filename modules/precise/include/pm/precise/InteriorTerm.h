#pragma once
/*!
  \file InteriorTerm.h
  The precise stage's interior term: where the outline alone leaves a degree of freedom weak (a
  round head turning about its own axis, a box's printed front seen face-on), the colours inside the
  outline pin it. Each S_in point of the viewpoint nearest the camera carries the surface's colour
  (PhotoModel::hasColours); at the pose being refined it should see that colour in the image. The
  residual is the difference of chromaticities (two opponent channels divided by the brightness, so
  that shading and exposure change it little), its Jacobian the image's chromaticity gradient (over
  the segment's length) times the point's projection Jacobian, linearised at each Gauss-Newton step
  (the texture varies over a pixel or two); a Huber weight bounds what a shadow, a highlight or an
  occluder can do.

  \code
      pm::precise::InteriorTerm interior(model, 200);
      interior.measure(camera, view, phi, 1.0, samples);          // at each step
      pm::precise::InteriorTerm::accumulate(camera, phi, samples, 0.05, 1.0, g, H, nullptr); // each step
  \endcode
*/
#include <cstddef>
#include <vector>

#include "pm/core/PhotoModel.h"
#include "pm/core/Pose.h"
#include "pm/precise/CorrespondenceLines.h"
#include "pm/precise/StereoOcclusion.h"

namespace pm::precise {

/*!
  One camera's interior samples, measured at a pose (InteriorTerm::measure()): for each point, where
  it projected, the image's chromaticity there and its gradient. Held by the caller per camera, so
  that accumulate() reads them without touching the image. PreciseStage measures them again at every
  Gauss-Newton step (linearised once per scale instead, as the lines are, the stage ended 1.3-2.0 deg
  off in test_precise where it ends 0.5-0.8 deg off).
*/
struct InteriorSamples
{
  //! One point as measured.
  struct Sample
  {
    float X[3];     //!< in the model frame (mm)
    float u;        //!< where it projected at the measurement: column (px)
    float v;        //!< ... and row (px)
    float c[2];     //!< the image's chromaticity there
    float dc[2][2]; //!< its gradient: dc[k][0] = d c_k / du, dc[k][1] = d c_k / dv
    float model[2]; //!< the model's chromaticity
  };
  std::vector<Sample> samples; //!< reserved once (no allocation while measuring)
  std::size_t n = 0;           //!< the samples of the last measurement
};

/*!
  The interior colour term of the precise stage (see InteriorTerm.h): the S_in points of every
  viewpoint with their colour, in the order of OutlineViews (the model's own view, then its views).
  measure() and accumulate() allocate nothing once the samples are reserved (reserve()).
  \code
  const pm::precise::InteriorTerm interior(model, 200);  // model.hasColours
  pm::precise::InteriorSamples s;
  interior.reserve(s);
  interior.measure(camera, outlines.nearest(c), phi, 1.0, s);
  double g[6] = {0}, H[36] = {0};
  pm::precise::InteriorTerm::accumulate(camera, phi, s, 0.05, 1.0, g, H, nullptr);
  \endcode
*/
class InteriorTerm
{
public:
  //! One interior point: its place in the model frame and the chromaticity of its colour.
  struct Point
  {
    float X[3]; //!< in the model frame (mm)
    float c[2]; //!< chromaticity (chroma())
  };
  /*!
    Takes the S_in points and colours of every view of \e model, at most \e maxPoints a view (evenly
    chosen). Throws pm::core::Error unless the model carries colours.
  */
  InteriorTerm(const core::PhotoModel &model, std::size_t maxPoints);
  //! Reserves \e s for the largest viewpoint.
  void reserve(InteriorSamples &s) const { s.samples.resize(m_maxPoints); }
  /*!
    Measures the points of viewpoint \e view in camera \e cam at pose \e phi: the chromaticity where
    each projects (bilinear) and its gradient (central differences over \e stepPx pixels: wider at
    the coarse scales, a smoother texture). Points off the image are left out. Returns the samples kept.
  */
  std::size_t measure(const LineCamera &cam, std::size_t view, const core::Phi &phi, double stepPx, InteriorSamples &s) const;
  /*!
    measure() of a part of the points only: the \e part-th of \e parts runs of them, in order (for
    one camera's work on two cores; the parts' samples together are measure()'s).
  */
  std::size_t measurePart(const LineCamera &cam, std::size_t view, const core::Phi &phi, double stepPx, InteriorSamples &s, std::size_t part,
                          std::size_t parts) const;
  /*!
    measure(), leaving out the points hidden in \e cam and seen by \e other (the rig's other camera),
    by \e occlusion's rule (StereoOcclusion.h).
  */
  std::size_t measure(const LineCamera &cam, std::size_t view, const core::Phi &phi, double stepPx, InteriorSamples &s, const LineCamera &other,
                      const StereoOcclusion &occlusion) const;
  /*!
    Adds \e weight times the term's gradient (of the log-likelihood, 6, twist) to \e g and its
    Gauss-Newton information to \e H, for camera \e cam at pose \e phi from its measured samples
    \e s (the image's chromaticity linearised about each sample's measured place); \e sigma is the
    chromaticity's noise (a Huber weight beyond twice it). \e residual2 (when given) gets the sum of
    squared residuals. Returns the samples used.
  */
  static std::size_t accumulate(const LineCamera &cam, const core::Phi &phi, const InteriorSamples &s, double sigma, double weight, double g[6],
                                double H[36], double *residual2);
  //! The chromaticity of a colour: (R - G, R + G - 2 B) / (R + G + B + 30), each in about [-1, 1].
  static void chroma(double r, double g, double b, double out[2])
  {
    const double s = 1.0 / (r + g + b + 30.0);
    out[0] = (r - g) * s;
    out[1] = (r + g - 2 * b) * s;
  }
  std::size_t views() const { return m_views.size(); } //!< viewpoints

private:
  //! measure(), leaving out what \e occlusion finds hidden when given.
  std::size_t measureVisible(const LineCamera &cam, std::size_t view, const core::Phi &phi, double stepPx, InteriorSamples &s, const LineCamera *other,
                             const StereoOcclusion *occlusion, std::size_t part = 0, std::size_t parts = 1) const;
  struct View
  {
    std::size_t begin, end;
  };
  std::vector<View> m_views;
  std::vector<Point> m_points;
  std::size_t m_maxPoints = 0;
};

} // namespace pm::precise
