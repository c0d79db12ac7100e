#pragma once
/*!
  \file Scene.h
  The simulated lab scene: a 3-D toy resting on a sea-bottom panel (both in the target frame),
  an optional occluder in front of it, seen by the stereo rig on the hand with per-pixel
  sensor noise and an exposure (brightness) change.

  Two lightings: the hand light (lightDirHand: a lamp on the rig, moving with the cameras; no
  shadows), the default for the 12 sea creatures; and the scene light (sceneLightDir: a lamp
  fixed in the target frame, off the cameras) with cast shadows of the toy on the backdrop and on
  itself (a ShadowMap of the toy, built once per scene) and a stronger gloss on the toy, the
  default for the relief targets R1..R3 (ShadowMode::Auto). Rendering is deterministic: the noise of
  an image is a function of (seed, frame, camera).
*/
#include <cstdint>
#include <memory>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/StereoRig.h"
#include "pm/sim/Rasterizer.h"
#include "pm/sim/SeaBottom.h"
#include "pm/sim/ShadowMap.h"
#include "pm/sim/TargetShape.h"

namespace pm::sim {

//! Which light a scene uses: see SceneParams::shadows.
enum class ShadowMode
{
  Auto, //!< On for the relief targets (R1..R3), Off for the others
  Off,  //!< the hand light, no shadows (the images of the 12 sea creatures, unchanged)
  On    //!< the scene light with cast shadows and the scene gloss
};

//! Everything that sets how a scene looks; validate() checks the ranges.
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
  /*!
    On: the scene light (sceneLightDir, fixed in the target frame) replaces the hand light and
    the toy casts shadows (where hidden from it a surface gets the ambient term only), and the toy
    shines with sceneSpecular / sceneShininess instead of specular.
  */
  ShadowMode shadows = ShadowMode::Auto;
  //! Toward the scene light, target frame: upper left, in front, 40 deg off the view axis (-z).
  double sceneLightDir[3] = {-0.59341, -0.59341, -1.0};
  double sceneSpecular = 0.35;              //!< the toy's specular strength under the scene light
  double sceneShininess = 40;               //!< its Blinn-Phong exponent under the scene light
  double shadowTexelMm = 0.35;              //!< shadow-map texel (across the light)
  /*!
    A look-alike in view (Scene::setDistractor gives its shape): drawn when on, at this pose of
    its own frame in the target frame (x, y, z mm, eps1, eps2, eps3; beside the toy on the same
    backdrop by default), lit like the toy. A scenario moves it by changing the pose per frame.
  */
  bool distractor = false;
  double distractorPose[6] = {-190, 0, 0, 0, 0, 0};

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
    A camera with lens distortion sees through it: the scene is rendered in an ideal image large
    enough to hold the whole raw one, resampled into the raw image (bilinear, through a map
    computed once per camera and kept), then the sensor noise is added.
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

  /*!
    The look-alike's shape (a second toy: the same kind as the target, or another of similar hue);
    it is drawn while params().distractor is on. Throws pm::Error if the shape is invalid.
  */
  void setDistractor(const TargetShape &shape);
  bool hasDistractor() const { return !m_distractor.triangles.empty(); }

  //! True if this scene is lit by the scene light with shadows (params().shadows, Auto resolved).
  bool sceneLit() const;
  /*!
    The shadow map of the toy for the current params() (built on first use and whenever the scene
    light changed; thread-safe).
  */
  std::shared_ptr<const ShadowMap> shadowMap() const;

  const TargetShape &target() const { return m_target; }
  const SceneParams &params() const { return m_params; }
  SceneParams &params() { return m_params; }
  std::size_t targetTriangles() const { return m_toy.triangles.size(); }

private:
  TargetShape m_target;
  SceneParams m_params;
  Mesh m_toy, m_backdrop, m_occluder, m_distractor;
  struct ShadowCache;
  std::shared_ptr<ShadowCache> m_shadowCache; // shared by copies; the map is rebuilt if the light changed
  struct LensCache;
  std::shared_ptr<LensCache> m_lensCache; // the distorted cameras' resampling maps, shared by copies
  void renderIdeal(Rasterizer &raster, const RigCamera &camera, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
                   unsigned stream, vpImage<vpRGBa> &out, bool withTarget, double noiseSigma) const;
};

} // namespace pm::sim
