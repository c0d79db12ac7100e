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

namespace pm::core {

/*!
  The grid of a fitness map: which two variables of phi vary, over which ranges, in which step.
  Ranges and step are in phi's units: mm for x, y, z, none for eps1..eps3. A variable
  takes round((hi - lo) / step) + 1 values lo, lo + step, ...: its last is hi when step divides the range.
*/
struct FitnessMapSpec
{
  /*! \var FitnessMapSpec::a
      \brief index into phi of the first mapped variable, the map's columns (0..5: x, y, z, eps1, eps2, eps3) */
  std::size_t a = 0, b = 1;  //!< index into phi of the second mapped variable, the map's rows (0..5), not \e a
  /*! \var FitnessMapSpec::loA
      \brief first value of \e a
      \var FitnessMapSpec::hiA
      \brief last value of \e a (greater than loA)
      \var FitnessMapSpec::loB
      \brief first value of \e b
      \var FitnessMapSpec::hiB
      \brief last value of \e b (greater than loB) */
  double loA = -180, hiA = 180, loB = -180, hiB = 180, step = 1; //!< grid step of both variables (positive)
};

/*!
  A fitness map computed by computeFitnessMap(): F on the grid of \e spec, and where it peaks (see
  FitnessMap.h). Coordinates are in phi's units (mm, or none for eps).
*/
struct FitnessMap
{
  FitnessMapSpec spec; //!< the grid
  /*! \var FitnessMap::nA
      \brief number of values of \e a (columns) */
  int nA = 0, nB = 0; //!< number of values of \e b (rows)
  std::vector<double> values; //!< nB rows of nA values; row j at b = loB + j step, column i at a = loA + i step
  /*! \var FitnessMap::peakA
      \brief \e a of the centroid of the top level set: the peak */
  double peakA = 0, peakB = 0;     //!< \e b of the centroid of the top level set
  /*! \var FitnessMap::argmaxA
      \brief \e a of the first cell (row by row) reaching the maximum */
  double argmaxA = 0, argmaxB = 0; //!< \e b of the first cell (row by row) reaching the maximum
  double maxFitness = 0;           //!< the largest F on the map
  int topCells = 0;                //!< number of cells in the top level set (F within topFraction of the range below the maximum)
  double seconds = 0;              //!< wall-clock time of computing the values (s)

  //! F at column \e i, row \e j.
  double at(int i, int j) const { return values[static_cast<std::size_t>(j) * nA + i]; }
  //! Value of \e a at column \e i.
  double coordA(int i) const { return spec.loA + i * spec.step; }
  //! Value of \e b at row \e j.
  double coordB(int j) const { return spec.loB + j * spec.step; }
};

/*!
  Computes the map around \e reference (cells whose pose is invalid, |eps| > 1, get 0). Uses the
  OpenMP threads available. \e fitness must have its images (StereoFitness::setImages()).
  \e topFraction: the top level set's depth, as a fraction of the map's range of F, in [0, 1).
  Throws pm::core::Error for a bad spec (a, b not two different indices 0..5, an empty range, a step
  that is not positive or gives more than 1e5 cells along an axis) or a bad \e topFraction.
  \code
  // fitness: a pm::core::StereoFitness given its images; truth: the pm::core::Phi to map around
  const std::vector<pm::core::FitnessMapSpec> specs = pm::core::paperFitnessMaps();
  const pm::core::FitnessMap map = pm::core::computeFitnessMap(fitness, truth, specs[0]); // F over x-y, 1 mm steps
  std::cout << "peak at x = " << map.peakA << " mm, y = " << map.peakB << " mm\n";
  \endcode
*/
FitnessMap computeFitnessMap(const StereoFitness &fitness, const Phi &reference, const FitnessMapSpec &spec,
                             double topFraction = 0.02);

/*!
  The paper's four grids: x-y, y-z (posStep mm), eps1-eps2, eps2-eps3 (epsStep), over its search
  ranges: x, y in [-180, 180] mm, z in [320, 680] mm, eps in [-0.37, 0.37].
*/
std::vector<FitnessMapSpec> paperFitnessMaps(double posStep = 1.0, double epsStep = 0.01);

} // namespace pm::core
