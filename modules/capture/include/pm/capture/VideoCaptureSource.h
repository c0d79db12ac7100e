#pragma once
/*!
  \file VideoCaptureSource.h
  Two cameras, video files or GStreamer pipelines read through OpenCV's VideoCapture, their
  frames paired by timestamp. A source is a device index ("0"), a V4L2 path ("/dev/video2"), a
  video file ("left.avi") or a GStreamer pipeline (any text with a '!', ending in appsink).

  Pairing: each stream's next frame is held; when their timestamps (CAP_PROP_POS_MSEC: the
  buffer's time for a camera, the frame's for a file) differ by at most maxSkewMs they make a
  pair, otherwise the older one is dropped and counted as unpaired, so streams of different
  rates still pair (the faster one's extra frames dropped). When a backend gives no timestamps,
  the time of arrival is used. The source ends when either stream ends; a camera that delivers
  nothing for stallTimeoutS, or two streams of different image sizes, are errors. A live stream
  (a device or a pipeline) is read by a thread of its own each time, so that a driver that never
  returns is given up on; a file is read directly.

      pm::capture::VideoCaptureSource src("/dev/video0", "/dev/video2");
      pm::capture::StereoFrame f;
      while (src.next(f)) { ... }
*/
#include <memory>
#include "pm/capture/StereoSource.h"

namespace pm::capture {

struct VideoCaptureParams
{
  double maxSkewMs = 10;      //!< largest left-right time difference of a pair
  double stallTimeoutS = 5;   //!< a stream silent this long is an error
  long maxPairs = 0;          //!< stop after this many pairs (0: until a stream ends)
  void validate() const;
};

class VideoCaptureSource : public StereoSource
{
public:
  //! Opens both sources. Throws pm::Error naming the one that does not open.
  VideoCaptureSource(const std::string &left, const std::string &right, const VideoCaptureParams &params = VideoCaptureParams());
  ~VideoCaptureSource() override;
  bool next(StereoFrame &f) override;
  std::string describe() const override;

private:
  struct Stream;
  std::unique_ptr<Stream> m_s[2];
  VideoCaptureParams m_params;
  double m_t0 = -1;
};

} // namespace pm::capture
