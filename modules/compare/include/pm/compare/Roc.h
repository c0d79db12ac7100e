#pragma once
/*!
  \file Roc.h
  How well a score separates right frames from wrong ones: the ROC curve (true accept rate
  against false accept rate as the threshold falls), its area (AUROC, the probability that a
  right frame scores above a wrong one, ties counted half), the threshold for a largest false
  accept rate, and a logistic model fitted to labelled features (Newton's method with a small
  ridge, the normal equations solved by OpenCV).

  \code
    const std::vector<pm::compare::RocPoint> curve = pm::compare::rocCurve(scores, right);
    const double a = pm::compare::auroc(scores, right);
    const pm::compare::LogisticFit fit = pm::compare::fitLogistic(features, right);
  \endcode
*/
#include <vector>

namespace pm::compare {

//! One point of a ROC curve: a threshold and the rates of frames it accepts.
struct RocPoint
{
  double threshold = 0;      //!< accept when score >= threshold
  double trueAcceptRate = 0; //!< right frames accepted / right frames
  double falseAcceptRate = 0;//!< wrong frames accepted / wrong frames
};

/*!
  The ROC of \e scores against \e right (same sizes), one point per distinct score, from the
  highest threshold down, starting at (0, 0). Throws pm::core::Error if the sizes differ, a score is not
  finite, or either class is empty.
*/
std::vector<RocPoint> rocCurve(const std::vector<double> &scores, const std::vector<bool> &right);
//! The area under rocCurve() (Mann-Whitney, ties half). Same contract.
double auroc(const std::vector<double> &scores, const std::vector<bool> &right);
/*!
  The lowest threshold whose false accept rate is at most \e maxFalseAcceptRate (the point of
  \e curve with the highest true accept rate among those).
*/
RocPoint thresholdFor(const std::vector<RocPoint> &curve, double maxFalseAcceptRate);

//! A logistic model of P(right | x), as fitLogistic() fits it.
struct LogisticFit
{
  std::vector<double> weights; //!< one per feature
  double bias = 0;             //!< b, the intercept (not under the ridge)
  int iterations = 0;          //!< Newton steps taken (at most the maxIterations given)
  //! P(right | x) for a row \e x of the fitted size. Throws pm::core::Error for a row of another size.
  double probability(const std::vector<double> &x) const;
};

/*!
  Fits P(right | x) = 1 / (1 + exp(-(w . x + b))) to the rows of \e x (each of the same size)
  by Newton's method on the log-likelihood with a ridge \e l2 on w. Throws pm::core::Error if the rows
  are empty, ragged or not finite, the labels' count differs, or either class is empty.
*/
LogisticFit fitLogistic(const std::vector<std::vector<double>> &x, const std::vector<bool> &right, double l2 = 1e-3,
                        int maxIterations = 50);

/*!
  Cross-validation: each row scored by the logistic model fitted on the rows of the other folds
  (\e fold: each row's fold, 0..folds-1; e.g. its run's index modulo folds, so that no run is
  scored by a model that saw it). Throws pm::core::Error (naming the fold) if the rows of the other
  folds hold one class only, and as fitLogistic().
  \code
    const std::vector<double> held = pm::compare::crossValidatedLogistic(features, right, runIndexMod2, 2);
    const double heldOutAuroc = pm::compare::auroc(held, right);
  \endcode
*/
std::vector<double> crossValidatedLogistic(const std::vector<std::vector<double>> &x, const std::vector<bool> &right,
                                           const std::vector<int> &fold, int folds, double l2 = 1e-3);

} // namespace pm::compare
