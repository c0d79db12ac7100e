#pragma once
/*!
  \file StereoSource.h
  Where stereo pairs come from: recorded image files (ImageSequenceSource) or two live cameras,
  video files or GStreamer pipelines read through OpenCV's VideoCapture (VideoCaptureSource).
  A source hands out pairs in order and counts what it could not pair or read; the programs only
  loop over next().

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

//! What a StereoSource has handed out, dropped and skipped so far (StereoSource::stats()).
struct SourceStats
{
  long pairs = 0;                   //!< pairs handed out
  long skipped = 0;                 //!< pairs that could not be read (image sequences) and were skipped
  long unpaired[2] = {0, 0};        //!< frames of each stream dropped for want of a partner in time
  long framesRead[2] = {0, 0};      //!< frames read from each stream
  double maxSkewMs = 0;             //!< largest |left - right| among the pairs
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
  //! The next pair into \e f; false when the source has no more. Throws pm::core::Error on failure (see each source).
  virtual bool next(StereoFrame &f) = 0;
  //! What the source reads, in words (for logs), e.g. "video sources 0 + 1".
  virtual std::string describe() const = 0;
  const SourceStats &stats() const { return m_stats; } //!< the counts so far

protected:
  SourceStats m_stats; //!< the counts, kept up to date by next()
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
