// The usage example of modules/calib/include/pm/calib/RigCalibration.h, a whole program (compiled, never linked).
#include <iostream>

#include "pm/calib/RigCalibration.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"

int main()
{
  std::vector<pm::calib::StereoImagePair> pairs;
  for (int k = 1; k <= 15; ++k) {
    const std::string n = std::to_string(k);
    pm::calib::StereoImagePair p;
    p.name = "left" + n + ".jpg + right" + n + ".jpg";
    p.left = pm::io::readColorImage("left" + n + ".jpg");
    p.right = pm::io::readColorImage("right" + n + ".jpg");
    pairs.push_back(p);
  }
  pm::calib::ChessBoard board;
  board.innerRows = 6;
  board.innerCols = 9;
  board.squareMm = 25;
  const pm::calib::RigCalibration c = pm::calib::calibrateRig(pairs, board);
  std::cout << c.pairsUsed << " pairs, baseline " << c.baselineMm << " mm, stereo rms " << c.rmsStereoPx << " px"
            << std::endl;
  pm::io::saveRig(c.rig, "rig.json", "rig_cameras.xml", "calibrated from 15 pairs");
}
