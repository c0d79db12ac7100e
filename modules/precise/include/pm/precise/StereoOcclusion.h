#pragma once
/*!
  \file StereoOcclusion.h
  Which correspondence lines are hidden: what a stereo rig sees of what stands in front of the
  target (the fitness's stereo visibility, core::FitnessParams::stereoVisibility, for the
  precise stage's lines). A line of camera k starts at a contour point X of the model; just inside
  the outline, at a few probe points X - d n (n the outline's outward normal, d a few pixels at X's
  depth), lies the target's volume, which both cameras see as the target wherever nothing hides it
  (a point inside a solid projects inside its silhouette from anywhere). A probe is hidden in camera
  k when camera k sees there a hue that is neither one of the target's own (core::TargetHues: a miss
  on the target's colours is a wrong pose) nor the background's (a miss on the background is a
  wrong pose too), while the other camera, at the probe's own projection, sees one of the target's
  hues, and sees that same hue somewhere in front of the probe on camera k's ray through it (the
  stereo depth of what camera k sees: something in front of the model, not a wrong pose's view of
  what lies beside or behind the target). The fitness's stereo visibility
  (core::FitnessParams::stereoVisibility) has the same rule without the depth: there it made RM-GA
  lose the crab behind the strand (docs/occlusion.md). A line is hidden when most of its probes
  are; a camera's hidden lines leave the precise stage's objective, its colour learning and its cues (residual, separation), unless they are more
  than maxHiddenShare of its lines, when all are kept (as DLR's M3T brings its lines back when too
  few remain).

  \code
      pm::precise::StereoOcclusion occlusion(model, pm::precise::StereoOcclusionParams());
      const bool h = occlusion.hidden(left, leftPose, leftCentre, right, rightPose, contourPoint, pxPerMm);
  \endcode
*/
#include <cmath>
#include <array>

#include "pm/core/PhotoModel.h"
#include "pm/core/PinholeCamera.h"
#include "pm/core/TargetHues.h"

namespace pm::precise {

struct LineCamera;

//! The hidden lines' test (StereoOcclusion.h) and its rule's parameters.
struct StereoOcclusionParams
{
  bool enabled = true;                  //!< look for hidden lines at all (off: every line counts)
  double maxHiddenShare = 0.5;          //!< a camera with more of its lines hidden keeps them all
  double backgroundTolDeg = 30;         //!< a hue within this of the model's background hue is the background's (deg; the fitness's inBgTolDeg)
  float minSaturation = 0.f;            //!< pixels less saturated have no hue (the fitness's minSaturation)
  std::array<double, 3> probesPx{3, 6, 9}; //!< the probes' distances inside the outline (px at the point's depth; at most 0.8 of the target's extent there)
  double frontMinMm = 10;               //!< an occluder stands at least this far in front of the model's surface (mm) ...
  double frontMaxMm = 300;              //!< ... and at most this far (mm)
  double frontStepMm = 5;               //!< camera k's ray is searched in the other camera at this step (mm)
  double sameHueDeg = 15;               //!< the two cameras see the occluder's hue within this (deg)
  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

//! The model in a camera's frame: cMo, R row-major and t (mm).
struct ModelInCamera
{
  double R[9]; //!< cMo's rotation, row-major
  double t[3]; //!< cMo's translation (mm)
};

/*!
  The test of StereoOcclusion.h for one line at a time. Copyable; hidden() allocates nothing.
  \code
  const pm::precise::StereoOcclusion occlusion(model, pm::precise::StereoOcclusionParams());
  // cams[k]: the rig's cameras as the lines see them; poses[k]: the model in each camera's frame;
  // centre: the left camera's centre in the model frame (precise::cameraInModel)
  if (occlusion.hidden(cams[0], poses[0], centre, cams[1], poses[1], model.contour[i], cams[0].px / depthMm))
    std::cout << "contour point " << i << " is hidden in the left camera\n";
  \endcode
*/
class StereoOcclusion
{
public:
  //! Throws pm::core::Error for parameters out of range.
  StereoOcclusion(const core::PhotoModel &model, const StereoOcclusionParams &params);
  //! The background's hue a probe is compared with (deg, [0, 360)): the model's until set (tracker::BackgroundLearning).
  void setBackgroundHue(double deg) { m_backgroundHue = std::lround(deg * 10.0) % 3600; }
  /*!
    Whether the target just inside contour point \e q is hidden in camera \e self (the model at
    \e selfPose, its centre at \e selfCentre in the model frame, mm) and seen by camera \e other (at
    \e otherPose); \e pxPerMm: \e self's pixels per mm at the point's depth.
  */
  bool hidden(const LineCamera &self, const ModelInCamera &selfPose, const double selfCentre[3], const LineCamera &other,
              const ModelInCamera &otherPose, const core::ContourPoint &q, double pxPerMm) const;
  /*!
    Whether model point \e X (mm, model frame; on the target's surface or inside it) is hidden in
    camera \e self and seen by \e other, by the rule of StereoOcclusion.h (a probe's).
  */
  bool pointHidden(const LineCamera &self, const ModelInCamera &selfPose, const double selfCentre[3], const LineCamera &other,
                   const ModelInCamera &otherPose, const double X[3]) const;
  const StereoOcclusionParams &params() const { return m_params; } //!< the parameters

private:
  //! The hue (HuePlane's tenths of a degree or kNoHue) under model point \e X in camera \e cam, or -1 off its image.
  long hueUnder(const LineCamera &cam, const ModelInCamera &pose, const double X[3]) const;
  //! Whether camera \e other sees hue \e h somewhere on the ray from \e X toward \e centre, frontMinMm to frontMaxMm in front of X.
  bool seenInFront(long h, const double X[3], const double centre[3], const LineCamera &other, const ModelInCamera &otherPose) const;
  bool sameHue(long a, long b) const; //!< hues (or no hue) within sameHueDeg
  StereoOcclusionParams m_params;
  core::TargetHues m_targetHues;
  long m_backgroundHue = 0, m_backgroundTol = 0, m_sameHueTol = 0; //!< tenths of a degree
};

} // namespace pm::precise
