#pragma once
/*!
  \file BackgroundLearning.h
  The background's hue as the tracker sees it now, learnt on trusted frames. The
  photo-model carries the hue of the background it was photographed on (H_B, the fitness's S_out
  test); the world's changes: another light's colour, a target carried in front of another wall, a
  backdrop that turns as the hand moves. On each trusted frame the image hues under the S_out
  points at the trusted pose, in both cameras, that lie within \e windowDeg of the hue used now are
  the background's (the rest are the target, an occluder, a neighbour: left out); their circular
  mean moves the learnt hue by \e rate of the difference. The fitness (and the precise stage's
  hidden lines) take the learnt hue once it is \e switchDeg away from the one they use: on a
  background that does not change, nothing does.

  \code
    pm::tracker::BackgroundLearning bg(params.background, scorer);
    // after each frame's judgement:
    if (const std::optional<double> hue = bg.learn(frame, result.phi, result.trusted))
      frame.setBackgroundHue(*hue);
  \endcode
*/
#include <optional>
#include <vector>

#include "pm/core/Pose.h"
#include "pm/core/StereoScorer.h"

namespace pm::tracker {

//! How the background's hue is learnt (see BackgroundLearning.h); validate() checks it.
struct BackgroundParams
{
  bool learn = true;       //!< learn it on trusted frames (false: the model's hue for good)
  double rate = 0.1;       //!< the share of a trusted frame's background hue in the learnt one, in (0, 1]
  double windowDeg = 30;   //!< S_out hues within this of the hue used now are the background's (deg)
  double switchDeg = 5;    //!< the scoring takes the learnt hue once it is this far from the one it uses (deg)
  int minSamples = 20;     //!< a frame with fewer background hues teaches nothing

  //! Throws core::Error naming the first parameter out of range.
  void validate() const;
};

//! The learnt background hue (see BackgroundLearning.h). Keeps a reference to the scorer: it must outlive it.
class BackgroundLearning
{
public:
  //! Starts from the model's hue (\e scorer's).
  BackgroundLearning(const BackgroundParams &params, const core::StereoScorer &scorer);

  /*!
    One frame: when \e trusted, the background hues of \e frame under the S_out points at \e phi teach the
    learnt hue. Returns the hue the scoring should use from now on when it changed (deg, [0, 360)).
    Allocates nothing.
  */
  std::optional<double> learn(const core::HueFrame &frame, const core::Phi &phi, bool trusted);
  //! Back to the model's hue (returned, for the scoring).
  double reset();
  double learntDeg() const { return m_learnt; } //!< the learnt hue (deg)
  double usedDeg() const { return m_used; }     //!< the hue the scoring uses (deg)
  double modelDeg() const { return m_model; }   //!< the model's own (deg)

private:
  BackgroundParams m_p;
  const core::StereoScorer &m_scorer;
  double m_model, m_learnt, m_used;
  std::vector<float> m_hues; //!< one camera's S_out hues (sized once)
};

} // namespace pm::tracker
