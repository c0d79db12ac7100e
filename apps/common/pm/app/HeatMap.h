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

namespace pm::app {

struct Grid2D
{
  std::string xName, yName;        //!< axis labels, e.g. "x [mm]"
  double x0 = 0, dx = 1, y0 = 0, dy = 1;
  int nx = 0, ny = 0;
  std::vector<double> values;      //!< ny rows of nx values, row j at y = y0 + j dy

  double at(int i, int j) const { return values[static_cast<std::size_t>(j) * nx + i]; }
};

struct Marker
{
  double x, y;
  std::string label;
  vpRGBa color;
  bool cross; //!< a cross, else a circle
};

vpImage<vpRGBa> drawHeatMap(const Grid2D &g, const std::string &title, const std::vector<Marker> &markers);

} // namespace pm::app
