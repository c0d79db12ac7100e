// The usage example of modules/tracker/include/pm/tracker/TrackerParams.h, a whole program (compiled, never linked).
#include <pm/io/PhotoModelFile.h>
#include <pm/io/RigFile.h>
#include <pm/tracker/PhotoModelTracker.h>

int main()
{
  pm::tracker::TrackerParams params;            // the measured defaults
  params.search.budgetEvaluations = 0;          // a wall-time budget instead of evaluations:
  params.search.budgetMs = 30;                  // 30 ms of search a frame
  params.search.ga.seed = 7;                    // another random sequence
  params.judgement.confidence.threshold = 0.99; // trust fewer frames
  params.validate();                            // throws pm::core::Error naming the first value out of range
  pm::tracker::PhotoModelTracker tracker(pm::io::loadRig("rig.json"), pm::io::loadPhotoModel("model.json"), params);
}
