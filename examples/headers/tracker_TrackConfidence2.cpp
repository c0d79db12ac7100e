// The usage example of modules/tracker/include/pm/tracker/TrackConfidence.h, a whole program (compiled, never linked).
#include <iostream>
#include <pm/tracker/TrackConfidence.h>

int main()
{
  pm::tracker::ConfidenceCues cues; // in a program: TrackResult::cues of the frame
  cues.quality = 0.6;
  cues.qualityMin = 0.55;
  cues.inMatchMin = 0.8;
  cues.outBackgroundMin = 0.9;
  cues.competitorMargin = 0.2;
  cues.framesTracked = 30;
  cues.verified = true;
  cues.tracking = true;
  const pm::tracker::ConfidenceModel m; // the shipped coefficients
  const double c = m.confidence(cues);
  std::cout << "confidence " << c << (c >= m.threshold ? ": trusted" : ": not trusted") << "\n";
}
