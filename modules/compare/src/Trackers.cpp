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
  OurTracker(const core::CameraRig &rig, const core::PhotoModel &model, const tracker::TrackerParams &params, std::string name)
    : m_tracker(rig, model, params), m_name(std::move(name))
  {
  }
  std::string name() const override { return m_name; }
  bool needsInitialPose() const override { return false; }
  void start(const core::CameraImages &, const vpHomogeneousMatrix &) override { m_tracker.initialize(); }
  Estimate track(const core::CameraImages &images) override
  {
    const tracker::TrackResult r = m_tracker.track(images);
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
  MbtTracker(const core::CameraRig &rig, MbtFeatures features, const std::string &caoPath, const std::string &xmlPath)
    : m_rig(rig), m_features(features), m_gray(rig.size())
  {
    const int type = features == MbtFeatures::Edge  ? vpMbGenericTracker::EDGE_TRACKER
                     : features == MbtFeatures::Klt ? vpMbGenericTracker::KLT_TRACKER
                                                    : (vpMbGenericTracker::EDGE_TRACKER | vpMbGenericTracker::KLT_TRACKER);
    // ViSP's cameras "Camera1" .. "CameraN", the first the reference: one camera is MBT's native monocular case.
    std::vector<std::string> names;
    std::map<std::string, std::string> xml, cao;
    std::map<std::string, vpCameraParameters> cams;
    std::map<std::string, vpHomogeneousMatrix> T;
    for (std::size_t k = 0; k < rig.size(); ++k) {
      names.push_back("Camera" + std::to_string(k + 1));
      xml[names[k]] = xmlPath;
      cao[names[k]] = caoPath;
      cams[names[k]] = rig[k].cam;
      T[names[k]] = rig[k].cMh() * rig[0].hMc; // the reference camera in camera k
    }
    m_mbt = std::make_unique<vpMbGenericTracker>(names, std::vector<int>(rig.size(), type));
    try {
      pm::io::QuietStdout quiet; // ViSP reports the settings it reads on std::cout
      if (rig.size() == 1) {
        m_mbt->loadConfigFile(xmlPath, false);
        m_mbt->setCameraParameters(rig[0].cam);
        m_mbt->loadModel(caoPath, false);
      } else if (rig.size() == 2) { // the stereo calls of before
        m_mbt->loadConfigFile(xmlPath, xmlPath, false);
        m_mbt->setCameraParameters(rig[0].cam, rig[1].cam);
        std::map<std::string, vpHomogeneousMatrix> T2{{"Camera1", vpHomogeneousMatrix()}, {"Camera2", rig.stereo().cLMcR().inverse()}};
        m_mbt->setCameraTransformationMatrix(T2);
        m_mbt->loadModel(caoPath, caoPath, false);
      } else {
        m_mbt->loadConfigFile(xml, false);
        m_mbt->setCameraParameters(cams);
        m_mbt->setCameraTransformationMatrix(T);
        m_mbt->loadModel(cao, false);
      }
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
  void start(const core::CameraImages &images, const vpHomogeneousMatrix &hMm) override
  {
    images.checkFor(m_rig, "ViSP MBT");
    grayOf(images);
    if (m_rig.size() == 1)
      m_mbt->initFromPose(m_gray[0], m_rig[0].cMh() * hMm);
    else if (m_rig.size() == 2)
      m_mbt->initFromPose(m_gray[0], m_gray[1], m_rig[0].cMh() * hMm, m_rig[1].cMh() * hMm);
    else {
      std::map<std::string, const vpImage<unsigned char> *> I;
      std::map<std::string, vpHomogeneousMatrix> cMm;
      for (std::size_t k = 0; k < m_rig.size(); ++k) {
        I["Camera" + std::to_string(k + 1)] = &m_gray[k];
        cMm["Camera" + std::to_string(k + 1)] = m_rig[k].cMh() * hMm;
      }
      m_mbt->initFromPose(I, cMm);
    }
    m_hMm = hMm;
  }
  Estimate track(const core::CameraImages &images) override
  {
    images.checkFor(m_rig, "ViSP MBT");
    grayOf(images);
    bool ok = true;
    try {
      QuietCerr quiet;
      if (m_rig.size() == 1)
        m_mbt->track(m_gray[0]);
      else if (m_rig.size() == 2)
        m_mbt->track(m_gray[0], m_gray[1]);
      else {
        std::map<std::string, const vpImage<unsigned char> *> I;
        for (std::size_t k = 0; k < m_rig.size(); ++k)
          I["Camera" + std::to_string(k + 1)] = &m_gray[k];
        m_mbt->track(I);
      }
      vpHomogeneousMatrix cMm;
      m_mbt->getPose(cMm);
      m_hMm = m_rig[0].hMc * cMm;
    } catch (const vpException &) {
      ok = false; // no feature left to track: the pose stays where it was
    }
    return {m_hMm, ok};
  }

private:
  //! The images in grey, as MBT reads them.
  void grayOf(const core::CameraImages &images)
  {
    for (std::size_t k = 0; k < images.size(); ++k)
      vpImageConvert::convert(images[k], m_gray[k]);
  }
  core::CameraRig m_rig;
  MbtFeatures m_features;
  std::unique_ptr<vpMbGenericTracker> m_mbt;
  std::vector<vpImage<unsigned char>> m_gray; //!< camera k's image in grey
  vpHomogeneousMatrix m_hMm;
};

// ---------------------------------------------------------------------------------------------
class TemplateTracker : public ComparedTracker
{
public:
  TemplateTracker(const core::CameraRig &rig, TemplateCost cost, const std::vector<vpPoint> &polygon)
    : m_cam(rig[0]), m_cost(cost), m_polygon(polygon)
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

  void start(const core::CameraImages &images, const vpHomogeneousMatrix &hMm) override
  {
    vpImageConvert::convert(images[0], m_gl); // the first camera's image alone
    const vpHomogeneousMatrix cMm = m_cam.cMh() * hMm;
    // The template: cells of 6 px inside the outline as the left camera sees it, 2 triangles each.
    std::vector<vpImagePoint> outline;
    for (const auto &[i, j] : projectPolygon(m_polygon, cMm, m_cam.cam))
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

  Estimate track(const core::CameraImages &images) override
  {
    vpImageConvert::convert(images[0], m_gl);
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
        vpPixelMeterConversion::convertPoint(m_cam.cam, ip, x, y);
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
    return {m_cam.hMc * m_cMm, ok && !m_tt->getDiverge()};
  }

private:
  core::PinholeCamera m_cam; //!< the rig's first camera, the one it tracks in
  TemplateCost m_cost;
  std::vector<vpPoint> m_polygon;
  vpTemplateTrackerWarpHomography m_warp;
  std::unique_ptr<vpTemplateTracker> m_tt;
  vpImage<unsigned char> m_gl;
  std::vector<vpImagePoint> m_ref; //!< the outline in the first left image
  vpHomogeneousMatrix m_cMm;
};

} // namespace

std::unique_ptr<ComparedTracker> makeOurTracker(const core::CameraRig &rig, const core::PhotoModel &model, const tracker::TrackerParams &params,
                                                const std::string &name)
{
  return std::make_unique<OurTracker>(rig, model, params, name);
}

std::unique_ptr<ComparedTracker> makeMbtTracker(const core::CameraRig &rig, MbtFeatures features, const std::string &caoPath,
                                                const std::string &xmlPath)
{
  return std::make_unique<MbtTracker>(rig, features, caoPath, xmlPath);
}

std::unique_ptr<ComparedTracker> makeTemplateTracker(const core::CameraRig &rig, TemplateCost cost, const std::vector<vpPoint> &polygon)
{
  return std::make_unique<TemplateTracker>(rig, cost, polygon);
}

} // namespace pm::compare
