#pragma once
/*!
  \file FitnessMap.h
  The fitness-distribution experiment of the paper (Sec. 5, Figs. 10, 11): F on a 2-D grid of
  two of phi's variables, the four others held at a reference pose, computed in parallel.

  The peak of a map is the centroid of its top level set, the cells whose F is within
  \e topFraction (2 %) of the map's range below the maximum: F is made of point counts, so its
  maximum is a small, noisy plateau, and the centroid of the top region locates it better than
  the first cell that reaches the maximum (reported too, as argmax).
*/
#include <string>
#include <vector>

#include "pm/core/StereoFitness.h"

namespace pm {

struct FitnessMapSpec
{
  std::size_t a = 0, b = 1;  //!< indices into phi of the two mapped variables (0..5)
  double loA = -180, hiA = 180, loB = -180, hiB = 180, step = 1;
};

struct FitnessMap
{
  FitnessMapSpec spec;
  int nA = 0, nB = 0;
  std::vector<double> values; //!< nB rows of nA values; row j at b = loB + j step, column i at a = loA + i step
  double peakA = 0, peakB = 0;     //!< centroid of the top level set
  double argmaxA = 0, argmaxB = 0; //!< first cell reaching the maximum
  double maxFitness = 0;
  int topCells = 0;
  double seconds = 0;

  double at(int i, int j) const { return values[static_cast<std::size_t>(j) * nA + i]; }
  double coordA(int i) const { return spec.loA + i * spec.step; }
  double coordB(int j) const { return spec.loB + j * spec.step; }
};

/*!
  Computes the map around \e reference (cells whose pose is invalid, |eps| > 1, get 0). Uses the
  OpenMP threads available. Throws pm::Error for a bad spec.
*/
FitnessMap computeFitnessMap(const StereoFitness &fitness, const Phi &reference, const FitnessMapSpec &spec,
                             double topFraction = 0.02);

//! The paper's four grids: x-y, y-z (posStep mm), eps1-eps2, eps2-eps3 (epsStep), over its search ranges.
std::vector<FitnessMapSpec> paperFitnessMaps(double posStep = 1.0, double epsStep = 0.01);

} // namespace pm
