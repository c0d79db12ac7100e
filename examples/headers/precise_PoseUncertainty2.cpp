// The usage example of modules/precise/include/pm/precise/PoseUncertainty.h, a whole program (compiled, never linked).
#include <iostream>
#include <pm/precise/PoseUncertainty.h>

int main()
{
  std::array<double, 36> information{};  // in a program: PreciseResult::information
  for (int i = 0; i < 6; ++i)
    information[7 * i] = i < 3 ? 4.0 : 4.0e6; // 0.5 mm and 0.5 mrad from the lines
  const pm::precise::UncertaintyModel model;       // the shipped scales and floors
  const pm::precise::PoseUncertainty u = model.uncertainty(information, 0.9); // a residual of 0.9 px
  std::cout << "x: " << u.sigmaMm[0] << " mm, about x: " << u.sigmaDeg[0] << " deg\n";
}
