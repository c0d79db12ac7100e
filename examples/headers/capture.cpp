// The usage examples of pm::capture's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/capture/ImageSequenceSource.h"
#include "pm/capture/StereoSource.h"
#include "pm/capture/VideoCaptureSource.h"

#include <iostream>
#include "pm/tracker/PhotoModelTracker.h"
namespace pm_examples {

// ImageSequenceSource.h
void exampleImageSequenceSource()
{
  pm::capture::ImageSequenceSource src("rec/L_%04d.png", "rec/R_%04d.png", 0, 30.0, 640, 480);
  std::cout << src.describe() << ": " << src.length() << " frames\n";
  pm::capture::StereoFrame f;
  while (src.next(f))
    std::cout << "frame " << f.index << " at " << f.timeS << " s\n";
  for (const std::string &p : src.stats().problems)
    std::cerr << p << "\n";
}

// StereoSource.h
void exampleStereoSource()
{
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
}

// VideoCaptureSource.h
void exampleVideoCaptureSource()
{
  pm::capture::VideoCaptureParams p;
  p.maxSkewMs = 5;     // pair frames at most 5 ms apart
  p.maxPairs = 300;    // 10 s at 30 Hz
  pm::capture::VideoCaptureSource src("/dev/video0", "/dev/video2", p);
  pm::capture::StereoFrame f;
  while (src.next(f))
    std::cout << f.index << ": " << f.timeS << " s, skew " << f.skewMs << " ms\n";
  std::cout << src.stats().describe() << "\n";
}

// StereoSource.h
void exampleStereoSourceFile(pm::tracker::PhotoModelTracker &tracker)
{
  std::unique_ptr<pm::capture::StereoSource> src = std::make_unique<pm::capture::VideoCaptureSource>("0", "1");
  pm::capture::StereoFrame f;
  while (src->next(f))
    tracker.track(f.left, f.right);
  std::cout << src->stats().describe() << "\n";
}

// VideoCaptureSource.h
void exampleVideoCaptureSourceFile(pm::tracker::PhotoModelTracker &tracker)
{
  pm::capture::VideoCaptureSource src("/dev/video0", "/dev/video2");
  pm::capture::StereoFrame f;
  while (src.next(f))
    tracker.track(f.left, f.right);
}

// ImageSequenceSource.h
void exampleImageSequenceSource3(pm::tracker::PhotoModelTracker &tracker)
{
  const auto one = pm::capture::ImageSequenceSource::ofCameras({"rec/C_%04d.png"}, 0, 30.0, 640, 480);
  pm::capture::CameraFrame f;
  while (one->nextFrame(f))
    tracker.track(f.view());
}

// StereoSource.h
void exampleStereoSource2(pm::capture::StereoSource &source, pm::tracker::PhotoModelTracker &tracker)
{
  pm::capture::CameraFrame f;
  while (source.nextFrame(f))
    tracker.track(f.view()); // one image per camera
}

// VideoCaptureSource.h
void exampleVideoCaptureSource3(pm::tracker::PhotoModelTracker &tracker)
{
  pm::capture::VideoCaptureSource one(std::vector<std::string>{"/dev/video0"});
  pm::capture::CameraFrame f;
  while (one.nextFrame(f))
    tracker.track(f.view());
}

} // namespace pm_examples
