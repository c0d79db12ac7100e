#pragma once
/*!
  \file OutlineRefinement.h
  The model's surface moved until its outline lies on every pass view's outline at once:
  a small adjustment with the views' poses fixed. The hull is the least of the views' silhouette
  distances, so where several views graze the surface nearly together (everywhere on a smooth
  target: the views whose directions lie near the plane across its normal) the most inward of
  their errors wins, and the outlines end up a quarter to half a pixel inside the toy's. Here each
  vertex on a pass camera's outline (an edge between a face turned toward it and one turned away)
  (the mesh's outline points in that camera, each shared between its edge's two vertices) reads
  that camera's sub-pixel silhouette distance there (SubpixelOutline.h) and moves along its normal
  by the mean of what its cameras ask (px times depth over focal length);
  the vertices between outlines follow their neighbours and every move is smoothed against its
  neighbours' (a regularised least squares); a few rounds, as the outlines move.

  \code
      pm::model::OutlineRefinementStats st = pm::model::refineOutlines(mesh, usedCams, pm::model::OutlineRefinementParams());
      std::cout << "outline residual " << st.meanBeforePx << " -> " << st.meanAfterPx << " px\n";
  \endcode
*/
#include <vector>

#include "pm/model/HullGeometry.h"
#include "pm/model/HullMesh.h"

namespace pm::model {

//! How refineOutlines() moves the surface; validate() checks it.
struct OutlineRefinementParams
{
  int rounds = 4;              //!< rounds of measuring the outlines and moving the surface (0: off)
  double maxResidualPx = 1.5;  //!< an outline vertex farther than this from its camera's outline is on an inner contour: not read
  double gain = 0.8;           //!< the share of the mean asked for that a round moves
  double maxStepMm = 0.5;      //!< at most this far in one round (mm)
  double smoothness = 4.0;     //!< the weight of a vertex's neighbours' moves against its own outline points' asks ...
  double stay = 0.05;          //!< ... and of not moving (the moves fade away from the outlines)
  int smoothIterations = 40;   //!< Jacobi sweeps of that balance
  void validate() const;       //!< throws pm::core::Error naming the first value out of range
};

//! What refineOutlines() measured: the outline vertices' residuals (px, positive: inside the camera's outline).
struct OutlineRefinementStats
{
  double meanBeforePx = 0; //!< mean residual in the first round
  double rmsBeforePx = 0;  //!< its rms
  double meanAfterPx = 0;  //!< mean residual measured after the last round
  double rmsAfterPx = 0;   //!< its rms
  long samples = 0;        //!< outline vertex readings in the last measurement, over every camera
};

/*!
  Moves \e mesh's vertices (the frame of \e cams) so that its outline in each of \e cams lies on that
  camera's silhouette (HullView::signedDist, sub-pixel); calls HullMesh::update(). See the file.
*/
OutlineRefinementStats refineOutlines(HullMesh &mesh, const std::vector<const hull::HullView *> &cams, const OutlineRefinementParams &p);

} // namespace pm::model
