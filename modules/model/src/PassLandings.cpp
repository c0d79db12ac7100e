#include "pm/model/PassLandings.h"

#include <cmath>

#include <visp3/core/vpThetaUVector.h>

#include "pm/core/Error.h"
#include "pm/core/Pose.h"
#include "pm/precise/PreciseStage.h"

namespace pm::model {

namespace {
constexpr double kMaxOffsetMm = 20;  //!< a landing farther than this on an axis (mm) ...
constexpr double kMaxOffsetDeg = 10; //!< ... or turned more (deg) is not kept
} // namespace

std::vector<core::PassLanding> measurePassLandings(const core::StereoRig &rig, const core::PhotoModel &model,
                                                   const std::vector<PassView> &pass, const std::vector<bool> &used,
                                                   const vpHomogeneousMatrix &fMm)
{
  if (!model.hasContours())
    throw core::Error("pass landings: the model has no outlines (an all-around model has)");
  if (used.size() != pass.size())
    throw core::Error("pass landings: " + std::to_string(used.size()) + " flags for " + std::to_string(pass.size()) + " views");
  precise::PreciseStage stage(rig, model);
  std::vector<core::PassLanding> out;
  for (std::size_t v = 0; v < pass.size(); ++v) {
    if (!used[v])
      continue;
    const vpHomogeneousMatrix hMm = pass[v].fMh.inverse() * fMm; // the model's true pose in the view's hand frame
    stage.setImages({pass[v].left, pass[v].right});
    const precise::PreciseResult r = stage.refine(core::fromHomogeneousMatrix(hMm), true);
    if (!r.ok)
      continue;
    const vpHomogeneousMatrix hMe = core::toHomogeneousMatrix(r.phi);
    // The offsets in the hand frame, turned into the model frame's axes (so that another view near
    // this one, with the hand turned otherwise about it, reads them in its own hand frame).
    const vpRotationMatrix hRm = hMm.getRotationMatrix(), mRh = hRm.t();
    const vpThetaUVector turn(vpRotationMatrix(hMe.getRotationMatrix() * hRm.t()));
    vpColVector dt(3), dw(3);
    for (unsigned i = 0; i < 3; ++i) {
      dt[i] = 1e3 * (hMe[i][3] - hMm[i][3]);
      dw[i] = vpMath::deg(turn[i]);
    }
    const vpColVector mt = mRh * dt, mw = mRh * dw;
    const vpHomogeneousMatrix mMc = hMm.inverse() * rig.left.hMc;
    core::PassLanding l;
    bool near = true;
    for (unsigned i = 0; i < 3; ++i) {
      l.cameraMm[i] = 1e3 * mMc[i][3];
      l.offsetMm[i] = mt[i];
      l.offsetDeg[i] = mw[i];
      near = near && std::fabs(mt[i]) <= kMaxOffsetMm && std::fabs(mw[i]) <= kMaxOffsetDeg;
    }
    if (near) // farther, the stage went elsewhere (a view it cannot read), not the model's error
      out.push_back(l);
  }
  return out;
}

} // namespace pm::model
