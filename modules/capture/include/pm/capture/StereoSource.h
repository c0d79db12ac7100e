#pragma once
/*!
  \file StereoSource.h
  Where frames come from: recorded image files (ImageSequenceSource) or live cameras, video files
  or GStreamer pipelines read through OpenCV's VideoCapture (VideoCaptureSource), for a stereo rig
  or a rig of one to four cameras. A source hands out frames in order and counts what it could not
  pair or read; the programs only loop over next() (a stereo pair) or nextFrame() (one image per
  camera, any rig).

  \code
      std::unique_ptr<pm::capture::StereoSource> src = std::make_unique<pm::capture::VideoCaptureSource>("0", "1");
      pm::capture::StereoFrame f;
      while (src->next(f))
        tracker.track(f.left, f.right);
      std::cout << src->stats().describe() << "\n";
  \endcode
*/
#include <string>
#include <vector>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/CameraImages.h"

namespace pm::capture {

//! One stereo pair handed out by a StereoSource.
struct StereoFrame
{
  //! The left camera's image.
  vpImage<vpRGBa> left, right; //!< the right camera's image (the same size as the left one)
  long index = 0;      //!< the pair's number in the source (the file index of an image sequence)
  double timeS = 0;    //!< its time from the first pair (s): the cameras' timestamps, or the file rate
  double skewMs = 0;   //!< left minus right timestamp (ms)
};

/*!
  One frame of every camera handed out by a source's nextFrame(): the images in the rig's order.
  \code
  pm::capture::CameraFrame f;
  while (source.nextFrame(f))
    tracker.track(f.view()); // one image per camera
  \endcode
*/
struct CameraFrame
{
  std::vector<vpImage<vpRGBa>> images; //!< one per camera, in the rig's order, all of one size
  long index = 0;      //!< the frame's number in the source (the file index of an image sequence)
  double timeS = 0;    //!< its time from the first frame (s): the first camera's timestamps, or the file rate
  double skewMs = 0;   //!< the largest difference of the cameras' timestamps (ms; 0 for one camera)
  //! The images as the tracker takes them (pointers into this frame).
  core::CameraImages view() const { return core::CameraImages::of(images); }
};

//! What a StereoSource has handed out, dropped and skipped so far (StereoSource::stats()).
struct SourceStats
{
  static constexpr std::size_t kMaxStreams = 4; //!< cameras a source reads at most
  long pairs = 0;                   //!< frames (pairs, for a stereo rig) handed out
  long skipped = 0;                 //!< frames that could not be read (image sequences) and were skipped
  long unpaired[kMaxStreams] = {0, 0, 0, 0};   //!< frames of each stream dropped for want of a partner in time
  long framesRead[kMaxStreams] = {0, 0, 0, 0}; //!< frames read from each stream
  std::size_t streams = 2;          //!< the cameras read
  double maxSkewMs = 0;             //!< largest difference of the cameras' timestamps among the frames
  std::vector<std::string> problems;//!< one line per skipped pair, and why a stream ended
  //! One line, e.g. "412 pairs (frames read: 415 left, 412 right; unpaired 3 left, 0 right; largest skew 4.2 ms)" or "98 pairs, 2 skipped".
  std::string describe() const;
};

/*!
  A source of stereo pairs, read in order with next() (see StereoSource.h): ImageSequenceSource
  or VideoCaptureSource. A program holds one through a pointer to this base, so that recorded
  and live input are read alike.
  \code
  const bool live = true;
  std::unique_ptr<pm::capture::StereoSource> src;
  if (live)
    src = std::make_unique<pm::capture::VideoCaptureSource>("/dev/video0", "/dev/video2");
  else
    src = std::make_unique<pm::capture::ImageSequenceSource>("rec/L_%04d.png", "rec/R_%04d.png", 0, 30.0);
  std::cout << src->describe() << "\n";
  pm::capture::StereoFrame f;
  while (src->next(f)) {
    // f.left, f.right: the pair; f.timeS: its time (s)
  }
  std::cout << src->stats().describe() << "\n";
  \endcode
*/
class StereoSource
{
public:
  virtual ~StereoSource() = default;
  //! The next pair into \e f; false when the source has no more. Throws pm::core::Error on failure (see each source), or for a source of other than two cameras.
  virtual bool next(StereoFrame &f) = 0;
  /*!
    The next frame of every camera into \e f (its images reused from call to call); false when the
    source has no more. This default reads a pair through next(StereoFrame&); a source of any number
    of cameras overrides it. Throws as next().
  */
  virtual bool nextFrame(CameraFrame &f);
  //! The cameras the source reads (2 unless the source says otherwise).
  virtual std::size_t cameraCount() const { return 2; }
  //! What the source reads, in words (for logs), e.g. "video sources 0 + 1".
  virtual std::string describe() const = 0;
  const SourceStats &stats() const { return m_stats; } //!< the counts so far

protected:
  //! For a source of any number of cameras: next() as a pair read through nextFrame(); throws unless it reads two.
  bool pairThroughFrame(StereoFrame &f);
  SourceStats m_stats; //!< the counts, kept up to date by next()

private:
  CameraFrame m_pair;   //!< pairThroughFrame()'s images, reused
  StereoFrame m_stereo; //!< the default nextFrame()'s pair, reused
};

//! The two pairs a stereo photo-model is made of (pm::model::buildStereoPhotoModel).
struct ModelPairs
{
  //! The backdrop pair: the backdrop alone in view.
  StereoFrame background, photo; //!< the photo pair: the target placed, the hand not moved
};

/*!
  Takes the backdrop pair and the target pair from a running source: it reads on to the first pair
  whose StereoFrame::index reaches \e backgroundIndex, then to the first that reaches \e photoIndex
  (photoIndex > backgroundIndex; the index is the pair's number for a live source, the file index
  for an image sequence). With photoIndex < 0 it asks on the terminal instead: Enter with the
  backdrop alone in view, then Enter with the target placed; after each Enter it reads on until the
  index reaches the number of pairs handed out before it plus 4 (for a live source: the fifth pair,
  past what the cameras buffered while waiting). Throws pm::core::Error when the source ends first, when
  photoIndex \<= backgroundIndex, or when the frames are not given and stdin is not a terminal.
*/
ModelPairs grabModelPairs(StereoSource &source, long backgroundIndex, long photoIndex);

} // namespace pm::capture
