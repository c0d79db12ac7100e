#pragma once
/*!
  \file TimePlot.h
  Time-series panels in a grid, like the paper's Figs. 13 and 14: each panel has axes, ticks, a
  title, its curves with a legend, and optionally a shaded band (a tolerance) around zero.
*/
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::app {

struct Series
{
  std::string name;
  vpRGBa color;
  std::vector<double> t, y;
  bool dashed = false;
};

struct Panel
{
  std::string title, yLabel;
  std::vector<Series> series;
  double band = 0;               //!< > 0: shade [-band, +band]
  std::vector<double> marks;     //!< vertical dotted lines at these times (e.g. convergence)
};

//! The panels in \e cols columns, each \e panelWidth x 300 px, under a title.
vpImage<vpRGBa> drawTimePlots(const std::vector<Panel> &panels, int cols, const std::string &title,
                              const std::string &xLabel = "time [s]", int panelWidth = 520);

} // namespace pm::app
