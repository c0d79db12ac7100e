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
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/CameraRig.h"
#include "pm/core/StereoRig.h"
#include "pm/sim/Gripper.h"
#include "pm/sim/ImageVariation.h"
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
  //! Ambient term of the lighting (fraction of the surface colour, everywhere).
  double ambient = 0.5, diffuse = 0.6; //!< strength of the diffuse (Lambert) term
  double specular = 0.12;                   //!< gloss of the toy's plastic
  double meshStepMm = 1.0;                  //!< vertex spacing of the toy's mesh
  double backdropGapMm = 0.5;               //!< backdrop behind the toy's base
  SeaBottomParams seaBottom;                //!< the backdrop panel (size, texel, seed)
  bool occluder = false;                    //!< a strand of seaweed in front of the toy
  double occluderCentreMm[3] = {25, 0, -70};//!< its centre in the target frame
  double occluderSizeMm[2] = {22, 260};     //!< its width and height
  /*!
    A violet bar, 300 mm tall, that sweeps to and fro across the front of the toy along the target
    frame's x (Scene::barOffsetMm(): its offset at a frame, from the frame number); drawn as an
    occluder (id 3).
  */
  bool sweepingBar = false;
  double barDepthMm = -100;   //!< its plane in the target frame (z; negative: in front of the toy)
  double barWidthMm = 60;     //!< its width (mm)
  double barTravelMm = 500;   //!< the span it sweeps, centred on the target (mm)
  double barMmPerFrame = 4;   //!< its speed (mm a frame: 120 mm/s at 30 frames a second)
  /*!
    A backdrop that stands still in the world while the target moves in front of it: the panel
    stands stillBackdropGapMm farther behind the toy's base (the pass and the photos see both at
    rest), and the scenarios (lab::ClosedLoop, lab::LabSequence) give render() its pose in the
    target frame each frame, so that the background slides behind the target's outline as the
    target and the hand move (the toy casts no shadow on it). Off: the toy rests on its panel,
    which moves with it. It may be turned on or off between renders (pm-compare's scenarios).
  */
  bool stillBackdrop = false;
  double stillBackdropGapMm = 50; //!< how much farther behind the toy's base the still panel stands (mm)
  /*!
    A background that changes: the backdrop's colours turn about the grey axis by this many degrees
    a second of the lab's frames (render()'s frame number over kLabFramesPerSecond), as a light's
    colour or a slowly changing background would turn its hue. The model's pass and photos see it
    as it was (targetAlone()); the tracker sees the background's hue drift away from the photos'.
    0: the renderer's images, bit for bit.
  */
  double backdropHueDriftDegPerS = 0;
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
  double distractorPose[6] = {-190, 0, 0, 0, 0, 0}; //!< the look-alike's pose in the target frame (x, y, z mm, eps1..3)
  /*!
    Clutter: three other toys of the catalogue around the target (sim::clutterAround(): one of
    similar hue, a green and a blue one), standing on the backdrop and moving with it (still with a
    still backdrop), lit like the toy. Their meshes are built by the constructor when this is on
    (turning it on afterwards draws nothing).
  */
  bool clutter = false;
  /*!
    A parallel gripper's two fingers on the hand (sim::makeGripperMesh()), fixed in the hand frame
    below the rig, entering the bottom of both images: the end of a grasp approach, where they hide
    the lower part of a target 300 to 350 mm ahead. Drawn as an occluder (id 3).
  */
  bool gripper = false;
  GripperParams gripperShape; //!< the fingers' shape and place on the hand
  /*!
    Another camera's images (ImageVariation.h: defocus, motion blur, vignetting, shot noise, white
    balance, gamma, JPEG); none by default: the renderer's own images, bit for bit.
  */
  ImageVariation variation;

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

//! The two images of one frame of the stereo rig (Scene::renderStereo()).
struct StereoImages
{
  //! The left camera's image.
  vpImage<vpRGBa> left, right; //!< the right camera's image
};

//! The lab's frame rate (frames a second): render()'s frame number over it is the scene's time.
constexpr double kLabFramesPerSecond = 30;

/*!
  The simulated lab scene of one target (see Scene.h): renders what the rig's cameras see for a
  pose hMo of the target frame in the hand frame. A scene owns copies of the target and of its
  meshes; copies of a scene share its shadow-map and lens caches. render() may run in several
  threads at once, each with its own Rasterizer (renderStereo() does so), while params() is not changed.
  \code
  pm::sim::SceneParams sp;
  sp.exposure = 0.8;                                     // a darker lab
  const pm::sim::Scene scene(pm::sim::makeTarget("C12"), sp); // the crab
  const vpCameraParameters cam(800, 800, 320, 240);
  const pm::core::StereoRig rig = pm::core::StereoRig::symmetric(cam, 640, 480, 0.12, pm::core::StereoRig::toeInFor(0.12, 0.5));
  const vpHomogeneousMatrix hMo = pm::core::toHomogeneousMatrix(pm::core::Phi{0, 0, 500, 0, 0, 0}); // 500 mm ahead
  for (std::uint64_t frame = 0; frame < 30; ++frame) {
    const pm::sim::StereoImages im = scene.renderStereo(rig, hMo, frame);
    // im.left, im.right: what the two cameras see
  }
  \endcode
*/
class Scene
{
public:
  /*!
    Builds the meshes of the toy (every params.meshStepMm), of the backdrop (params.backdropGapMm
    behind the toy's base), of the occluder, of the gripper's fingers and of the clutter (when
    params.clutter is on). Throws pm::core::Error for a parameter out of range or a target whose
    grids do not match.
  */
  Scene(const TargetShape &target, const SceneParams &params = SceneParams());

  /*!
    Renders what \e camera sees with the target at hMo (pose of the target frame in the hand
    frame); \e stream distinguishes images of the same frame (0 left, 1 right, 2+ others).
    A camera with lens distortion sees through it: the scene is rendered in an ideal image large
    enough to hold the whole raw one, resampled into the raw image (bilinear, through a map
    computed once per camera and kept), then the sensor noise is added. \e withTarget false: the
    backdrop alone (no toy, no shadow of it). Afterwards \e raster's coverage() and depthAt() tell the
    objects apart by id (1 backdrop, 2 toy, 3 occluder: the strand, the bar or the gripper's fingers, 4 look-alike or
    clutter); for a distorted camera they
    hold the larger ideal canvas, not \e out. \e oMb: the backdrop's pose in the target frame (the
    identity: where it rests behind the toy; SceneParams::stillBackdrop), the toy's shadow left off
    it when it is elsewhere or still. Throws pm::core::Error (see Rasterizer::render()).
  */
  void render(Rasterizer &raster, const core::PinholeCamera &camera, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
              unsigned stream, vpImage<vpRGBa> &out, bool withTarget = true, const vpHomogeneousMatrix &oMb = vpHomogeneousMatrix()) const;
  /*!
    Every camera's view for the target at \e hMo, camera k's image k (rendered in parallel, stream k of
    \e frame), the backdrop at \e oMb (render()): a stereo rig's two are renderStereo()'s. Throws
    pm::core::Error for an invalid rig (CameraRig::validate()) or as render().
  */
  std::vector<vpImage<vpRGBa>> renderRig(const core::CameraRig &rig, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
                                         const vpHomogeneousMatrix &oMb = vpHomogeneousMatrix()) const;
  //! Both views of the rig for the target at \e hMo (rendered in parallel, streams 0 and 1 of \e frame), the backdrop at \e oMb (render()).
  StereoImages renderStereo(const core::StereoRig &rig, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
                            const vpHomogeneousMatrix &oMb = vpHomogeneousMatrix()) const;
  /*!
    The two photos of the paper's Fig. 4, taken by one camera (the \e cam intrinsics, w x h)
    looking straight at the target from \e distanceMm: (a) the backdrop alone, (b) with the toy.
    Throws pm::core::Error unless \e distanceMm > 0.
  */
  void renderPhotos(const vpCameraParameters &cam, unsigned w, unsigned h, double distanceMm, vpImage<vpRGBa> &background,
                    vpImage<vpRGBa> &withTarget) const;

  /*!
    The look-alike's shape (a second toy: the same kind as the target, or another of similar hue);
    it is drawn while params().distractor is on. Throws pm::core::Error if the shape is invalid.
  */
  void setDistractor(const TargetShape &shape);
  bool hasDistractor() const { return !m_distractor.triangles.empty(); } //!< true once setDistractor() gave a shape
  bool hasClutter() const { return !m_clutter.empty(); } //!< true if made with SceneParams::clutter on (its toys can be drawn)
  //! The sweeping bar's offset along the target frame's x at \e frame (mm; SceneParams::sweepingBar).
  double barOffsetMm(std::uint64_t frame) const;

  //! True if this scene is lit by the scene light with shadows (params().shadows, Auto resolved).
  bool sceneLit() const;
  /*!
    The shadow map of the toy for the current params() (built on first use and whenever the scene
    light changed; thread-safe).
  */
  std::shared_ptr<const ShadowMap> shadowMap() const;

  /*!
    A copy of this scene with the target alone on its backdrop: no look-alike, clutter, strand, bar
    or gripper, the backdrop's colours as they were at the start (the all-around pass and the
    model's photos: a user photographs the target alone).
  */
  Scene targetAlone() const;

  const TargetShape &target() const { return m_target; } //!< the target (the scene's own copy)
  const SceneParams &params() const { return m_params; }  //!< the parameters
  /*!
    The parameters, to change between renders (exposure, noise, lights, shadows, occluder on or
    off, the look-alike's pose...). Not validated here. The meshes were built by the constructor:
    changing meshStepMm, specular, backdropGapMm, stillBackdropGapMm, seaBottom, occluderCentreMm, occluderSizeMm or
    gripperShape
    afterwards has no effect on them (setDistractor() uses the meshStepMm and specular of its call).
  */
  SceneParams &params() { return m_params; }
  std::size_t targetTriangles() const { return m_toy.triangles.size(); } //!< triangles in the toy's mesh

private:
  TargetShape m_target;
  SceneParams m_params;
  double m_stillGapMm; //!< the still panel's gap the meshes were built with (SceneParams::stillBackdropGapMm)
  //! A flat textured quad facing the hand, centred at (x, y, z) of the target frame (mm).
  static Mesh makeFlatQuad(double xMm, double yMm, double zMm, double widthMm, double heightMm, int r, int g, int b);
  Mesh m_toy, m_backdrop, m_stillBackdrop, m_occluder, m_distractor, m_bar, m_gripper;
  //! The clutter's toys (SceneParams::clutter) and their poses on the panel the toy rests on (on the still one: its gap farther).
  struct ClutterMesh
  {
    Mesh mesh;
    vpHomogeneousMatrix oMn;
  };
  std::vector<ClutterMesh> m_clutter;
  struct ShadowCache;
  std::shared_ptr<ShadowCache> m_shadowCache; // shared by copies; the map is rebuilt if the light changed
  struct LensCache;
  std::shared_ptr<LensCache> m_lensCache; // the distorted cameras' resampling maps, shared by copies
  //! The backdrop's pixels of \e image (the raster's last render) turned in hue for \e frame (SceneParams::backdropHueDriftDegPerS).
  void driftBackdropHue(const Rasterizer &raster, std::uint64_t frame, vpImage<vpRGBa> &image) const;
  void renderIdeal(Rasterizer &raster, const core::PinholeCamera &camera, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
                   unsigned stream, vpImage<vpRGBa> &out, bool withTarget, double noiseSigma, const vpHomogeneousMatrix &oMb) const;
};

} // namespace pm::sim
