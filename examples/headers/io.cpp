// The usage examples of pm::io's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/io/CameraFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/QuietStdout.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/io/WellFormedXml.h"

#include "pm/io/AllAroundParamsJson.h"
#include "pm/io/DataDir.h"
#include "pm/io/PlyFile.h"
#include "pm/io/PoseFile.h"
#include "pm/io/ViewsFolder.h"
namespace pm_examples {

// The build defines these for its programs (apps/CMakeLists.txt): the source tree's data and the installed one's.
#define PM_SOURCE_DATA_DIR "data"
#define PM_INSTALL_DATA_DIR "/usr/local/share/visp-photomodel"

// WellFormedXml.h
void exampleWellFormedXml()
{
  pm::io::requireWellFormedXml("<opencv_storage><a>1</a></opencv_storage>"); // fine
  pm::io::requireWellFormedXml("<opencv_storage><a type_id=");                // throws
}

// AllAroundParamsJson.h
void exampleAllAroundParamsJson()
{
  pm::model::AllAroundParams p;
  p.viewpoints.count = 120;
  const std::string json = pm::io::allAroundParamsToJson(p); // {"backdrop_hue_deg":-1.0, ..., "viewpoints":{..., "count":120, ...}}
}

// PlyFile.h
void examplePlyFile(const pm::model::AllAroundBuild &build)
{
  pm::io::writeTextFile("model.ply", pm::io::plyText(build.surface, &build.mesh));
}

// CameraFile.h
void exampleCameraFile(pm::core::StereoRig &rig)
{
  const pm::io::CameraFile c = pm::io::readCameraFile("left.yml", "left", 640, 480);
  rig.left.cam = c.camera.cam;  rig.left.distortion = c.camera.distortion;
}

// DataDir.h
void exampleDataDir()
{
  const std::string rig = pm::io::dataDir(PM_SOURCE_DATA_DIR, PM_INSTALL_DATA_DIR) + "/rig/pa10_stereo.json";
}

// RigFile.h
void exampleRigFileAnyCameras()
{
  const pm::core::CameraRig rig = pm::io::loadCameraRig("data/rig/pa10_mono.json");
  std::cout << rig.size() << " camera(s), the first " << rig[0].name << " " << rig[0].width << "x" << rig[0].height << "\n";
}

// PoseFile.h
void examplePoseFile()
{
  const vpHomogeneousMatrix fMh = pm::io::readPoseYaml("views/pose_fPh_00.yaml");
  pm::io::writePoseYaml(fMh, "copy.yaml");
}

// ViewsFolder.h
void exampleViewsFolder(const pm::core::StereoRig &rig)
{
  const std::vector<pm::model::PassView> pass = pm::io::loadViewsFolder("views", rig);
  pm::io::saveViewsFolder(pass, "copy");   // all files appear together, or none
}

} // namespace pm_examples
