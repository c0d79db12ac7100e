// The usage example of modules/tracker/include/pm/tracker/PhotoModelTracker.h, a whole program (compiled, never linked).
#include <iostream>
#include <pm/io/ImageFile.h>
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/tracker/PhotoModelTracker.h>

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json");
  pm::tracker::PhotoModelTracker tracker(rig, model); // the default TrackerParams
  tracker.initialize();                               // search from scratch
  for (int k = 0; k < 100; ++k) {
    const vpImage<vpRGBa> IL = pm::io::readColorImage("left_" + std::to_string(k) + ".png");
    const vpImage<vpRGBa> IR = pm::io::readColorImage("right_" + std::to_string(k) + ".png");
    // eye-in-hand: tracker.applyHandMotion(hNowMhPrev) here, when the hand moved since the last frame
    const pm::tracker::TrackResult r = tracker.track(IL, IR);
    std::cout << pm::tracker::toString(r.state) << " q " << r.quality << " confidence " << r.confidence << "\n";
    if (r.trusted && (!r.uncertainty.known || (r.uncertainty.maxMm() < 2 && r.uncertainty.maxDeg() < 2)))
      std::cout << "hMo (m):\n" << r.hMo << "\n"; // tracking, verified, confident, precise enough: a pose to act on
  }
}
