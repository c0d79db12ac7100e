#pragma once
/*!
  \file ViewpointModel.h
  One viewpoint of the all-around model (AllAroundModelBuilder.h, the last step): a camera at the
  pass's distance looking at the model's origin from a direction of the cap, and what the tracker
  needs from there:
  - S_in: the surface points with a hue it sees (a depth buffer of the surface), at most nIn of
    them spread over the image;
  - the outline (ContourPoint, for the precise stage): the mesh's edges between a face turned
    toward the camera and one turned away that lie on the silhouette's boundary, sampled evenly
    along their projection; each point on the surface, exactly where the mesh's outline passes,
    with the outline's outward normal and how far target and background reach along it;
  - S_out: points offset outward from that outline by the strip (stripGapPx to stripGapPx +
    stripWidthPx), at the outline's depth, where the strip falls off the target.

  \code
      pm::model::ViewpointScratch scratch; // kept from one viewpoint to the next
      const pm::core::ModelView v = pm::model::sampleViewpoint(cam, surface, mesh, bgHue, params, scratch);
  \endcode
*/
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "pm/core/PhotoModel.h"
#include "pm/model/HullGeometry.h"
#include "pm/model/HullMesh.h"

namespace pm::model {

struct AllAroundParams;
struct SurfacePoint;

/*!
  The hull's depth buffer seen by \e cam: every point of \e pts splatted over a square of \e radius
  pixels (nearest depth kept, +inf where none falls), into \e zbuf (w x h, row-major).
*/
void depthBuffer(const core::PinholeCamera::Projection &cam, const std::vector<hull::Vec3> &pts, int radius, std::vector<float> &zbuf);

/*!
  The buffers of sampleViewpoint() (each the size of the image or of the mesh), kept by the caller
  from one viewpoint to the next: a model's 240 viewpoints would otherwise make them 240 times.
*/
struct ViewpointScratch
{
  std::vector<float> zbuf;                   //!< the hull's depth (HullMesh::depthMap)
  std::vector<HullMesh::Projected> vertices; //!< the mesh's vertices as the camera sees them
  std::vector<unsigned char> facing;         //!< per face: turned toward the camera
  cv::Mat mask;                              //!< the coverage (meshOutline)
  cv::Mat inside;                            //!< its distance inside (meshOutline)
  cv::Mat cover;                             //!< its blur over the coverage's box (meshOutline)
};

/*!
  The viewpoint of camera \e cam (in the model frame; core::PinholeCamera::Projection::lookingAtOrigin) of a model whose
  surface is \e mesh (triangles, model frame) and \e surface (its vertices' colours and normals, one a
  vertex, in the same order): S_in, S_out and the outline (see ViewpointModel.h); \e scratch holds the
  buffers (its zbuf then the hull's depth seen by \e cam, its vertices the mesh's projected, which S_in
  reads). S_out points carry \e bgHue. The view's cameraMm is the camera's centre. Throws
  pm::core::Error when \e surface and the mesh's vertices differ in number.
*/
core::ModelView sampleViewpoint(const core::PinholeCamera::Projection &cam, const std::vector<SurfacePoint> &surface, const HullMesh &mesh,
                                float bgHue, const AllAroundParams &p, ViewpointScratch &scratch);

/*!
  The outline of \e mesh seen by \e cam (see ViewpointModel.h): \e n points evenly along the contour
  edges that border the background in \e mask (the mesh's coverage, HullMesh::depthMap: non-zero on
  it). For the precise stage's lines and for S_out.
*/
std::vector<core::ContourPoint> meshOutline(const core::PinholeCamera::Projection &cam, const HullMesh &mesh, const std::vector<unsigned char> &mask, int n);
//! Where a point of meshOutline() lies on the mesh: on the edge from vertex \e a to \e b, at \e t (0 at a, 1 at b).
struct OutlineOrigin
{
  std::uint32_t a = 0; //!< the edge's first vertex
  std::uint32_t b = 0; //!< its second vertex
  double t = 0;        //!< how far along it
  double u = 0;        //!< the point's image column (px)
  double v = 0;        //!< its image row (px)
  double z = 0;        //!< its depth (mm)
};

/*!
  The same, \e mask w x h bytes (row-major), with \e scratch's facing and cover as buffers; with
  \e origins, where each point lies on the mesh (one per point returned, in order).
*/
std::vector<core::ContourPoint> meshOutline(const core::PinholeCamera::Projection &cam, const HullMesh &mesh, const unsigned char *mask, int n,
                                            ViewpointScratch &scratch, std::vector<OutlineOrigin> *origins = nullptr);

} // namespace pm::model
