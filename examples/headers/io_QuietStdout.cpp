// The usage example of modules/io/include/pm/io/QuietStdout.h, a whole program (compiled, never linked).
#include <visp3/core/vpXmlParserCamera.h>

#include "pm/io/QuietStdout.h"

int main()
{
  vpCameraParameters cam;
  vpXmlParserCamera parser;
  pm::io::QuietStdout quiet; // until the end of the scope
  return parser.parse(cam, "cameras.xml", "left", vpCameraParameters::perspectiveProjWithoutDistortion, 640, 480);
}
