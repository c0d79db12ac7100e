#pragma once
/*!
  \file ViewpointIndex.h
  The one nearest-viewpoint lookup of a photo-model: which of its views (view 0 the model's own,
  then PhotoModel::views) was made from the direction nearest a camera's, as seen from the model's
  origin. The stereo fitness scores that view's points for a camera (StereoFitness.h), the precise
  stage measures that view's outline (precise::OutlineViews): both through this index, so that they
  always agree on the view.

  The answer is the exact nearest (the view of largest dot product with the direction, the first
  one on a tie; view 0 when every view looks from more than about 90 degrees away), at the cost of a lookup and a few dot products: for a model of many views (an
  all-around model) the sphere of directions is cut into the cells of a cube map, and each cell
  keeps the views that can be nearest anywhere in it.

  \code
    const pm::core::ViewpointIndex views(model);
    const double camera[3] = {0, 0, -500};          // a camera 500 mm in front of the model's origin
    const std::size_t k = views.nearest(camera);    // 0: the model's own view
  \endcode
*/
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pm/core/PhotoModel.h"
#include "pm/core/Vec3.h"

namespace pm::core {

//! The model's views by direction (see the file's description). Copies the directions; allocates nothing in nearest().
class ViewpointIndex
{
public:
  ViewpointIndex() = default;
  //! The views of \e model: its own (view 0), then each of PhotoModel::views. Throws core::Error for more than 65,535 views.
  explicit ViewpointIndex(const PhotoModel &model);
  //! The views of these directions (view k: \e directions[k], made unit).
  explicit ViewpointIndex(std::vector<Vec3> directions);

  std::size_t size() const { return m_dirs.size(); }                 //!< views
  const Vec3 &direction(std::size_t k) const { return m_dirs[k]; }    //!< view \e k's unit direction from the model's origin
  //! The view whose direction is nearest that of \e c (any length but 0: a camera's centre in the model frame).
  std::size_t nearest(const double c[3]) const;

private:
  void buildCells();
  //! The cube-map cell of direction \e c (any length, not zero).
  static std::size_t cell(const double c[3]);
  static constexpr int kCells = 64;         //!< cells along each side of a face of the cube
  static constexpr std::size_t kScan = 16;  //!< up to this many views, nearest() scans them all

  std::vector<Vec3> m_dirs;
  std::vector<std::uint32_t> m_cellStart;   //!< cell c's candidates: m_candidates[m_cellStart[c], m_cellStart[c + 1])
  std::vector<std::uint16_t> m_candidates;  //!< the views that can be nearest somewhere in each cell, in increasing order
};

} // namespace pm::core
