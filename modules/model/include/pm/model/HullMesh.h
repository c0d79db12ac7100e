#pragma once
/*!
  \file HullMesh.h
  The surface of the visual hull as a triangle mesh (AllAroundModelBuilder.h, step 3), to a fraction
  of a cell: the hull's field (VisualHull.h: the least silhouette signed distance) is sampled at the
  grid's corners around the carved surface, each cell the surface crosses gets one vertex (the mean
  of where the field crosses zero along its edges: "surface nets"), and each crossed grid edge
  joins the four cells around it by a quad, cut into two triangles facing out. A hull carved from
  cells of 1 mm has its surface within about a tenth of a millimetre of the silhouettes' cones,
  where the cells' own boundary lies up to half a cell off.

  The mesh keeps its edges with the faces on either side, so that the outline seen from any
  direction is found exactly: the edges between a face turned toward the camera and one turned
  away (ViewpointModel.h).

  \code
      const pm::model::HullMesh mesh = pm::model::meshVisualHull(hull, cams);
      std::cout << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles\n";
  \endcode
*/
#include <array>
#include <cstdint>
#include <vector>

#include "pm/model/HullGeometry.h"
#include "pm/model/VisualHull.h"

namespace pm::model {

//! An edge of a HullMesh: its two vertices and the faces on either side (-1: none).
struct MeshEdge
{
  std::uint32_t a = 0;   //!< its first vertex
  std::uint32_t b = 0;   //!< its second vertex
  std::int32_t f0 = -1;  //!< a face it borders
  std::int32_t f1 = -1;  //!< the other face it borders (-1 at an open border)
};

/*!
  A triangle mesh of a hull's surface (see HullMesh.h), in the frame of its vertices.
  \code
  const pm::model::HullMesh mesh = pm::model::meshVisualHull(hull, cams);
  for (const pm::model::MeshEdge &e : mesh.edges)
    if (e.f1 >= 0 && facesCamera(mesh, e.f0, C) != facesCamera(mesh, e.f1, C)) use(e); // on the outline
  \endcode
*/
struct HullMesh
{
  std::vector<hull::Vec3> vertices;   //!< positions (mm)
  std::vector<hull::Vec3> normals;    //!< outward unit normals of the vertices (the faces' around them, area-weighted)
  std::vector<std::array<std::uint32_t, 3>> triangles; //!< counter-clockwise seen from outside
  std::vector<hull::Vec3> faceNormals; //!< outward unit normal of each triangle
  std::vector<MeshEdge> edges;        //!< every edge once

  //! Fills faceNormals, normals and edges from vertices and triangles (after moving vertices, say).
  void update();
  //! Moves every vertex and normal by \e R (row-major) and \e t (mm): X' = R (X - \e from), into a new frame.
  void transform(const double R[9], const hull::Vec3 &from);
  //! Whether face \e f is turned toward a camera at \e centre.
  bool facing(std::size_t f, const hull::Vec3 &centre) const
  {
    return hull::dot(faceNormals[f], hull::sub(centre, vertices[triangles[f][0]])) > 0;
  }
  /*!
    Taubin's smoothing (a shrinking step lambda then an inflating step mu, \e iterations times, each
    vertex toward the mean of its neighbours): the cells' staircase goes, the shape's volume stays.
    Calls update() at the end.
  */
  void smooth(int iterations, double lambda = 0.5, double mu = -0.53);
  //! The volume enclosed (mm^3; the mesh closed and facing out).
  double volume() const;
  /*!
    A coarser mesh of the same surface, by vertex clustering: the vertices within each cube of
    \e cellMm merged into their mean, the triangles left with three distinct vertices kept (faces
    as before, outward). For a CAD model of a few hundred faces (ViSP's model-based trackers).
  */
  HullMesh decimated(double cellMm) const;
  /*!
    The mesh's depth as camera \e cam sees it: for each pixel whose centre a face covers, the nearest
    face's depth there (mm), +inf elsewhere, into \e zbuf (w x h, row-major). The coverage is exact
    (pixel centres against the projected triangles; every face, so that a fold of the mesh's small
    noise leaves no hole).
  */
  void depthMap(const core::PinholeCamera::Projection &cam, std::vector<float> &zbuf) const;
  //! A vertex as a camera sees it (depthMap()'s scratch): its image position and depth, or not in front.
  struct Projected
  {
    double u = 0; //!< image column (px)
    double v = 0; //!< image row (px)
    double z = 0; //!< depth (mm)
    double iz = 0; //!< 1 / z (1/mm), for the perspective-correct depth
    // The pixel centres a face's box holds run from the least ceiling to the greatest floor of its
    // vertices' coordinates (each kept within [-1, w] or [-1, h]):
    int cu = 0;  //!< ceil(u), within [-1, w]
    int fu = -1; //!< floor(u), within [-1, w]
    int cv = 0;  //!< ceil(v), within [-1, h]
    int fv = -1; //!< floor(v), within [-1, h]
    bool ok = false;            //!< in front of the camera (core::PinholeCamera::Projection::project())
  };
  /*!
    The same, each vertex projected once (not once per face around it) into \e scratch, which a
    caller drawing many views keeps from one to the next.
  */
  void depthMap(const core::PinholeCamera::Projection &cam, std::vector<float> &zbuf, std::vector<Projected> &scratch) const;
};

/*!
  The mesh of \e hull's surface (see HullMesh.h): the field of \e cams sampled at the corners around
  the carved cells. Throws pm::core::Error when the surface has no face.
*/
HullMesh meshVisualHull(const VisualHull &hull, const std::vector<const hull::HullView *> &cams);

/*!
  The same from any field sampled on \e hull's corners: \e corner(x, y, z) gives the field at grid
  corner (x, y, z) (positive inside), called only around the carved cells' boundary.
*/
template <class Field>
HullMesh meshField(const VisualHull &hull, Field corner);

} // namespace pm::model

#include "pm/model/HullMesh.inl"
