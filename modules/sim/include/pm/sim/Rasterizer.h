#pragma once
/*!
  \file Rasterizer.h
  A small z-buffered, perspective-correct triangle rasterizer with supersampling, for the
  simulated cameras. Pinhole projection of vpCameraParameters (no distortion), Gouraud
  shading (ambient + Lambert + Blinn-Phong specular per vertex), bilinear texture fetch,
  per-fragment mask discard. resolve() averages the SSxSS samples of each pixel (box
  filter: anti-aliased edges), applies an exposure gain and adds Gaussian sensor noise.

  Buffers are allocated once by reset() (draw() allocates the whole frame's colour buffer on first
  use, render() a band of it) and grow only when a mesh is larger than any drawn before. One
  instance must not be used from two threads at once.
*/
#include <cstdint>
#include <utility>
#include <vector>

#include <visp3/core/vpCameraParameters.h>
#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

#include "pm/sim/Mesh.h"
#include "pm/sim/ShadowMap.h"

namespace pm::sim {

/*!
  One directional light and the ambient term. With a shadow map (built in the frame of the meshes
  drawn, with the same light direction) fragments hidden from the light get the ambient term only.
  A fragment's colour is texture * (ambient + lit * diffuse * max(0, n.l)) + lit * specular *
  max(0, n.h)^shininess, with lit the shadow map's visibility (1 without one); the normal is turned
  toward the camera first (two-sided). Rasterizer::draw() and render() throw pm::core::Error if \e shadow
  was made for another direction than \e dirCamera seen in the mesh's frame.
*/
struct Lighting
{
  double dirCamera[3] = {-0.3, -0.5, -0.8}; //!< direction toward the light, camera frame (normalised on use)
  double ambient = 0.45;             //!< ambient term (fraction of the texture's colour, everywhere)
  double diffuse = 0.65;             //!< Lambert term's strength (times max(0, n.l))
  double specular = -1;              //!< specular strength for this draw; negative: the mesh's own
  double shininess = -1;             //!< Blinn-Phong exponent for this draw; negative: the mesh's own
  const ShadowMap *shadow = nullptr; //!< cast shadows (object frame of the mesh drawn); null: none
  double shadowBiasM = 4e-4;         //!< constant depth bias of the shadow test (m)
  double shadowSlopeBias = 1.5;      //!< plus this many shadow-map texels times tan(angle of incidence)
};

/*!
  The software renderer of the simulated cameras: see Rasterizer.h. Draw meshes with draw() then
  resolve() into an image, or do both in one cache-friendly pass with render() (what Scene does).
  The object ids written while drawing let coverage() and depthAt() tell, afterwards, which
  object each pixel shows and at what depth (the ground truth of the simulations).
  \code
  pm::sim::Rasterizer r;
  r.reset(640, 480, 2);                            // 640 x 480 pixels, 2 x 2 samples each
  r.clear(0.04f, 0.06f, 0.09f);
  r.draw(backdrop, cMo, cam, pm::sim::Lighting(), 1); // backdrop, toy: pm::sim::Mesh; cMo (m)
  r.draw(toy, cMo, cam, pm::sim::Lighting(), 2);
  vpImage<vpRGBa> I;
  r.resolve(I, 1.0, 2.0, 42);                      // exposure 1, noise sigma 2 grey levels, seed 42
  const double onToy = r.coverage(320, 240, 2);    // fraction of the centre pixel on the toy
  \endcode
*/
class Rasterizer
{
public:
  /*!
    Sets the image size (pixels) and the supersampling factor (1..4: SSxSS samples per pixel) and
    empties the depth and id buffers (the clear colour stays the last clear()'s; black on a new
    instance). Throws pm::core::Error for a zero size or a factor out of range.
  */
  void reset(unsigned width, unsigned height, unsigned supersampling);
  //! Empties the frame before draw(): no sample drawn, the background colour (r, g, b in [0, 1]) everywhere.
  void clear(float r, float g, float b);
  /*!
    Draws \e mesh (object frame) seen by camera \e cam with the object at \e cMo (its pose in the
    camera frame, metres); \e id (1..255; 0 is refused) is written to the id buffer where visible.
    Throws pm::core::Error before reset(), after render() without a clear(), for a mesh without texture,
    and for a shadow map made for another light direction.
  */
  void draw(const Mesh &mesh, const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam, const Lighting &light,
            std::uint8_t id);
  /*!
    Box-filters the samples into \e out (width x height), multiplied by \e exposure, plus
    Gaussian noise of \e noiseSigma grey levels per channel drawn from \e noiseSeed.
  */
  void resolve(vpImage<vpRGBa> &out, double exposure, double noiseSigma, std::uint64_t noiseSeed) const;
  //! The sensor noise resolve() adds, on an image made otherwise (the same draws for the same pixel and seed).
  static void addNoise(vpImage<vpRGBa> &out, double noiseSigma, std::uint64_t noiseSeed);
  //! Fraction of the samples of pixel (u, v) that show object \e id.
  double coverage(unsigned u, unsigned v, std::uint8_t id) const;
  /*!
    Depth (the camera's z, in the units of cMo's translation) of object \e id at pixel (u, v),
    averaged over its samples when all of them show \e id; NaN otherwise (an edge, or not there).
    The ground truth of a stereo reconstruction.
  */
  double depthAt(unsigned u, unsigned v, std::uint8_t id) const;

  /*!
    Shade 8 samples at a time with AVX2 where the processor has it (true, the default) or one at a
    time (false). The two give the same images bit for bit (the same operations in the same order);
    the switch is there to test that. The cast-shadow path is always one at a time.
  */
  void setSimd(bool on) { m_simd = on; }
  //! True if this processor and build have the 8-wide path.
  static bool simdAvailable();

  //! One mesh of a frame drawn by render(); the mesh is not copied (it must outlive the call).
  struct DrawCall
  {
    const Mesh *mesh = nullptr; //!< the mesh to draw (not owned; required)
    vpHomogeneousMatrix cMo;    //!< the mesh's object frame in the camera frame (metres)
    Lighting light;             //!< its lighting (a shadow map in it is not owned either)
    std::uint8_t id = 1; //!< 1..255
  };
  /*!
    clear(), draw() of each call in order and resolve() in one pass, band by band: a band of pixel
    rows is drawn and filtered while its colour samples (16 bytes each) are still in the core's
    cache, instead of going through memory for the whole frame (20 MB at 640 x 480 with
    supersampling 2). The same image bit for bit. Afterwards coverage() and depthAt() hold the
    frame; resolve() does not (it throws until clear()).
    \code
    pm::sim::Rasterizer r;
    r.reset(640, 480, 2);
    const float sky[3] = {0.04f, 0.06f, 0.09f};
    pm::sim::Rasterizer::DrawCall calls[2];
    calls[0].mesh = &backdrop; calls[0].cMo = cMo; calls[0].id = 1;
    calls[1].mesh = &toy;      calls[1].cMo = cMo; calls[1].id = 2;
    vpImage<vpRGBa> I;
    r.render(sky, calls, 2, cam, I, 1.0, 2.0, seed);
    \endcode
  */
  void render(const float clearColor[3], const DrawCall *calls, std::size_t n, const vpCameraParameters &cam,
              vpImage<vpRGBa> &out, double exposure, double noiseSigma, std::uint64_t noiseSeed);

  unsigned width() const { return m_w; }               //!< image width (pixels), as set by reset()
  unsigned height() const { return m_h; }              //!< image height (pixels), as set by reset()
  unsigned supersampling() const { return m_ss; }      //!< samples per pixel along each axis

private:
  struct ProjVertex
  {
    float X, Y, w;       // supersampled screen position, 1/z
    float s, t, mask;    // attributes pre-divided by z (times w)
    float diff, spec;
    float su, sv, sd;    // shadow-map coordinates (with their bias), times w
    bool valid;
  };
  //! A mesh's vertices projected and shaded for one draw, and its triangles binned per band.
  struct Scratch
  {
    std::vector<ProjVertex> proj;
    std::vector<std::uint32_t> binStart, binFill, binTris;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> triBands;
  };
  void project(const Mesh &mesh, const vpHomogeneousMatrix &cMo, const vpCameraParameters &cam, const Lighting &light,
               std::vector<ProjVertex> &proj) const;
  void bin(const Mesh &mesh, Scratch &sc, unsigned rows, unsigned nBands) const;
  /*!
    Draws triangles \e tris[0..count) (all of the mesh's in order if null) on sample rows
    [yBegin, yEnd); the colour of sample idx goes to color + 4 (idx - colorOffset).
  */
  template <bool kShadow>
  void drawTriangles(const Mesh &mesh, const std::vector<ProjVertex> &proj, const Lighting &light, std::uint8_t id,
                     const std::uint32_t *tris, std::size_t count, int yBegin, int yEnd, float *color,
                     std::size_t colorOffset);
  /*!
    Shades samples [first, end] of a span whose attributes are \e v0 at \e first and step by \e d per
    sample (depth-tested, masked); 8 at a time with AVX2 when \e useAvx2 and no cast shadows.
  */
  template <bool kShadow>
  void shadeSpan(const Mesh &mesh, const Lighting &light, std::uint8_t id, const float *v0, const float *d, std::size_t first,
                 std::size_t end, float *color, std::size_t colorOffset, bool useAvx2);
  void resolveRows(vpImage<vpRGBa> &out, unsigned vBegin, unsigned vEnd, const float *color, std::size_t colorOffset,
                   double exposure, double noiseSigma, std::uint64_t noiseSeed) const;
  unsigned m_w = 0, m_h = 0, m_ss = 1, m_W = 0, m_H = 0;
  bool m_simd = true;
  std::vector<float> m_color;      // 4 * m_W * m_H (R, G, B, pad), for draw(); valid where m_id is not 0
  bool m_colorValid = true;        // false after render() until clear()
  std::vector<float> m_band;       // render()'s colour samples of one band
  mutable std::vector<float> m_noise; // resolve()'s noise draws of one row
  float m_clearColor[4] = {0, 0, 0, 0};
  std::vector<float> m_invDepth;   // 1/z, 0 = empty
  std::vector<std::uint8_t> m_id;  // object id per sample
  std::vector<Scratch> m_scratch;  // per draw call of render() (draw() uses the first)
};

} // namespace pm::sim
