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

  \code
      pm::capture::VideoCaptureSource src("/dev/video0", "/dev/video2");
      pm::capture::StereoFrame f;
      while (src.next(f))
        tracker.track(f.left, f.right);
  \endcode
*/
#include <memory>
#include "pm/capture/StereoSource.h"

namespace pm::capture {

//! How a VideoCaptureSource pairs its streams and when it gives up.
struct VideoCaptureParams
{
  double maxSkewMs = 10;      //!< largest left-right time difference of a pair (ms)
  double stallTimeoutS = 5;   //!< a live stream silent this long (s) is an error
  long maxPairs = 0;          //!< stop after this many pairs (0: until a stream ends)
  //! Throws pm::core::Error unless maxSkewMs \>= 0 (finite) and stallTimeoutS \> 0.
  void validate() const;
};

/*!
  Stereo pairs from two cameras, video files or GStreamer pipelines, paired by timestamp (see
  VideoCaptureSource.h for the sources it takes and the pairing). It owns both captures; not
  copyable. Pairs are converted to RGBA (grey and BGR(A) frames alike).
  \code
  pm::capture::VideoCaptureParams p;
  p.maxSkewMs = 5;     // pair frames at most 5 ms apart
  p.maxPairs = 300;    // 10 s at 30 Hz
  pm::capture::VideoCaptureSource src("/dev/video0", "/dev/video2", p);
  pm::capture::StereoFrame f;
  while (src.next(f))
    std::cout << f.index << ": " << f.timeS << " s, skew " << f.skewMs << " ms\n";
  std::cout << src.stats().describe() << "\n";
  \endcode
*/
class VideoCaptureSource : public StereoSource
{
public:
  /*!
    Opens both sources (\e left, \e right: a device index, a /dev path, a video file or a GStreamer
    pipeline). Throws pm::core::Error for invalid \e params or naming the source that does not open.
  */
  VideoCaptureSource(const std::string &left, const std::string &right, const VideoCaptureParams &params = VideoCaptureParams());
  /*!
    A rig of one to four cameras: camera k reads \e sources[k] (as above). Frames are held together
    as a pair is: the oldest frame is dropped until all lie within maxSkewMs. Throws as above, or for
    no source or more than four.
    \code
    pm::capture::VideoCaptureSource one(std::vector<std::string>{"/dev/video0"});
    pm::capture::CameraFrame f;
    while (one.nextFrame(f))
      tracker.track(f.view());
    \endcode
  */
  explicit VideoCaptureSource(const std::vector<std::string> &sources, const VideoCaptureParams &params = VideoCaptureParams());
  //! Releases both captures (a read still stuck in a driver keeps its own until it returns).
  ~VideoCaptureSource() override;
  /*!
    The next pair: StereoFrame::index counts the pairs from 0, timeS is the left frame's time since
    the first pair's (s), skewMs left minus right (ms). False when a stream ends or maxPairs is
    reached. Throws pm::core::Error if a live stream stalls (stallTimeoutS; the source cannot be read
    again) or the two streams' images differ in size.
  */
  bool next(StereoFrame &f) override;
  //! The next frame of every camera (see the N-camera constructor); the pair's rules otherwise.
  bool nextFrame(CameraFrame &f) override;
  //! The sources opened.
  std::size_t cameraCount() const override { return m_s.size(); }
  //! "video sources " and the two source names.
  std::string describe() const override;

private:
  struct Stream;
  //! Reads until every stream holds a frame within maxSkewMs of the others; false when one ends.
  bool holdTogether();
  std::vector<std::unique_ptr<Stream>> m_s;
  VideoCaptureParams m_params;
  double m_t0 = -1;
};

} // namespace pm::capture
