// The usage example of modules/io/include/pm/io/CameraFile.h, a whole program (compiled, never linked).
#include <iostream>

#include "pm/io/CameraFile.h"

int main()
{
  const pm::io::CameraFile c = pm::io::readCameraFile("left.yml", "left", 640, 480);
  std::cout << c.format << ": " << c.camera.cam << "distortion: " << c.camera.distortion.coefficients.size() << " coefficients"
            << std::endl;
}
