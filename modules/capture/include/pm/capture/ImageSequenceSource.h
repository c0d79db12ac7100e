#pragma once
/*!
  \file ImageSequenceSource.h
  A recorded stereo sequence: image files named by printf patterns (e.g. "L_%04d.png"), from
  \e firstFrame while either image of a frame exists. A pair that cannot be read, or whose size
  is not the expected one, is skipped and counted (stats().problems says why); the times follow
  \e fps.

      pm::capture::ImageSequenceSource src("rec/L_%04d.png", "rec/R_%04d.png", 0, 30.0, 640, 480);
*/
#include "pm/capture/StereoSource.h"

namespace pm::capture {

class ImageSequenceSource : public StereoSource
{
public:
  /*!
    \e width, \e height: the size both images must have (0: any). \e maxFrames: stop after that
    many (0: all). Throws pm::Error if the sequence is empty.
  */
  ImageSequenceSource(const std::string &leftPattern, const std::string &rightPattern, int firstFrame, double fps,
                      unsigned width = 0, unsigned height = 0, long maxFrames = 0);
  bool next(StereoFrame &f) override;
  std::string describe() const override;
  //! Frames in the sequence (readable or not).
  long length() const { return m_length; }

private:
  std::string m_left, m_right;
  int m_first;
  double m_fps;
  unsigned m_w, m_h;
  long m_length = 0, m_pos = 0;
};

//! \e pattern with \e index substituted (printf), e.g. ("L_%04d.png", 7) -> "L_0007.png".
std::string frameFileName(const std::string &pattern, long index);

} // namespace pm::capture
