#pragma once
/*!
  \file InteriorTerm.h
  The precise stage's interior term: where the outline alone leaves a degree of freedom weak (a
  round head turning about its own axis, a box's printed front seen face-on), the colours inside the
  outline pin it. Each S_in point of the viewpoint nearest the camera carries the surface's colour
  (PhotoModel::hasColours); at the pose being refined it should see that colour in the image. The
  residual is the difference of chromaticities (two opponent channels divided by the brightness, so
  that shading and exposure change it little), its Jacobian the image's chromaticity gradient (central
  differences over \e stepPx pixels, wider at the coarse scales) times the point's projection
  Jacobian; a Huber weight bounds what a shadow, a highlight or an occluder can do.

      pm::InteriorTerm interior(model, 200);
      interior.accumulate(camera, view, phi, 1.0, 0.05, 1.0, g, H, nullptr);
*/
#include <cstddef>
#include <vector>

#include "pm/core/PhotoModel.h"
#include "pm/core/Pose.h"
#include "pm/precise/CorrespondenceLines.h"

namespace pm {

/*!
  The interior colour term of the precise stage (see InteriorTerm.h): the S_in points of every
  viewpoint with their colour, in the order of OutlineViews (the model's own view, then its views).
  accumulate() allocates nothing.
  \code
  const pm::InteriorTerm interior(model, 200);  // model.hasColours
  double g[6] = {0}, H[36] = {0};
  interior.accumulate(camera, outlines.nearest(c), phi, 1.0, 0.05, 1.0, g, H, nullptr);
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
    chosen). Throws pm::Error unless the model carries colours.
  */
  InteriorTerm(const PhotoModel &model, std::size_t maxPoints);
  /*!
    Adds \e weight times the term's gradient (of the log-likelihood, 6, twist) to \e g and its
    Gauss-Newton information to \e H, for camera \e cam at pose \e phi with the points of viewpoint
    \e view; \e sigma is the chromaticity's noise, \e stepPx the gradient's half-width. \e residual2
    (when given) gets the sum of squared residuals of the points used. Returns the points used.
  */
  std::size_t accumulate(const LineCamera &cam, std::size_t view, const Phi &phi, double stepPx, double sigma, double weight,
                         double g[6], double H[36], double *residual2) const;
  //! The chromaticity of a colour: (R - G, R + G - 2 B) / (R + G + B + 30), each in about [-1, 1].
  static void chroma(double r, double g, double b, double out[2])
  {
    const double s = 1.0 / (r + g + b + 30.0);
    out[0] = (r - g) * s;
    out[1] = (r + g - 2 * b) * s;
  }
  std::size_t views() const { return m_views.size(); } //!< viewpoints

private:
  struct View
  {
    std::size_t begin, end;
  };
  std::vector<View> m_views;
  std::vector<Point> m_points;
};

} // namespace pm
