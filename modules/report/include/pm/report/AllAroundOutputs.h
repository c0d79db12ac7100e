#pragma once
/*!
  \file AllAroundOutputs.h
  What a person looks at after an all-around build, written into an output folder:

  - model.ply: the hull's surface as a coloured point cloud with normals (ASCII PLY, model frame,
    millimetres; opens in MeshLab or CloudCompare);
  - contact.png: for 8 views of the pass, the photo (left camera) beside the hull drawn from that
    camera, in its colours and shaded by its normals;
  - summary.json, model.json;
  - silhouettes.png: every view's left photo with its silhouette (green) and the hull's outline
    from that camera (red) over it.

  \code
      pm::io::StagedFiles out("model_dir");
      pm::report::writeAllAroundPictures(build, pass, rig, out);
      out.commit();
  \endcode
*/
#include <string>
#include <vector>

#include "pm/core/StereoRig.h"
#include "pm/io/StagedFiles.h"
#include "pm/model/AllAroundModelBuilder.h"

namespace pm::report {

//! Stages model.ply, contact.png and silhouettes.png into \e out.
void writeAllAroundPictures(const model::AllAroundBuild &build, const std::vector<model::PassView> &pass, const core::StereoRig &rig,
                            io::StagedFiles &out);

/*!
  Writes everything of an all-around build into the folder \e dir, all at once or nothing:
  model.json, model.ply, contact.png, silhouettes.png, summary.json (n_views, n_views_used,
  n_surface_points, n_viewpoints, hull_volume_cm3, fMm as fMo, build_s, ...) and, with
  \e keepViews, the pass itself in views/ (the layout loadViewsFolder reads; written after the rest
  has appeared, so that its failure leaves the model in place). \e source says where the pass
  came from (summary.json); \e truthJson (a JSON object, when not empty: the lab's check against the
  toy) goes into the summary as "truth". The model's trust calibration (core::TrustCalibration), when
  measured, goes into the summary as "trust_calibration"; \e moreFiles (name, text) are written with
  the rest. Returns the summary's text.
*/
std::string writeAllAroundModel(const model::AllAroundBuild &build, const std::vector<model::PassView> &pass, const core::StereoRig &rig,
                                const std::string &dir, const std::string &source, bool keepViews, const std::string &truthJson = "",
                                const std::vector<std::pair<std::string, std::string>> &moreFiles = {});

} // namespace pm::report
