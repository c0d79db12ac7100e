// The usage example of modules/calib/include/pm/calib/CameraCalibration.h, a whole program (compiled, never linked).
#include <iostream>

#include "pm/calib/CameraCalibration.h"
#include "pm/calib/ChessBoard.h"
#include "pm/io/ImageFile.h"

int main()
{
  std::vector<pm::calib::CalibrationView> views;
  for (int k = 1; k <= 14; ++k) {
    pm::calib::CalibrationView v;
    v.name = "left" + std::to_string(k) + ".jpg";
    v.image = pm::io::readColorImage(v.name);
    views.push_back(v);
  }
  pm::calib::ChessBoard board;
  board.innerRows = 6;
  board.innerCols = 9;
  board.squareMm = 25;
  const pm::calib::CameraCalibration c = pm::calib::calibrateCamera(views, board);
  std::cout << c.viewsUsed << " views, rms " << c.rmsPx << " px" << std::endl;
}
