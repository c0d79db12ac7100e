#pragma once
/*!
  \file Scene.h
  The simulated lab scene: a 3-D toy resting on a sea-bottom panel (both in the target frame),
  an optional occluder in front of it, seen by the stereo rig on the hand with per-pixel
  sensor noise and an exposure (brightness) change. Rendering is deterministic: the noise of
  an image is a function of (seed, frame, camera).
*/
#include <cstdint>
#include <memory>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/StereoRig.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/SeaBottom.h"
#include "pm/sim/TargetShape.h"

namespace pm::sim {

struct SceneParams
{
  unsigned supersampling = 2;               //!< SSxSS samples per pixel (anti-aliasing)
  double noiseSigma = 2.0;                  //!< sensor noise, grey levels per channel
  double exposure = 1.0;                    //!< global gain: the brightness / lighting change
  double lightDirHand[3] = {-0.35, -0.6, -1.0}; //!< toward the light, hand frame (upper left, in front)
  double ambient = 0.5, diffuse = 0.6;
  double specular = 0.12;                   //!< gloss of the toy's plastic
  double meshStepMm = 1.0;                  //!< vertex spacing of the toy's mesh
  double backdropGapMm = 0.5;               //!< backdrop behind the toy's base
  SeaBottomParams seaBottom;
  bool occluder = false;                    //!< a strand of seaweed in front of the toy
  double occluderCentreMm[3] = {25, 0, -70};//!< its centre in the target frame
  double occluderSizeMm[2] = {22, 260};     //!< its width and height
  std::uint64_t seed = 1;                   //!< noise seed

  //! Throws pm::Error naming the first parameter out of range.
  void validate() const;
};

struct StereoImages
{
  vpImage<vpRGBa> left, right;
};

class Scene
{
public:
  Scene(const TargetShape &target, const SceneParams &params = SceneParams());

  /*!
    Renders what \e camera sees with the target at hMo (pose of the target frame in the hand
    frame); \e stream distinguishes images of the same frame (0 left, 1 right, 2+ others).
  */
  void render(Rasterizer &raster, const RigCamera &camera, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
              unsigned stream, vpImage<vpRGBa> &out, bool withTarget = true) const;
  //! Both views of the rig (rendered in parallel).
  StereoImages renderStereo(const StereoRig &rig, const vpHomogeneousMatrix &hMo, std::uint64_t frame) const;
  /*!
    The two photos of the paper's Fig. 4, taken by one camera (the \e cam intrinsics, w x h)
    looking straight at the target from \e distanceMm: (a) the backdrop alone, (b) with the toy.
  */
  void renderPhotos(const vpCameraParameters &cam, unsigned w, unsigned h, double distanceMm, vpImage<vpRGBa> &background,
                    vpImage<vpRGBa> &withTarget) const;

  const TargetShape &target() const { return m_target; }
  const SceneParams &params() const { return m_params; }
  SceneParams &params() { return m_params; }
  std::size_t targetTriangles() const { return m_toy.triangles.size(); }

private:
  TargetShape m_target;
  SceneParams m_params;
  Mesh m_toy, m_backdrop, m_occluder;
};

} // namespace pm::sim
