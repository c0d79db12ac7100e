#pragma once
/*!
  \file TimePlot.h
  Time-series panels in a grid, like the paper's Figs. 13 and 14: each panel has axes, ticks, a
  title, its curves with a legend, and optionally a shaded band (a tolerance) around zero.
  The horizontal axis need not be time: it is whatever the series' \e t hold, named by
  drawTimePlots()'s \e xLabel (pm-confidence draws a ROC curve with it).
*/
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::report {

/*!
  One curve of a Panel: the points (t[k], y[k]) joined by straight lines, in one colour, named in
  the panel's legend. A sample whose \e y is not finite (NaN, infinity) is left out, with the two
  segments that touch it: a gap in the curve.
*/
struct Series
{
  std::string name;              //!< the curve's name in the panel's legend
  vpRGBa color;                  //!< the curve's colour (its alpha is ignored)
  /*! \var pm::report::Series::t
      \brief horizontal coordinates of the samples, in the unit of the plot's \e xLabel (s for "time [s]") */
  std::vector<double> t, y;      //!< vertical coordinates of the samples, one per entry of \e t (unit: the panel's yLabel)
  bool dashed = false;           //!< a thin (1 px) dashed line (about 4 segments on, 4 off), else a solid 2 px line
};

/*!
  One panel of a figure made by drawTimePlots(): a plot with its title, its y label, its curves and
  their legend. Both axes span the finite samples of all the series (and [-band, +band] when a band
  is shaded), the vertical one with 6 % of margin above and below; a grey line marks y = 0 when the
  range crosses it. The legend goes beside the title when it fits there, else in a box in the plot's
  top-right corner.
*/
struct Panel
{
  /*! \var pm::report::Panel::title
      \brief the panel's title, written above the plot on the left */
  std::string title, yLabel;     //!< the vertical axis's label (e.g. its unit, "mm"), in the top-left corner, left of the title
  std::vector<Series> series;    //!< the curves, drawn in this order (the last on top)
  double band = 0;               //!< when positive, shade [-band, +band] (light green), in the y values' unit; 0: no band
  std::vector<double> marks;     //!< vertical dotted grey lines at these times, in the unit of \e t (e.g. convergence)
};

/*!
  The panels in \e cols columns, each \e panelWidth x 300 px, under a title.
  The panels fill the grid row by row; the image is cols * panelWidth px wide and
  36 + 300 * rows px high (rows = panels.size() / cols rounded up), on white, with \e title centred
  in the top 36 px and \e xLabel under each panel's horizontal axis. \e cols must be at least 1.
  \code
  pm::report::Series error;
  error.name = "x error";
  error.color = vpRGBa(220, 40, 40);
  for (int k = 0; k <= 100; ++k) {
    error.t.push_back(0.1 * k);                    // s
    error.y.push_back(5.0 * std::exp(-0.05 * k));  // mm
  }
  pm::report::Panel panel;
  panel.title = "position error";
  panel.yLabel = "mm";
  panel.series.push_back(error);
  panel.band = 1.0;                                // the +-1 mm tolerance, shaded
  panel.marks.push_back(3.2);                      // converged at 3.2 s: a dotted line
  const vpImage<vpRGBa> figure = pm::report::drawTimePlots({panel}, 1, "pm-servo run"); // 520 x 336 px
  pm::io::writeImage(figure, "errors.png");        // pm/io/ImageFile.h
  \endcode
*/
vpImage<vpRGBa> drawTimePlots(const std::vector<Panel> &panels, int cols, const std::string &title,
                              const std::string &xLabel = "time [s]", int panelWidth = 520);

} // namespace pm::report
