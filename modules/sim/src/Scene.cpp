#include "pm/sim/Scene.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <mutex>

#include <opencv2/imgproc.hpp>

#include "pm/core/BatchPool.h"
#include "pm/core/Error.h"
#include "pm/core/Pose.h"
#include "pm/sim/Clutter.h"
#include "pm/sim/Noise.h"
#include "pm/sim/TargetCatalog.h"

namespace pm::sim {

namespace {
//! Whether \e M is exactly the identity (a backdrop where it rests).
bool isIdentity(const vpHomogeneousMatrix &M)
{
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 4; ++c)
      if (M[r][c] != (r == c ? 1.0 : 0.0))
        return false;
  return true;
}
} // namespace


void SceneParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("scene parameter ") + what);
  };
  check(supersampling >= 1 && supersampling <= 4, "supersampling must lie in [1, 4]");
  check(noiseSigma >= 0 && noiseSigma <= 100, "noise sigma must lie in [0, 100] grey levels");
  check(exposure > 0 && exposure <= 10, "exposure must lie in (0, 10]");
  check(ambient >= 0 && diffuse >= 0 && specular >= 0, "ambient, diffuse and specular must be non-negative");
  check(meshStepMm >= 0.2 && meshStepMm <= 10, "mesh step must lie in [0.2, 10] mm");
  check(std::isfinite(lightDirHand[0] + lightDirHand[1] + lightDirHand[2]) &&
            std::fabs(lightDirHand[0]) + std::fabs(lightDirHand[1]) + std::fabs(lightDirHand[2]) > 0,
        "light direction must be a non-zero vector");
  check(occluderSizeMm[0] > 0 && occluderSizeMm[1] > 0, "occluder size must be positive");
  check(barWidthMm > 0 && barTravelMm > 0 && barMmPerFrame > 0 && barDepthMm < 0,
        "sweeping bar: width, travel and speed must be positive, its depth negative (in front of the toy)");
  check(std::isfinite(backdropHueDriftDegPerS) && std::fabs(backdropHueDriftDegPerS) <= 90,
        "backdrop hue drift must lie in [-90, 90] degrees a second");
  gripperShape.validate();
  variation.validate();
  check(stillBackdropGapMm >= 0 && stillBackdropGapMm <= 500, "still backdrop: its gap must lie in [0, 500] mm");
  check(shadows == ShadowMode::Auto || shadows == ShadowMode::Off || shadows == ShadowMode::On,
        "shadow mode must be Auto, Off or On");
  check(std::isfinite(sceneLightDir[0] + sceneLightDir[1] + sceneLightDir[2]) && sceneLightDir[2] < 0,
        "scene light direction must be finite and point toward the front (negative z: the viewer's side)");
  check(sceneSpecular >= 0 && sceneSpecular <= 10, "scene specular must lie in [0, 10]");
  check(sceneShininess >= 1 && sceneShininess <= 1000, "scene shininess must lie in [1, 1000]");
  check(shadowTexelMm >= 0.05 && shadowTexelMm <= 5, "shadow texel must lie in [0.05, 5] mm");
  core::Phi d{distractorPose[0], distractorPose[1], distractorPose[2], distractorPose[3], distractorPose[4], distractorPose[5]};
  check(d.isValid() && std::fabs(d.x) < 1e4 && std::fabs(d.y) < 1e4 && std::fabs(d.z) < 1e4,
        "distractor pose must be finite, within 10 m, with |eps| <= 1");
}

struct Scene::ShadowCache
{
  std::mutex mutex;
  std::shared_ptr<const ShadowMap> map;
  double dir[3] = {0, 0, 0}, texelMm = 0;
};

bool Scene::sceneLit() const
{
  switch (m_params.shadows) {
  case ShadowMode::On:
    return true;
  case ShadowMode::Off:
    return false;
  case ShadowMode::Auto:
    break;
  }
  return isReliefTarget(m_target.info.code);
}

std::shared_ptr<const ShadowMap> Scene::shadowMap() const
{
  std::lock_guard<std::mutex> lock(m_shadowCache->mutex);
  ShadowCache &c = *m_shadowCache;
  const double *d = m_params.sceneLightDir;
  if (!c.map || c.dir[0] != d[0] || c.dir[1] != d[1] || c.dir[2] != d[2] || c.texelMm != m_params.shadowTexelMm) {
    m_params.validate();
    c.map = std::make_shared<const ShadowMap>(m_toy, d, m_params.shadowTexelMm * 1e-3);
    std::copy(d, d + 3, c.dir);
    c.texelMm = m_params.shadowTexelMm;
  }
  return c.map;
}

//! A distorted camera's ideal canvas (big enough for the whole raw image) and the raw image's map into it.
struct LensWarp
{
  vpCameraParameters canvasCam;
  unsigned canvasW = 0, canvasH = 0;
  cv::Mat mapU, mapV; //!< canvas position of each raw pixel
  std::vector<double> key;
};

struct Scene::LensCache
{
  std::mutex mutex;
  std::vector<std::shared_ptr<const LensWarp>> warps;
  std::shared_ptr<const LensWarp> get(const core::PinholeCamera &camera)
  {
    std::vector<double> key{camera.cam.get_px(), camera.cam.get_py(), camera.cam.get_u0(), camera.cam.get_v0(),
                            static_cast<double>(camera.width), static_cast<double>(camera.height)};
    key.insert(key.end(), camera.distortion.coefficients.begin(), camera.distortion.coefficients.end());
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto &w : warps)
      if (w->key == key)
        return w;
    camera.distortion.validate(camera.cam, camera.width, camera.height, camera.name + " camera");
    auto w = std::make_shared<LensWarp>();
    w->key = key;
    const int W = static_cast<int>(camera.width), H = static_cast<int>(camera.height);
    std::vector<vpImagePoint> raw;
    raw.reserve(static_cast<std::size_t>(W) * static_cast<std::size_t>(H));
    for (int v = 0; v < H; ++v)
      for (int u = 0; u < W; ++u)
        raw.emplace_back(v, u);
    const std::vector<vpImagePoint> ideal = camera.distortion.undistort(camera.cam, raw);
    double umin = 0, umax = W - 1, vmin = 0, vmax = H - 1;
    for (const vpImagePoint &p : ideal) {
      umin = std::min(umin, p.get_u());
      umax = std::max(umax, p.get_u());
      vmin = std::min(vmin, p.get_v());
      vmax = std::max(vmax, p.get_v());
    }
    umin = std::floor(umin) - 2;
    vmin = std::floor(vmin) - 2;
    w->canvasW = static_cast<unsigned>(std::ceil(umax - umin) + 3);
    w->canvasH = static_cast<unsigned>(std::ceil(vmax - vmin) + 3);
    if (w->canvasW > 4 * camera.width || w->canvasH > 4 * camera.height)
      throw core::Error(camera.name + " camera: its lens (" + camera.distortion.describe() +
                  ") spreads the image over more than four times its size; the simulator does not render it");
    w->canvasCam.initPersProjWithoutDistortion(camera.cam.get_px(), camera.cam.get_py(), camera.cam.get_u0() - umin,
                                               camera.cam.get_v0() - vmin);
    w->mapU.create(H, W, CV_32F);
    w->mapV.create(H, W, CV_32F);
    for (int v = 0; v < H; ++v)
      for (int u = 0; u < W; ++u) {
        const vpImagePoint &p = ideal[static_cast<std::size_t>(v) * static_cast<std::size_t>(W) + static_cast<std::size_t>(u)];
        w->mapU.at<float>(v, u) = static_cast<float>(p.get_u() - umin);
        w->mapV.at<float>(v, u) = static_cast<float>(p.get_v() - vmin);
      }
    warps.push_back(w);
    return w;
  }
};

Scene::Scene(const TargetShape &target, const SceneParams &params)
    : m_target(target), m_params(params), m_stillGapMm(params.stillBackdropGapMm), m_shadowCache(std::make_shared<ShadowCache>()),
      m_lensCache(std::make_shared<LensCache>())
{
  m_params.validate();
  m_toy = buildTargetMesh(m_target, m_params.meshStepMm, static_cast<float>(m_params.specular));
  // The panel the toy rests on, and the still one farther back (either may be drawn: SceneParams::stillBackdrop).
  const std::shared_ptr<const Texture> sea = makeSeaBottomTexture(m_params.seaBottom);
  m_backdrop = makeBackdropMesh(sea, m_params.seaBottom, m_params.backdropGapMm);
  m_stillBackdrop = makeBackdropMesh(sea, m_params.seaBottom, m_params.backdropGapMm + m_stillGapMm);
  // The occluder: a strand of seaweed, a flat olive-green quad with a little texture.
  const double *c = m_params.occluderCentreMm;
  m_occluder = makeFlatQuad(c[0], c[1], c[2], m_params.occluderSizeMm[0], m_params.occluderSizeMm[1], 60, 120, 40);
  // The sweeping bar: a violet quad centred on the target's z axis, moved along x at each render.
  m_bar = makeFlatQuad(0, 0, m_params.barDepthMm, m_params.barWidthMm, 300, 120, 50, 140);
  m_gripper = makeGripperMesh(m_params.gripperShape); // in the hand frame
  // The clutter stands where the target's base rests: on the panel, or on the still panel farther back.
  if (m_params.clutter)
    for (const ClutterToy &t : clutterAround(m_target)) {
      const double *p = t.poseMm;
      m_clutter.push_back({buildTargetMesh(makeTarget(t.code), m_params.meshStepMm, static_cast<float>(m_params.specular)),
                           core::toHomogeneousMatrix(core::Phi{p[0], p[1], p[2], p[3], p[4], p[5]})});
    }
}

Mesh Scene::makeFlatQuad(double xMm, double yMm, double zMm, double widthMm, double heightMm, int r, int g, int b)
{
  // A flat quad facing the hand (-z), of colour (r, g, b) with a little texture.
  const std::shared_ptr<Texture> tex = speckledTexture(8, 64, 5, 0.8, 0.4, [&](int, int) {
    return std::array<double, 3>{static_cast<double>(r), static_cast<double>(g), static_cast<double>(b)};
  });
  const float cx = static_cast<float>(xMm * 1e-3), cy = static_cast<float>(yMm * 1e-3), cz = static_cast<float>(zMm * 1e-3);
  const float hw = static_cast<float>(widthMm / 2e3), hh = static_cast<float>(heightMm / 2e3);
  Mesh m;
  m.vertices = {{cx - hw, cy - hh, cz, 0, 0, -1, 0, 0, -1},
                {cx + hw, cy - hh, cz, 0, 0, -1, 7, 0, -1},
                {cx + hw, cy + hh, cz, 0, 0, -1, 7, 63, -1},
                {cx - hw, cy + hh, cz, 0, 0, -1, 0, 63, -1}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.texture = tex;
  return m;
}

Scene Scene::targetAlone() const
{
  Scene s = *this;
  s.m_params.distractor = false;
  s.m_params.clutter = false;
  s.m_params.occluder = false;
  s.m_params.sweepingBar = false;
  s.m_params.gripper = false;
  s.m_params.backdropHueDriftDegPerS = 0; // the pass sees the background as it was
  return s;
}

double Scene::barOffsetMm(std::uint64_t frame) const
{
  // To and fro over [-travel / 2, travel / 2], starting at the left end.
  const double travel = m_params.barTravelMm, period = 2 * travel;
  const double d = std::fmod(static_cast<double>(frame) * m_params.barMmPerFrame, period);
  return (d < travel ? d : period - d) - travel / 2;
}

void Scene::setDistractor(const TargetShape &shape)
{
  m_distractor = buildTargetMesh(shape, m_params.meshStepMm, static_cast<float>(m_params.specular));
}

void Scene::render(Rasterizer &raster, const core::PinholeCamera &camera, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
                   unsigned stream, vpImage<vpRGBa> &out, bool withTarget, const vpHomogeneousMatrix &oMb) const
{
  // Another camera's images (SceneParams::variation): the optics before the sensor's noise, its processing after.
  // A background that changes (SceneParams::backdropHueDriftDegPerS) is turned before the noise too.
  const ImageVariation &variation = m_params.variation;
  const bool vary = variation.any(), drift = m_params.backdropHueDriftDegPerS != 0;
  const std::uint64_t noiseSeed = hash64(m_params.seed ^ hash64(frame * 8 + stream));
  if (camera.distortion.isNone()) {
    renderIdeal(raster, camera, hMo, frame, stream, out, withTarget, vary || drift ? 0.0 : m_params.noiseSigma, oMb);
    if (drift)
      driftBackdropHue(raster, frame, out);
    if (!vary && !drift)
      return;
  } else {
    const std::shared_ptr<const LensWarp> warp = m_lensCache->get(camera);
    core::PinholeCamera ideal = camera;
    ideal.cam = warp->canvasCam;
    ideal.width = warp->canvasW;
    ideal.height = warp->canvasH;
    ideal.distortion = core::LensDistortion();
    vpImage<vpRGBa> canvas;
    renderIdeal(raster, ideal, hMo, frame, stream, canvas, withTarget, 0.0, oMb);
    if (drift)
      driftBackdropHue(raster, frame, canvas);
    out.resize(camera.height, camera.width);
    const cv::Mat src(static_cast<int>(canvas.getHeight()), static_cast<int>(canvas.getWidth()), CV_8UC4, canvas.bitmap);
    cv::Mat dst(static_cast<int>(camera.height), static_cast<int>(camera.width), CV_8UC4, out.bitmap);
    cv::remap(src, dst, warp->mapU, warp->mapV, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  }
  if (vary)
    variation.applyOptics(out);
  Rasterizer::addNoise(out, m_params.noiseSigma, noiseSeed);
  if (vary)
    variation.applyAfterSensor(out, hash64(noiseSeed ^ 0x5407u)); // the shot noise's own draws
}

void Scene::driftBackdropHue(const Rasterizer &raster, std::uint64_t frame, vpImage<vpRGBa> &image) const
{
  // A turn of the colours about the grey axis (brightness kept): cos t I + (1 - cos t) / 3 J + sin t / sqrt(3) K,
  // J all ones, K the cross product with (1, 1, 1); blended by the pixel's share of backdrop (its edges).
  const double t = m_params.backdropHueDriftDegPerS * static_cast<double>(frame) / kLabFramesPerSecond * M_PI / 180.0;
  const double c = std::cos(t), a = (1 - c) / 3, b = std::sin(t) / std::sqrt(3.0);
  const double m[3][3] = {{c + a, a - b, a + b}, {a + b, c + a, a - b}, {a - b, a + b, c + a}};
  for (unsigned v = 0; v < image.getHeight(); ++v)
    for (unsigned u = 0; u < image.getWidth(); ++u) {
      const double share = raster.coverage(u, v, 1);
      if (share <= 0)
        continue;
      vpRGBa &p = image[v][u];
      const double in[3] = {static_cast<double>(p.R), static_cast<double>(p.G), static_cast<double>(p.B)};
      unsigned char *ch[3] = {&p.R, &p.G, &p.B};
      for (int i = 0; i < 3; ++i) {
        const double turned = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2];
        *ch[i] = static_cast<unsigned char>(std::clamp(std::lround(share * turned + (1 - share) * in[i]), 0L, 255L));
      }
    }
}

void Scene::renderIdeal(Rasterizer &raster, const core::PinholeCamera &camera, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
                        unsigned stream, vpImage<vpRGBa> &out, bool withTarget, double noiseSigma, const vpHomogeneousMatrix &oMb) const
{
  if (raster.width() != camera.width || raster.height() != camera.height || raster.supersampling() != m_params.supersampling)
    raster.reset(camera.width, camera.height, m_params.supersampling);
  const bool lit = sceneLit();
  const vpHomogeneousMatrix cMh = camera.cMh();
  const vpHomogeneousMatrix cMo = cMh * hMo;
  Lighting light;
  light.ambient = m_params.ambient;
  light.diffuse = m_params.diffuse;
  for (unsigned i = 0; i < 3; ++i) {
    light.dirCamera[i] = 0;
    for (unsigned k = 0; k < 3; ++k)
      light.dirCamera[i] += cMh[i][k] * m_params.lightDirHand[k];
  }
  std::shared_ptr<const ShadowMap> shadow;
  Lighting toyLight = light;
  if (lit) {
    // The scene light, fixed in the target frame, in this camera's frame; the toy's shadow map.
    shadow = shadowMap();
    const double *t = shadow->towardLight();
    for (unsigned i = 0; i < 3; ++i) {
      light.dirCamera[i] = 0;
      for (unsigned k = 0; k < 3; ++k)
        light.dirCamera[i] += cMo[i][k] * t[k];
    }
    toyLight = light;
    toyLight.shadow = shadow.get();
    if (withTarget) // no toy, no shadow (the background photo)
      light.shadow = shadow.get();
    toyLight.specular = m_params.sceneSpecular;
    toyLight.shininess = m_params.sceneShininess;
  }
  Rasterizer::DrawCall calls[10];
  std::size_t n = 0;
  auto add = [&](const Mesh &mesh, const vpHomogeneousMatrix &M, const Lighting &l, std::uint8_t id) {
    calls[n].mesh = &mesh;
    calls[n].cMo = M;
    calls[n].light = l;
    calls[n].id = id;
    ++n;
  };
  // Front to back: the gripper, the occluders, the toys, then the backdrop behind them all, whose samples under
  // a toy then fail the depth test before they are shaded (the same image: no two surfaces are at
  // the same depth, the backdrop lies backdropGapMm behind the toys' base).
  if (m_params.gripper) {
    Lighting onHand = light;
    onHand.shadow = nullptr; // the toy's shadow map does not hold the fingers, nor their shadow
    add(m_gripper, cMh, onHand, 3);
  }
  if (m_params.occluder)
    add(m_occluder, cMo, light, 3);
  if (m_params.sweepingBar)
    add(m_bar, cMo * vpHomogeneousMatrix(barOffsetMm(frame) * 1e-3, 0, 0, 0, 0, 0), light, 3);
  if (withTarget)
    add(m_toy, cMo, toyLight, 2);
  if (m_params.distractor && hasDistractor()) {
    const double *d = m_params.distractorPose;
    Lighting look = toyLight;
    look.shadow = nullptr; // the toy's shadow map does not hold it
    add(m_distractor, cMo * core::toHomogeneousMatrix(core::Phi{d[0], d[1], d[2], d[3], d[4], d[5]}), look, 4);
  }
  // The clutter stands on the panel drawn: the resting one, or the still one farther back.
  const vpHomogeneousMatrix onPanel =
      m_params.stillBackdrop ? oMb * vpHomogeneousMatrix(0, 0, 1e-3 * m_stillGapMm, 0, 0, 0) : oMb;
  if (m_params.clutter)
    for (const ClutterMesh &c : m_clutter) {
      Lighting look = toyLight;
      look.shadow = nullptr; // the toy's shadow map does not hold them
      add(c.mesh, cMo * onPanel * c.oMn, look, 4);
    }
  if (!m_params.stillBackdrop && isIdentity(oMb)) {
    add(m_backdrop, cMo, light, 1);
  } else {
    Lighting still = light;
    still.shadow = nullptr; // the toy's shadow map is of the panel it rests on: none on a still one, at rest or not
    add(m_params.stillBackdrop ? m_stillBackdrop : m_backdrop, cMo * oMb, still, 1);
  }
  const std::uint64_t noiseSeed = hash64(m_params.seed ^ hash64(frame * 8 + stream));
  const float tank[3] = {0.04f, 0.06f, 0.09f}; // the dark tank beyond the panel
  raster.render(tank, calls, n, camera.cam, out, m_params.exposure, noiseSigma, noiseSeed);
}

std::vector<vpImage<vpRGBa>> Scene::renderRig(const core::CameraRig &rig, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
                                              const vpHomogeneousMatrix &oMb) const
{
  rig.validate();
  std::vector<vpImage<vpRGBa>> im(rig.size());
  // The cameras on two cores, through the pool the fitness uses: an OpenMP region here left
  // libgomp's worker spinning after it, on the core the tracker's helper needs (1,900 evaluations
  // took 5.0 ms with it, 3.2 ms with OMP_WAIT_POLICY=passive).
  std::vector<std::exception_ptr> error(rig.size());
  core::BatchPool::shared().run(rig.size(), [&](std::size_t i) {
    try {
      // Each thread keeps its sample buffers from frame to frame (21 MB at 640 x 480 with
      // supersampling 2) instead of allocating and zeroing them anew (pm-bench
      // Render_StereoPair: 43.3 -> 40.7 ms in one measurement, within the spread between runs).
      // clear() sets every sample, so the images are the same.
      thread_local Rasterizer raster;
      render(raster, rig[i], hMo, frame, static_cast<unsigned>(i), im[i], true, oMb);
    } catch (...) {
      error[i] = std::current_exception();
    }
  });
  for (const auto &e : error)
    if (e)
      std::rethrow_exception(e);
  return im;
}

StereoImages Scene::renderStereo(const core::StereoRig &rig, const vpHomogeneousMatrix &hMo, std::uint64_t frame,
                                 const vpHomogeneousMatrix &oMb) const
{
  std::vector<vpImage<vpRGBa>> im = renderRig(rig, hMo, frame, oMb);
  StereoImages pair;
  pair.left = std::move(im[0]);
  pair.right = std::move(im[1]);
  return pair;
}

void Scene::renderPhotos(const vpCameraParameters &cam, unsigned w, unsigned h, double distanceMm,
                         vpImage<vpRGBa> &background, vpImage<vpRGBa> &withTarget) const
{
  if (!(distanceMm > 0))
    throw core::Error("photo distance must be positive");
  const core::PinholeCamera photo{"photo", cam, w, h, vpHomogeneousMatrix(), core::LensDistortion()};
  const vpHomogeneousMatrix hMo(0, 0, distanceMm * 1e-3, 0, 0, 0);
  Rasterizer r;
  render(r, photo, hMo, 0, 2, background, false);
  render(r, photo, hMo, 0, 3, withTarget, true);
}

} // namespace pm::sim
