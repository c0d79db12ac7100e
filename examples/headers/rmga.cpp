// The usage examples of pm::rmga's headers, each as its header shows it: this file is compiled
// (never run), and scripts/header-examples.py checks that every example of a header is part of a file
// here. What an example takes as given is its function's parameters.
#include "pm/rmga/RmGa.h"

namespace pm_examples {

// RmGa.h
void exampleRmGa2(pm::rmga::RmGa &ga, const pm::core::Phi &lastTrusted)
{
  ga.setAnchor(lastTrusted); // a lost target is searched for near where it was last seen too
  ga.restart(1);
}

// RmGa.h
void exampleRmGa3(pm::rmga::RmGa &ga, const pm::core::Phi &refused)
{
  ga.avoid(refused, 20, 20, 15); // not there again for half a second
  ga.scatter(0, 0);
}

} // namespace pm_examples
