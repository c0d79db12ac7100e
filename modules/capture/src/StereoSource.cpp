#include "pm/capture/StereoSource.h"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "pm/core/Error.h"

namespace pm::capture {

std::string SourceStats::describe() const
{
  std::ostringstream os;
  const std::size_t n = std::min(streams, kMaxStreams);
  if (n == 2) {
    os << pairs << " pairs";
    if (framesRead[0] || framesRead[1])
      os << " (frames read: " << framesRead[0] << " left, " << framesRead[1] << " right; unpaired " << unpaired[0]
         << " left, " << unpaired[1] << " right; largest skew " << maxSkewMs << " ms)";
  } else {
    os << pairs << " frames";
    bool read = false;
    for (std::size_t k = 0; k < n; ++k)
      read = read || framesRead[k];
    if (read && n > 1) {
      os << " (frames read per camera:";
      for (std::size_t k = 0; k < n; ++k)
        os << " " << framesRead[k];
      os << "; unpaired:";
      for (std::size_t k = 0; k < n; ++k)
        os << " " << unpaired[k];
      os << "; largest skew " << maxSkewMs << " ms)";
    }
  }
  if (skipped)
    os << ", " << skipped << " skipped";
  return os.str();
}

bool StereoSource::nextFrame(CameraFrame &f)
{
  StereoFrame &p = m_stereo;
  if (!next(p))
    return false;
  f.images.resize(2);
  swap(f.images[0], p.left);
  swap(f.images[1], p.right);
  f.index = p.index;
  f.timeS = p.timeS;
  f.skewMs = p.skewMs;
  return true;
}

bool StereoSource::pairThroughFrame(StereoFrame &f)
{
  if (cameraCount() != 2)
    throw core::Error(describe() + ": " + std::to_string(cameraCount()) + " camera" + (cameraCount() == 1 ? "" : "s") +
                      ", not a stereo pair (read it with nextFrame())");
  if (!nextFrame(m_pair))
    return false;
  swap(f.left, m_pair.images[0]);
  swap(f.right, m_pair.images[1]);
  f.index = m_pair.index;
  f.timeS = m_pair.timeS;
  f.skewMs = m_pair.skewMs;
  return true;
}

namespace {
//! Reads up to pair \e index (or, with \e fresh, \e fresh more pairs) into \e f.
void readUntil(StereoSource &source, long index, StereoFrame &f, const char *what)
{
  do {
    if (!source.next(f))
      throw core::Error("the source ended at pair " + std::to_string(source.stats().pairs) + ", before the " + what + " pair (" +
                  std::to_string(index) + ")");
  } while (f.index < index);
}
} // namespace

ModelPairs grabModelPairs(StereoSource &source, long backgroundIndex, long photoIndex)
{
  ModelPairs p;
  if (photoIndex >= 0) {
    if (photoIndex <= backgroundIndex)
      throw core::Error("the photo pair (" + std::to_string(photoIndex) + ") must come after the background pair (" +
                  std::to_string(backgroundIndex) + ")");
    readUntil(source, backgroundIndex, p.background, "background");
    readUntil(source, photoIndex, p.photo, "photo");
    return p;
  }
  if (!::isatty(STDIN_FILENO))
    throw core::Error("no --photo-frame given and no terminal to ask on: give --background-frame and --photo-frame");
  const auto ask = [&](const char *prompt, StereoFrame &f) {
    std::cerr << prompt << std::flush;
    std::string line;
    std::getline(std::cin, line);
    // The freshest pair: skip what the cameras buffered while waiting.
    const long from = source.stats().pairs;
    readUntil(source, from + 4, f, "requested");
  };
  ask("Only the backdrop in view of both cameras? Press Enter. ", p.background);
  ask("Now place the target (same hand pose) and press Enter. ", p.photo);
  return p;
}

} // namespace pm::capture
