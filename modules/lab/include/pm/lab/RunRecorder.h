#pragma once
/*!
  \file RunRecorder.h
  The pictures of a closed-loop run, as pm-servo records them: a video of both views with the
  model's points drawn at the pose the servo used (half size, every other frame: a minute of
  servoing in about 30 MB, OpenCV's MJPG writer) and an overlay PNG every N frames.
*/
#include <functional>
#include <memory>
#include <string>

#include "pm/lab/ClosedLoop.h"

namespace pm::lab {

/*!
  Records a run frame by frame (see RunRecorder.h).

  \code
    pm::lab::RunRecorder rec("servo.avi", 30.0, 2 * 640, 480, 150, false); // a stereo rig of 640 x 480 cameras
    for (long k = 0; k < n; ++k) {
      const pm::lab::LoopFrame f = loop.step();
      rec.record(k, f, loop, [](const std::string &name) { return "out/" + name; });
    }
    rec.finish();
  \endcode
*/
class RunRecorder
{
public:
  /*!
    \e videoPath: the video file (empty: none), at \e fps / 2 frames per second and half size, of
    a rig whose cameras' views side by side are \e width x \e height; \e overlayEvery: an overlay PNG every N frames (0: none);
    \e oracle: the run servoes on the true pose (so labelled). Throws pm::core::Error if the video
    cannot be opened.
  */
  RunRecorder(const std::string &videoPath, double fps, unsigned width, unsigned height, int overlayEvery, bool oracle);
  ~RunRecorder();
  /*!
    Records frame \e k (just made by \e loop.step()): into the video on even frames, and as
    overlay_%05d.png at the path \e place gives for that name every overlayEvery frames.
  */
  void record(long k, const LoopFrame &f, const ClosedLoop &loop, const std::function<std::string(const std::string &name)> &place);
  //! Closes the video.
  void finish();
  //! The overlay PNGs written.
  int overlays() const { return m_overlays; }

private:
  struct Video;
  std::unique_ptr<Video> m_video;
  int m_every, m_overlays = 0;
  bool m_oracle;
};

} // namespace pm::lab
