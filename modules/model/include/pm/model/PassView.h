#pragma once
/*!
  \file PassView.h
  One hand pose of a pass around the target: the stereo pair with the target in view, the pair
  from the same hand pose with the target removed (the backgrounds), and the pose of the hand frame
  (the frame the rig file gives its cameras in) in a fixed world frame f.

  A pass is a list of these, as pm::io::loadViewsFolder() reads them from a views folder
  (left_00.png, right_00.png, background_left_00.png, background_right_00.png, pose_fPh_00.yaml,
  then 01, ...) and as the lab's simulated PA-10 makes them (pm::lab::runPass). The all-around
  builder (buildAllAroundModel) takes it.

  \code
      std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder("views", rig);
      std::cout << pass.size() << " views, the first from " << pass[0].fMh.getTranslationVector().t() << "\n";
  \endcode
*/
#include <string>

#include <visp3/core/vpHomogeneousMatrix.h>
#include <visp3/core/vpImage.h>
#include <visp3/core/vpRGBa.h>

namespace pm::model {

//! One hand pose of a pass (see the file): the images of both cameras and the hand's pose.
struct PassView
{
  //! The left camera's photo, the target in view.
  vpImage<vpRGBa> left, right;                     //!< the right camera's photo, the target in view
  //! The left camera's photo from the same hand pose, the target removed.
  vpImage<vpRGBa> backgroundLeft, backgroundRight; //!< the right camera's, the target removed
  vpHomogeneousMatrix fMh;                         //!< the hand frame in the world frame (metres)
  std::string name;                                //!< how messages name it ("view 03")
};

} // namespace pm::model
