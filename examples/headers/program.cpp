// The usage examples of pm::program's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/program/ArmProgram.h"

namespace pm_examples {

} // namespace pm_examples
