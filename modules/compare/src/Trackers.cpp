#include "pm/compare/Trackers.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

#include <visp3/core/vpException.h>
#include <visp3/core/vpImageConvert.h>
#include <visp3/core/vpMeterPixelConversion.h>
#include <visp3/core/vpPixelMeterConversion.h>
#include <visp3/core/vpPolygon.h>
#include <visp3/mbt/vpMbGenericTracker.h>
#include <visp3/tt/vpTemplateTrackerSSDInverseCompositional.h>
#include <visp3/tt/vpTemplateTrackerWarpHomography.h>
#include <visp3/tt/vpTemplateTrackerZNCCInverseCompositional.h>
#include <visp3/tt/vpTemplateTrackerZone.h>
#include <visp3/vision/vpPose.h>

#include "pm/compare/OutlineModel.h"
#include "pm/core/Error.h"
#include "pm/io/QuietStdout.h"

namespace pm::compare {

namespace {

//! vpMbGenericTracker reports its KLT failures on std::cerr ("Error in KLT tracking: ...") every
//! frame; the failure itself is what the scores show. Swallowed while an object lives.
class QuietCerr
{
public:
  QuietCerr() : m_old(std::cerr.rdbuf(m_sink.rdbuf())) {}
  ~QuietCerr() { std::cerr.rdbuf(m_old); }
  QuietCerr(const QuietCerr &) = delete;
  QuietCerr &operator=(const QuietCerr &) = delete;

private:
  std::ostringstream m_sink;
  std::streambuf *m_old;
};

// ---------------------------------------------------------------------------------------------
class OurTracker : public ComparedTracker
{
public:
  OurTracker(const core::StereoRig &rig, const core::PhotoModel &model, const tracker::TrackerParams &params, std::string name)
    : m_tracker(rig, model, params), m_name(std::move(name))
  {
  }
  std::string name() const override { return m_name; }
  bool needsInitialPose() const override { return false; }
  void start(const vpImage<vpRGBa> &, const vpImage<vpRGBa> &, const vpHomogeneousMatrix &) override { m_tracker.initialize(); }
  Estimate track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right) override
  {
    const tracker::TrackResult r = m_tracker.track(left, right);
    return {r.hMo, r.state == tracker::TrackState::Tracking};
  }

private:
  tracker::PhotoModelTracker m_tracker;
  std::string m_name;
};

// ---------------------------------------------------------------------------------------------
class MbtTracker : public ComparedTracker
{
public:
  MbtTracker(const core::StereoRig &rig, MbtFeatures features, const std::string &caoPath, const std::string &xmlPath)
    : m_rig(rig), m_features(features)
  {
    const int type = features == MbtFeatures::Edge  ? vpMbGenericTracker::EDGE_TRACKER
                     : features == MbtFeatures::Klt ? vpMbGenericTracker::KLT_TRACKER
                                                    : (vpMbGenericTracker::EDGE_TRACKER | vpMbGenericTracker::KLT_TRACKER);
    m_mbt = std::make_unique<vpMbGenericTracker>(std::vector<std::string>{"Camera1", "Camera2"}, std::vector<int>{type, type});
    try {
      pm::io::QuietStdout quiet; // ViSP reports the settings it reads on std::cout
      m_mbt->loadConfigFile(xmlPath, xmlPath, false);
      m_mbt->setCameraParameters(rig.left.cam, rig.right.cam);
      std::map<std::string, vpHomogeneousMatrix> T{{"Camera1", vpHomogeneousMatrix()}, {"Camera2", rig.cLMcR().inverse()}};
      m_mbt->setCameraTransformationMatrix(T);
      m_mbt->loadModel(caoPath, caoPath, false);
      m_mbt->setDisplayFeatures(false);
    } catch (const vpException &e) {
      throw core::Error("vpMbGenericTracker: cannot load " + xmlPath + " or " + caoPath + ": " + e.getStringMessage());
    }
  }
  std::string name() const override
  {
    return m_features == MbtFeatures::Edge  ? "ViSP MBT edge"
           : m_features == MbtFeatures::Klt ? "ViSP MBT KLT"
                                            : "ViSP MBT edge+KLT";
  }
  bool needsInitialPose() const override { return true; }
  void start(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right, const vpHomogeneousMatrix &hMm) override
  {
    vpImageConvert::convert(left, m_gl);
    vpImageConvert::convert(right, m_gr);
    m_mbt->initFromPose(m_gl, m_gr, m_rig.left.cMh() * hMm, m_rig.right.cMh() * hMm);
    m_hMm = hMm;
  }
  Estimate track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &right) override
  {
    vpImageConvert::convert(left, m_gl);
    vpImageConvert::convert(right, m_gr);
    bool ok = true;
    try {
      QuietCerr quiet;
      m_mbt->track(m_gl, m_gr);
      vpHomogeneousMatrix cMm;
      m_mbt->getPose(cMm);
      m_hMm = m_rig.left.hMc * cMm;
    } catch (const vpException &) {
      ok = false; // no feature left to track: the pose stays where it was
    }
    return {m_hMm, ok};
  }

private:
  core::StereoRig m_rig;
  MbtFeatures m_features;
  std::unique_ptr<vpMbGenericTracker> m_mbt;
  vpImage<unsigned char> m_gl, m_gr;
  vpHomogeneousMatrix m_hMm;
};

// ---------------------------------------------------------------------------------------------
class TemplateTracker : public ComparedTracker
{
public:
  TemplateTracker(const core::StereoRig &rig, TemplateCost cost, const std::vector<vpPoint> &polygon)
    : m_rig(rig), m_cost(cost), m_polygon(polygon)
  {
    if (cost == TemplateCost::Ssd)
      m_tt = std::make_unique<vpTemplateTrackerSSDInverseCompositional>(&m_warp);
    else
      m_tt = std::make_unique<vpTemplateTrackerZNCCInverseCompositional>(&m_warp);
    // Settings of ViSP's tutorial-template-tracker, with more iterations for the larger motions.
    m_tt->setSampling(2, 2);
    m_tt->setLambda(0.001);
    m_tt->setIterationMax(50);
    m_tt->setPyramidal(3, 1);
  }
  std::string name() const override { return m_cost == TemplateCost::Ssd ? "ViSP template SSD" : "ViSP template ZNCC"; }
  bool needsInitialPose() const override { return true; }

  void start(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &, const vpHomogeneousMatrix &hMm) override
  {
    vpImageConvert::convert(left, m_gl);
    const vpHomogeneousMatrix cMm = m_rig.left.cMh() * hMm;
    // The template: cells of 6 px inside the outline as the left camera sees it, 2 triangles each.
    std::vector<vpImagePoint> outline;
    for (const auto &[i, j] : projectPolygon(m_polygon, cMm, m_rig.left.cam))
      outline.emplace_back(i, j);
    const vpPolygon poly(outline);
    const vpRect box = poly.getBoundingBox();
    vpTemplateTrackerZone zone;
    const double cell = 6;
    for (double i = std::floor(box.getTop()); i + cell <= box.getBottom(); i += cell)
      for (double j = std::floor(box.getLeft()); j + cell <= box.getRight(); j += cell) {
        const vpImagePoint a(i, j), b(i, j + cell), c(i + cell, j + cell), d(i + cell, j);
        if (poly.isInside(a) && poly.isInside(b) && poly.isInside(c) && poly.isInside(d)) {
          zone.add(vpTemplateTrackerTriangle(a, b, c));
          zone.add(vpTemplateTrackerTriangle(a, c, d));
        }
      }
    if (zone.getNbTriangle() == 0)
      throw core::Error("template tracker: the target is too small in the left image");
    m_tt->resetTracker();
    m_tt->initFromZone(m_gl, zone);
    // The points whose warp gives the pose: the outline's vertices, on the plane z = 0 of the model.
    m_ref = outline;
    m_cMm = cMm;
  }

  Estimate track(const vpImage<vpRGBa> &left, const vpImage<vpRGBa> &) override
  {
    vpImageConvert::convert(left, m_gl);
    bool ok = true;
    try {
      m_tt->track(m_gl);
      // ViSP's homography warp: (u, v) -> ((1+p0) u + p3 v + p6, p1 u + (1+p4) v + p7) / (p2 u + p5 v + 1).
      const vpColVector p = m_tt->getp();
      vpPose pose;
      for (std::size_t k = 0; k < m_ref.size(); ++k) {
        const double u = m_ref[k].get_u(), v = m_ref[k].get_v(), w = p[2] * u + p[5] * v + 1;
        if (!(w > 1e-6))
          throw vpException(vpException::fatalError, "the template's homography degenerated");
        const vpImagePoint ip(((p[1] * u + (1 + p[4]) * v + p[7]) / w), ((1 + p[0]) * u + p[3] * v + p[6]) / w);
        vpPoint P = m_polygon[k];
        double x = 0, y = 0;
        vpPixelMeterConversion::convertPoint(m_rig.left.cam, ip, x, y);
        P.set_x(x);
        P.set_y(y);
        pose.addPoint(P);
      }
      vpHomogeneousMatrix cMm = m_cMm; // starts from the last pose
      pose.computePose(vpPose::VIRTUAL_VS, cMm);
      // A diverged homography gives poses behind the camera or kilometres away: no pose then.
      if (!std::isfinite(cMm[0][3] + cMm[1][3] + cMm[2][3]) || cMm[2][3] < 0.05 || cMm.getTranslationVector().frobeniusNorm() > 5)
        throw vpException(vpException::fatalError, "the template's pose diverged");
      m_cMm = cMm;
    } catch (const vpException &) {
      ok = false;
    }
    return {m_rig.left.hMc * m_cMm, ok && !m_tt->getDiverge()};
  }

private:
  core::StereoRig m_rig;
  TemplateCost m_cost;
  std::vector<vpPoint> m_polygon;
  vpTemplateTrackerWarpHomography m_warp;
  std::unique_ptr<vpTemplateTracker> m_tt;
  vpImage<unsigned char> m_gl;
  std::vector<vpImagePoint> m_ref; //!< the outline in the first left image
  vpHomogeneousMatrix m_cMm;
};

} // namespace

std::unique_ptr<ComparedTracker> makeOurTracker(const core::StereoRig &rig, const core::PhotoModel &model, const tracker::TrackerParams &params,
                                                const std::string &name)
{
  return std::make_unique<OurTracker>(rig, model, params, name);
}

std::unique_ptr<ComparedTracker> makeMbtTracker(const core::StereoRig &rig, MbtFeatures features, const std::string &caoPath,
                                                const std::string &xmlPath)
{
  return std::make_unique<MbtTracker>(rig, features, caoPath, xmlPath);
}

std::unique_ptr<ComparedTracker> makeTemplateTracker(const core::StereoRig &rig, TemplateCost cost, const std::vector<vpPoint> &polygon)
{
  return std::make_unique<TemplateTracker>(rig, cost, polygon);
}

} // namespace pm::compare
