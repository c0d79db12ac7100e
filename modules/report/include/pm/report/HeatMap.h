#pragma once
/*!
  \file HeatMap.h
  A heat map of a function sampled on a regular 2-D grid, drawn as a person expects: axes with
  ticks and labels, a colour bar, a title, and markers (the truth, the peak).
*/
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::report {

/*!
  A function sampled on a regular grid of nx x ny points: sample (i, j) is the value at
  x = x0 + i dx, y = y0 + j dy, in the axes' own units (e.g. mm). The grid owns its values;
  drawHeatMap() needs nx * ny of them.
*/
struct Grid2D
{
  /*! \var pm::report::Grid2D::xName
      \brief horizontal axis label, e.g. "x [mm]" */
  std::string xName, yName;        //!< vertical axis label, e.g. "y [mm]"
  /*! \var pm::report::Grid2D::x0
      \brief x of the first column of samples (i = 0)
      \var pm::report::Grid2D::dx
      \brief step in x between two columns of samples
      \var pm::report::Grid2D::y0
      \brief y of the first row of samples (j = 0) */
  double x0 = 0, dx = 1, y0 = 0, dy = 1; //!< step in y between two rows of samples
  /*! \var pm::report::Grid2D::nx
      \brief number of samples along x (columns) */
  int nx = 0, ny = 0;              //!< number of samples along y (rows)
  std::vector<double> values;      //!< ny rows of nx values, row j at y = y0 + j dy

  //! The value at x = x0 + i dx, y = y0 + j dy (values[j * nx + i]); no bounds check.
  double at(int i, int j) const { return values[static_cast<std::size_t>(j) * nx + i]; }
};

/*!
  A point to mark on a heat map, in the grid's coordinates, with its entry in the legend under the
  colour bar (a small copy of the mark, then \e label). The mark is 20 px wide and outlined in white
  so that it shows on every colour of the map. Set x, y and cross: they have no default.
*/
struct Marker
{
  /*! \var pm::report::Marker::x
      \brief position along the horizontal axis, in the grid's x unit */
  double x, y;                     //!< position along the vertical axis, in the grid's y unit
  std::string label;               //!< its text in the legend, e.g. "truth"
  vpRGBa color;                    //!< colour of the mark (its alpha is ignored)
  bool cross; //!< a cross, else a circle
};

/*!
  The grid \e g as a 678 x 582 px image: a 480 x 480 px map, each sample a square cell centred on
  its (x, y), y growing upward, coloured with OpenCV's viridis map from the smallest value (dark
  violet) to the largest (yellow); ticks and labels on both axes (xName under the map, yName written
  upward along its left side), \e title above, a colour bar labelled "F" with the values' ticks on the right
  and, under it, the legend of \e markers, drawn on the map in their order.
  \e g must hold nx * ny finite values, at least one.
*/
vpImage<vpRGBa> drawHeatMap(const Grid2D &g, const std::string &title, const std::vector<Marker> &markers);

} // namespace pm::report
