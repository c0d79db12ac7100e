// The usage example of modules/calib/include/pm/calib/ChessBoard.h, a whole program (compiled, never linked).
#include <iostream>

#include "pm/calib/ChessBoard.h"
#include "pm/io/ImageFile.h"
#include "pm/io/RigFile.h"

int main()
{
  pm::calib::ChessBoard board; // 6 x 9 inner corners
  board.squareMm = 25;
  board.validate();
  pm::io::writeImage(board.render(10.0), "chessboard.png"); // 10 px per mm: print it at 254 dpi

  const pm::core::StereoRig rig = pm::io::loadRig("rig.json");
  const vpImage<vpRGBa> I = pm::io::readColorImage("left01.png");
  const pm::calib::BoardView view = board.find(I, rig.left.cam, rig.left.distortion, "left01.png");
  std::cout << "cMb:\n" << view.cMb << "\n" << view.reprojectionRmsPx << " px rms" << std::endl;
}
