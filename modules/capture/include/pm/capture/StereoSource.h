#pragma once
/*!
  \file StereoSource.h
  Where stereo pairs come from: recorded image files (ImageSequenceSource) or two live cameras,
  video files or GStreamer pipelines read through OpenCV's VideoCapture (VideoCaptureSource).
  A source hands out pairs in order and counts what it could not pair or read; the programs only
  loop over next().

      std::unique_ptr<pm::capture::StereoSource> src = std::make_unique<pm::capture::VideoCaptureSource>("0", "1");
      pm::capture::StereoFrame f;
      while (src->next(f))
        tracker.track(f.left, f.right);
      std::cout << src->stats().describe() << "\n";
*/
#include <string>
#include <vector>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::capture {

struct StereoFrame
{
  vpImage<vpRGBa> left, right;
  long index = 0;      //!< the pair's number in the source (the file index of an image sequence)
  double timeS = 0;    //!< its time from the first pair (s): the cameras' timestamps, or the file rate
  double skewMs = 0;   //!< left minus right timestamp (ms)
};

struct SourceStats
{
  long pairs = 0;                   //!< pairs handed out
  long skipped = 0;                 //!< pairs that could not be read (image sequences) and were skipped
  long unpaired[2] = {0, 0};        //!< frames of each stream dropped for want of a partner in time
  long framesRead[2] = {0, 0};      //!< frames read from each stream
  double maxSkewMs = 0;             //!< largest |left - right| among the pairs
  std::vector<std::string> problems;//!< one line per skipped pair, and why a stream ended
  std::string describe() const;     //!< e.g. "412 pairs; unpaired 3 left, 0 right; 1 skipped"
};

class StereoSource
{
public:
  virtual ~StereoSource() = default;
  //! The next pair into \e f; false when the source has no more. Throws pm::Error on failure (see each source).
  virtual bool next(StereoFrame &f) = 0;
  virtual std::string describe() const = 0;
  const SourceStats &stats() const { return m_stats; }

protected:
  SourceStats m_stats;
};

//! The two pairs a stereo photo-model is made of (pm::buildStereoPhotoModel).
struct ModelPairs
{
  StereoFrame background, photo;
};

/*!
  Takes the backdrop pair and the target pair from a running source: pairs number \e backgroundIndex
  and \e photoIndex (counted from the first, photoIndex > backgroundIndex). With photoIndex < 0 it
  asks on the terminal instead: Enter with the backdrop alone in view, then Enter with the target
  placed (the freshest pair each time). Throws pm::Error when the source ends first, or when the
  frames are not given and stdin is not a terminal.
*/
ModelPairs grabModelPairs(StereoSource &source, long backgroundIndex, long photoIndex);

} // namespace pm::capture
