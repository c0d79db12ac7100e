#include "pm/precise/IdealImage.h"

#include <algorithm>

#include "pm/core/Error.h"

namespace pm::precise {

IdealImage::IdealImage(std::shared_ptr<const core::UndistortMap> map) : m_map(std::move(map))
{
  if (!m_map)
    throw core::Error("IdealImage: no lens map");
  m_ideal.resize(m_map->height(), m_map->width(), vpRGBa(0, 0, 0, 255));
}

void IdealImage::setRaw(const vpImage<vpRGBa> &raw)
{
  if (raw.getWidth() != m_map->width() || raw.getHeight() != m_map->height())
    throw core::Error("IdealImage: the image is " + std::to_string(raw.getWidth()) + "x" + std::to_string(raw.getHeight()) +
                      " but the camera's is " + std::to_string(m_map->width()) + "x" + std::to_string(m_map->height()));
  m_raw = &raw;
  m_u0 = m_v0 = m_u1 = m_v1 = 0;
}

const vpRGBa *IdealImage::cover(int u0, int v0, int u1, int v1)
{
  if (!m_raw)
    throw core::Error("IdealImage: cover() before setRaw()");
  const int w = static_cast<int>(m_map->width()), h = static_cast<int>(m_map->height());
  u0 = std::max(u0, 0), v0 = std::max(v0, 0), u1 = std::min(u1, w), v1 = std::min(v1, h);
  if (u1 <= u0 || v1 <= v0)
    return m_ideal.bitmap;
  const bool empty = m_u1 <= m_u0 || m_v1 <= m_v0;
  if (!empty && u0 >= m_u0 && v0 >= m_v0 && u1 <= m_u1 && v1 <= m_v1)
    return m_ideal.bitmap; // already there
  if (!empty) { // grow to hold the old rectangle; resample the new strips only
    const int a0 = std::min(u0, m_u0), b0 = std::min(v0, m_v0), a1 = std::max(u1, m_u1), b1 = std::max(v1, m_v1);
    m_map->undistortRegion(*m_raw, m_ideal, a0, b0, a1, m_v0);  // above
    m_map->undistortRegion(*m_raw, m_ideal, a0, m_v1, a1, b1);  // below
    m_map->undistortRegion(*m_raw, m_ideal, a0, m_v0, m_u0, m_v1); // left
    m_map->undistortRegion(*m_raw, m_ideal, m_u1, m_v0, a1, m_v1); // right
    m_u0 = a0, m_v0 = b0, m_u1 = a1, m_v1 = b1;
    return m_ideal.bitmap;
  }
  m_map->undistortRegion(*m_raw, m_ideal, u0, v0, u1, v1);
  m_u0 = u0, m_v0 = v0, m_u1 = u1, m_v1 = v1;
  return m_ideal.bitmap;
}

} // namespace pm::precise
