// The usage example of modules/io/include/pm/io/StagedFiles.h, a whole program (compiled, never linked).
#include "pm/io/ImageFile.h"
#include "pm/io/StagedFiles.h"

int main()
{
  pm::io::StagedFiles out("results");
  pm::io::writeTextFile(out.stage("summary.json"), "{}\n");
  pm::io::writeImage(vpImage<unsigned char>(480, 640, 0), out.stage("mask.png"));
  out.commit(); // both files appear; an exception before this line leaves neither
}
