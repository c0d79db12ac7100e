#include "pm/capture/ImageSequenceSource.h"

#include <cctype>
#include <filesystem>

#include "pm/core/Error.h"
#include "pm/io/ImageFile.h"

namespace pm::capture {

/*!
  The file name of frame \e index from a pattern with one printf-style integer field ("%d" or
  "%0Nd"; "%%" is a literal %). Throws Error for any other pattern (never passed to printf).
*/
std::string frameFileName(const std::string &pattern, long index)
{
  std::string out;
  int fields = 0;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') {
      out += pattern[i];
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      out += '%';
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    int width = 0;
    bool zero = j < pattern.size() && pattern[j] == '0';
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width < 100)
      width = width * 10 + (pattern[j++] - '0');
    if (j >= pattern.size() || pattern[j] != 'd' || ++fields > 1)
      throw core::Error("the image pattern '" + pattern + "' must hold exactly one frame-number field, %d or %0Nd (e.g. L_%04d.png)");
    std::string num = std::to_string(index);
    if (static_cast<int>(num.size()) < width)
      num.insert(0, static_cast<std::size_t>(width) - num.size(), zero ? '0' : ' ');
    out += num;
    i = j;
  }
  if (fields != 1)
    throw core::Error("the image pattern '" + pattern + "' must hold exactly one frame-number field, %d or %0Nd (e.g. L_%04d.png)");
  return out;
}

ImageSequenceSource::ImageSequenceSource(const std::string &leftPattern, const std::string &rightPattern, int firstFrame,
                                         double fps, unsigned width, unsigned height, long maxFrames)
    : m_left(leftPattern), m_right(rightPattern), m_first(firstFrame), m_fps(fps), m_w(width), m_h(height)
{
  if (!(fps > 0))
    throw core::Error("image sequence: the frame rate must be positive");
  auto exists = [](const std::string &f) { return std::filesystem::exists(f); };
  while ((maxFrames <= 0 || m_length < maxFrames) &&
         (exists(frameFileName(m_left, m_first + m_length)) || exists(frameFileName(m_right, m_first + m_length)))) {
    m_files[0].push_back(frameFileName(m_left, m_first + m_length));
    m_files[1].push_back(frameFileName(m_right, m_first + m_length));
    ++m_length;
  }
  if (m_length == 0)
    throw core::Error("the sequence is empty: no frame " + frameFileName(m_left, m_first) + " nor " + frameFileName(m_right, m_first));
}

ImageSequenceSource::ImageSequenceSource(std::vector<std::string> leftFiles, std::vector<std::string> rightFiles, double fps,
                                         unsigned width, unsigned height, long maxFrames)
    : m_fps(fps), m_w(width), m_h(height)
{
  if (!(fps > 0))
    throw core::Error("image sequence: the frame rate must be positive");
  if (leftFiles.empty() || leftFiles.size() != rightFiles.size())
    throw core::Error("image sequence: " + std::to_string(leftFiles.size()) + " left images but " +
                std::to_string(rightFiles.size()) + " right ones (pairs are taken in order; both lists must be as long, and not empty)");
  if (maxFrames > 0 && static_cast<long>(leftFiles.size()) > maxFrames) {
    leftFiles.resize(static_cast<std::size_t>(maxFrames));
    rightFiles.resize(static_cast<std::size_t>(maxFrames));
  }
  m_length = static_cast<long>(leftFiles.size());
  m_left = leftFiles.front() + (m_length > 1 ? " (and " + std::to_string(m_length - 1) + " more)" : "");
  m_right = rightFiles.front() + (m_length > 1 ? " (and " + std::to_string(m_length - 1) + " more)" : "");
  m_files[0] = std::move(leftFiles);
  m_files[1] = std::move(rightFiles);
}

bool ImageSequenceSource::next(StereoFrame &f)
{
  while (m_pos < m_length) {
    const long idx = m_first + m_pos;
    f.index = idx;
    f.timeS = static_cast<double>(m_pos) / m_fps;
    f.skewMs = 0;
    ++m_pos;
    try {
      f.left = io::readColorImage(m_files[0][static_cast<std::size_t>(m_pos - 1)]);
      f.right = io::readColorImage(m_files[1][static_cast<std::size_t>(m_pos - 1)]);
      if (m_w && m_h &&
          (f.left.getWidth() != m_w || f.left.getHeight() != m_h || f.right.getWidth() != m_w || f.right.getHeight() != m_h))
        throw core::Error("frame " + std::to_string(idx) + ": image size differs from the rig's cameras");
    } catch (const core::Error &e) {
      ++m_stats.skipped;
      m_stats.problems.push_back(e.what());
      continue;
    }
    ++m_stats.pairs;
    return true;
  }
  return false;
}

std::string ImageSequenceSource::describe() const { return "recorded sequence " + m_left + " + " + m_right; }

} // namespace pm::capture
