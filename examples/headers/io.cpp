// The usage examples of pm::io's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/io/CameraFile.h"
#include "pm/io/PhotoModelFile.h"
#include "pm/io/QuietStdout.h"
#include "pm/io/RigFile.h"
#include "pm/io/StagedFiles.h"
#include "pm/io/WellFormedXml.h"

namespace pm_examples {

// WellFormedXml.h
void exampleWellFormedXml()
{
  pm::io::requireWellFormedXml("<opencv_storage><a>1</a></opencv_storage>"); // fine
  pm::io::requireWellFormedXml("<opencv_storage><a type_id=");                // throws
}

} // namespace pm_examples
