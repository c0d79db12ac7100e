#pragma once
/*!
  \file PhotoModelFile.h
  Photo-model files (JSON):

      {
        "format": "visp-photomodel-model", "version": 1,
        "distance_mm": 500,                                  // photo distance d
        "camera": { "px": 754, "py": 754, "u0": 320, "v0": 240, "width": 640, "height": 480 },
        "centroid_px": [cu, cv],                             // model origin in the photo
        "background_hue_deg": 212.0,                         // H_B
        "target_hue_deg": 12.0,                              // mean hue of S_in (report only)
        "s_in":  [[x_mm, y_mm, hue_deg, u_px, v_px], ...],   // z = 0 on the model plane
        "s_out": [[x_mm, y_mm, hue_deg, u_px, v_px], ...]    // hue: the background's there
      }

  Version 2 (a stereo model, with depth) has a z per point and what the rig measured:

      {
        "format": "visp-photomodel-model", "version": 2,
        ... as version 1 (distance_mm: the origin's depth in the hand frame; camera: the left one),
        "origin_in_hand_mm": [x, y, z],        // the model origin in the hand frame at the photo pose
        "depth_range_mm": [near, far],         // S_in's extent along the hand's z
        "n_in_dropped": 12,                    // S_in points without a reliable stereo match
        "s_in":  [[x_mm, y_mm, z_mm, hue_deg, u_px, v_px], ...],
        "s_out": [[x_mm, y_mm, z_mm, hue_deg, u_px, v_px], ...]
      }

  Version 3 (a multi-view stereo model) adds the camera that sampled S_in and S_out, and the
  further views, each with its own camera centre and points (StereoFitness scores each camera
  with the view taken from the nearest direction):

      {
        "format": "visp-photomodel-model", "version": 3,
        ... as version 2,
        "camera_mm": [x, y, z],                // the left camera's centre in the model frame
        "views": [ { "camera_mm": [x, y, z], "s_in": [[x, y, z, hue, u, v], ...], "s_out": [...] }, ... ]
      }

  An all-around model (16 views or more: its viewpoints) is written as version 4: the S_in points
  of all its views once, in a shared cloud (their positions to 0.01 mm, hues to 0.01 deg), each
  view naming its own by index, and S_out as bare positions (their hue is H_B). An eighth of
  version 3's size for 240 viewpoints (1.75 against 14.7 MB for the crab); u and v are not kept:

      {
        "format": "visp-photomodel-model", "version": 4,
        ... as version 2, "camera_mm" as version 3,
        "surface": [[x, y, z, hue], ...],      // every S_in point of every view, once
        "s_in": [i, ...], "s_out": [[x, y, z], ...],   // the model's own view, by index
        "views": [ { "camera_mm": [x, y, z], "s_in": [i, ...], "s_out": [[x, y, z], ...] }, ... ]
      }

  An all-around model with what the precise stage needs (its outlines and colours, PhotoModel::
  hasContours() and hasColours) is written as version 5: version 4, each surface point with its
  colour, each view with its outline (ContourPoint: positions to 0.01 mm, normals to 1e-4), and the
  colour histograms of the target and around it (non-zero bins only):

      {
        "format": "visp-photomodel-model", "version": 5,
        ... as version 4, and:
        "surface": [[x, y, z, hue, r, g, b], ...],
        "contour": [[x, y, z, nx, ny, nz, inside_mm, outside_mm], ...],   // the model's own view
        "views": [ { ... as version 4, "contour": [...] }, ... ],
        "colour_histograms": { "bins_per_channel": 16, "foreground": [[bin, p], ...], "background": [...] }
      }

  An all-around model calibrated from its pass (pm::trust, core::TrustCalibration) is written as
  version 6: version 5 and what the pass taught the confidence and the uncertainty through the
  user's camera (a model of version 5 loads with none: the shipped confidence and sigmas):

      {
        "format": "visp-photomodel-model", "version": 6,
        ... as version 5, and:
        "trust_calibration": { "cue_shifts": {"out_background_min": 0.06, ...},   // added to each feature
                               "right_readings": {"quality": 0.71, ...},          // the pass's right poses' medians
                               "sigma_gain": [gx, gy, gz, grx, gry, grz], "guard": 1,
                               "held_out_views": 15, "right_examples": 45, "wrong_examples": 260, "auroc": 0.998,
                               "right_trusted": 0.93, "right_trusted_shipped": 0.4, "wrong_trusted": 0, ... }
      }

  A model with every z = 0 is written as version 1, byte for byte as before; version 1 files
  load as flat models and behave exactly as they always did.
*/
#include <string>

#include "pm/core/PhotoModel.h"

namespace pm::io {

/*!
  Reads and validates a model (any version above); throws pm::core::Error naming the file and what is wrong.

  \code
#include <iostream>

#include "pm/io/PhotoModelFile.h"

int main()
{
  const pm::core::PhotoModel m = pm::io::loadPhotoModel("model.json");
  std::cout << m.inner.size() << " S_in and " << m.outer.size() << " S_out points, " << m.views.size()
            << " further views, photo distance " << m.distanceMm << " mm" << std::endl;
  pm::io::savePhotoModel(m, "copy.json");
}
  \endcode
*/
core::PhotoModel loadPhotoModel(const std::string &path);
//! How photoModelToJson() writes a model's numbers.
enum class ModelDigits
{
  Format, //!< positions and hues to 0.01, normals to 0.0001, pass landings to 0.001 (model.json: short, and what is read back is what was written)
  Exact   //!< every bit of each number (a cache that must give back the very model: pm::lab::ModelCache)
};
//! Serialises a model to the JSON text above.
std::string photoModelToJson(const core::PhotoModel &m, ModelDigits digits = ModelDigits::Format);
//! Writes a model (through a temporary file). Throws pm::core::Error.
void savePhotoModel(const core::PhotoModel &m, const std::string &path);

//! \e t as model.json's "trust_calibration" object (JSON text; pm-make-model's summary.json keeps it too).
std::string trustCalibrationToJson(const core::TrustCalibration &t);
//! The calibration that trustCalibrationToJson() wrote. Throws pm::core::Error naming what is wrong.
core::TrustCalibration trustCalibrationFromJson(const std::string &text);

} // namespace pm::io
