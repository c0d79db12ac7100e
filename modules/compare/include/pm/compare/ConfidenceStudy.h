#pragma once
/*!
  \file ConfidenceStudy.h
  pm-confidence's experiment: the labelled set of frames on which the tracker's confidence is
  measured (scenes and runs chosen to make it fail: seeds, small budgets, supersampling 1, a model
  of another toy, a look-alike of similar hue, an identical twin, the relief toys with cast
  shadows and highlights, the stereo model, a lens, a strand of seaweed in front all along), and its report: AUROC (all frames, and the
  frames the tracker claims to track), accept rates at the tracker's threshold, the threshold for
  a largest false accept rate, and the counts per run.
*/
#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "pm/compare/LabelledFrames.h"
#include "pm/compare/Roc.h"
#include "pm/core/StereoRig.h"

namespace pm::compare {

//! One scene of the study and the runs tracked on it.
struct ConfidencePass
{
  std::string label;           //!< the scene, in the runs' names
  std::string target;          //!< the toy filmed (catalogue code)
  unsigned supersampling = 2;  //!< the renderer's samples per pixel along each axis
  //! One tracker run on the scene.
  struct Run
  {
    std::string model;         //!< the toy the model is of (another toy: every frame is wrong)
    long budget = 0;           //!< evaluations per frame
    std::uint64_t seed = 0;    //!< RM-GA's seed
    double steady = 1.0;       //!< the fraction of the budget on steady frames
    bool stereo = false;       //!< the stereo photo-model instead of the flat one
  };
  std::vector<Run> runs;       //!< the runs, in order
  std::string distractor;      //!< a look-alike beside the toy (empty: none), swaying 40 mm sideways at 0.2 Hz
  std::string rig;             //!< a rig file under the data folder instead of the default rig (e.g. one with a lens)
  bool strand = false;         //!< pm-servo's strand of seaweed (22 mm wide) in front of the toy on every frame, instead of pm-compare's passing one
  /*!
    Another camera's images (sim::imageVariation()'s preset names, comma-separated; empty: the
    renderer's): the scene is filmed through it, and each run's model is made through it too (the
    model's photos or pass are taken by the same camera, as they would be).
  */
  std::string variation;
};

/*!
  The study's scenes and runs (\e quick: two runs on C12 only, for tests), and for each name of
  \e variations (sim::imageVariation()'s presets) the crab and the head through that camera, one
  run each.
*/
std::vector<ConfidencePass> confidencePasses(bool quick, const std::vector<std::string> &variations = {});

//! What the study runs.
struct ConfidenceStudyParams
{
  std::vector<std::string> scenarios = scenarioNames(); //!< pm-compare's scenarios
  std::string trajectoryPath;  //!< table2's waypoints
  int steps = 0;               //!< table2: only the first N steps (0: all)
  bool quick = false;          //!< confidencePasses(true)
  bool allAround = false;      //!< every run's model is the all-around one
  bool stereo = false;         //!< every run's model is the stereo one (unless allAround)
  bool precise = true;         //!< the tracker's precise stage (tracker::PreciseRefinementParams::enabled; all-around models only)
  std::string dataDir;         //!< where a pass's rig file is found
  std::vector<std::string> variations; //!< other cameras' images, one pass of C12 and one of R2 each (confidencePasses())
};

//! The labelled set: one frame per scenario frame and run.
struct ConfidenceStudy
{
  std::vector<LabelledFrame> frames;  //!< the labelled frames
  std::vector<std::string> runNames;  //!< every run, over all passes
  std::vector<std::size_t> runOf;     //!< each frame's index in runNames
  std::vector<std::string> runVariation; //!< each run's camera (ConfidencePass::variation; empty: the renderer's)
};

/*!
  Renders and tracks the study (each pass's scene once per scenario frame, tracked by each of its
  runs; \e onFrame after each). \e rig: the default rig. Throws pm::core::Error.

  \code
    pm::compare::ConfidenceStudyParams p;
    p.quick = true;
    p.trajectoryPath = "data/trajectories/table2.csv";
    p.dataDir = "data";
    const pm::compare::ConfidenceStudy s = pm::compare::runConfidenceStudy(rig, p);
    const pm::compare::ConfidenceReport r = pm::compare::reportConfidence(s, 0.001, 0.95);
    std::cout << "AUROC " << r.auroc << "\n";
  \endcode
*/
ConfidenceStudy runConfidenceStudy(const core::StereoRig &rig, const ConfidenceStudyParams &params, const std::function<void()> &onFrame = {});

//! The study's figures (see ConfidenceStudy.h).
struct ConfidenceReport
{
  std::size_t frames = 0;             //!< labelled frames
  std::size_t wrong = 0;              //!< the wrong ones among them
  std::size_t trackingWrong = 0;      //!< wrong frames the tracker claimed to track
  std::size_t trustedWrong = 0;       //!< wrong frames it trusted
  std::size_t trustedRight = 0;       //!< right frames it trusted
  std::vector<RocPoint> curve;        //!< the ROC of the confidence
  double auroc = 0;                   //!< its area
  double aurocTracking = 1;           //!< the area among the frames in the Tracking state (1 when they are all right or all wrong)
  double threshold = 0;               //!< the tracker's confidence threshold
  RocPoint atMaxFalseAccept;          //!< the lowest threshold whose false accept rate is at most the one asked
  double trueAcceptRate() const;      //!< trusted right / right
  double falseAcceptRate() const;     //!< trusted wrong / wrong
  //! Per run: frames, wrong frames, trusted wrong, trusted right.
  std::vector<std::array<std::size_t, 4>> perRun;
};

//! The report of \e study at the tracker's \e threshold, and the threshold for \e maxFalseAccept.
ConfidenceReport reportConfidence(const ConfidenceStudy &study, double maxFalseAccept, double threshold);

//! The frames as pm-confidence's frames.csv: run, scenario, frame, state, the cues' features, confidence, trusted, errors, right.
void writeConfidenceCsv(std::ostream &csv, const ConfidenceStudy &study);

} // namespace pm::compare
