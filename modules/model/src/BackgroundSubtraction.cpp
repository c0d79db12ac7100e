#include "pm/model/BackgroundSubtraction.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "pm/core/Error.h"

namespace pm::model {

void BackgroundParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("background subtraction parameter ") + what);
  };
  check(colourTolGrey > 0 && colourTolGrey < 255, "colour tolerance must lie in (0, 255) grey levels");
  check(colourTolShare >= 0 && colourTolShare < 1, "colour tolerance's share must lie in [0, 1)");
  check(darkRatio >= 0 && darkRatio < 1, "dark ratio must lie in [0, 1)");
  check(brightRatio > 1 && brightRatio < 10, "bright ratio must lie in (1, 10)");
}

cv::Mat subtractBackground(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background, const BackgroundParams &p, int *shadowPx,
                           cv::Mat *changed)
{
  const int h = static_cast<int>(photo.getHeight()), w = static_cast<int>(photo.getWidth());
  // The photo against the background pixel by pixel, in float, not smoothed: a blur widens the silhouette
  // by a pixel all around (on R2 a 393 px halo for 4 px without it); the cleaning after it removes the
  // specks of sensor noise. Each pixel's bytes are read as floats where they are used (no float copy of
  // the images: 2 x 4.9 MB a view, fresh pages each time).
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  if (changed)
    *changed = cv::Mat(h, w, CV_8U, cv::Scalar(0));
  int shadow = 0;
  for (int v = 0; v < h; ++v) {
    const vpRGBa *ra = photo[static_cast<unsigned>(v)], *rb = background[static_cast<unsigned>(v)];
    unsigned char *m = mask.ptr<unsigned char>(v);
    unsigned char *c = changed ? changed->ptr<unsigned char>(v) : nullptr;
    for (int u = 0; u < w; ++u) {
      const float pa[3] = {static_cast<float>(ra[u].R), static_cast<float>(ra[u].G), static_cast<float>(ra[u].B)};
      const float pb[3] = {static_cast<float>(rb[u].R), static_cast<float>(rb[u].G), static_cast<float>(rb[u].B)};
      const float sa = pa[0] + pa[1] + pa[2], sb = pb[0] + pb[1] + pb[2];
      const double ratio = (sa + 3.0) / (sb + 3.0);
      bool target = ratio < p.darkRatio || ratio > p.brightRatio;
      if (!target) {
        // The background's colour dimmed by a shadow lies on the line a * B (0 <= a <= 1): the photo's
        // distance from that line, in grey levels, against the sensor's noise and a share of the light.
        const double bb = pb[0] * pb[0] + pb[1] * pb[1] + pb[2] * pb[2];
        const double pb_ = pa[0] * pb[0] + pa[1] * pb[1] + pa[2] * pb[2];
        const double dim = bb > 0 ? std::clamp(pb_ / bb, 0.0, 1.0) : 0.0;
        const double dr = pa[0] - dim * pb[0], dg = pa[1] - dim * pb[1], db = pa[2] - dim * pb[2];
        const double tol = p.colourTolGrey + p.colourTolShare * dim * std::sqrt(bb);
        target = dr * dr + dg * dg + db * db > tol * tol;
      }
      const bool dimmed = !target && ratio < 1.0 / p.brightRatio; // darker along the background's own colour: a shadow
      if (target)
        m[u] = 255;
      shadow += dimmed;
      if (c && (target || dimmed))
        c[u] = 255;
    }
  }
  if (shadowPx)
    *shadowPx = shadow;
  return mask;
}

} // namespace pm::model
