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
    : ImageSequenceSource(PerCamera{}, {leftPattern, rightPattern}, firstFrame, fps, width, height, maxFrames)
{
}

std::unique_ptr<ImageSequenceSource> ImageSequenceSource::ofCameras(const std::vector<std::string> &patterns, int firstFrame, double fps,
                                                                    unsigned width, unsigned height, long maxFrames)
{
  return std::unique_ptr<ImageSequenceSource>(new ImageSequenceSource(PerCamera{}, patterns, firstFrame, fps, width, height, maxFrames));
}

ImageSequenceSource::ImageSequenceSource(PerCamera, const std::vector<std::string> &patterns, int firstFrame, double fps, unsigned width,
                                         unsigned height, long maxFrames)
    : m_names(patterns), m_files(patterns.size()), m_first(firstFrame), m_fps(fps), m_w(width), m_h(height)
{
  if (!(fps > 0))
    throw core::Error("image sequence: the frame rate must be positive");
  if (patterns.empty() || patterns.size() > SourceStats::kMaxStreams)
    throw core::Error("image sequence: " + std::to_string(patterns.size()) + " image patterns; one per camera, one to four");
  m_stats.streams = patterns.size();
  auto anyExists = [&](long k) {
    for (const std::string &p : patterns)
      if (std::filesystem::exists(frameFileName(p, m_first + k)))
        return true;
    return false;
  };
  while ((maxFrames <= 0 || m_length < maxFrames) && anyExists(m_length)) {
    for (std::size_t c = 0; c < patterns.size(); ++c)
      m_files[c].push_back(frameFileName(patterns[c], m_first + m_length));
    ++m_length;
  }
  if (m_length == 0) {
    std::string none;
    for (const std::string &p : patterns)
      none += (none.empty() ? "no frame " : " nor ") + frameFileName(p, m_first);
    throw core::Error("the sequence is empty: " + none);
  }
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
  const std::string more = m_length > 1 ? " (and " + std::to_string(m_length - 1) + " more)" : "";
  m_names = {leftFiles.front() + more, rightFiles.front() + more};
  m_files = {std::move(leftFiles), std::move(rightFiles)};
}

bool ImageSequenceSource::next(StereoFrame &f) { return pairThroughFrame(f); }

bool ImageSequenceSource::nextFrame(CameraFrame &f)
{
  f.images.resize(m_files.size());
  while (m_pos < m_length) {
    const long idx = m_first + m_pos;
    f.index = idx;
    f.timeS = static_cast<double>(m_pos) / m_fps;
    f.skewMs = 0;
    ++m_pos;
    try {
      for (std::size_t c = 0; c < m_files.size(); ++c) {
        f.images[c] = io::readColorImage(m_files[c][static_cast<std::size_t>(m_pos - 1)]);
        if (m_w && m_h && (f.images[c].getWidth() != m_w || f.images[c].getHeight() != m_h))
          throw core::Error("frame " + std::to_string(idx) + ": image size differs from the rig's cameras");
      }
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

std::string ImageSequenceSource::describe() const
{
  std::string d = "recorded sequence ";
  for (std::size_t c = 0; c < m_names.size(); ++c)
    d += (c ? " + " : "") + m_names[c];
  return d;
}

} // namespace pm::capture
