// The usage example of modules/calib/include/pm/calib/TagBoard.h, a whole program (compiled, never linked).
#include <iostream>

#include "pm/calib/TagBoard.h"
#include "pm/io/ImageFile.h"

int main()
{
  pm::calib::TagBoard board;
  board.rows = 4;
  board.cols = 6;
  board.tagSizeMm = 30;
  board.pitchMm = 40; // at least 1.25 x tagSizeMm
  board.validate();
  std::cout << board.describe() << std::endl;
  pm::io::writeImage(board.render(10.0), "tags.png"); // 10 px per mm: print it at 254 dpi

  const vpCameraParameters cam(800, 800, 320, 240); // px, py, u0, v0 of a pinhole camera
  const pm::calib::BoardView view = board.find(pm::io::readColorImage("photo.png"), cam, "photo.png");
  std::cout << view.features << " tags, cMb:\n" << view.cMb << std::endl;
}
