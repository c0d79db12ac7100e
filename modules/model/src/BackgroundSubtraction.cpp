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
  check(chromaTol > 0 && chromaTol < 1, "chroma tolerance must lie in (0, 1)");
  check(darkRatio > 0 && darkRatio < 1, "dark ratio must lie in (0, 1)");
  check(brightRatio > 1 && brightRatio < 10, "bright ratio must lie in (1, 10)");
  check(minBrightness >= 0 && minBrightness < 255, "minimum brightness must lie in [0, 255)");
}

cv::Mat subtractBackground(const vpImage<vpRGBa> &photo, const vpImage<vpRGBa> &background, const BackgroundParams &p, int *shadowPx)
{
  const int h = static_cast<int>(photo.getHeight()), w = static_cast<int>(photo.getWidth());
  // Both images as float RGBA, not smoothed: a blur widens the silhouette by a pixel all around (on R2 a
  // 393 px halo for 4 px without it); the cleaning after it removes the specks of sensor noise.
  cv::Mat a(h, w, CV_8UC4, const_cast<vpRGBa *>(photo.bitmap)), b(h, w, CV_8UC4, const_cast<vpRGBa *>(background.bitmap));
  cv::Mat af, bf;
  a.convertTo(af, CV_32FC4);
  b.convertTo(bf, CV_32FC4);
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  int shadow = 0;
  for (int v = 0; v < h; ++v) {
    const cv::Vec4f *pa = af.ptr<cv::Vec4f>(v), *pb = bf.ptr<cv::Vec4f>(v);
    unsigned char *m = mask.ptr<unsigned char>(v);
    for (int u = 0; u < w; ++u) {
      // vpRGBa is R, G, B, A in memory.
      const float sa = pa[u][0] + pa[u][1] + pa[u][2], sb = pb[u][0] + pb[u][1] + pb[u][2];
      const double ratio = (sa + 3.0) / (sb + 3.0);
      bool target = ratio < p.darkRatio || ratio > p.brightRatio;
      bool changed = target;
      // Chromaticity where the background has some light: a dark photo pixel's is noisier (its
      // tolerance grows as its brightness falls), but a dark target on a lit backdrop (dark hair on
      // blue) differs in it where a shadow does not (R2: 33 missed pixels of hair to 0).
      if (!target && sb > 3 * p.minBrightness && sa > 24) {
        const double dr = pa[u][0] / sa - pb[u][0] / sb, dg = pa[u][1] / sa - pb[u][1] / sb;
        const double tol = p.chromaTol * std::max(1.0, 3 * p.minBrightness / sa);
        target = std::max(std::fabs(dr), std::fabs(dg)) > tol;
      }
      if (!target && ratio < 1.0 / p.brightRatio)
        changed = true; // darker with the same chromaticity: a shadow
      if (target)
        m[u] = 255;
      else if (changed)
        ++shadow;
    }
  }
  if (shadowPx)
    *shadowPx = shadow;
  return mask;
}

} // namespace pm::model
