#pragma once
/*!
  \file Comparison.h
  pm-compare's runner, in the manner of M3T's evaluator: configure (ComparisonParams), set up
  (the scene, the photo-models each of our trackers needs, the outline and .cao model ViSP's
  trackers need), run every scenario through every tracker on the same rendered frames, and
  summarise (per scenario, pooled per tracker, ViSP's fastest, our time against it).
*/
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpPoint.h>
#include <visp3/core/vpRGBa.h>

#include "pm/compare/ComparedTracker.h"
#include "pm/compare/Metrics.h"
#include "pm/model/AllAroundModelBuilder.h"
#include "pm/compare/Scenario.h"
#include "pm/core/CameraRig.h"
#include "pm/model/PassPlanner.h"
#include "pm/sim/Scene.h"
#include "pm/sim/SimulatedPhotoModel.h"
#include "pm/tracker/PhotoModelTracker.h"

namespace pm::compare {

//! The trackers a comparison can run, by key: ours (five kinds) and ViSP's (five).
const std::vector<std::string> &comparedTrackerKeys();

//! What a comparison runs (pm-compare's options).
struct ComparisonParams
{
  std::string target = "C12";                 //!< the lab target (catalogue code)
  std::vector<std::string> scenarios = scenarioNames(); //!< in order (allScenarioNames())
  std::vector<std::string> trackers = comparedTrackerKeys(); //!< in order (comparedTrackerKeys())
  int steps = 0;                              //!< table2: only the first N steps (0: all)
  std::string trajectoryPath;                 //!< table2's waypoints file
  std::string mbtXml;                         //!< vpMbGenericTracker's XML settings
  double distanceMm = 500;                    //!< photo distance of the flat and stereo models (mm)
  double outlineTolPx = 1.5;                  //!< simplification of the outline for ViSP's trackers (px)
  /*!
    ViSP's model-based trackers' CAD model: the all-around model's surface, decimated to cells of
    this size (mm; CadMesh.h), the shape ours follows; 0: the flat model's outline (one face).
  */
  double mbtMeshCellMm = 8;
  bool mbtTrueCad = false;                    //!< ViSP's MBT given the toy's own mesh (the lab knows it; CadMesh.h), decimated the same way
  bool refineOutlines = false;                //!< the all-around model's outlines refined (model::HullSurfaceParams::refineOutlines)
  bool calibrateTrust = true; //!< the all-around model's trust calibrated from its pass (pm::trust; the shipped confidence otherwise)
  int viewpoints = model::AllAroundParams().viewpoints.count; //!< the all-around model's viewing directions (model::ViewpointSamplingParams::count)
  double minInsidePx = model::AllAroundParams().viewpoints.inMinInsidePx; //!< its S_in points this far inside the outline (model::ViewpointSamplingParams::inMinInsidePx)
  model::PassPlan pass;                       //!< the all-around model's pass (its views and rings)
  double viewTurnDeg = 0;                     //!< ours-3d: the stereo model's further pairs (deg; 0: one pair)
  double steadyVariant = 0.25;                //!< ours-steady: the fraction of the budget on steady frames
  sim::SceneParams scene;                     //!< the lab's scene
  tracker::TrackerParams tracker;                      //!< our tracker's settings
};

//! What a comparison measured.
struct ComparisonResult
{
  std::vector<Scenario> scenarios;                 //!< the scenarios run, in order
  std::vector<std::string> keys;                   //!< the trackers' keys, in order
  std::vector<std::string> names;                  //!< their names (ComparedTracker::name())
  std::vector<bool> needsPose;                     //!< whether each needs an initial pose (ViSP's)
  std::vector<std::vector<std::vector<FrameScore>>> scores; //!< scores[scenario][tracker][frame]
  std::vector<std::vector<Summary>> perScenario;   //!< perScenario[scenario][tracker]
  std::vector<Summary> overall;                    //!< per tracker, pooled over the scenarios
  std::size_t ours = 0;                            //!< index of "ours", else of the first of ours run ("ours-aa", ...); keys.size() when none
  std::size_t fastest = 0;                         //!< index of ViSP's fastest tracker (keys.size() when none)
  bool hadLoss = false;                            //!< some scenario forced a loss
  //! Two snapshots per scenario (the middle and the last frame): the left image with the true
  //! outline in white and each tracker's in its colour (trackerColor()); labels are the caller's.
  std::vector<vpImage<vpRGBa>> snapshots;
  std::vector<long> snapshotFrames;                //!< the frame of each snapshot
};

//! The colour of tracker \e index in snapshots and plots.
vpRGBa trackerColor(std::size_t index);

/*!
  The comparison of ComparisonParams' trackers on its scenarios (see Comparison.h).

  \code
    pm::compare::ComparisonParams p;
    p.scenarios = {"table2"};
    p.trackers = {"ours-aa", "mbt-klt"};
    p.trajectoryPath = "data/trajectories/table2.csv";
    p.mbtXml = "data/compare/mbt.xml";
    pm::compare::Comparison c(rig, p);
    pm::io::writeTextFile("model.cao", c.caoText());
    std::ofstream csv("frames.csv");
    const pm::compare::ComparisonResult r = c.run("model.cao", csv);
    std::cout << pm::compare::comparisonTable(r);
  \endcode
*/
class Comparison
{
public:
  //! Builds the scene and the models; throws pm::core::Error for an unknown tracker or scenario, or an unreadable file.
  Comparison(const core::CameraRig &rig, const ComparisonParams &params);
  ~Comparison();
  //! The one-face .cao model of the target's outline (metres, model frame) that ViSP's MBT trackers read.
  std::string caoText() const;
  //! Frames per tracker over all scenarios.
  std::size_t totalFrames() const;
  /*!
    Runs every scenario through every tracker (ours from nothing, ViSP's from the truth), with the
    .cao model at \e caoPath, writing one row per frame and tracker to \e framesCsv (scenario,
    frame, t, tracker, translation_error_mm, rotation_error_deg, frame_ms, valid) and calling
    \e onFrame after each frame. Throws pm::core::Error when \e framesCsv fails.
  */
  ComparisonResult run(const std::string &caoPath, std::ostream &framesCsv, const std::function<void()> &onFrame = {});

private:
  struct Setup;
  core::CameraRig m_rig;
  ComparisonParams m_p;
  std::unique_ptr<Setup> m_s;
};

//! The comparison's table (Markdown): one row per tracker, then ours against ViSP's fastest, then per scenario.
std::string comparisonTable(const ComparisonResult &r);

} // namespace pm::compare
