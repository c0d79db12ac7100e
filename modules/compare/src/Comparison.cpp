#include "pm/compare/Comparison.h"

#include "pm/compare/CadMesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <ostream>
#include <sstream>

#include <visp3/core/vpImageDraw.h>

#include "pm/compare/OutlineModel.h"
#include "pm/compare/Trackers.h"
#include "pm/core/Error.h"
#include "pm/lab/ClosedLoop.h"
#include "pm/lab/LabPass.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::compare {

namespace {

const vpRGBa kColors[] = {vpRGBa(220, 50, 40), vpRGBa(240, 120, 150), vpRGBa(40, 90, 200), vpRGBa(40, 160, 80), vpRGBa(140, 60, 170),
                          vpRGBa(230, 150, 20), vpRGBa(90, 90, 90)};

//! The outline at \e hMm drawn on the left image.
void drawOutline(vpImage<vpRGBa> &I, const std::vector<vpPoint> &outline, const vpHomogeneousMatrix &hMm, const core::PinholeCamera &cam,
                 const vpRGBa &color)
{
  const auto px = projectPolygon(outline, cam.cMh() * hMm, cam.cam);
  for (std::size_t i = 0; i < px.size(); ++i) {
    const auto &a = px[i], &b = px[(i + 1) % px.size()];
    vpImageDraw::drawLine(I, vpImagePoint(a.first, a.second), vpImagePoint(b.first, b.second), vpColor(color.R, color.G, color.B), 2);
  }
}

bool has(const std::vector<std::string> &v, const std::string &key) { return std::find(v.begin(), v.end(), key) != v.end(); }

std::string fmt(double v, int precision)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(precision) << v;
  return s.str();
}

std::string recoveryText(const Summary &s, bool hadLoss)
{
  if (!hadLoss)
    return "-";
  if (s.neverRecovered())
    return "never";
  return std::to_string(s.worstRecovery().value_or(0));
}

} // namespace

const std::vector<std::string> &comparedTrackerKeys()
{
  static const std::vector<std::string> keys{"ours",    "ours-3d",      "ours-aa",      "ours-aa-rmga",  "ours-steady",
                                             "mbt-edge", "mbt-klt", "mbt-edge-klt", "template-ssd", "template-zncc"};
  return keys;
}

vpRGBa trackerColor(std::size_t index) { return kColors[index % std::size(kColors)]; }

// The scene, the models and the outline (built once; each scenario makes fresh trackers).
struct Comparison::Setup
{
  sim::Scene scene;
  sim::SimulatedPhotoModel flat, stereo, allAround;
  model::AllAroundBuild allAroundBuild;      //!< its build, when ViSP's trackers are given its surface's mesh (else empty)
  model::HullMesh cad;                        //!< ViSP's trackers' CAD model (empty: the flat outline)
  bool cadIsTrue = false;                     //!< ... the toy's own mesh, in the toy's frame
  vpHomogeneousMatrix toyFrame;               //!< the toy's own frame in itself (the true CAD model's)
  std::vector<vpPoint> outline;
  std::vector<Scenario> scenarios;
  Setup(const sim::TargetShape &target, const sim::SceneParams &params) : scene(target, params) {}
  // The truth of a tracker's own model frame: each model has its own (the 3-D centroid of S_in, ...).
  const vpHomogeneousMatrix &ownFrame(const std::string &key) const
  {
    if (key.rfind("mbt", 0) == 0 && !cad.triangles.empty()) // ViSP's MBT on the all-around model's surface, or the toy's
      return cadIsTrue ? toyFrame : allAround.oMm;
    return key == "ours-3d" ? stereo.oMm : key.rfind("ours-aa", 0) == 0 ? allAround.oMm : flat.oMm;
  }
};

Comparison::Comparison(const core::CameraRig &rig, const ComparisonParams &params) : m_rig(rig), m_p(params)
{
  if (m_p.trackers.empty())
    throw core::Error("compare: at least one tracker");
  for (const std::string &k : m_p.trackers)
    if (!has(comparedTrackerKeys(), k))
      throw core::Error("compare: unknown tracker '" + k + "'");
  if (!std::ifstream(m_p.mbtXml))
    throw core::Error("cannot read the MBT settings " + m_p.mbtXml);
  prepareForScenarios(m_p.scenarios, m_p.scene, m_p.tracker.search.space);
  m_s = std::make_unique<Setup>(sim::makeTarget(m_p.target), m_p.scene);
  m_s->scenarios = makeScenarios(m_p.scenarios, m_p.trajectoryPath, m_p.steps);
  m_s->flat = sim::makeSimulatedPhotoModel(m_s->scene, rig[0].cam, rig[0].width, rig[0].height, m_p.distanceMm);
  m_s->outline = outlinePolygon(m_s->flat.build.region, m_s->flat.build.model, m_p.outlineTolPx);
  if (has(m_p.trackers, "ours-3d"))
    m_s->stereo = sim::makeSimulatedStereoPhotoModel(m_s->scene, rig.stereo(), m_p.distanceMm, model::StereoModelParams(), m_p.viewTurnDeg);
  bool mbt = false;
  for (const std::string &k : m_p.trackers)
    mbt = mbt || k.rfind("mbt", 0) == 0;
  if (m_p.mbtTrueCad && !(m_p.mbtMeshCellMm > 0))
    throw core::Error("compare: the true CAD model is decimated to cells of --mbt-mesh-cell-mm, which must be above 0");
  const bool aaForMbt = mbt && m_p.mbtMeshCellMm > 0 && !m_p.mbtTrueCad;
  model::AllAroundParams aa;
  aa.surface.refineOutlines = m_p.refineOutlines;
  aa.viewpoints.count = m_p.viewpoints;
  aa.viewpoints.inMinInsidePx = m_p.minInsidePx;
  if (has(m_p.trackers, "ours-aa") || has(m_p.trackers, "ours-aa-rmga") || aaForMbt)
    m_s->allAround = lab::makeSimulatedAllAroundModel(m_s->scene, rig, m_p.pass, "pa10", m_p.distanceMm, aa,
                                                      aaForMbt ? &m_s->allAroundBuild : nullptr, m_p.calibrateTrust); // the build kept only for its mesh
  if (aaForMbt)
    m_s->cad = m_s->allAroundBuild.mesh.decimated(m_p.mbtMeshCellMm);
  if (mbt && m_p.mbtTrueCad) {
    m_s->cad = toyCadMesh(sim::buildTargetMesh(m_s->scene.target(), 1.0)).decimated(m_p.mbtMeshCellMm);
    m_s->cadIsTrue = true;
  }
}

Comparison::~Comparison() = default;

std::string Comparison::caoText() const
{
  if (m_s->cadIsTrue)
    return meshCaoText(m_s->cad, "the true mesh of " + m_p.target + " (the lab's), decimated to " + std::to_string(m_s->cad.triangles.size()) +
                                     " triangles, metres, the toy's own frame");
  if (!m_s->cad.triangles.empty())
    return meshCaoText(m_s->cad, "surface of " + m_p.target + " from its all-around photo-model, " + std::to_string(m_s->cad.triangles.size()) +
                                     " triangles, metres, the all-around model's frame");
  return compare::caoText(m_s->outline, "outline of " + m_p.target + " from its photo-model, " + std::to_string(m_s->outline.size()) +
                                            " vertices, metres, model frame");
}

std::size_t Comparison::totalFrames() const
{
  std::size_t n = 0;
  for (const auto &s : m_s->scenarios)
    n += s.frames.size();
  return n;
}

ComparisonResult Comparison::run(const std::string &caoPath, std::ostream &csv, const std::function<void()> &onFrame)
{
  const core::CameraRig &rig = m_rig;
  Setup &s = *m_s;
  auto makeTracker = [&](const std::string &key) -> std::unique_ptr<ComparedTracker> {
    if (key == "ours")
      return makeOurTracker(rig, s.flat.build.model, m_p.tracker);
    if (key == "ours-3d")
      return makeOurTracker(rig, s.stereo.build.model, m_p.tracker, "photo-model with depth (ours, stereo model)");
    if (key == "ours-aa")
      return makeOurTracker(rig, s.allAround.build.model, m_p.tracker, "all-around photo-model (ours, PA-10 pass)");
    if (key == "ours-aa-rmga") {
      tracker::TrackerParams rmga = m_p.tracker;
      rmga.refinement.precise.enabled = false;
      return makeOurTracker(rig, s.allAround.build.model, rmga, "all-around photo-model, RM-GA alone (ours, no precise stage)");
    }
    if (key == "ours-steady") {
      tracker::TrackerParams fast = m_p.tracker;
      fast.steady.budgetFraction = m_p.steadyVariant;
      return makeOurTracker(rig, s.flat.build.model, fast,
                            "photo-model (ours, steady frames " + std::to_string(std::lround(100 * m_p.steadyVariant)) + " %)");
    }
    if (key == "mbt-edge")
      return makeMbtTracker(rig, MbtFeatures::Edge, caoPath, m_p.mbtXml);
    if (key == "mbt-klt")
      return makeMbtTracker(rig, MbtFeatures::Klt, caoPath, m_p.mbtXml);
    if (key == "mbt-edge-klt")
      return makeMbtTracker(rig, MbtFeatures::EdgeKlt, caoPath, m_p.mbtXml);
    if (key == "template-ssd")
      return makeTemplateTracker(rig, TemplateCost::Ssd, s.outline);
    return makeTemplateTracker(rig, TemplateCost::Zncc, s.outline);
  };

  ComparisonResult r;
  r.scenarios = s.scenarios;
  r.keys = m_p.trackers;
  const std::size_t nT = r.keys.size(), nS = r.scenarios.size();
  r.names.resize(nT);
  r.needsPose.resize(nT);
  r.scores.assign(nS, std::vector<std::vector<FrameScore>>(nT));
  r.perScenario.assign(nS, std::vector<Summary>(nT));
  csv << "scenario,frame,t,tracker,translation_error_mm,rotation_error_deg,frame_ms,valid\n" << std::setprecision(6);
  for (std::size_t si = 0; si < nS; ++si) {
    const Scenario &seq = r.scenarios[si];
    std::vector<std::unique_ptr<ComparedTracker>> ts;
    for (std::size_t ti = 0; ti < nT; ++ti) {
      ts.push_back(makeTracker(r.keys[ti]));
      r.names[ti] = ts.back()->name();
      r.needsPose[ti] = ts.back()->needsInitialPose();
    }
    for (std::size_t k = 0; k < seq.frames.size(); ++k) {
      const ScenarioFrame &f = seq.frames[k];
      const std::vector<vpImage<vpRGBa>> views = renderScenarioViews(s.scene, rig, seq, k);
      const core::CameraImages im = core::CameraImages::of(views);
      const bool snap = k + 1 == seq.frames.size() / 2 || k + 1 == seq.frames.size();
      vpImage<vpRGBa> shot;
      if (snap) {
        shot = im[0];
        drawOutline(shot, s.outline, f.hMo * s.flat.oMm, rig[0], vpRGBa(255, 255, 255));
      }
      for (std::size_t ti = 0; ti < nT; ++ti) {
        const vpHomogeneousMatrix truth = f.hMo * s.ownFrame(r.keys[ti]); // each tracker in its own model frame
        if (k == 0)
          ts[ti]->start(im, truth);
        const auto t0 = std::chrono::steady_clock::now();
        const Estimate e = ts[ti]->track(im);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        FrameScore sc = scoreFrame(e.hMm, truth);
        sc.ms = ms;
        sc.valid = e.valid;
        r.scores[si][ti].push_back(sc);
        if (snap) // the outline is in the flat model's frame: an estimate of another model's frame is moved to it
          drawOutline(shot, s.outline, e.hMm * s.ownFrame(r.keys[ti]).inverse() * s.flat.oMm, rig[0], trackerColor(ti));
        csv << seq.name << "," << k << "," << static_cast<double>(k) / seq.fps << "," << r.keys[ti] << "," << sc.translationMm << ","
            << sc.rotationDeg << "," << sc.ms << "," << (sc.valid ? 1 : 0) << "\n";
      }
      if (snap) {
        r.snapshots.push_back(shot);
        r.snapshotFrames.push_back(static_cast<long>(k));
      }
      if (onFrame)
        onFrame();
    }
    for (std::size_t ti = 0; ti < nT; ++ti)
      r.perScenario[si][ti] = summarize(r.scores[si][ti], seq.lossEnds);
  }
  if (!csv)
    throw core::Error("cannot write the frames' table");

  r.overall.resize(nT);
  for (std::size_t ti = 0; ti < nT; ++ti) {
    std::vector<Summary> parts;
    std::vector<std::vector<FrameScore>> frames;
    for (std::size_t si = 0; si < nS; ++si) {
      parts.push_back(r.perScenario[si][ti]);
      frames.push_back(r.scores[si][ti]);
    }
    r.overall[ti] = pool(parts, frames);
  }
  // What times are held against: "ours" when run, else the first of ours that was ("ours-aa", ...).
  r.ours = static_cast<std::size_t>(std::find(r.keys.begin(), r.keys.end(), "ours") - r.keys.begin());
  if (r.ours == r.keys.size())
    r.ours = static_cast<std::size_t>(std::find_if(r.keys.begin(), r.keys.end(), [](const std::string &k) {
                                        return k.rfind("ours", 0) == 0;
                                      }) - r.keys.begin());
  for (const auto &sc : r.scenarios)
    r.hadLoss = r.hadLoss || !sc.lossEnds.empty();
  // ViSP's fastest tracker in this run: what our time per frame is held against.
  r.fastest = nT;
  for (std::size_t ti = 0; ti < nT; ++ti)
    if (r.needsPose[ti] && (r.fastest == nT || r.overall[ti].meanMs < r.overall[r.fastest].meanMs))
      r.fastest = ti;
  return r;
}

std::string comparisonTable(const ComparisonResult &r)
{
  const std::size_t nT = r.keys.size();
  const bool haveOurs = r.ours < nT;
  std::ostringstream md;
  md << "| tracker | initial pose | ms/frame mean (p99) | time / ours | translation error mean (max) mm | rotation error mean (max) deg "
        "| success 5 cm 5 deg | success 1 cm 2 deg | recovery frames |\n|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t ti = 0; ti < nT; ++ti) {
    const Summary &s = r.overall[ti];
    md << "| " << r.names[ti] << " | " << (r.needsPose[ti] ? "needed" : "not needed") << " | " << fmt(s.meanMs, 2) << " ("
       << fmt(s.p99Ms, 2) << ") | " << (haveOurs ? fmt(s.meanMs / r.overall[r.ours].meanMs, 2) : "-") << " | "
       << fmt(s.meanTranslationMm, 1) << " (" << fmt(s.maxTranslationMm, 1) << ") | " << fmt(s.meanRotationDeg, 2) << " ("
       << fmt(s.maxRotationDeg, 1) << ") | " << fmt(100 * s.success5cm5deg, 1) << " % | " << fmt(100 * s.success1cm2deg, 1)
       << " % | " << recoveryText(s, r.hadLoss) << " |\n";
  }
  if (r.fastest < nT)
    for (std::size_t ti = 0; ti < nT; ++ti)
      if (!r.needsPose[ti])
        md << (ti == 0 ? "\n" : "") << "- " << r.names[ti] << ": " << fmt(r.overall[ti].meanMs, 2) << " ms per frame, "
           << fmt(r.overall[ti].meanMs / r.overall[r.fastest].meanMs, 2) << " times ViSP's fastest here (" << r.names[r.fastest] << ", "
           << fmt(r.overall[r.fastest].meanMs, 2) << " ms)\n";
  md << "\nPer scenario, success 5 cm 5 deg / 1 cm 2 deg (mean translation error):\n\n| tracker |";
  for (const auto &s : r.scenarios)
    md << " " << s.name << " |";
  md << "\n|---|";
  for (std::size_t si = 0; si < r.scenarios.size(); ++si)
    md << "---|";
  md << "\n";
  for (std::size_t ti = 0; ti < nT; ++ti) {
    md << "| " << r.names[ti] << " |";
    for (std::size_t si = 0; si < r.scenarios.size(); ++si) {
      const Summary &p = r.perScenario[si][ti];
      md << " " << fmt(100 * p.success5cm5deg, 0) << " / " << fmt(100 * p.success1cm2deg, 0) << " % (" << fmt(p.meanTranslationMm, 1)
         << " mm) |";
    }
    md << "\n";
  }
  return md.str();
}

} // namespace pm::compare
