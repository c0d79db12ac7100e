#pragma once
/*!
  \file PlotUtil.h
  Small drawing helpers shared by the heat maps and the time-series plots (OpenCV drawing).
*/
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::app {

//! A number for an axis: no decimals for large or whole values, else two.
std::string tickLabel(double v);
//! About \e n round tick values over [a, b].
std::vector<double> niceTicks(double a, double b, int n = 6);
//! Text at p (baseline), aligned left (0), centred (1) or right (2).
void putLabel(cv::Mat &m, const std::string &s, cv::Point p, double scale = 0.45, int align = 0,
              cv::Scalar color = cv::Scalar(20, 20, 20));
//! A BGR cv::Mat as a ViSP image.
vpImage<vpRGBa> toVisp(const cv::Mat &bgr);

} // namespace pm::app
