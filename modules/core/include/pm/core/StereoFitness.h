#pragma once
/*!
  \file StereoFitness.h
  The stereo fitness of one pair at a time: a StereoScorer (the model on the rig, never changed)
  and the HueFrame it scores (the pair's hue planes, the background's hue), held together for a
  program or a tool that scores poses on the last pair it was given (a fitness map, a detector, a
  test). The fitness itself, its equations and its rules are StereoScorer.h's; a part that is
  given the frame to score keeps a StereoScorer instead.
*/
#include <array>
#include <vector>

#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/core/HueFrame.h"
#include "pm/core/StereoScorer.h"

namespace pm::core {

/*!
  The stereo fitness F(phi) of a photo-model in the last stereo pair given (see StereoFitness.h):
  a StereoScorer and its HueFrame. The evaluate functions are const and may run from several
  threads at once; setImages(), addHueUnder() and setBackgroundHue() change the frame and must not.
  Cameras are numbered 0 (left) and 1 (right).
  \code
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");              // pm/io/RigFile.h
  const pm::core::PhotoModel model = pm::io::loadPhotoModel("model.json");  // pm/io/PhotoModelFile.h
  pm::core::StereoFitness fitness(rig, model);       // the paper's parameters
  vpImage<vpRGBa> IL, IR;
  vpImageIo::read(IL, "left.png");
  vpImageIo::read(IR, "right.png");
  fitness.setImages(IL, IR);                   // a new pair: the hue planes
  pm::core::Phi phi;                                 // hMo: the model 500 mm ahead of the hand,
  phi.z = 500;                                 // its axes those of the hand
  const double F = fitness.evaluate(phi);      // the higher, the better phi fits the pair
  const pm::core::FitnessDetail d = fitness.evaluateDetail(phi);
  std::cout << "F = " << F << " (left " << d.score[0] << ", right " << d.score[1] << ")\n";
  \endcode
*/
class StereoFitness
{
public:
  //! StereoScorer's constructor (same contract); no images yet.
  StereoFitness(const CameraRig &rig, const PhotoModel &model, const FitnessParams &params = FitnessParams())
    : m_scorer(rig, model, params), m_frame(m_scorer.newFrame())
  {
  }

  //! The scorer (the model on the rig): never changed, it may be kept by whoever scores.
  const StereoScorer &scorer() const { return m_scorer; }
  //! The frame of the last pair given.
  const HueFrame &frame() const { return m_frame; }

  //! StereoScorer::setImages on this fitness's frame: one image per camera.
  void setImages(const vpImage<vpRGBa> *const *images) { m_scorer.setImages(m_frame, images); }
  //! The same inside \e windows (windows[k] camera k's).
  void setImages(const vpImage<vpRGBa> *const *images, const PixelRect *windows) { m_scorer.setImages(m_frame, images, windows); }
  //! StereoScorer::addHueUnder on this fitness's frame: one image per camera.
  void addHueUnder(const vpImage<vpRGBa> *const *images, const Phi *poses, std::size_t n) { m_scorer.addHueUnder(m_frame, images, poses, n); }
  //! StereoScorer::setImages on this fitness's frame.
  void setImages(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right) { m_scorer.setImages(m_frame, left, right); }
  //! StereoScorer::setImages with windows on this fitness's frame.
  void setImages(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const std::array<PixelRect, 2> &windows)
  {
    m_scorer.setImages(m_frame, left, right, windows);
  }
  //! StereoScorer::addHueUnder on this fitness's frame.
  void addHueUnder(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const Phi *poses, std::size_t n)
  {
    m_scorer.addHueUnder(m_frame, left, right, poses, n);
  }
  //! HueFrame::setBackgroundHue: the background's hue the scores compare with from now on (deg).
  void setBackgroundHue(double deg) { m_frame.setBackgroundHue(deg); }
  //! The background's hue the scores compare with now (deg): the model's until set.
  double backgroundHue() const { return m_frame.backgroundHue(); }

  //! StereoScorer::evaluate on the last pair.
  double evaluate(const Phi &phi) const { return m_scorer.evaluate(m_frame, phi); }
  //! StereoScorer::evaluate of \e n poses on the last pair.
  void evaluate(const Phi *phis, std::size_t n, double *out) const { m_scorer.evaluate(m_frame, phis, n, out); }
  //! StereoScorer::evaluate with early rejection on the last pair.
  void evaluate(const Phi *phis, std::size_t n, double *out, double rejectBelow, double *cost) const
  {
    m_scorer.evaluate(m_frame, phis, n, out, rejectBelow, cost);
  }
  //! Every kRejectStride-th point of S_in and of S_out makes the first share that early rejection scores.
  static constexpr std::size_t kRejectStride = StereoScorer::kRejectStride;
  //! StereoScorer::evaluateSmooth on the last pair.
  double evaluateSmooth(const Phi &phi) const { return m_scorer.evaluateSmooth(m_frame, phi); }
  //! StereoScorer::evaluateSmoothGradient on the last pair.
  double evaluateSmoothGradient(const Phi &phi, double grad[6], double *metric = nullptr) const
  {
    return m_scorer.evaluateSmoothGradient(m_frame, phi, grad, metric);
  }
  //! StereoScorer::evaluateDetail on the last pair.
  FitnessDetail evaluateDetail(const Phi &phi) const { return m_scorer.evaluateDetail(m_frame, phi); }
  //! StereoScorer::pointScores on the last pair.
  std::vector<PointScore> pointScores(const Phi &phi, int camera) const { return m_scorer.pointScores(m_frame, phi, camera); }
  //! StereoScorer::outerHues on the last pair.
  std::size_t outerHues(const Phi &phi, int camera, float *out, std::size_t capacity) const
  {
    return m_scorer.outerHues(m_frame, phi, camera, out, capacity);
  }
  //! The most S_out points a view has (outerHues()' capacity).
  std::size_t outerPointsMax() const { return m_scorer.outerPointsMax(); }

  //! StereoScorer::footprint (needs no images).
  PixelRect footprint(const Phi &phi, int camera) const { return m_scorer.footprint(phi, camera); }
  //! StereoScorer::reprojectionRms (needs no images).
  double reprojectionRms(const Phi &a, const Phi &b) const { return m_scorer.reprojectionRms(a, b); }
  //! StereoScorer::visibleFraction (needs no images).
  double visibleFraction(const Phi &phi, int camera) const { return m_scorer.visibleFraction(phi, camera); }

  //! Camera \e camera's hue plane (0 left, 1 right), as the last setImages() (and addHueUnder()) left it.
  const HuePlane &huePlane(int camera) const { return m_frame.plane(camera); }
  //! Number of points of the model's own S_in and S_out (those of further views not counted).
  std::size_t modelSize() const { return m_scorer.modelSize(); }
  //! True when the model carries depth (some point off the plane z = 0).
  bool hasDepth() const { return m_scorer.hasDepth(); }
  //! The parameters given to the constructor.
  const FitnessParams &params() const { return m_scorer.params(); }
  //! "avx2" or "scalar": the kernel this fitness runs.
  const char *kernelName() const { return m_scorer.kernelName(); }
  //! StereoScorer::useScalarKernel: for the tests and benchmarks that compare the kernels.
  void useScalarKernel(bool on) { m_scorer.useScalarKernel(on); }
  //! Camera \e camera (0 left, 1 right) placed in the hand frame, as the kernels read it.
  const PinholeCamera::Projection &camera(int camera) const { return m_scorer.camera(camera); }

private:
  StereoScorer m_scorer;
  HueFrame m_frame;
};

} // namespace pm::core
