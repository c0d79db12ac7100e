#include "pm/core/CameraImages.h"

#include <string>

#include "pm/core/Error.h"

namespace pm::core {

CameraImages CameraImages::of(const std::vector<vpImage<vpRGBa>> &images)
{
  if (images.empty() || images.size() > CameraRig::kMaxCameras)
    throw Error("a frame holds 1 to " + std::to_string(CameraRig::kMaxCameras) + " images (one per camera), not " +
                std::to_string(images.size()));
  CameraImages c;
  for (const vpImage<vpRGBa> &im : images)
    c.add(im);
  return c;
}

CameraImages &CameraImages::add(const vpImage<vpRGBa> &image)
{
  if (m_count == CameraRig::kMaxCameras)
    throw Error("a frame holds at most " + std::to_string(CameraRig::kMaxCameras) + " images (one per camera)");
  m_images[m_count++] = &image;
  return *this;
}

void CameraImages::checkCount(std::size_t images, std::size_t cameras, const char *who)
{
  if (images != cameras)
    throw Error(std::string(who) + ": " + std::to_string(images) + (images == 1 ? " image" : " images") + " for a rig of " +
                std::to_string(cameras) + (cameras == 1 ? " camera" : " cameras") + " (one image per camera)");
}

void CameraImages::checkFor(const CameraRig &rig, const char *who) const
{
  checkCount(m_count, rig.size(), who);
  for (std::size_t k = 0; k < m_count; ++k) {
    const PinholeCamera &c = rig[k];
    const vpImage<vpRGBa> &im = *m_images[k];
    if (im.getWidth() != c.width || im.getHeight() != c.height)
      throw Error(std::string(who) + ": camera " + std::to_string(k) + "'s image is " + std::to_string(im.getWidth()) + "x" +
                  std::to_string(im.getHeight()) + " but the camera is " + std::to_string(c.width) + "x" + std::to_string(c.height));
  }
}

} // namespace pm::core
