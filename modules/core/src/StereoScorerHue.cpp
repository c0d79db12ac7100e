#include "pm/core/StereoScorer.h"

#include <exception>
#include <string>

#include "FitnessKernels.h"
#include "pm/core/BatchPool.h"
#include "pm/core/Error.h"

namespace pm::core {

void StereoScorer::checkSizes(const vpImage<vpRGBa> *const *im) const
{
  for (int k = 0; k < m_nCams; ++k) {
    const PinholeCamera::Projection &c = m_cams[static_cast<std::size_t>(k)];
    if (static_cast<int>(im[k]->getWidth()) != c.w || static_cast<int>(im[k]->getHeight()) != c.h) {
      const std::string name = m_nCams == 2 ? std::string(k == 0 ? "left" : "right") : "camera " + std::to_string(k) + "'s";
      throw Error(name + " image is " + std::to_string(im[k]->getWidth()) + "x" + std::to_string(im[k]->getHeight()) +
                  " but the rig's camera is " + std::to_string(c.w) + "x" + std::to_string(c.h));
    }
  }
}

namespace {

//! Throws pm::core::Error unless the scorer's rig has two cameras (the stereo pair's calls).
void needPair(int cameras, const char *what)
{
  if (cameras != 2)
    throw Error(std::string("fitness: ") + what + " given a stereo pair, but the rig has " + std::to_string(cameras) +
                (cameras == 1 ? " camera" : " cameras"));
}

} // namespace

void StereoScorer::setImages(HueFrame &f, const vpImage<vpRGBa> *const *images) const
{
  std::array<PixelRect, CameraRig::kMaxCameras> whole;
  for (std::size_t k = 0; k < static_cast<std::size_t>(m_nCams); ++k)
    whole[k] = PixelRect{0, 0, m_cams[k].w, m_cams[k].h};
  setImages(f, images, whole.data());
}

void StereoScorer::setImages(HueFrame &f, const vpImage<vpRGBa> *const *im, const PixelRect *windows) const
{
  checkSizes(im);
  // The cameras' planes on two cores (BatchPool: on the caller alone when the other core is busy).
  std::array<std::exception_ptr, CameraRig::kMaxCameras> error;
  BatchPool::shared().run(static_cast<std::size_t>(m_nCams), [&](std::size_t k) {
    try {
      if (const auto &map = m_undistort[k])
        f.m_planes[k].compute(*im[k], m_params.minSaturation, *map);
      else
        f.m_planes[k].compute(*im[k], m_params.minSaturation, windows[k]);
    } catch (...) {
      error[k] = std::current_exception();
    }
  });
  for (const auto &e : error)
    if (e)
      std::rethrow_exception(e);
  f.m_hasImages = true;
}

void StereoScorer::setImages(HueFrame &f, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right) const
{
  needPair(m_nCams, "setImages");
  const vpImage<vpRGBa> *im[2] = {&left, &right};
  setImages(f, im);
}

void StereoScorer::setImages(HueFrame &f, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right,
                             const std::array<PixelRect, 2> &windows) const
{
  needPair(m_nCams, "setImages");
  const vpImage<vpRGBa> *im[2] = {&left, &right};
  setImages(f, im, windows.data());
}

void StereoScorer::addHueUnder(HueFrame &f, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const Phi *poses,
                               std::size_t n) const
{
  needPair(m_nCams, "addHueUnder");
  const vpImage<vpRGBa> *im[2] = {&left, &right};
  addHueUnder(f, im, poses, n);
}

void StereoScorer::addHueUnder(HueFrame &f, const vpImage<vpRGBa> *const *im, const Phi *poses, std::size_t n) const
{
  for (std::size_t k = 0; k < n; ++k)
    check(f, poses[k]);
  for (int cam = 0; cam < m_nCams; ++cam)
    if (im[cam]->getWidth() != f.plane(cam).width() || im[cam]->getHeight() != f.plane(cam).height())
      throw Error("fitness: the hue is added from images of another size than the last pair's");
  // The cameras on two cores; addPixels cannot throw here (the sizes match, the pixels are in the image).
  BatchPool::shared().run(static_cast<std::size_t>(m_nCams), [&](std::size_t cam) {
    if (m_undistort[cam]) // its plane is the whole ideal image
      return;
    std::vector<std::int64_t> &pixels = f.m_pixelScratch[cam];
    pixels.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const Projection p = projectionOf(static_cast<int>(cam), poses[k]);
      const View &view = viewFor(p);
#ifdef PM_HAVE_X86
      const kernels::ModelSoA m{m_x.data(), m_y.data(), m_z.data(), m_hue.data()};
      if (m_avx2) // the counting kernel's projection, 8 points at a time
        (m_hasDepth ? kernels::collectPixelsAvx2<true> : kernels::collectPixelsAvx2<false>)(p, m, view.inBegin, view.outEnd, f.m_planes[cam].window(), pixels);
      else
#endif
        (m_hasDepth ? kernels::collectPixels<true> : kernels::collectPixels<false>)(p, m_x.data(), m_y.data(), m_z.data(), view.inBegin,
                                                                 view.outEnd, f.m_planes[cam].window(), pixels);
    }
    f.m_planes[cam].addPixels(*im[cam], m_params.minSaturation, pixels.data(), pixels.size());
  });
}

PixelRect StereoScorer::footprint(const Phi &phi, int camera) const
{
  if (!phi.isValid())
    throw Error("footprint of an invalid pose " + phi.toString());
  checkCamera(camera);
  const Projection p = projectionOf(camera, phi);
  const View &view = viewFor(p);
  double umin = 1e9, vmin = 1e9, umax = -1e9, vmax = -1e9;
  for (std::size_t i = view.inBegin; i < view.outEnd; ++i) {
    const double X = m_x[i], Y = m_y[i], Z = m_z[i];
    const double zc = p.r[6] * X + p.r[7] * Y + p.r[8] * Z + p.t[2];
    if (zc <= 1e-3)
      continue;
    const double u = p.px * (p.r[0] * X + p.r[1] * Y + p.r[2] * Z + p.t[0]) / zc + p.u0;
    const double v = p.py * (p.r[3] * X + p.r[4] * Y + p.r[5] * Z + p.t[1]) / zc + p.v0;
    umin = std::min(umin, u), umax = std::max(umax, u), vmin = std::min(vmin, v), vmax = std::max(vmax, v);
  }
  if (umax < umin)
    return {};
  // A point at u lands on pixel round(u): the box of the pixels they land on, clipped.
  const PixelRect box{static_cast<int>(std::max(-1.0, std::floor(umin))), static_cast<int>(std::max(-1.0, std::floor(vmin))),
                      static_cast<int>(std::min(1e6, std::ceil(umax) + 1)), static_cast<int>(std::min(1e6, std::ceil(vmax) + 1))};
  return box.grown(0, p.w, p.h);
}

} // namespace pm::core
