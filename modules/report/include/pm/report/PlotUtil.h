#pragma once
/*!
  \file PlotUtil.h
  Small drawing helpers shared by the heat maps and the time-series plots (OpenCV drawing).
  The figures are drawn into a BGR cv::Mat (8 bits a channel) and handed over as ViSP images.
*/
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::report {

//! A number for an axis: no decimals for large or whole values (|v| >= 100 or whole: "250", "3"), else two ("0.25"), two significant digits under 0.1 ("0.005").
std::string tickLabel(double v);
/*!
  About \e n round tick values over [a, b].
  The ticks are the multiples of a step of 1, 2, 2.5 or 5 times a power of ten (the smallest such
  step not under (b - a) / n) that lie in [a, b], in increasing order, a value within rounding of
  zero given as exactly 0. When b <= a (or either is NaN): just {a}. \e n must be positive.
*/
std::vector<double> niceTicks(double a, double b, int n = 6);
/*!
  Text at p (baseline), aligned left (0), centred (1) or right (2).
  Draws \e s into \e m in OpenCV's Hershey simplex font, 1 px thick, anti-aliased: \e p is in pixels
  (x column, y row of the baseline) and is where the text starts (0), its middle (1) or its end (2).
  \e scale is OpenCV's font scale; \e color is BGR (default: near black).
*/
void putLabel(cv::Mat &m, const std::string &s, cv::Point p, double scale = 0.45, int align = 0,
              cv::Scalar color = cv::Scalar(20, 20, 20));
/*!
  A BGR cv::Mat as a ViSP image.
  \e bgr must be of type CV_8UC3; its pixels are copied (alpha: vpRGBa's default), so the result
  shares no memory with it.
*/
vpImage<vpRGBa> toVisp(const cv::Mat &bgr);

} // namespace pm::report
