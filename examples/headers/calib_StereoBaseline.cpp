// The usage example of modules/calib/include/pm/calib/StereoBaseline.h, a whole program (compiled, never linked).
#include <cmath>
#include <iostream>

#include "pm/calib/StereoBaseline.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"

int main()
{
  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const pm::calib::TagBoard board; // 3 x 3 tags of 40 mm, 55 mm apart
  std::vector<vpHomogeneousMatrix> perPair;
  std::vector<double> rms;
  for (int k = 0; k < 10; ++k) {
    const std::string L = "L_" + std::to_string(k) + ".png", R = "R_" + std::to_string(k) + ".png";
    const pm::calib::BoardView l = board.find(pm::io::readColorImage(L), rig.left.cam, rig.left.distortion, L);
    const pm::calib::BoardView r = board.find(pm::io::readColorImage(R), rig.right.cam, rig.right.distortion, R);
    perPair.push_back(l.cMb * r.cMb.inverse()); // cLMcR = cLMb * cRMb^-1
    rms.push_back(std::sqrt(0.5 * (l.reprojectionRmsPx * l.reprojectionRmsPx + r.reprojectionRmsPx * r.reprojectionRmsPx)));
  }
  const pm::calib::BaselineResult res = pm::calib::aggregateBaseline(perPair, rms, rig);
  std::cout << res.baselineMm << " mm (rig: " << res.baselineErrorMm << " mm off), rotation " << res.rotationErrorDeg
            << " deg off, " << res.pairsRejected << " pairs rejected" << std::endl;
}
