#include "pm/compare/LabelledFrames.h"

#include <memory>

#include "pm/core/Error.h"

namespace pm::compare {

void collectLabelledFrames(const core::StereoRig &rig, sim::Scene &scene, const Scenario &s, const std::vector<ConfidenceRun> &runs,
                           std::vector<LabelledFrame> &out, const std::function<void()> &onFrame,
                           const std::function<void(sim::Scene &, double t)> &sceneAt)
{
  std::vector<std::unique_ptr<tracker::PhotoModelTracker>> trackers;
  for (const ConfidenceRun &r : runs) {
    if (!r.model)
      throw core::Error("confidence run '" + r.name + "' has no model");
    trackers.push_back(std::make_unique<tracker::PhotoModelTracker>(rig, *r.model, r.params));
  }
  for (std::size_t k = 0; k < s.frames.size(); ++k) {
    if (sceneAt)
      sceneAt(scene, static_cast<double>(k) / s.fps);
    const sim::StereoImages im = renderScenarioFrame(scene, rig, s, k);
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const tracker::TrackResult t = trackers[i]->track(im.left, im.right);
      const core::Phi truth = core::fromHomogeneousMatrix(s.frames[k].hMo * runs[i].oMm);
      LabelledFrame lf;
      lf.run = i;
      lf.scenario = s.name;
      lf.frame = static_cast<int>(k);
      lf.state = t.state;
      lf.cues = t.cues;
      lf.confidence = t.confidence;
      lf.trusted = t.trusted;
      lf.errorMm = core::translationDistanceMm(t.phi, truth);
      lf.errorDeg = core::rotationDistanceDeg(t.phi, truth);
      lf.right = !runs[i].otherToy && lf.errorMm <= kRightMm && lf.errorDeg <= kRightDeg;
      out.push_back(lf);
    }
    if (onFrame)
      onFrame();
  }
}

} // namespace pm::compare
