#pragma once
/*!
  \file ImageSequenceSource.h
  A recorded sequence of a stereo rig, or of a rig of one to four cameras: image files named by
  printf patterns (e.g. "L_%04d.png"), one per camera, from \e firstFrame while any image of a
  frame exists. A pair that cannot be read, or whose size
  is not the expected one, is skipped and counted (stats().problems says why); the times follow
  \e fps.

  \code
      pm::capture::ImageSequenceSource src("rec/L_%04d.png", "rec/R_%04d.png", 0, 30.0, 640, 480);
  \endcode
*/
#include <memory>
#include <string>
#include <vector>

#include "pm/capture/StereoSource.h"

namespace pm::capture {

/*!
  Stereo pairs from recorded image files (see ImageSequenceSource.h). The length is fixed when it
  is made (files added later are not seen); unreadable pairs are skipped by next() and counted.
  \code
  pm::capture::ImageSequenceSource src("rec/L_%04d.png", "rec/R_%04d.png", 0, 30.0, 640, 480);
  std::cout << src.describe() << ": " << src.length() << " frames\n";
  pm::capture::StereoFrame f;
  while (src.next(f))
    std::cout << "frame " << f.index << " at " << f.timeS << " s\n";
  for (const std::string &p : src.stats().problems)
    std::cerr << p << "\n";
  \endcode
*/
class ImageSequenceSource : public StereoSource
{
public:
  /*!
    Frames \e firstFrame, firstFrame + 1 ... of the patterns (see frameFileName()) while the left or
    the right file exists, at \e fps frames per second (\> 0). \e width, \e height: the size both
    images must have (pixels; checked when both are not 0). \e maxFrames: stop after that many (0:
    all). Throws pm::core::Error if the sequence is empty, for fps \<= 0 or for a bad pattern.
  */
  ImageSequenceSource(const std::string &leftPattern, const std::string &rightPattern, int firstFrame, double fps,
                      unsigned width = 0, unsigned height = 0, long maxFrames = 0);
  /*!
    The pairs (\e leftFiles[k], \e rightFiles[k]) in order, numbered from 0, at \e fps frames per
    second; \e width, \e height and \e maxFrames as above. Throws pm::core::Error if the lists are empty or
    of different lengths, or for fps \<= 0.
  */
  ImageSequenceSource(std::vector<std::string> leftFiles, std::vector<std::string> rightFiles, double fps,
                      unsigned width = 0, unsigned height = 0, long maxFrames = 0);
  /*!
    A rig of any number of cameras (one to four): camera k's images from \e patterns[k], frames
    \e firstFrame, firstFrame + 1 ... while any camera's file exists; the rest as the stereo
    constructor. Throws pm::core::Error as it does, or for no pattern or more than four.
    \code
    const auto one = pm::capture::ImageSequenceSource::ofCameras({"rec/C_%04d.png"}, 0, 30.0, 640, 480);
    pm::capture::CameraFrame f;
    while (one->nextFrame(f))
      tracker.track(f.view());
    \endcode
  */
  static std::unique_ptr<ImageSequenceSource> ofCameras(const std::vector<std::string> &patterns, int firstFrame, double fps,
                                                        unsigned width = 0, unsigned height = 0, long maxFrames = 0);
  /*!
    The next readable pair: StereoFrame::index is its file index, timeS (index - firstFrame) / fps,
    skewMs 0. A pair that cannot be read or has the wrong size is skipped (SourceStats::skipped,
    SourceStats::problems). False after the last frame.
  */
  bool next(StereoFrame &f) override;
  //! The next readable frame of every camera, as next() reads a pair (see there).
  bool nextFrame(CameraFrame &f) override;
  //! The cameras of the sequence (2 for the stereo constructors).
  std::size_t cameraCount() const override { return m_files.size(); }
  //! "recorded sequence " and the patterns joined by " + " (or the first files and their count).
  std::string describe() const override;
  //! Frames in the sequence (readable or not).
  long length() const { return m_length; }

private:
  struct PerCamera {}; // ofCameras()'s constructor, apart from the stereo ones
  ImageSequenceSource(PerCamera, const std::vector<std::string> &patterns, int firstFrame, double fps, unsigned width, unsigned height,
                      long maxFrames);
  std::vector<std::string> m_names;              // each camera's pattern, or its first file
  std::vector<std::vector<std::string>> m_files; // the files of each camera, frame by frame
  int m_first = 0;
  double m_fps;
  unsigned m_w, m_h;
  long m_length = 0, m_pos = 0;
};

/*!
  \e pattern with \e index substituted, e.g. ("L_%04d.png", 7) -> "L_0007.png". The pattern must hold
  exactly one field, "%d" or "%Nd" / "%0Nd" (padded with spaces / zeros to N characters); "%%" is a
  literal %. Parsed here, never passed to printf; throws pm::core::Error for any other pattern.
*/
std::string frameFileName(const std::string &pattern, long index);

} // namespace pm::capture
