#include "pm/report/Overlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <visp3/core/vpColor.h>
#include <visp3/core/vpFont.h>
#include <visp3/core/vpImageDraw.h>

namespace pm::report {

namespace {
vpColor hueColor(float hueDeg)
{
  const double h = hueDeg / 60.0;
  const int i = static_cast<int>(std::floor(h)) % 6;
  const double f = h - std::floor(h);
  const double tab[6][3] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f}, {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
  return vpColor(static_cast<unsigned char>(255 * tab[i][0]), static_cast<unsigned char>(255 * tab[i][1]),
                 static_cast<unsigned char>(255 * tab[i][2]));
}
} // namespace

namespace {
//! A colour from red (t = 0) through yellow, green, cyan to blue (t = 1).
vpRGBa depthColor(double t)
{
  t = std::min(1.0, std::max(0.0, t));
  const vpColor c = hueColor(static_cast<float>(240.0 * t));
  return vpRGBa(c.R, c.G, c.B);
}
} // namespace

vpImage<vpRGBa> drawDepth(const vpImage<vpRGBa> &photo, const vpImage<float> &depthMm, const core::PhotoModel &m,
                          const std::vector<core::ModelPoint> &dropped, double nearMm, double farMm)
{
  const unsigned h = photo.getHeight(), w = photo.getWidth(), bar = 40;
  vpImage<vpRGBa> I(h + bar, w, vpRGBa(255, 255, 255));
  const double span = farMm > nearMm ? farMm - nearMm : 1.0;
  for (unsigned v = 0; v < h; ++v)
    for (unsigned u = 0; u < w; ++u) {
      const vpRGBa &p = photo[v][u];
      const auto g = static_cast<unsigned char>(0.5 * (0.3 * p.R + 0.59 * p.G + 0.11 * p.B) + 40);
      const bool has = depthMm.getHeight() == h && depthMm.getWidth() == w && std::isfinite(depthMm[v][u]);
      I[v][u] = has ? depthColor((depthMm[v][u] - nearMm) / span) : vpRGBa(g, g, g);
    }
  for (const auto &p : m.inner)
    vpImageDraw::drawPoint(I, vpImagePoint(p.v, p.u), vpColor::white, 2);
  for (const auto &p : dropped)
    vpImageDraw::drawPoint(I, vpImagePoint(p.v, p.u), vpColor::black, 2);
  const unsigned x0 = 100, x1 = w > 200 ? w - 100 : w;
  for (unsigned u = x0; u < x1; ++u)
    for (unsigned v = h + 6; v < h + 18; ++v)
      I[v][u] = depthColor(static_cast<double>(u - x0) / std::max(1u, x1 - x0 - 1));
  char text[96];
  std::snprintf(text, sizeof text, "%.0f mm", nearMm);
  drawLabel(I, text, static_cast<int>(h + 22), static_cast<int>(x0), vpRGBa(0, 0, 0));
  std::snprintf(text, sizeof text, "%.0f mm", farMm);
  drawLabel(I, text, static_cast<int>(h + 22), static_cast<int>(x1) - 50, vpRGBa(0, 0, 0));
  drawLabel(I, "depth in the hand frame: near", static_cast<int>(h + 6), 4, vpRGBa(0, 0, 0));
  drawLabel(I, "far", static_cast<int>(h + 6), static_cast<int>(x1) + 8, vpRGBa(0, 0, 0));
  drawLabel(I, "S_in kept (white) " + std::to_string(m.inner.size()) + ", dropped (black) " + std::to_string(dropped.size()),
            8, 8, vpRGBa(255, 255, 255));
  return I;
}

vpImage<vpRGBa> drawModelOnPhoto(const vpImage<vpRGBa> &photo, const vpImage<unsigned char> &region, const core::PhotoModel &m)
{
  vpImage<vpRGBa> I = photo;
  const unsigned h = I.getHeight(), w = I.getWidth();
  if (region.getHeight() == h && region.getWidth() == w)
    for (unsigned v = 1; v + 1 < h; ++v)
      for (unsigned u = 1; u + 1 < w; ++u)
        if (region[v][u] && (!region[v - 1][u] || !region[v + 1][u] || !region[v][u - 1] || !region[v][u + 1]))
          I[v][u] = vpRGBa(255, 230, 0);
  for (const auto &p : m.inner)
    vpImageDraw::drawPoint(I, vpImagePoint(p.v, p.u), vpColor::green, 3);
  for (const auto &p : m.outer)
    vpImageDraw::drawPoint(I, vpImagePoint(p.v, p.u), vpColor::red, 3);
  vpImageDraw::drawCross(I, vpImagePoint(m.centroidV, m.centroidU), 15, vpColor::white, 2);
  drawLabel(I, "S_in (green) " + std::to_string(m.inner.size()) + " pts, S_out (red) " + std::to_string(m.outer.size()) + " pts",
            8, 8, vpRGBa(255, 255, 255));
  return I;
}

vpImage<vpRGBa> drawModel(const core::PhotoModel &m)
{
  vpImage<vpRGBa> I(m.photoHeight, m.photoWidth, vpRGBa(40, 40, 40));
  for (const auto &p : m.inner)
    vpImageDraw::drawPoint(I, vpImagePoint(p.v, p.u), hueColor(p.hue), 4);
  for (const auto &p : m.outer)
    vpImageDraw::drawPoint(I, vpImagePoint(p.v, p.u), vpColor::white, 3);
  drawLabel(I, "model: S_in in its hues, S_out white", 8, 8, vpRGBa(255, 255, 255));
  return I;
}

vpImage<vpRGBa> drawPointScores(const vpImage<vpRGBa> &image, const std::vector<core::PointScore> &scores,
                                const std::string &label)
{
  vpImage<vpRGBa> I = image;
  for (const auto &s : scores) {
    if (s.cls == core::PointScore::Off)
      continue;
    vpColor c = vpColor::gray;
    switch (s.cls) {
    case core::PointScore::InMatch: c = vpColor::green; break;
    case core::PointScore::InBackground: c = vpColor::yellow; break;
    case core::PointScore::InOther: c = vpColor::lightGray; break;
    case core::PointScore::OutBackground: c = vpColor(60, 160, 255); break;
    case core::PointScore::OutOther: c = vpColor::red; break;
    case core::PointScore::Hidden: c = vpColor(255, 0, 255); break; // left out: the other camera sees the model there
    case core::PointScore::Off: break;
    }
    vpImageDraw::drawPoint(I, vpImagePoint(s.v, s.u), c, 3);
  }
  drawLabel(I, label, 8, 8, vpRGBa(255, 255, 255));
  return I;
}

void drawLabel(vpImage<vpRGBa> &I, const std::string &text, int row, int col, const vpRGBa &color)
{
  static vpFont font(16, vpFont::GENERIC_MONOSPACE);
  font.drawText(I, text, vpImagePoint(row + 1, col + 1), vpColor::black);
  font.drawText(I, text, vpImagePoint(row, col), vpColor(color.R, color.G, color.B));
}

void drawCorrespondenceLines(vpImage<vpRGBa> &I, const precise::CorrespondenceLines &lines)
{
  auto stroke = [&I](const precise::LineMeasure &m, double along, double half, const vpColor &c) {
    const double u = m.cu + along * m.nu, v = m.cv + along * m.nv;
    const double w = I.getWidth() - 2.0, h = I.getHeight() - 2.0;
    for (const double k : {-half, half})
      if (!(u + k * m.nu >= 1 && u + k * m.nu <= w && v + k * m.nv >= 1 && v + k * m.nv <= h))
        return; // a stroke off the image's edge is not drawn
    vpImageDraw::drawLine(I, vpImagePoint(v - half * m.nv, u - half * m.nu), vpImagePoint(v + half * m.nv, u + half * m.nu), c, 2);
  };
  for (std::size_t i = 0; i < lines.size(); ++i)
    stroke(lines.line(i), lines.line(i).mean, 4, vpColor::cyan);
  for (std::size_t i = 0; i < lines.hiddenCount(); ++i)
    stroke(lines.hiddenLine(i), 0, 10, vpColor(255, 0, 255));
}

vpImage<vpRGBa> sideBySide(const vpImage<vpRGBa> &a, const vpImage<vpRGBa> &b)
{
  vpImage<vpRGBa> I(std::max(a.getHeight(), b.getHeight()), a.getWidth() + b.getWidth(), vpRGBa(0, 0, 0));
  I.insert(a, vpImagePoint(0, 0));
  I.insert(b, vpImagePoint(0, a.getWidth()));
  return I;
}

vpImage<vpRGBa> drawCameras(const core::CameraImages &images, const std::vector<std::vector<core::PointScore>> &scores,
                            const std::vector<std::string> &labels)
{
  static const std::vector<core::PointScore> none;
  vpImage<vpRGBa> all;
  for (std::size_t k = 0; k < images.size(); ++k) {
    const vpImage<vpRGBa> one = drawPointScores(images[k], k < scores.size() ? scores[k] : none, k < labels.size() ? labels[k] : "");
    all = k ? sideBySide(all, one) : one;
  }
  return all;
}

std::vector<std::string> cameraLabels(std::size_t n, const std::string &prefix)
{
  if (n == 2)
    return {prefix + "left", "right"};
  std::vector<std::string> out;
  for (std::size_t k = 0; k < n; ++k)
    out.push_back((k ? "" : prefix) + "camera " + std::to_string(k));
  return out;
}

} // namespace pm::report
