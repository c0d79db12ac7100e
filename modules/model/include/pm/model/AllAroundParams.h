#pragma once
/*!
  \file AllAroundParams.h
  The parameters of the all-around model's build (AllAroundModelBuilder.h), a section per stage, in
  the build's order: the silhouettes (1), the carving (2-3), the fusion (3), the surface (3-5), its
  colours (6), the viewpoints (7) and the pass's landings (9). Each section checks its own values.

  \code
    pm::model::AllAroundParams p;
    p.viewpoints.count = 120;       // a lighter model: half the viewpoints
    p.surface.refineOutlines = true; // the outlines to a fraction of a pixel
    p.validate();                   // throws pm::core::Error naming the first value out of range
  \endcode
*/
#include <cstddef>

#include "pm/model/OutlineRefinement.h"
#include "pm/model/Silhouette.h"
#include "pm/model/SurfaceFusion.h"

namespace pm::model {

//! Stages 2-3: the views that agree and the hull carved from their silhouettes.
struct HullCarvingParams
{
  std::size_t minViews = 6;          //!< fewer usable views: refused
  double coarsestMm = 16;            //!< first cell size of the carving (mm)
  double finestMm = 1;               //!< last cell size (mm; raised for large targets: at most 256 cells across)
  double outlierCarveFraction = 0.4; //!< a view carving more than this of what the others keep is left out

  //! Throws pm::core::Error naming the first value out of range.
  void validate() const;
};

//! Stages 3-4: the surface of the hull: its outlines and which cameras see it.
struct HullSurfaceParams
{
  double visibilityTolMm = 3; //!< a surface point is seen when within this of the depth buffer (mm)
  /*!
    The outlines to a fraction of a pixel: each silhouette's distance from the photo's own outline
    (SubpixelOutline.h) and the surface moved until its outline lies on every view's
    (OutlineRefinement.h, \e outline). Off by default (why, with the figures: docs/model-outline.md).
  */
  bool refineOutlines = false;
  OutlineRefinementParams outline; //!< the refinement, when refineOutlines

  //! Throws pm::core::Error naming the first value out of range.
  void validate() const;
};

//! Stage 5: each surface point's hue from the views that see it.
struct SurfaceColourParams
{
  double minSaturation = 0.15;         //!< colour samples paler than this have no hue
  double minValue = 0.08;              //!< ... or darker than this
  double minHueFromBackgroundDeg = 30; //!< S_in points need a hue this far from H_B
  double maxHueSpreadDeg = 20;         //!< views disagreeing more (median distance to the median hue): marked

  //! Throws pm::core::Error naming the first value out of range.
  void validate() const;
};

//! Stage 6: the model's viewpoints and the points each holds.
struct ViewpointSamplingParams
{
  int count = 240;             //!< K, the viewpoints within the cap
  double capDeg = 75;          //!< viewpoints within this of the first view's direction
  int nIn = 400;               //!< S_in points per viewpoint (fewer where fewer are seen)
  double inMinInsidePx = 2;    //!< S_in points lie at least this far inside the viewpoint's outline (px), a sharp camera's
  /*!
    A soft camera's S_in farther inside (docs/model-outline.md, "Blur"): the first view's outline read
    (EdgeBlur.h), the blur's sigma beyond a sharp camera's (\e sharpEdgeWidthPx, what the lab's
    renders give) adds this many px per px once over \e blurDeadZonePx; 0: never.
  */
  double blurInsideGain = 2;
  double sharpEdgeWidthPx = 0.75; //!< a sharp camera's 25-75 % rise across the outline (px)
  double blurDeadZonePx = 0.5;    //!< a blur's sigma under this beyond a sharp camera's is not counted (px)
  int nOut = 160;                 //!< S_out points per viewpoint
  double stripGapPx = 5;          //!< S_out: the first row this far outside the outline (px; the hull's exact one, HullMesh.h)
  double stripWidthPx = 8;        //!< ... the last this much farther
  int stripRows = 2;              //!< rows of S_out points across the strip
  int nContour = 200;             //!< outline points per viewpoint, for the precise stage (ContourPoint)

  //! Throws pm::core::Error naming the first value out of range.
  void validate() const;
};

//! Parameters of buildAllAroundModel(), a section per stage (see the file's description); validate() checks them.
struct AllAroundParams
{
  SilhouetteParams silhouette;      //!< 1. how each photo's silhouette is found
  double backdropHueDeg = -1;       //!< 1. >= 0: a plain backdrop of this hue, no background images needed (silhouetteOnBackdrop)
  HullCarvingParams carving;        //!< 2-3. the views that agree, the hull's cells
  FusionParams fusion;              //!< 3. the surface from the views' stereo pairs and the backdrop (SurfaceFusion.h)
  HullSurfaceParams surface;        //!< 3-5. the outlines, the visibility, photo-consistency
  SurfaceColourParams colour;       //!< 6. the surface's colours
  ViewpointSamplingParams viewpoints; //!< 7. the viewpoints
  bool passLandings = true;         //!< 8. the precise stage on the pass's own views, the model's error there (PassLandings.h; the tracker's uncertainty floor)

  //! Throws pm::core::Error naming the first parameter out of range.
  void validate() const;
};

} // namespace pm::model
