#pragma once
/*!
  \file ViewsFolder.h
  A pass around the target on disk, the layout any rig can write: for k = 0, 1, ...

      left_%02d.png, right_%02d.png                        the target in view
      background_left_%02d.png, background_right_%02d.png  the same hand pose, the target removed
      pose_fPh_%02d.yaml                                   the hand frame in a fixed world frame (vpPoseVector YAML)

  The views are numbered from 0 without gaps; the first number with none of the five files ends
  the pass. The lab writes its passes in exactly this layout (pm-make-model --all-around), so the
  lab's views and a user's go through one code path.

  \code
      const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder("views", rig);
      pm::io::saveViewsFolder(pass, "copy");   // all files appear together, or none
  \endcode
*/
#include <string>
#include <vector>

#include "pm/core/StereoRig.h"
#include "pm/model/PassView.h"

namespace pm::io {

/*!
  Reads every view of the folder \e dir. Throws pm::core::Error with a one-line message naming the view
  and the file for: a folder that does not exist or holds no view, a view with one of its five
  files missing, an image of another size than its camera's in \e rig, a pose file that is not a
  vpPoseVector, and fewer than \e minViews views (saying how many there are). Without \e backgrounds
  (a plain backdrop) the background images are neither needed nor read.
*/
std::vector<model::PassView> loadViewsFolder(const std::string &dir, const core::StereoRig &rig, std::size_t minViews = 1,
                                      bool backgrounds = true);
//! Writes \e views into \e dir (created if missing) in the layout above; nothing appears unless all of it is written.
void saveViewsFolder(const std::vector<model::PassView> &views, const std::string &dir);
//! The file name of view \e k: \e stem is "left", "right", "background_left", "background_right" (.png) or "pose_fPh" (.yaml).
std::string viewFileName(const std::string &stem, std::size_t k);

} // namespace pm::io
