#include "pm/report/TimePlot.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "pm/report/PlotUtil.h"

namespace pm::report {

namespace {

void drawPanel(cv::Mat &img, cv::Rect area, const Panel &p, const std::string &xLabel)
{
  const int left = 62, right = 12, top = 28, bottom = 42;
  const cv::Rect plot(area.x + left, area.y + top, area.width - left - right, area.height - top - bottom);
  double t0 = 1e300, t1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto &s : p.series)
    for (std::size_t i = 0; i < s.t.size(); ++i)
      if (std::isfinite(s.y[i])) {
        t0 = std::min(t0, s.t[i]);
        t1 = std::max(t1, s.t[i]);
        y0 = std::min(y0, s.y[i]);
        y1 = std::max(y1, s.y[i]);
      }
  if (p.band > 0) {
    y0 = std::min(y0, -p.band);
    y1 = std::max(y1, p.band);
  }
  if (!(t1 > t0))
    t1 = t0 + 1;
  if (!(y1 > y0)) {
    y0 -= 1;
    y1 += 1;
  }
  const double pad = 0.06 * (y1 - y0);
  y0 -= pad;
  y1 += pad;
  auto X = [&](double t) { return plot.x + static_cast<int>(std::lround((t - t0) / (t1 - t0) * plot.width)); };
  auto Y = [&](double y) { return plot.y + plot.height - static_cast<int>(std::lround((y - y0) / (y1 - y0) * plot.height)); };
  if (p.band > 0)
    cv::rectangle(img, cv::Point(plot.x, Y(p.band)), cv::Point(plot.x + plot.width, Y(-p.band)), cv::Scalar(225, 240, 225),
                  cv::FILLED);
  for (double v : niceTicks(y0, y1, 5)) {
    cv::line(img, {plot.x, Y(v)}, {plot.x + plot.width, Y(v)}, cv::Scalar(230, 230, 230));
    putLabel(img, tickLabel(v), {plot.x - 6, Y(v) + 5}, 0.4, 2);
  }
  for (double v : niceTicks(t0, t1, 6)) {
    cv::line(img, {X(v), plot.y + plot.height}, {X(v), plot.y + plot.height + 4}, cv::Scalar(0, 0, 0));
    putLabel(img, tickLabel(v), {X(v), plot.y + plot.height + 18}, 0.4, 1);
  }
  if (y0 < 0 && y1 > 0)
    cv::line(img, {plot.x, Y(0)}, {plot.x + plot.width, Y(0)}, cv::Scalar(160, 160, 160));
  for (double m : p.marks)
    for (int y = plot.y; y < plot.y + plot.height; y += 6)
      cv::line(img, {X(m), y}, {X(m), y + 3}, cv::Scalar(120, 120, 120));
  cv::rectangle(img, plot, cv::Scalar(0, 0, 0));
  cv::Mat roi = img(plot);
  for (const auto &s : p.series) {
    const cv::Scalar c(s.color.B, s.color.G, s.color.R);
    for (std::size_t i = 1; i < s.t.size(); ++i) {
      if (!std::isfinite(s.y[i - 1]) || !std::isfinite(s.y[i]) || (s.dashed && (i / 4) % 2))
        continue;
      cv::line(roi, {X(s.t[i - 1]) - plot.x, Y(s.y[i - 1]) - plot.y}, {X(s.t[i]) - plot.x, Y(s.y[i]) - plot.y}, c,
               s.dashed ? 1 : 2, cv::LINE_AA);
    }
  }
  putLabel(img, p.title, {area.x + left, area.y + 19}, 0.5);
  putLabel(img, xLabel, {plot.x + plot.width / 2, area.y + area.height - 6}, 0.42, 1);
  putLabel(img, p.yLabel, {area.x + 4, plot.y - 6}, 0.4);
  // The legend: on the title line when it fits beside the title, else a boxed list in the plot's top right.
  int base = 0, total = 0, widest = 0;
  for (const auto &s : p.series) {
    const int w = cv::getTextSize(s.name, cv::FONT_HERSHEY_SIMPLEX, 0.4, 1, &base).width;
    total += w + 34;
    widest = std::max(widest, w);
  }
  const int titleW = cv::getTextSize(p.title, cv::FONT_HERSHEY_SIMPLEX, 0.5, 1, &base).width;
  if (left + titleW + 16 + total <= area.width - right) {
    int lx = plot.x + plot.width - 4;
    for (auto it = p.series.rbegin(); it != p.series.rend(); ++it) {
      const int w = cv::getTextSize(it->name, cv::FONT_HERSHEY_SIMPLEX, 0.4, 1, &base).width;
      putLabel(img, it->name, {lx, area.y + 19}, 0.4, 2);
      cv::line(img, {lx - w - 26, area.y + 15}, {lx - w - 6, area.y + 15}, cv::Scalar(it->color.B, it->color.G, it->color.R), 2);
      lx -= w + 34;
    }
  } else {
    const int bw = widest + 40, bh = 16 * static_cast<int>(p.series.size()) + 8;
    const cv::Rect box(plot.x + plot.width - bw - 6, plot.y + 6, bw, bh);
    cv::rectangle(img, box, cv::Scalar(255, 255, 255), cv::FILLED);
    cv::rectangle(img, box, cv::Scalar(180, 180, 180));
    int y = box.y + 16;
    for (const auto &s : p.series) {
      cv::line(img, {box.x + 6, y - 4}, {box.x + 26, y - 4}, cv::Scalar(s.color.B, s.color.G, s.color.R), 2);
      putLabel(img, s.name, {box.x + 32, y}, 0.4);
      y += 16;
    }
  }
}

} // namespace

vpImage<vpRGBa> drawTimePlots(const std::vector<Panel> &panels, int cols, const std::string &title, const std::string &xLabel,
                              int panelWidth)
{
  const int pw = panelWidth, ph = 300, head = 36;
  const int rows = static_cast<int>((panels.size() + static_cast<std::size_t>(cols) - 1) / static_cast<std::size_t>(cols));
  cv::Mat img(head + rows * ph, cols * pw, CV_8UC3, cv::Scalar(255, 255, 255));
  putLabel(img, title, {cols * pw / 2, 25}, 0.6, 1);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const int r = static_cast<int>(i) / cols, c = static_cast<int>(i) % cols;
    drawPanel(img, cv::Rect(c * pw, head + r * ph, pw, ph), panels[i], xLabel);
  }
  return toVisp(img);
}

} // namespace pm::report
