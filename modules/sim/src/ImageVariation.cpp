#include "pm/sim/ImageVariation.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "pm/core/Error.h"
#include "pm/sim/Noise.h"

namespace pm::sim {

bool ImageVariation::any() const
{
  return optics() || shotNoise > 0 || whiteBalance[0] != 1 || whiteBalance[1] != 1 || whiteBalance[2] != 1 || gamma != 1 ||
         jpegQuality > 0;
}

void ImageVariation::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("image variation: ") + what);
  };
  check(defocusSigmaPx >= 0 && defocusSigmaPx <= 20, "the defocus sigma must lie in [0, 20] px");
  check(motionBlurPx >= 0 && motionBlurPx <= 100 && std::isfinite(motionBlurAngleDeg), "the motion blur must lie in [0, 100] px");
  check(vignetting >= 0 && vignetting < 1, "the vignetting must lie in [0, 1)");
  check(shotNoise >= 0 && shotNoise <= 10, "the shot noise must lie in [0, 10]");
  for (double g : whiteBalance)
    check(g > 0.1 && g <= 10, "the white balance gains must lie in (0.1, 10]");
  check(gamma >= 0.2 && gamma <= 5, "the gamma must lie in [0.2, 5]");
  check(jpegQuality >= 0 && jpegQuality <= 100, "the JPEG quality must lie in [0, 100] (0: none)");
}

namespace {
cv::Mat wrap(vpImage<vpRGBa> &image)
{
  return cv::Mat(static_cast<int>(image.getHeight()), static_cast<int>(image.getWidth()), CV_8UC4, image.bitmap);
}

unsigned char toByte(double v) { return static_cast<unsigned char>(std::clamp(std::lround(v), 0L, 255L)); }
} // namespace

void ImageVariation::applyOptics(vpImage<vpRGBa> &image) const
{
  if (image.getSize() == 0)
    return;
  cv::Mat m = wrap(image);
  if (defocusSigmaPx > 0)
    cv::GaussianBlur(m, m, cv::Size(0, 0), defocusSigmaPx, defocusSigmaPx, cv::BORDER_REPLICATE);
  if (motionBlurPx > 0) { // a normalised line through the kernel's centre
    const int half = static_cast<int>(std::ceil(motionBlurPx / 2));
    cv::Mat k = cv::Mat::zeros(2 * half + 1, 2 * half + 1, CV_32F);
    const double a = motionBlurAngleDeg * M_PI / 180;
    cv::line(k, cv::Point2d(half - std::cos(a) * motionBlurPx / 2, half - std::sin(a) * motionBlurPx / 2),
             cv::Point2d(half + std::cos(a) * motionBlurPx / 2, half + std::sin(a) * motionBlurPx / 2), cv::Scalar(1), 1, cv::LINE_AA);
    k /= cv::sum(k)[0];
    cv::filter2D(m, m, -1, k, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
  }
  if (vignetting > 0) { // (cos theta)^4 of a lens whose corners are this much darker
    const double cx = 0.5 * (image.getWidth() - 1), cy = 0.5 * (image.getHeight() - 1), r2max = cx * cx + cy * cy;
    const double k = std::pow(1 - vignetting, -0.5) - 1; // 1 / (1 + k)^2 = 1 - vignetting at the corners
    for (unsigned v = 0; v < image.getHeight(); ++v)
      for (unsigned u = 0; u < image.getWidth(); ++u) {
        const double r2 = ((u - cx) * (u - cx) + (v - cy) * (v - cy)) / r2max, f = 1 / ((1 + k * r2) * (1 + k * r2));
        vpRGBa &p = image[v][u];
        p.R = toByte(p.R * f);
        p.G = toByte(p.G * f);
        p.B = toByte(p.B * f);
      }
  }
}

void ImageVariation::applyAfterSensor(vpImage<vpRGBa> &image, std::uint64_t seed) const
{
  const bool tone = whiteBalance[0] != 1 || whiteBalance[1] != 1 || whiteBalance[2] != 1 || gamma != 1;
  if (shotNoise > 0 || tone) {
    unsigned char lut[3][256];
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 256; ++i)
        lut[c][i] = toByte(255 * std::pow(std::min(1.0, i * whiteBalance[c] / 255), 1 / gamma));
    const unsigned w = image.getWidth();
    for (unsigned v = 0; v < image.getHeight(); ++v)
      for (unsigned u = 0; u < w; ++u) {
        vpRGBa &p = image[v][u];
        unsigned char *ch[3] = {&p.R, &p.G, &p.B};
        float g[3] = {0, 0, 0};
        if (shotNoise > 0)
          fastGaussian3(seed, static_cast<std::uint64_t>(v) * w + u, g);
        for (int c = 0; c < 3; ++c) {
          const unsigned char s = shotNoise > 0 ? toByte(*ch[c] + shotNoise * std::sqrt(static_cast<double>(*ch[c])) * g[c]) : *ch[c];
          *ch[c] = lut[c][s];
        }
      }
  }
  if (jpegQuality > 0 && image.getSize() > 0) {
    cv::Mat bgr;
    cv::cvtColor(wrap(image), bgr, cv::COLOR_RGBA2BGR);
    std::vector<unsigned char> buf;
    cv::imencode(".jpg", bgr, buf, {cv::IMWRITE_JPEG_QUALITY, jpegQuality});
    const cv::Mat back = cv::imdecode(buf, cv::IMREAD_COLOR);
    cv::Mat m = wrap(image);
    cv::cvtColor(back, m, cv::COLOR_BGR2RGBA);
  }
}

const std::vector<std::string> &imageVariationNames()
{
  static const std::vector<std::string> names{"defocus", "motion-blur", "vignetting", "shot-noise", "white-balance", "gamma", "jpeg", "camera"};
  return names;
}

namespace {
void setPreset(const std::string &name, ImageVariation &v)
{
  if (name == "defocus") {
    v.defocusSigmaPx = 1.2;
  } else if (name == "motion-blur") {
    v.motionBlurPx = 6;
    v.motionBlurAngleDeg = 20;
  } else if (name == "vignetting") {
    v.vignetting = 0.35;
  } else if (name == "shot-noise") {
    v.shotNoise = 0.6;
  } else if (name == "white-balance") { // a white balance set for daylight under a warm lamp
    v.whiteBalance[0] = 1.15;
    v.whiteBalance[2] = 0.85;
  } else if (name == "gamma") {
    v.gamma = 0.75;
  } else if (name == "jpeg") {
    v.jpegQuality = 60;
  } else if (name == "camera") {
    v.defocusSigmaPx = 0.8;
    v.vignetting = 0.25;
    v.shotNoise = 0.4;
    v.whiteBalance[0] = 1.08;
    v.whiteBalance[2] = 0.92;
    v.gamma = 0.9;
    v.jpegQuality = 75;
  } else {
    throw core::Error("unknown image variation '" + name + "' (defocus, motion-blur, vignetting, shot-noise, white-balance, gamma, jpeg, camera)");
  }
}
} // namespace

ImageVariation imageVariation(const std::string &names)
{
  ImageVariation v;
  std::stringstream in(names);
  std::string name;
  while (std::getline(in, name, ','))
    if (!name.empty())
      setPreset(name, v);
  return v;
}

} // namespace pm::sim
