#pragma once
/*!
  \file StereoScorer.h
  The stereo fitness of the paper (Eqs. 8-11): the photo-model placed at a candidate pose phi
  is projected into the left and right images (into each camera's image on a rig of one camera or
  more: CameraRig.h), and each model point scores by the image hue where it lands:

      S_in :  p_in  = +2      if |H_I - H_M(i)| <= 30   (the model overlaps the target)
                    = -0.005  else if |H_B - H_I| <= 30 (the model lies on background)
                    =  0      otherwise
      S_out:  p_out = +0.1    if |H_B - H_I| <= 20      (the strip lies on background)
                    = -0.5    otherwise                 (the strip lies on the target)
      F_L = (sum of p over S_in and S_out) / n,  F = (F_L + F_R) / 2
      (on a rig of N cameras, F the mean of the N cameras' scores; one camera: F = F_0)

  Hue distances wrap around the circle; a point projected off the image (or behind the camera)
  scores \e offImage (0). A model point is (x, y, z) in the model frame: z = 0 for the paper's
  flat model (then the kernels run exactly the flat operations), the relief for a stereo model. Tolerances and scores are parameters with the paper's defaults.

  Each point is counted into its class and F is made from the integer counts, so the result is
  exact and identical whatever the instruction set (AVX2 or scalar) and the order of points.
  A camera with lens distortion is read through its ideal (pinhole) image: setImages() resamples
  each hue plane through the camera's UndistortMap (one gather per pixel, about 0.3 ms a frame for
  both 640x480 cameras) and the kernels project as for a pinhole, at the same cost; a pinhole rig
  runs exactly as before. (The other way, distorting each projected point in the kernels, would
  cost per point and per evaluation: see pm-bench Distortion_*.)
  evaluate() is const and thread-safe, allocates nothing, and refuses an invalid phi
  (|eps| > 1 or not finite) with pm::core::Error: it never returns NaN.

  The fitness is two things: the scorer (StereoScorer), made once for a model on a rig and never
  changed after, and the frame it scores (HueFrame: the pair's hue planes and the background's hue
  in use), passed to every score. A part of a program that scores poses keeps the scorer and is
  given the frame; StereoFitness (StereoFitness.h) holds one of each for a program that scores
  one pair at a time.
*/
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/HueFrame.h"
#include "pm/core/CameraRig.h"
#include "pm/core/HuePlane.h"
#include "pm/core/PhotoModel.h"
#include "pm/core/Pose.h"
#include "pm/core/StereoRig.h"
#include "pm/core/TargetHues.h"
#include "pm/core/UndistortMap.h"
#include "pm/core/ViewpointIndex.h"

namespace pm::core {

/*!
  The tolerances and scores of the fitness (Eqs. 8, 9; see StereoScorer.h), with the paper's
  defaults. Tolerances are hue distances in degrees, in [0, 180], used to a tenth of a degree.
*/
struct FitnessParams
{
  double inTolDeg = 30;      //!< |H_I - H_M(i)| tolerance of S_in (deg)
  double inBgTolDeg = 30;    //!< |H_B - H_I| tolerance of S_in's background case (deg)
  double outBgTolDeg = 20;   //!< |H_B - H_I| tolerance of S_out (deg)
  double inMatch = 2.0;      //!< p_in when the model overlaps the target
  double inBackground = -0.005; //!< p_in when the model lies on background
  double inOther = 0.0;      //!< p_in otherwise (another hue, or a pixel without hue)
  double outBackground = 0.1; //!< p_out when the strip lies on background
  double outOther = -0.5;    //!< p_out otherwise (the strip lies on the target, or a pixel without hue)
  double offImage = 0.0;     //!< score of a point projected off the image (or behind the camera)
  float minSaturation = 0.f; //!< image pixels less saturated have no hue (0: the paper, every pixel has one)
  /*!
    Stereo visibility (what a stereo rig can see of what hides the target): a point on the image
    that misses in one camera (S_in: not its own hue; S_out: not the background) where the other
    camera (on a rig of more than two, camera k's partner: k + 1, the last camera's the one before
    it; one camera has none, and this test is off) sees what the model says is there (its hue; the background), on a hue that is neither
    the target's own nor the background's, is hidden in the first: something stands in front of
    it there. It scores 0 in F, neither for the pose nor against it, and stays in the count (a pose
    never gains by hiding its misses); FitnessDetail's visible scores, which judge a pose, leave
    it out of the count too (docs/occlusion.md). False: the paper's fitness, each camera alone.
  */
  bool stereoVisibility = true;
  /*!
    At most this share of a camera's S_in, and of its S_out, leaves its score as hidden; the hidden
    points beyond it count as the misses they are (a pose cannot hide most of its model).
  */
  double maxHiddenShare = 0.5;

  void validate() const; //!< throws pm::core::Error naming the parameter out of range
};

/*!
  How the points of one camera fell: the classes of Eqs. (8), (9), each scored by the
  FitnessParams member of the same name (off the image: offImage).
*/
struct FitnessCounts
{
  /*! \var FitnessCounts::inMatch
      \brief S_in points on a hue within inTolDeg of their own
      \var FitnessCounts::inBackground
      \brief other S_in points on a hue within inBgTolDeg of the background's
      \var FitnessCounts::inOther
      \brief other S_in points in the image (another hue, or a pixel without hue) */
  int inMatch = 0, inBackground = 0, inOther = 0, inOff = 0; //!< S_in points off the image or behind the camera
  /*! \var FitnessCounts::outBackground
      \brief S_out points on a hue within outBgTolDeg of the background's
      \var FitnessCounts::outOther
      \brief other S_out points in the image */
  int outBackground = 0, outOther = 0, outOff = 0; //!< S_out points off the image or behind the camera
  /*! \var FitnessCounts::inHidden
      \brief S_in points hidden in this camera (FitnessParams::stereoVisibility) */
  int inHidden = 0, outHidden = 0; //!< S_out points hidden in this camera
  //! The share of the points on the image that are not hidden (1 when none is; 1 when none is on the image).
  double visibleShare() const;
};

/*!
  Where one model point fell and how it scored (for drawing; not the hot path): see
  StereoScorer::pointScores().
*/
struct PointScore
{
  //! The class of the point, as counted in FitnessCounts.
  enum Class : std::uint8_t { InMatch, InBackground, InOther, OutBackground, OutOther, Off, Hidden };
  /*! \var PointScore::InMatch
      \brief S_in point on its own hue (FitnessCounts::inMatch)
      \var PointScore::InBackground
      \brief S_in point on the background's hue (FitnessCounts::inBackground)
      \var PointScore::InOther
      \brief S_in point on another pixel (FitnessCounts::inOther)
      \var PointScore::OutBackground
      \brief S_out point on the background's hue (FitnessCounts::outBackground)
      \var PointScore::OutOther
      \brief S_out point on another pixel (FitnessCounts::outOther)
      \var PointScore::Off
      \brief point off the image or behind the camera
      \var PointScore::Hidden
      \brief point hidden in this camera (FitnessCounts::inHidden, outHidden) */
  /*! \var PointScore::u
      \brief column in the raw image (px), the lens's distortion applied; -1 behind the camera */
  float u, v;  //!< row in the raw image (px), the lens's distortion applied; -1 behind the camera
  Class cls;   //!< how it scored
  bool inner;  //!< S_in (else S_out)
};

/*!
  The fitness at one pose with its parts, camera by camera: see StereoScorer::evaluateDetail().
  Cameras are numbered as on the rig (a stereo rig: 0 left, 1 right); entries past \e cameras are 0.
*/
struct FitnessDetail
{
  double fitness = 0; //!< F, the mean of the cameras' scores (a stereo rig: (F_L + F_R) / 2)
  int cameras = 0;    //!< the number of cameras scored
  std::array<double, CameraRig::kMaxCameras> score{};         //!< F_k, camera k's score
  std::array<FitnessCounts, CameraRig::kMaxCameras> counts{}; //!< how camera k's points fell
  /*!
    F_k over the points not hidden only (as ViSP's render-based drift detector averages over the
    visible points): a right pose behind an occluder keeps the score it has in the open. For judging
    a pose, never for searching one (a pose would gain by hiding its misses); equal to score[k] when
    nothing is hidden.
  */
  std::array<double, CameraRig::kMaxCameras> visible{};
  //! The mean of visible over the cameras (as F is the mean of score).
  double meanVisible() const;
};

namespace kernels {
struct Tolerances; // the kernels' hue tolerances (src/FitnessKernels.h)
} // namespace kernels

/*!
  The stereo fitness F(phi) of a photo-model on a rig of one to four cameras (see StereoScorer.h),
  scoring the frame it is given. It copies what it needs from the rig and the model and keeps no reference to
  them; it is never changed after its construction (but for useScalarKernel(), for the tests and
  benchmarks), so any number of parts may keep a reference to it. Every function is const and
  may run from several threads at once, but for setImages() and addHueUnder() on one frame.
  Cameras are numbered as on the rig (a stereo rig: 0 left, 1 right).
  \code
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");              // pm/io/RigFile.h
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json");  // pm/io/PhotoModelFile.h
  const pm::core::StereoScorer scorer(rig, model); // the paper's parameters
  pm::core::HueFrame frame = scorer.newFrame();
  vpImage<vpRGBa> IL, IR;
  vpImageIo::read(IL, "left.png");
  vpImageIo::read(IR, "right.png");
  scorer.setImages(frame, IL, IR);                 // a new pair: the frame's hue planes
  pm::core::Phi phi;                               // hMo: the model 500 mm ahead of the hand,
  phi.z = 500;                                     // its axes those of the hand
  const double F = scorer.evaluate(frame, phi);    // the higher, the better phi fits the pair
  \endcode
*/
class StereoScorer
{
public:
  /*!
    Prepares the model for \e rig (copies both; a StereoRig converts). Throws pm::core::Error for an
    invalid rig, model or parameters, or a model of more than 65,535 views.
  */
  StereoScorer(const CameraRig &rig, const PhotoModel &model, const FitnessParams &params = FitnessParams());

  //! The number of cameras of the rig (1 to CameraRig::kMaxCameras).
  int cameraCount() const { return m_nCams; }

  //! A frame without images, comparing with the model's background hue.
  HueFrame newFrame() const;
  //! The model's background hue (deg, to a tenth): what a new frame compares with.
  double modelBackgroundHue() const { return m_modelBgHue / 10.0; }
  /*!
    Fills \e frame with a new set of images, \e images[k] camera k's (cameraCount() of them): their hue
    planes (no allocation once the size is set). Throws pm::core::Error if an image's size differs from
    its rig camera's.
  */
  void setImages(HueFrame &frame, const vpImage<vpRGBa> *const *images) const;
  /*!
    The same with the hue computed only inside \e windows (windows[k] camera k's; see footprint()): a
    point outside its window matches nothing. A camera with lens distortion gets its whole image (its
    window is in the ideal image, which the raw one maps into pixel by pixel).
  */
  void setImages(HueFrame &frame, const vpImage<vpRGBa> *const *images, const PixelRect *windows) const;
  //! A stereo pair (cameras 0 and 1). Throws pm::core::Error on a rig of another number of cameras.
  void setImages(HueFrame &frame, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right) const;
  //! A stereo pair inside \e windows (left, right). Same contract.
  void setImages(HueFrame &frame, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const std::array<PixelRect, 2> &windows) const;
  /*!
    Where the model lands in camera \e camera at \e phi: the bounding box of its points in front of
    the camera (of the view scored there), clipped to the image; empty if none falls in it.
    Needs no images. Throws pm::core::Error for an invalid pose.
  */
  PixelRect footprint(const Phi &phi, int camera) const;
  /*!
    After setImages with windows: the hue under every model point at each of the \e n \e poses too
    (the pixels a pose outside the windows reads), so that F there is what the whole images give.
    \e images (one per camera) must be those \e frame was last set from. Throws pm::core::Error for an
    invalid pose, no images or images of another size.
  */
  void addHueUnder(HueFrame &frame, const vpImage<vpRGBa> *const *images, const Phi *poses, std::size_t n) const;
  //! The same for a stereo pair. Throws pm::core::Error on a rig of another number of cameras.
  void addHueUnder(HueFrame &frame, const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const Phi *poses, std::size_t n) const;

  //! F(phi) on \e frame. Throws pm::core::Error if phi is invalid or the frame has no images.
  double evaluate(const HueFrame &frame, const Phi &phi) const;
  //! F for the \e n poses \e phis into \e out, on two cores (BatchPool); the same values as evaluate(). Same contract.
  void evaluate(const HueFrame &frame, const Phi *phis, std::size_t n, double *out) const;
  /*!
    Early rejection of hopeless poses: F for \e n poses as evaluate(), except that a pose whose
    first share of points (an even sample of S_in and S_out: every kRejectStride-th point) already
    puts its estimated F under \e rejectBelow stops there; its \e out is then that estimate (under
    \e rejectBelow) and \e cost[i] the share of the work done (about 1 / kRejectStride), else F
    exactly and 1. Deterministic: the same poses and threshold give the same values whoever
    computes them. Same contract as evaluate().
      \code
      scorer.evaluate(frame, children, n, F, worstSurvivor - margin, cost); // a GA's children
      \endcode
  */
  void evaluate(const HueFrame &frame, const Phi *phis, std::size_t n, double *out, double rejectBelow, double *cost) const;
  //! Every kRejectStride-th point of S_in and of S_out makes the first share that early rejection scores.
  static constexpr std::size_t kRejectStride = 4;
  /*!
    F with each point's score interpolated bilinearly between the four pixels around its exact
    projection (each pixel scored as evaluate() scores the pixel a point lands on): continuous in
    phi, so that a local continuous search can climb it where F is a staircase (steps of one
    pixel, flat in tilt over a degree or two). Scalar, four samples per point: about 13 times the
    cost of evaluate() with AVX2 (pm-bench Fitness_1000Points_Depth_Smooth); allocates
    nothing. Same contract as evaluate().
  */
  double evaluateSmooth(const HueFrame &frame, const Phi &phi) const;
  /*!
    The smooth score (evaluateSmooth's, within float rounding: AVX2 where the CPU has it) and its
    gradient \e grad with respect to a small motion of the model (applyTwist's six components: mm,
    then rad). With \e metric: the 6x6 (row-major) mean over the points that fall in the images of
    J^T J, J the 2x6 motion of a point's image per unit of that motion (px per mm, px per rad), so
    that sqrt(d^T metric d) is the rms image motion of a small motion d. The score is piecewise
    bilinear in each point's image position: the gradient is exact between pixel boundaries.
    Allocates nothing; same contract as evaluate().
      \code
      double g[6], M[36];
      const double s = scorer.evaluateSmoothGradient(frame, phi, g, M); // climb along M^-1 g (SmoothAscent)
      \endcode
  */
  double evaluateSmoothGradient(const HueFrame &frame, const Phi &phi, double grad[6], double *metric = nullptr) const;
  //! F, each camera's score and the class counts of each camera.
  FitnessDetail evaluateDetail(const HueFrame &frame, const Phi &phi) const;
  //! Every model point's image position and class in camera \e camera, for drawing. Same contract as evaluate().
  std::vector<PointScore> pointScores(const HueFrame &frame, const Phi &phi, int camera) const;
  /*!
    The image hues (deg) under the S_out points of the view scored in camera \e camera at \e phi, as
    \e frame's planes hold them (points off the image, behind the camera or on a pixel without hue
    left out): at most \e capacity of them written to \e out, their number returned
    (outerPointsMax() is always enough). Allocates nothing; same contract as evaluate().
  */
  std::size_t outerHues(const HueFrame &frame, const Phi &phi, int camera, float *out, std::size_t capacity) const;
  //! The most S_out points a view has (outerHues()' capacity).
  std::size_t outerPointsMax() const;

  /*!
    RMS distance (px) between the model's points projected at \e a and at \e b, over every camera
    (points in front of both): how far apart two poses look. Throws pm::core::Error for an invalid pose.
  */
  double reprojectionRms(const Phi &a, const Phi &b) const;
  /*!
    Fraction of the model's points (of the view scored there) that project inside camera \e camera's
    image at \e phi. Needs no images; throws pm::core::Error for an invalid pose.
  */
  double visibleFraction(const Phi &phi, int camera) const;

  //! Number of points of the model's own S_in and S_out (those of further views not counted).
  std::size_t modelSize() const { return m_nIn + m_nOut; }
  //! True when the model carries depth (some point off the plane z = 0): the kernels then project (x, y, z).
  bool hasDepth() const { return m_hasDepth; }
  //! The parameters given to the constructor.
  const FitnessParams &params() const { return m_params; }
  //! "avx2" or "scalar": the kernel this scorer runs (AVX2 where the CPU has it, unless useScalarKernel()).
  const char *kernelName() const;
  /*!
    The scalar kernels instead of the AVX2 ones even where the CPU has them (\e on), or back to the
    machine's best: for the tests and benchmarks that compare them (F is the same to the bit).
  */
  void useScalarKernel(bool on);
  //! Camera \e camera placed in the hand frame, as the kernels read it: cMh (mm), intrinsics, image size.
  const PinholeCamera::Projection &camera(int camera) const { return m_cams[camera]; }

private:
  void check(const HueFrame &f, const Phi &phi) const;
  //! Throws pm::core::Error unless \e camera names a camera of the rig.
  void checkCamera(int camera) const;
  //! Camera \e cam at \e phi, reading \e f's plane (none: a projection that samples no hue).
  struct Projection projectionOf(int cam, const Phi &phi, const HueFrame *f = nullptr) const;
  FitnessCounts countCamera(const HueFrame &f, int cam, const Phi &phi) const;
  //! The camera whose view tests camera \e cam's stereo visibility: cam + 1, the last camera's the one before it; -1 when off or alone.
  int partnerOf(int cam) const { return m_partner[static_cast<std::size_t>(cam)]; }
  //! F of a pose already checked, or, when its first share of points scores it under \e rejectBelow, that estimate (\e cost: the share of the work done).
  double stereoScoreOrReject(const HueFrame &f, const Phi &phi, double rejectBelow, double &cost) const;
  double score(const FitnessCounts &c) const;
  double visibleScore(const FitnessCounts &c) const; //!< score() over the points not hidden (FitnessDetail::visible)
  double scoreOf(const FitnessCounts &c, bool visibleOnly) const; //!< score() or visibleScore()
  struct View
  {
    std::size_t inBegin, inEnd, outBegin, outEnd; //!< its S_in and S_out in m_x, m_y, m_z, m_hue
    //! The first share of each (every kRejectStride-th point of the model's order): [inBegin, inSplit), [outBegin, outSplit).
    std::size_t inSplit, outSplit;
  };
  //! The kernels' tolerances, comparing with \e f's background hue.
  kernels::Tolerances tolerances(const HueFrame &f) const;
  //! Counts one camera's points of a view: \e stage 0 all, 1 the first share, 2 the rest; \e other: the other camera, for stereo visibility (null: off).
  void countView(const HueFrame &f, const struct Projection &p, const struct Projection *other, const View &v, int stage, FitnessCounts &counts) const;
  //! The view scored for a camera at projection \e p: the one whose camera looked from the nearest direction (ViewpointIndex).
  const View &viewFor(const struct Projection &p) const;
  /*!
    Camera \e cam's normalised smooth score at \e phi; adds its gradient to \e grad and (\e metric) its
    image-motion metric to \e metricOut when given. \e vectorised: the AVX2 kernel where the CPU has
    it (float sums), else the scalar one (double, the reference).
  */
  double smoothCamera(const HueFrame &f, int cam, const Phi &phi, bool vectorised, bool metric, double *grad, double *metricOut,
                      std::size_t *inside) const;
  //! The smooth score's sums of points [b, e) of a view whose S_in ends at \e inEnd (scalar, double).
  void smoothSumsScalar(const HueFrame &f, const struct Projection &p, std::size_t b, std::size_t e, std::size_t inEnd, bool metric,
                        struct SmoothSums &out) const; //!< the interpolated point scores of its view, normalised
  //! A view's summed point scores over its nIn + nOut points, on the scale of the model's own view.
  double normalised(double sum, std::size_t nIn, std::size_t nOut) const;
  //! F of a pose already checked: the mean of the cameras' scores.
  double stereoScore(const HueFrame &f, const Phi &phi) const;
  //! The images' sizes against the cameras'; throws pm::core::Error naming the camera.
  void checkSizes(const vpImage<vpRGBa> *const *images) const;
  //! The hidden points a score leaves out: at most maxHiddenShare of each set (S_in, S_out).
  void cappedHidden(const FitnessCounts &c, int &inHidden, int &outHidden) const;

  FitnessParams m_params;
  int m_nCams = 0;                                                  //!< the rig's number of cameras
  double m_camWeight = 1;                                           //!< 1 / m_nCams: F the mean of the cameras' scores
  std::array<int, CameraRig::kMaxCameras> m_partner{};              //!< partnerOf(), set once
  std::array<PinholeCamera::Projection, CameraRig::kMaxCameras> m_cams; //!< the rig's cameras in the hand frame
  std::size_t m_nIn = 0, m_nOut = 0;
  // Model points, structure of arrays: x, y, z (mm), hue (tenths of a degree).
  std::vector<float> m_x, m_y, m_z;
  std::vector<std::int32_t> m_hue;
  std::vector<View> m_views; //!< view 0: the model's own points (the only one of a flat or one-view model)
  ViewpointIndex m_viewpoints; //!< the view each camera scores: the one made from the nearest direction (the model's own lookup)
  std::vector<std::uint32_t> m_order; //!< m_order[k]: where the k-th point of the model's order (S_in then S_out of each view) is kept
  std::int32_t m_modelBgHue = 0, m_tolIn = 0, m_tolInBg = 0, m_tolOutBg = 0; //!< tenths of a degree
  TargetHues m_targetHues; //!< a point that misses on one of the target's own hues is a wrong pose, never hidden
  std::array<std::shared_ptr<const UndistortMap>, CameraRig::kMaxCameras> m_undistort; //!< null for a camera without distortion
  std::array<LensDistortion, CameraRig::kMaxCameras> m_distortion;
  std::array<vpCameraParameters, CameraRig::kMaxCameras> m_intrinsics;
  bool m_avx2 = false;     //!< the AVX2 kernels run (the CPU has them and useScalarKernel() did not say otherwise)
  bool m_hasDepth = false; //!< some point has z != 0 (the 3-D model); else the flat model's exact kernel
};

} // namespace pm::core
