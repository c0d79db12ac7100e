#include "pm/app/Overlay.h"

#include <algorithm>
#include <cmath>

#include <visp3/core/vpColor.h>
#include <visp3/core/vpFont.h>
#include <visp3/core/vpImageDraw.h>

namespace pm::app {

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

vpImage<vpRGBa> drawModelOnPhoto(const vpImage<vpRGBa> &photo, const vpImage<unsigned char> &region, const PhotoModel &m)
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

vpImage<vpRGBa> drawModel(const PhotoModel &m)
{
  vpImage<vpRGBa> I(m.photoHeight, m.photoWidth, vpRGBa(40, 40, 40));
  for (const auto &p : m.inner)
    vpImageDraw::drawPoint(I, vpImagePoint(p.v, p.u), hueColor(p.hue), 4);
  for (const auto &p : m.outer)
    vpImageDraw::drawPoint(I, vpImagePoint(p.v, p.u), vpColor::white, 3);
  drawLabel(I, "model: S_in in its hues, S_out white", 8, 8, vpRGBa(255, 255, 255));
  return I;
}

vpImage<vpRGBa> drawPointScores(const vpImage<vpRGBa> &image, const std::vector<PointScore> &scores,
                                const std::string &label)
{
  vpImage<vpRGBa> I = image;
  for (const auto &s : scores) {
    if (s.cls == PointScore::Off)
      continue;
    vpColor c = vpColor::gray;
    switch (s.cls) {
    case PointScore::InMatch: c = vpColor::green; break;
    case PointScore::InBackground: c = vpColor::yellow; break;
    case PointScore::InOther: c = vpColor::lightGray; break;
    case PointScore::OutBackground: c = vpColor(60, 160, 255); break;
    case PointScore::OutOther: c = vpColor::red; break;
    case PointScore::Off: break;
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

vpImage<vpRGBa> sideBySide(const vpImage<vpRGBa> &a, const vpImage<vpRGBa> &b)
{
  vpImage<vpRGBa> I(std::max(a.getHeight(), b.getHeight()), a.getWidth() + b.getWidth(), vpRGBa(0, 0, 0));
  I.insert(a, vpImagePoint(0, 0));
  I.insert(b, vpImagePoint(0, a.getWidth()));
  return I;
}

} // namespace pm::app
