#pragma once
/*!
  \file VisualHull.h
  The visual hull of the all-around model (AllAroundModelBuilder.h, step 2): the cells of a cube
  around the target that project inside every silhouette of the pass, carved coarse to fine, and
  the continuous field whose zero level is the hull's surface (the least of the silhouettes' signed
  distances where a point projects), from which HullMesh.h takes the surface to a fraction of a cell.

  \code
      // views: the pass's cameras (hull::HullView), masks: their silhouettes
      const pm::model::hull::Vec3 c = pm::model::hull::silhouettesMeet(views, masks);
      std::vector<const pm::model::hull::HullView *> cams;
      for (const pm::model::hull::HullView &v : views)
        cams.push_back(&v);
      pm::model::VisualHull hull = pm::model::hullGrid(c, radiusMm, 1.0);
      pm::model::carveVisualHull(cams, hull, 16.0);
      std::cout << hull.volumeCm3() << " cm3\n";
  \endcode
*/
#include <cstdint>
#include <string>
#include <vector>

#include "pm/model/HullGeometry.h"

namespace pm::model {

/*!
  A visual hull on a dense grid of cubic cells (see VisualHull.h): occupied cells project inside
  every silhouette.
  \code
  pm::model::VisualHull hull = pm::model::hullGrid(centre, 120, 1.0);
  pm::model::carveVisualHull(cams, hull, 16.0);
  for (int z = 0; z < hull.n; ++z) // the occupied cells' centres
    for (int y = 0; y < hull.n; ++y)
      for (int x = 0; x < hull.n; ++x)
        if (hull.at(x, y, z)) use(hull.centre(x, y, z));
  \endcode
*/
struct VisualHull
{
  hull::Vec3 origin{0, 0, 0};   //!< the world position of cell (0, 0, 0)'s corner (mm)
  double cell = 1;              //!< the cells' size (mm)
  int n = 0;                    //!< cells along each axis
  std::vector<std::uint8_t> occ; //!< 1 where occupied, x fastest

  //! The index of cell (\e x, \e y, \e z) in occ.
  std::size_t idx(int x, int y, int z) const
  {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(n) + static_cast<std::size_t>(y)) * static_cast<std::size_t>(n) +
           static_cast<std::size_t>(x);
  }
  //! Whether cell (\e x, \e y, \e z) is occupied (false outside the grid).
  bool at(int x, int y, int z) const { return x >= 0 && y >= 0 && z >= 0 && x < n && y < n && z < n && occ[idx(x, y, z)]; }
  //! The world position of cell (\e x, \e y, \e z)'s centre (mm).
  hull::Vec3 centre(int x, int y, int z) const
  {
    return {origin[0] + (x + 0.5) * cell, origin[1] + (y + 0.5) * cell, origin[2] + (z + 0.5) * cell};
  }
  //! The world position of grid corner (\e x, \e y, \e z) (mm).
  hull::Vec3 corner(int x, int y, int z) const { return {origin[0] + x * cell, origin[1] + y * cell, origin[2] + z * cell}; }
  long occupied() const;     //!< occupied cells
  double volumeCm3() const;  //!< the occupied volume (cm^3)
};

namespace hull {
//! The point nearest (least squares) to the rays from each camera through its silhouette's centroid. Throws pm::core::Error if they do not meet.
Vec3 silhouettesMeet(const std::vector<hull::HullView> &cams, const std::vector<vpImage<unsigned char>> &masks);
/*!
  The hull's field at \e X: the least over \e cams of the silhouette's signed distance where \e X
  projects (px, HullView::sdSmooth): positive inside the hull, 0 on its surface. Behind a camera: -1e6.
*/
double field(const std::vector<const hull::HullView *> &cams, const Vec3 &X);
} // namespace hull

/*!
  The views whose silhouettes disagree with the others' (a wrong pose, a wrong background): on a
  coarse grid of \e cell mm over the cube (\e origin, \e n cells of \e cell) the cells each view alone
  carves of what the others keep; a view carving more than \e maxFraction of it is left out, the
  worst first, up to a quarter of the views. Returns whether each view is used; \e why gets a line per
  view left out, named by \e names.
*/
std::vector<bool> agreeingViews(const std::vector<hull::HullView> &cams, std::size_t nViews, const hull::Vec3 &origin, int n, double cell,
                                double maxFraction, const std::vector<std::string> &names, std::vector<std::string> &why);

/*!
  The empty grid of the hull in the cube of half-width \e radiusMm around \e centre: cells of
  \e finestMm, raised so that the cube holds at most 256 cells across.
*/
VisualHull hullGrid(const hull::Vec3 &centre, double radiusMm, double finestMm);

/*!
  Carves the hull of \e cams in \e grid (hullGrid()): cells of up to \e coarsestMm split down to
  the grid's. A cell projecting wholly outside a silhouette is carved, wholly inside all of them
  kept, otherwise split; at the finest size, kept when its centre projects inside all. Throws
  pm::core::Error when nothing is left.
*/
void carveVisualHull(const std::vector<const hull::HullView *> &cams, VisualHull &grid, double coarsestMm);

/*!
  The cube the hull is carved in: where the silhouettes' rays meet (silhouettesMeet) and a half-width
  that holds each silhouette's farthest pixel from there, with a margin. Throws pm::core::Error if the
  centre is behind a camera.
*/
void hullBox(const std::vector<hull::HullView> &cams, const std::vector<vpImage<unsigned char>> &masks, hull::Vec3 &centre, double &radiusMm);

} // namespace pm::model
