#pragma once
/*!
  \file TargetShape.h
  A 3-D target (a toy) as the renderer needs it: on a texel grid over the model plane, the
  colour of the surface, the signed distance to the outline and the relief (height above the
  base plane). buildTargetMesh() turns it into a height-field mesh whose outline is cut
  smoothly by the signed distance, whose relief hides parts of itself seen from the side.

  Target frame (= model frame at the true pose): x right, y down, z away from the viewer;
  origin on the outline's centroid, on the base plane: the toy rests on the backdrop at z = 0
  and its relief rises toward the viewer, up to z = -depth. The photo-model's region is where
  the toy hides the backdrop, its footprint, so the model plane is the base plane and the
  photo distance is measured to it (in a lab: the distance from the camera to the backdrop).
*/
#include <memory>
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/sim/Mesh.h"

namespace pm::sim {

//! What a target is called and its nominal size (an entry of the catalogues of TargetCatalog.h).
struct TargetInfo
{
  std::string code;     //!< "C12", or "user"
  std::string name;     //!< "crab"
  double widthMm = 0;   //!< nominal extent along x (mm)
  double heightMm = 0;  //!< nominal extent along y (mm)
  double depthMm = 0;   //!< relief (thickness toward the viewer, mm)
};

/*!
  A 3-D target on a texel grid (see TargetShape.h): row-major grids of cols x rows texels, texel
  (c, r) at x = (c - originCol) texelMm, y = (r - originRow) texelMm in the target frame. Made by
  makeTarget(), targetFromImage() or flatPrint(); buildTargetMesh() makes its mesh.
*/
struct TargetShape
{
  TargetInfo info;        //!< code, name and nominal size
  double texelMm = 0.25;  //!< texel size of the grids (mm)
  //! Grid width (texels, along x).
  int cols = 0, rows = 0; //!< grid height (texels, along y)
  //! Column (texel coordinate, along x) of the frame origin.
  double originCol = 0, originRow = 0; //!< row (texel coordinate, along y) of the frame origin
  std::vector<std::uint8_t> rgb;       //!< albedo, 3 per texel
  std::vector<float> sdf;              //!< signed distance to the outline (mm), negative inside
  std::vector<float> height;           //!< relief above the base (mm); continued linearly below 0 outside
  /*!
    The underside (optional): its height above the base plane (the backdrop, z = 0) in mm, on the
    same grid. Empty: the toy lies flat on its base, its outline at z = 0 (the 12 sea creatures).
    Otherwise the toy is a closed body between the underside (z = -base) and the top
    (z = -height), which meet on the outline: its outline sits at the height \e base has there,
    above the backdrop, and only where base = 0 (a stand) does the toy touch the backdrop.
    Outside the outline, base is continued linearly upward (height downward) so that the two
    sheets cross on it.
  */
  std::vector<float> base;

  //! Extent of the outline (sdf < 0) along x and y (mm), measured on the grid.
  void measuredExtent(double &widthMm, double &heightMm) const;
  //! Bilinear sample of a grid at model-plane position (mm).
  float sampleGrid(const std::vector<float> &grid, double xMm, double yMm) const;
  //! Recentres the frame origin on the outline's centroid.
  void centreOnOutline();
  //! Multiplies the relief (heights, underside and depth) by \e s >= 0 (0: a flat picture of the toy).
  void scaleRelief(double s);
};

/*!
  The height-field mesh of a target, vertices every \e stepMm (the outline itself is cut at
  the zero of the interpolated signed distance, much finer than the step). When the shape has an
  underside (TargetShape::base), a second sheet for it, cut by the same outline: a closed body.
  Positions in metres in the target frame, the shape's colours as texture, Mesh::specular =
  \e specular. Throws pm::core::Error for a grid smaller than 2 x 2 or grids that do not match its size.
*/
Mesh buildTargetMesh(const TargetShape &shape, double stepMm = 1.0, float specular = 0.12f);

/*!
  A target from a user's photo (PNG/JPEG): the image is the texture, \e widthMm its physical
  width (height by aspect ratio); the outline is the alpha channel where the image has one
  (alpha < 128 is outside), the whole rectangle otherwise; the default relief is a rounded
  dome of \e depthMm (0: flat). Its code is "user", its origin the outline's centroid. Throws
  pm::core::Error for an empty image, \e widthMm \<= 0, \e depthMm \< 0, or an alpha channel with nothing opaque.
*/
TargetShape targetFromImage(const vpImage<vpRGBa> &image, double widthMm, double depthMm, const std::string &name);

/*!
  A flat printed sheet (a calibration pattern) \e widthMm wide, its frame at the image's centre
  (x right, y down), as pm::calib's patterns define theirs.
*/
TargetShape flatPrint(const vpImage<vpRGBa> &image, double widthMm, const std::string &name);

//! Height profile of a rounded edge: 0 at the outline, 1 from \e t = 1 inward (quarter circle),
//! continued below 0 outside with the slope of its first \e stepFrac.
double edgeProfile(double t, double stepFrac);

} // namespace pm::sim
