#include "pm/model/AllAroundModelBuilder.h"
#include "pm/model/PassLandings.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <thread>

#include <opencv2/imgproc.hpp>

#include "pm/core/BatchPool.h"
#include "pm/core/Error.h"
#include "pm/core/Hue.h"
#include "pm/core/Rounding.h"
#include "pm/core/UndistortMap.h"
#include "pm/model/EdgeBlur.h"
#include "pm/model/HullMesh.h"
#include "pm/model/SubpixelOutline.h"
#include "pm/model/OutlineRefinement.h"
#include "pm/model/ViewpointModel.h"
#include "pm/model/VisualHull.h"

namespace pm::model {

namespace {

using hull::Vec3;
using hull::HullView;
using hull::cross;
using hull::dot;
using hull::sub;
using hull::unit;

//! Circular median-like hue: the sample with the least summed distance to the others (deg).
float medoidHue(const std::vector<float> &h, float &spread)
{
  float best = h[0];
  double bestSum = 1e18;
  for (float a : h) {
    double s = 0;
    for (float b : h)
      s += core::hueDistance(a, b);
    if (s < bestSum) {
      bestSum = s;
      best = a;
    }
  }
  std::vector<float> d;
  d.reserve(h.size());
  for (float b : h)
    d.push_back(core::hueDistance(best, b));
  std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
  spread = d[d.size() / 2];
  return best;
}

struct ColourSample
{
  float h, s, v;
  unsigned char r, g, b;
};

/*!
  The colour of surface point \e s from its samples: the median colour; highlights (much brighter
  and paler than the point's median) left out; the medoid hue of the saturated samples, the point
  marked (highlight) when they disagree over maxHueSpreadDeg; a hue far enough from \e bgHue may be S_in.
*/
void colourPoint(std::vector<ColourSample> &sm, float bgHue, const AllAroundParams &p, SurfacePoint &s, AllAroundBuild &out)
{
  s.hue = 0, s.r = s.g = s.b = 128, s.nSeen = static_cast<std::uint8_t>(std::min<std::size_t>(255, sm.size()));
  s.hasHue = false, s.highlight = false;
  if (sm.empty())
    return;
  std::vector<float> vs, ss;
  for (const ColourSample &c : sm)
    vs.push_back(c.v), ss.push_back(c.s);
  std::nth_element(vs.begin(), vs.begin() + static_cast<long>(vs.size() / 2), vs.end());
  std::nth_element(ss.begin(), ss.begin() + static_cast<long>(ss.size() / 2), ss.end());
  const float mv = vs[vs.size() / 2], ms = ss[ss.size() / 2];
  std::vector<float> hues;
  std::vector<unsigned char> rs, gs, bs;
  for (const ColourSample &c : sm) {
    if (sm.size() >= 3 && c.v > mv + 0.15f && c.s < ms - 0.1f) {
      ++out.nHighlightSamples;
      continue;
    }
    rs.push_back(c.r), gs.push_back(c.g), bs.push_back(c.b);
    if (c.s >= p.colour.minSaturation && c.v >= p.colour.minValue)
      hues.push_back(c.h);
  }
  auto med = [](std::vector<unsigned char> &x) {
    std::nth_element(x.begin(), x.begin() + static_cast<long>(x.size() / 2), x.end());
    return x[x.size() / 2];
  };
  if (!rs.empty())
    s.r = med(rs), s.g = med(gs), s.b = med(bs);
  if (hues.size() * 2 < sm.size() || hues.empty())
    return; // mostly pale: no hue to score
  float spread = 0;
  s.hue = medoidHue(hues, spread);
  if (hues.size() >= 2 && spread > p.colour.maxHueSpreadDeg) {
    s.highlight = true;
    ++out.nHighlight;
    return;
  }
  s.hasHue = core::hueDistance(s.hue, bgHue) > p.colour.minHueFromBackgroundDeg;
}

//! About \e n directions within \e capDeg of \e pole (a Fibonacci lattice about it), the pole first.
std::vector<Vec3> capDirections(const Vec3 &pole, double capDeg, int n)
{
  const double capCos = std::cos(capDeg * M_PI / 180);
  const int nSphere = static_cast<int>(std::ceil(n * 2.0 / (1.0 - capCos)));
  std::vector<Vec3> dirs{pole};
  const Vec3 a = unit(cross(pole, std::fabs(pole[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
  const Vec3 b = cross(pole, a);
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < nSphere; ++i) {
    const double zz = 1.0 - (i + 0.5) * 2.0 / nSphere;
    if (zz < capCos)
      break;
    const double r = std::sqrt(std::max(0.0, 1 - zz * zz)), phi = golden * i;
    const Vec3 d{zz * pole[0] + r * (std::cos(phi) * a[0] + std::sin(phi) * b[0]), zz * pole[1] + r * (std::cos(phi) * a[1] + std::sin(phi) * b[1]),
                 zz * pole[2] + r * (std::cos(phi) * a[2] + std::sin(phi) * b[2])};
    if (dot(d, pole) < 1 - 1e-6)
      dirs.push_back(d);
  }
  return dirs;
}

/*!
  The colour histograms of the target (the photos' pixels over 2 px inside the silhouettes) and of
  its surroundings (2 to 30 px outside), PhotoModel::kColourBins^3 bins each, normalised.
*/
void colourHistograms(const std::vector<const HullView *> &cams, std::vector<float> &fg, std::vector<float> &bg)
{
  const int B = core::PhotoModel::kColourBins, shift = 8 - 4; // 16 bins: the top 4 bits
  static_assert(core::PhotoModel::kColourBins == 16, "the shift assumes 16 bins per channel");
  fg.assign(static_cast<std::size_t>(B) * B * B, 0.f);
  bg.assign(fg.size(), 0.f);
  double nf = 0, nb = 0;
  for (const HullView *vc : cams)
    for (int y = 0; y < vc->cam.h; y += 2)
      for (int x = 0; x < vc->cam.w; x += 2) {
        const float d = vc->signedDist.at<float>(y, x);
        if (!(d > 2 || (d < -2 && d > -30)))
          continue;
        const vpRGBa c = vc->photo[static_cast<unsigned>(y)][static_cast<unsigned>(x)];
        const std::size_t bin = (static_cast<std::size_t>(c.R >> shift) * B + static_cast<std::size_t>(c.G >> shift)) * B +
                                static_cast<std::size_t>(c.B >> shift);
        if (d > 0)
          fg[bin] += 1.f, nf += 1;
        else
          bg[bin] += 1.f, nb += 1;
      }
  if (nf <= 0 || nb <= 0) {
    fg.clear(), bg.clear();
    return;
  }
  for (float &v : fg)
    v = static_cast<float>(v / nf);
  for (float &v : bg)
    v = static_cast<float>(v / nb);
}

} // namespace

namespace {

//! The pass's photos in the ideal images: each camera of each view with its silhouette's field.
struct PassImages
{
  std::vector<HullView> cams;                //!< two per view, left then right
  std::vector<vpImage<vpRGBa>> backgrounds;    //!< each camera's background (the photo against a plain backdrop)
  std::vector<std::string> names;              //!< each view's name
  std::vector<double> edgeWidthsPx;            //!< the first view's outline's rise in each camera where read (EdgeBlur.h)
};

constexpr std::size_t kMinEdgeSamples = 50; //!< fewer outline points read: the camera's softness is not judged

/*!
  S_in's distance inside the outline for images whose outline rises over \e widthPx (EdgeBlur.h;
  <= 0: not read): \e p's, plus blurInsideGain px per pixel of the blur's sigma beyond a sharp
  camera's, once that is over blurDeadZonePx.
*/
double minInsideForBlur(const AllAroundParams &p, double widthPx)
{
  if (!(widthPx > p.viewpoints.sharpEdgeWidthPx))
    return p.viewpoints.inMinInsidePx;
  const double sigma = std::sqrt(widthPx * widthPx - p.viewpoints.sharpEdgeWidthPx * p.viewpoints.sharpEdgeWidthPx) / 1.349; // 25-75 % of a Gaussian: 1.349 sigma
  return sigma < p.viewpoints.blurDeadZonePx ? p.viewpoints.inMinInsidePx : p.viewpoints.inMinInsidePx + p.viewpoints.blurInsideGain * sigma;
}

//! A raw image's signed distance \e dist resampled into the ideal image through \e map (in place); returns the ideal mask (255 where positive).
vpImage<unsigned char> idealSilhouette(const core::UndistortMap &map, cv::Mat &dist)
{
  if (!dist.isContinuous())
    dist = dist.clone();
  cv::Mat ideal(dist.rows, dist.cols, CV_32F);
  map.undistortField(dist.ptr<float>(), ideal.ptr<float>(), -1e3f);
  dist = ideal;
  vpImage<unsigned char> mask(static_cast<unsigned>(dist.rows), static_cast<unsigned>(dist.cols), 0);
  for (unsigned i = 0; i < mask.getSize(); ++i)
    mask.bitmap[i] = ideal.ptr<float>()[i] > 0 ? 255 : 0;
  return mask;
}

//! Stage 1: the silhouettes in the ideal images (out: silhouettes, shadowPx). Throws pm::core::Error.
PassImages silhouettesOfPass(const core::StereoRig &rig, const std::vector<PassView> &pass, const AllAroundParams &p, AllAroundBuild &out)
{
  PassImages images;
  std::vector<HullView> &cams = images.cams;
  std::vector<vpImage<vpRGBa>> &backgrounds = images.backgrounds;
  std::vector<std::string> &names = images.names;
  const core::PinholeCamera *rc[2] = {&rig.left, &rig.right};
  std::unique_ptr<core::UndistortMap> und[2];
  for (int c = 0; c < 2; ++c)
    if (!rc[c]->distortion.isNone())
      und[c] = std::make_unique<core::UndistortMap>(*rc[c]);
  for (std::size_t k = 0; k < pass.size(); ++k) {
    const PassView &v = pass[k];
    const std::string name = v.name.empty() ? "view " + std::to_string(k) : v.name;
    names.push_back(name);
    const vpImage<vpRGBa> *ph[2] = {&v.left, &v.right}, *bg[2] = {&v.backgroundLeft, &v.backgroundRight};
    for (int c = 0; c < 2; ++c) {
      const char *side = c ? "right" : "left";
      const bool plain = p.backdropHueDeg >= 0; // a plain backdrop: the photo alone
      for (const vpImage<vpRGBa> *im : {ph[c], bg[c]})
        if ((im == ph[c] || !plain) && (im->getWidth() != rc[c]->width || im->getHeight() != rc[c]->height))
          throw core::Error(name + ": a " + side + " image is " + std::to_string(im->getWidth()) + "x" +
                      std::to_string(im->getHeight()) + " but the rig's " + side + " camera is " +
                      std::to_string(rc[c]->width) + "x" + std::to_string(rc[c]->height));
      // The silhouette and its signed distance in the raw images; through a lens the distance is
      // resampled into the ideal image (a mask resampled would move its edge outward), the photos
      // too for their colours.
      const vpImage<vpRGBa> &rawBack = plain ? *ph[c] : *bg[c]; // against a plain backdrop the photo is its own background
      SilhouetteStats st;
      vpImage<unsigned char> mask = plain ? silhouetteOnBackdrop(*ph[c], p.backdropHueDeg, p.silhouette, &st, name + " (" + side + ")")
                                          : silhouette(*ph[c], rawBack, p.silhouette, &st, name + " (" + side + ")");
      if (st.touchesBorder)
        throw core::Error(name + ": the target is cut by the " + std::string(side) +
                    " image's border: every view must see the whole target");
      out.shadowPx += st.shadowPx;
      if (k == 0) { // how soft the camera's images are, across the first view's outline
        const EdgeWidth ew = edgeWidth(mask, *ph[c], plain ? nullptr : &rawBack);
        if (ew.samples >= kMinEdgeSamples)
          images.edgeWidthsPx.push_back(ew.widthPx);
      }
      HullView vc;
      vc.cam = core::PinholeCamera::Projection(v.fMh * rc[c]->hMc, rc[c]->cam, rc[c]->width, rc[c]->height);
      vc.signedDist = p.surface.refineOutlines ? hull::subpixelSignedDistance(mask, *ph[c], plain ? nullptr : &rawBack) : hull::signedDistance(mask);
      vpImage<vpRGBa> back = und[c] ? und[c]->undistorted(rawBack) : rawBack;
      vc.photo = und[c] ? und[c]->undistorted(*ph[c]) : *ph[c];
      if (und[c])
        mask = idealSilhouette(*und[c], vc.signedDist);
      vc.view = static_cast<int>(k);
      cams.push_back(std::move(vc));
      backgrounds.push_back(std::move(back));
      out.silhouettes.push_back(std::move(mask));
    }
  }

  return images;
}

//! The centroid of the hull's occupied cells (mm).
Vec3 occupiedCentroid(const VisualHull &g)
{
  Vec3 mean{0, 0, 0};
  {
    long nOcc = 0;
    for (int z = 0; z < g.n; ++z)
      for (int y = 0; y < g.n; ++y)
        for (int x = 0; x < g.n; ++x)
          if (g.occ[g.idx(x, y, z)]) {
            mean = hull::add(mean, g.centre(x, y, z));
            ++nOcc;
          }
    mean = hull::scaled(mean, 1.0 / static_cast<double>(nOcc));
  }
  return mean;
}

//! Stage 4: which cameras see each vertex (the mesh's depth, the normal facing the camera, off the outline).
std::vector<std::vector<std::uint16_t>> camerasSeeing(const std::vector<const HullView *> &usedCams, const HullMesh &mesh,
                                                      const AllAroundParams &p, ViewpointScratch &scratch)
{
  const std::vector<Vec3> &pts = mesh.vertices;
  const std::vector<Vec3> &normals = mesh.normals;
  std::vector<std::vector<std::uint16_t>> seenBy(pts.size());
  for (std::size_t ci = 0; ci < usedCams.size(); ++ci) {
    const HullView *vc = usedCams[ci];
    mesh.depthMap(vc->cam, scratch.zbuf, scratch.vertices);
    const std::vector<float> &zbuf = scratch.zbuf;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      double u, v, z;
      if (!vc->cam.project(pts[i], u, v, z))
        continue;
      const Vec3 toCam = unit(sub(vc->cam.centre, pts[i]));
      if (dot(toCam, normals[i]) < 0.2)
        continue;
      const int ui = static_cast<int>(core::roundHalfAway(u)), vi = static_cast<int>(core::roundHalfAway(v));
      if (ui < 0 || vi < 0 || ui >= vc->cam.w || vi >= vc->cam.h)
        continue;
      if (z > zbuf[static_cast<std::size_t>(vi) * static_cast<std::size_t>(vc->cam.w) + static_cast<std::size_t>(ui)] + p.surface.visibilityTolMm)
        continue;
      if (vc->sd(u, v) < 2) // on the outline the pixel mixes target and background
        continue;
      seenBy[i].push_back(static_cast<std::uint16_t>(ci));
    }
  }
  return seenBy;
}

//! Each vertex's colour in each camera that sees it.
std::vector<std::vector<ColourSample>> colourSamples(const std::vector<const HullView *> &usedCams,
                                                     const std::vector<std::vector<std::uint16_t>> &seenBy, const std::vector<Vec3> &pts)
{
  std::vector<std::vector<ColourSample>> samples(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::uint16_t ci : seenBy[i]) {
      const HullView *vc = usedCams[ci];
      double u, v, z;
      if (!vc->cam.project(pts[i], u, v, z))
        continue;
      const int ui = static_cast<int>(core::roundHalfAway(u)), vi = static_cast<int>(core::roundHalfAway(v));
      if (ui < 0 || vi < 0 || ui >= vc->cam.w || vi >= vc->cam.h)
        continue;
      const vpRGBa px = vc->photo[static_cast<unsigned>(vi)][static_cast<unsigned>(ui)];
      const core::Hsv hsv = core::rgbToHsv(px);
      samples[i].push_back({hsv.h, hsv.s, hsv.v, px.R, px.G, px.B});
    }
  return samples;
}

//! H_B: the mean hue of the backgrounds around the used views' silhouettes.
float backgroundHueAround(const PassImages &im, const std::vector<vpImage<unsigned char>> &silhouettes, const std::vector<bool> &used)
{
  const std::vector<HullView> &cams = im.cams;
  const std::vector<vpImage<vpRGBa>> &backgrounds = im.backgrounds;
  std::vector<float> bgHues;
  for (std::size_t i = 0; i < cams.size(); ++i) {
    if (!used[static_cast<std::size_t>(cams[i].view)])
      continue;
    for (unsigned y = 0; y < silhouettes[i].getHeight(); y += 3)
      for (unsigned x = 0; x < silhouettes[i].getWidth(); x += 3) {
        const float d = cams[i].signedDist.at<float>(static_cast<int>(y), static_cast<int>(x));
        if (d < -3 && d > -40)
          bgHues.push_back(core::hueDeg(backgrounds[i][y][x]));
      }
  }
  return bgHues.empty() ? 0.f : core::circularMeanHue(bgHues);

}

//! Stage 6: the model's viewpoints along \e dirs at \e D mm (the first is the model's own view; out: M's points).
void sampleViewpoints(const core::StereoRig &rig, const std::vector<Vec3> &dirs, double D, const vpHomogeneousMatrix &mMh0,
                      const HullMesh &mesh, float bgHue, const AllAroundParams &p,
                      ViewpointScratch &scratch, AllAroundBuild &out)
{
  const vpCameraParameters &ci = rig.left.cam;
  core::PhotoModel &M = out.model;
  M.distanceMm = D;
  M.px = ci.get_px(), M.py = ci.get_py(), M.u0 = ci.get_u0(), M.v0 = ci.get_v0();
  M.photoWidth = rig.left.width, M.photoHeight = rig.left.height;
  M.centroidU = M.u0, M.centroidV = M.v0;
  M.backgroundHue = bgHue;
  M.nInDropped = out.nHighlight;
  for (int k = 0; k < 3; ++k)
    M.originInHandMm[k] = 1e3 * mMh0.inverse()[static_cast<unsigned>(k)][3];
  // The viewpoints on two cores (BatchPool: on the caller alone while another build holds the pool,
  // as the held-out models of the trust's calibration do), each from its own buffers; then taken in order.
  std::vector<core::ModelView> sampled(dirs.size());
  std::vector<std::exception_ptr> failed(dirs.size());
  const std::thread::id caller = std::this_thread::get_id();
  core::BatchPool::shared().run(dirs.size(), [&](std::size_t vi) {
    try {
      thread_local ViewpointScratch helperScratch; // the helper thread's buffers, kept from one build to the next
      ViewpointScratch &own = std::this_thread::get_id() == caller ? scratch : helperScratch;
      const Vec3 C = hull::scaled(dirs[vi], D);
      const core::PinholeCamera::Projection cam = core::PinholeCamera::Projection::lookingAtOrigin(C, ci, rig.left.width, rig.left.height);
      sampled[vi] = sampleViewpoint(cam, out.surface, mesh, bgHue, p, own);
    } catch (...) {
      failed[vi] = std::current_exception();
    }
  });
  for (const std::exception_ptr &f : failed)
    if (f)
      std::rethrow_exception(f);
  std::vector<float> vz;
  for (std::size_t vi = 0; vi < dirs.size(); ++vi) {
    core::ModelView &view = sampled[vi];
    if (view.inner.size() < 8 || view.outer.size() < 8 || view.contour.size() < 8) {
      if (vi == 0)
        throw core::Error("all-around model: from the first view's direction fewer than 8 points with a hue are seen (" +
                    std::to_string(view.inner.size()) + "): the target's colours are too close to the background's");
      continue; // a direction from which too little is seen: its neighbours serve it
    }
    if (vi == 0) {
      M.inner = std::move(view.inner);
      M.outer = std::move(view.outer);
      M.contour = std::move(view.contour);
      for (int k = 0; k < 3; ++k)
        M.cameraMm[k] = view.cameraMm[k];
      std::vector<float> hs;
      const vpHomogeneousMatrix hM0m = mMh0.inverse();
      for (const core::ModelPoint &q : M.inner) {
        hs.push_back(q.hue);
        vz.push_back(static_cast<float>(hM0m[2][0] * q.x + hM0m[2][1] * q.y + hM0m[2][2] * q.z + 1e3 * hM0m[2][3]));
      }
      M.targetHue = core::circularMeanHue(hs);
    } else
      M.views.push_back(std::move(view));
  }
  if (!vz.empty()) {
    M.depthRangeMm[0] = *std::min_element(vz.begin(), vz.end());
    M.depthRangeMm[1] = *std::max_element(vz.begin(), vz.end());
  }
}

} // namespace

//! Stage 3: the hull carved (coarse to fine, then by the views' depths) and its surface as a mesh, its outlines refined when asked (out: volumes, fusion counts, residuals).
HullMesh carvedSurface(const core::StereoRig &rig, const PassImages &im, const std::vector<bool> &used,
                       const std::vector<const HullView *> &usedCams, const Vec3 &centre, const AllAroundParams &p, VisualHull &g,
                       AllAroundBuild &out, const DepthEvidence *measured, DepthEvidence *keep)
{
  const std::vector<HullView> &cams = im.cams;
  carveVisualHull(usedCams, g, p.carving.coarsestMm);
  out.hullVolumeCm3 = g.volumeCm3();
  DepthEvidence evidence;
  if (p.fusion.enabled) {
    if (measured) { // the views' depths measured already, on the whole pass: those of the views used here
      evidence = measured->only(used);
    } else {
      core::StereoRig ideal = rig; // the photos are ideal already
      ideal.left.distortion = ideal.right.distortion = core::LensDistortion();
      evidence = measureStereo(ideal, cams, out.silhouettes, im.backgrounds, used, p.backdropHueDeg >= 0, g, p.fusion);
      if (keep)
        *keep = evidence;
    }
    out.fusionCarvedCells = evidence.carve(g, usedCams);
    evidence.counts(out.matchedTargetPx, out.matchedBackdropPx);
    if (g.occupied() < 8)
      throw core::Error("all-around model: the views' depths carve the hull to nothing (the rig's calibration or the poses are off)");
  }
  // One field in mm: the silhouettes' (px, at the pass's distance) and the depths'.
  double mmPerPx = 1;
  {
    double u, v, z;
    if (cams.front().cam.project(centre, u, v, z))
      mmPerPx = z / cams.front().cam.px;
  }
  HullMesh mesh = meshField(g, [&](int x, int y, int z) {
    const Vec3 X = g.corner(x, y, z);
    const double px = hull::field(usedCams, X), f = px * mmPerPx;
    return p.fusion.enabled ? std::min(f, evidence.fieldInside(X, px)) : f;
  });
  // The outline on every view's at once, where the least of their distances left it inside.
  if (p.surface.refineOutlines) {
    const OutlineRefinementStats refined = refineOutlines(mesh, usedCams, p.surface.outline);
    out.outlineResidualBeforePx = refined.meanBeforePx;
    out.outlineResidualPx = refined.meanAfterPx;
    out.outlineResidualRmsPx = refined.rmsAfterPx;
  }
  return mesh;
}

//! What the builder measured of each view (PassMeasurements).
struct PassMeasurements::Data
{
  PassImages images;                                //!< each camera's ideal photo, silhouette field, background
  std::vector<vpImage<unsigned char>> silhouettes;  //!< the silhouettes (AllAroundBuild::silhouettes)
  long shadowPx = 0;                                //!< AllAroundBuild::shadowPx
  DepthEvidence evidence;                           //!< the stereo depths of every view used (empty without fusion)
};

namespace {

//! Stage 2's result: the hull's grid around the target, and the views that agree.
struct AgreeingViews
{
  Vec3 centre;                           //!< the box's centre (mm, world frame)
  VisualHull grid;                       //!< the hull's grid over the box, nothing carved yet
  std::vector<bool> used;                //!< per view: used (agrees with the others, not held out)
  std::vector<const HullView *> usedCams; //!< the cameras of the views used
};

//! Stage 2: the box around the target and the views that agree with the others, \e heldOut left out too (out: cellMm, leftOut, nViewsUsed). Throws pm::core::Error.
AgreeingViews boxAndAgreeingViews(const PassImages &im, std::size_t nViews, const AllAroundParams &p, const std::vector<std::size_t> &heldOut,
                                  AllAroundBuild &out)
{
  AgreeingViews a;
  double radius;
  hullBox(im.cams, out.silhouettes, a.centre, radius);
  a.grid = hullGrid(a.centre, radius, p.carving.finestMm);
  const VisualHull &g = a.grid;
  out.cellMm = g.cell;
  const int coarse = std::max(1, static_cast<int>(std::lround(4.0 / g.cell)));
  a.used = agreeingViews(im.cams, nViews, g.origin, (g.n + coarse - 1) / coarse, coarse * g.cell, p.carving.outlierCarveFraction, im.names, out.leftOut);
  for (std::size_t k : heldOut)
    a.used[k] = false;
  out.nViewsUsed = static_cast<std::size_t>(std::count(a.used.begin(), a.used.end(), true));
  if (out.nViewsUsed < p.carving.minViews)
    throw core::Error("all-around model: " + std::to_string(out.nViewsUsed) + " views agree, at least " +
                std::to_string(p.carving.minViews) + " are needed (" + (out.leftOut.empty() ? "" : out.leftOut[0]) + ")");
  for (const HullView &vc : im.cams)
    if (a.used[static_cast<std::size_t>(vc.view)])
      a.usedCams.push_back(&vc);
  return a;
}

//! The first view used: the model's frame and viewpoints come from it.
std::size_t firstUsed(const std::vector<bool> &used)
{
  std::size_t first = 0;
  while (!used[first])
    ++first;
  return first;
}

/*!
  Stage 5: the model frame (origin at \e mean, the hull's centroid; axes those of the hand at \e
  firstView) and the surface in it, each vertex coloured from its \e samples (out: fMm, surface,
  surfaceVolumeCm3, the highlights). The mesh is moved into the model frame.
*/
void surfaceInModelFrame(const PassView &firstView, const Vec3 &mean, std::vector<std::vector<ColourSample>> &samples, float bgHue,
                         const AllAroundParams &p, HullMesh &mesh, AllAroundBuild &out)
{
  const vpRotationMatrix fRm = firstView.fMh.getRotationMatrix();
  out.fMm = vpHomogeneousMatrix(vpTranslationVector(mean[0] * 1e-3, mean[1] * 1e-3, mean[2] * 1e-3), fRm);
  double mRf[9];
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c)
      mRf[3 * r + c] = fRm[c][r];
  mesh.transform(mRf, mean); // vertices and normals: the model frame from here on
  const std::vector<Vec3> &mpts = mesh.vertices, &mnorm = mesh.normals;
  out.surface.resize(mpts.size());
  for (std::size_t i = 0; i < mpts.size(); ++i) {
    SurfacePoint &s = out.surface[i];
    s.x = static_cast<float>(mpts[i][0]), s.y = static_cast<float>(mpts[i][1]), s.z = static_cast<float>(mpts[i][2]);
    s.nx = static_cast<float>(mnorm[i][0]), s.ny = static_cast<float>(mnorm[i][1]), s.nz = static_cast<float>(mnorm[i][2]);
    colourPoint(samples[i], bgHue, p, s, out);
  }
  out.surfaceVolumeCm3 = std::fabs(mesh.volume()) * 1e-3;
}

/*!
  Stage 6: the viewpoints, a Fibonacci lattice over the directions within capDeg of \e firstView's,
  at its distance, S_in kept farther inside a soft camera's outline (EdgeBlur.h; out: the model's
  views, edgeWidthPx, minInsidePx).
*/
void viewpointsOfModel(const core::StereoRig &rig, const PassView &firstView, const PassImages &im, const HullMesh &mesh, float bgHue,
                       const AllAroundParams &p, ViewpointScratch &scratch, AllAroundBuild &out)
{
  const vpHomogeneousMatrix mMh0 = out.fMm.inverse() * firstView.fMh;
  const Vec3 rest{1e3 * mMh0[0][3], 1e3 * mMh0[1][3], 1e3 * mMh0[2][3]};
  const double D = std::sqrt(dot(rest, rest));
  const std::vector<Vec3> dirs = capDirections(unit(rest), p.viewpoints.capDeg, p.viewpoints.count);
  AllAroundParams ps = p;
  if (!im.edgeWidthsPx.empty())
    out.edgeWidthPx = std::accumulate(im.edgeWidthsPx.begin(), im.edgeWidthsPx.end(), 0.0) / static_cast<double>(im.edgeWidthsPx.size());
  ps.viewpoints.inMinInsidePx = out.minInsidePx = minInsideForBlur(p, out.edgeWidthPx);
  sampleViewpoints(rig, dirs, D, mMh0, mesh, bgHue, ps, scratch, out);
}

/*!
  The build of the file's description, of \e pass without its views \e heldOut: from \e shared (the views
  measured already) or measuring them, then into \e keep when given.
*/
AllAroundBuild build(const core::StereoRig &rig, const std::vector<PassView> &pass, const AllAroundParams &p,
                     const PassMeasurements::Data *shared, PassMeasurements::Data *keep, const std::vector<std::size_t> &heldOut)
{
  const auto t0 = std::chrono::steady_clock::now();
  p.validate();
  rig.validate();
  if (pass.size() < p.carving.minViews)
    throw core::Error("all-around model: the pass holds " + std::to_string(pass.size()) + " views; at least " +
                std::to_string(p.carving.minViews) + " are needed");
  AllAroundBuild out;
  out.nViews = pass.size();
  PassImages own; // 1. silhouettes in the ideal images (measured already, or now)
  if (shared) {
    out.silhouettes = shared->silhouettes;
    out.shadowPx = shared->shadowPx;
  } else {
    own = silhouettesOfPass(rig, pass, p, out);
  }
  const PassImages &im = shared ? shared->images : own;
  AgreeingViews views = boxAndAgreeingViews(im, pass.size(), p, heldOut, out); // 2. the box; the views that agree
  VisualHull &g = views.grid;
  HullMesh mesh = carvedSurface(rig, im, views.used, views.usedCams, views.centre, p, g, out, shared ? &shared->evidence : nullptr,
                                keep ? &keep->evidence : nullptr); // 3. carving, the views' depths, the surface
  const Vec3 mean = occupiedCentroid(g);
  ViewpointScratch scratch; // the image-sized buffers, kept from one camera or viewpoint to the next
  const std::vector<std::vector<std::uint16_t>> seenBy = camerasSeeing(views.usedCams, mesh, p, scratch); // 4. who sees each point
  std::vector<std::vector<ColourSample>> samples = colourSamples(views.usedCams, seenBy, mesh.vertices);
  const float bgHue = backgroundHueAround(im, out.silhouettes, views.used);
  const PassView &firstView = pass[firstUsed(views.used)];
  surfaceInModelFrame(firstView, mean, samples, bgHue, p, mesh, out);          // 5. the model frame; the colours
  viewpointsOfModel(rig, firstView, im, mesh, bgHue, p, scratch, out);         // 6. the viewpoints
  core::PhotoModel &M = out.model;
  colourHistograms(views.usedCams, M.foregroundHistogram, M.backgroundHistogram); // 7. the colours, for the precise stage
  out.mesh = std::move(mesh);
  M.hasColours = true;
  if (p.passLandings) // 8. the model's own error at each view of the pass
    M.passLandings = measurePassLandings(rig, M, pass, views.used, out.fMm);
  M.validate("the all-around model");
  if (keep) {
    keep->silhouettes = out.silhouettes;
    keep->shadowPx = out.shadowPx;
    keep->images = std::move(own); // the last use of its cameras is above
  }
  out.buildS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

} // namespace

AllAroundBuild buildAllAroundModel(const core::StereoRig &rig, const std::vector<PassView> &pass, const AllAroundParams &p)
{
  return build(rig, pass, p, nullptr, nullptr, {});
}

AllAroundBuild buildAllAroundModel(const core::StereoRig &rig, const std::vector<PassView> &pass, const AllAroundParams &p,
                                   PassMeasurements &measured)
{
  auto data = std::make_shared<PassMeasurements::Data>();
  AllAroundBuild b = build(rig, pass, p, nullptr, data.get(), {});
  measured = PassMeasurements(std::move(data));
  return b;
}

AllAroundBuild buildAllAroundModelWithout(const core::StereoRig &rig, const std::vector<PassView> &pass, const AllAroundParams &p,
                                          const PassMeasurements &measured, const std::vector<std::size_t> &heldOut)
{
  if (measured.empty() || measured.data()->silhouettes.size() != 2 * pass.size())
    throw core::Error("all-around model: the pass's views were not measured (buildAllAroundModel() with its measurements first)");
  for (std::size_t k : heldOut)
    if (k == 0 || k >= pass.size())
      throw core::Error("all-around model: view " + std::to_string(k) + " cannot be held out (the first view, or none of the pass's " +
                        std::to_string(pass.size()) + ")");
  return build(rig, pass, p, measured.data().get(), nullptr, heldOut);
}

} // namespace pm::model
