//! \example tutorial-photomodel-tracker.cpp
//! Tracks a photo-model through recorded stereo pairs and prints the pose of every trusted frame.
//! The tutorial docs/tutorial-own-program.md builds and runs it step by step.
#include <cstdio>
#include <iostream>

#include <visp3/core/vpPoseVector.h>

#include <pm/capture/ImageSequenceSource.h>
#include <pm/core/Error.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/tracker/PhotoModelTracker.h>

int main(int argc, char **argv)
{
  if (argc != 5) {
    std::cerr << "usage: tutorial-photomodel-tracker RIG.json MODEL.json LEFT_PATTERN RIGHT_PATTERN\n"
                 "  e.g. tutorial-photomodel-tracker rig.json model.json 'rec/L_%04d.png' 'rec/R_%04d.png'\n";
    return 2;
  }
  try {
    // 1. The rig (both cameras and the hand frame) and the photo-model, as pm-make-model wrote it.
    const pm::core::StereoRig rig = pm::io::loadRig(argv[1]);
    const pm::core::PhotoModel model = pm::io::loadPhotoModel(argv[2]);

    // 2. The tracker, with the defaults every pm-* program uses (800 evaluations per frame).
    //    It keeps its own copies of the rig and the model.
    pm::tracker::PhotoModelTracker tracker(rig, model, pm::tracker::TrackerParams());
    tracker.initialize(); // no initial pose: RM-GA starts from a random population

    // 3. The stereo pairs: image files named by printf patterns, from frame 0, at 30 fps.
    pm::capture::ImageSequenceSource source(argv[3], argv[4], 0, 30.0, rig.left.width, rig.left.height);
    pm::capture::StereoFrame frame;
    int trusted = 0;
    while (source.next(frame)) {
      const pm::tracker::TrackResult r = tracker.track(frame.left, frame.right);
      // 4. hMo: the model's pose in the hand frame (metres). Act on it only when it is trusted.
      if (r.trusted) {
        const vpPoseVector p(r.hMo);
        std::printf("frame %ld: t = (%.1f, %.1f, %.1f) mm, theta-u = (%.3f, %.3f, %.3f) rad, confidence %.2f\n",
                    frame.index, p[0] * 1e3, p[1] * 1e3, p[2] * 1e3, p[3], p[4], p[5], r.confidence);
        ++trusted;
      } else {
        std::printf("frame %ld: %s, not trusted yet (confidence %.2f)\n", frame.index, pm::tracker::toString(r.state),
                    r.confidence);
      }
    }
    std::printf("%d of %ld frames trusted; %s\n", trusted, source.stats().pairs, source.stats().describe().c_str());
    return trusted > 0 ? 0 : 1;
  } catch (const pm::core::Error &e) {
    std::cerr << "error: " << e.what() << std::endl;
    return 1;
  }
}
