#pragma once
/*!
  \file OutlineViews.h
  The outlines of an all-around photo-model as the precise stage reads them: for each of the model's
  viewpoints, its direction from the model's origin and its contour points (PhotoModel::contour,
  ModelView::contour: a point of the outline on the surface, the outline's outward normal, how far
  target and background reach along it). A camera at any pose is served by the viewpoint nearest
  its direction (the sparse viewpoint model of DLR's region-based trackers): the 3-D points of an
  outline seen a few degrees away still project onto the outline, since the contour generator of a
  smooth surface moves with the square of the angle.

  \code
      const pm::precise::OutlineViews outlines(model);             // throws unless model.hasContours()
      const std::size_t k = outlines.nearest(cameraInModelMm);
      for (std::size_t i = outlines.view(k).begin; i < outlines.view(k).end; ++i) use(outlines.point(i));
  \endcode
*/
#include <cstddef>
#include <vector>

#include "pm/core/PhotoModel.h"
#include "pm/core/ViewpointIndex.h"

namespace pm::precise {

/*!
  The contour points of every viewpoint of a model, in one array, and the nearest viewpoint to a
  direction (see OutlineViews.h). Copies what it needs from the model.
  \code
  const pm::precise::OutlineViews outlines(model);
  const double c[3] = {0, 0, -500};     // a camera 500 mm in front of the model's origin
  const pm::precise::OutlineViews::View &v = outlines.view(outlines.nearest(c));
  std::cout << (v.end - v.begin) << " outline points seen from there\n";
  \endcode
*/
class OutlineViews
{
public:
  //! One viewpoint: its points [begin, end).
  struct View
  {
    std::size_t begin = 0;          //!< its first point in point()
    std::size_t end = 0;            //!< one past its last point
  };
  //! Throws pm::core::Error unless the model carries outlines in every view (PhotoModel::hasContours()).
  explicit OutlineViews(const core::PhotoModel &model);

  std::size_t size() const { return m_views.size(); }                 //!< viewpoints
  const View &view(std::size_t k) const { return m_views[k]; }        //!< viewpoint \e k
  const core::ContourPoint &point(std::size_t i) const { return m_points[i]; } //!< contour point \e i of the array
  //! The viewpoint whose direction is nearest that of \e cameraMm (a camera's centre in the model frame, not 0; core::ViewpointIndex).
  std::size_t nearest(const double cameraMm[3]) const { return m_index.nearest(cameraMm); }
  //! The most contour points a viewpoint has.
  std::size_t maxPoints() const { return m_maxPoints; }

private:
  std::vector<View> m_views;
  core::ViewpointIndex m_index; //!< the model's own lookup of the nearest view
  std::vector<core::ContourPoint> m_points;
  std::size_t m_maxPoints = 0;
};

} // namespace pm::precise
