#pragma once
/*!
  \file Options.h
  Option groups shared by several programs, so that the same knob has the same name, range and
  help everywhere.
*/
#include <CLI/CLI.hpp>

#include "pm/core/PhotoModelBuilder.h"
#include "pm/core/StereoFitness.h"
#include "pm/sim/Scene.h"

namespace pm::app {

//! --step-px, --strip-gap-px, --strip-width-px, --strip-rows, --region-hue-tol-deg, --min-saturation
void addModelOptions(CLI::App &app, PhotoModelParams &p);
//! --noise, --exposure, --occluder, --supersampling, --seed
void addSceneOptions(CLI::App &app, sim::SceneParams &p);
//! --in-tol-deg, --in-bg-tol-deg, --out-bg-tol-deg
void addFitnessOptions(CLI::App &app, FitnessParams &p);

} // namespace pm::app
