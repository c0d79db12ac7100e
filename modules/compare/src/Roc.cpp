#include "pm/compare/Roc.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include <opencv2/core.hpp>

#include "pm/core/Error.h"

namespace pm::compare {

namespace {

void needBoth(const std::vector<bool> &right, const char *what)
{
  const auto nRight = std::count(right.begin(), right.end(), true);
  if (nRight == 0 || nRight == static_cast<long>(right.size()))
    throw core::Error(std::string(what) + ": needs both right and wrong frames");
}

void checkLabelled(const std::vector<double> &scores, const std::vector<bool> &right)
{
  if (scores.size() != right.size())
    throw core::Error("ROC: " + std::to_string(scores.size()) + " scores but " + std::to_string(right.size()) + " labels");
  for (double s : scores)
    if (!std::isfinite(s))
      throw core::Error("ROC: a score is not finite");
  needBoth(right, "ROC");
}

} // namespace

std::vector<RocPoint> rocCurve(const std::vector<double> &scores, const std::vector<bool> &right)
{
  checkLabelled(scores, right);
  std::vector<std::size_t> order(scores.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return scores[a] > scores[b]; });
  const double nRight = static_cast<double>(std::count(right.begin(), right.end(), true));
  const double nWrong = static_cast<double>(right.size()) - nRight;
  std::vector<RocPoint> curve{{scores[order[0]] + 1.0, 0.0, 0.0}};
  double tp = 0, fp = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    (right[order[i]] ? tp : fp) += 1;
    if (i + 1 == order.size() || scores[order[i + 1]] != scores[order[i]])
      curve.push_back({scores[order[i]], tp / nRight, fp / nWrong});
  }
  return curve;
}

double auroc(const std::vector<double> &scores, const std::vector<bool> &right)
{
  const std::vector<RocPoint> c = rocCurve(scores, right);
  double area = 0; // trapezoids: a tie block counts half
  for (std::size_t i = 1; i < c.size(); ++i)
    area += (c[i].falseAcceptRate - c[i - 1].falseAcceptRate) * 0.5 * (c[i].trueAcceptRate + c[i - 1].trueAcceptRate);
  return area;
}

RocPoint thresholdFor(const std::vector<RocPoint> &curve, double maxFalseAcceptRate)
{
  RocPoint best = curve.empty() ? RocPoint{} : curve.front();
  for (const RocPoint &p : curve)
    if (p.falseAcceptRate <= maxFalseAcceptRate && p.trueAcceptRate >= best.trueAcceptRate)
      best = p;
  return best;
}

LogisticFit fitLogistic(const std::vector<std::vector<double>> &x, const std::vector<bool> &right, double l2, int maxIterations)
{
  if (x.empty() || x.size() != right.size())
    throw core::Error("logistic fit: needs as many labels as rows, and at least one row");
  const std::size_t d = x.front().size();
  for (const auto &row : x) {
    if (row.size() != d)
      throw core::Error("logistic fit: the rows differ in size");
    for (double v : row)
      if (!std::isfinite(v))
        throw core::Error("logistic fit: a feature is not finite");
  }
  needBoth(right, "logistic fit");
  // Newton's method on the parameters (w, b): H = X^T S X + ridge, g = X^T (y - p) - ridge w.
  const int n = static_cast<int>(d) + 1;
  cv::Mat theta = cv::Mat::zeros(n, 1, CV_64F);
  LogisticFit fit;
  std::vector<double> xi(static_cast<std::size_t>(n));
  for (fit.iterations = 1; fit.iterations <= maxIterations; ++fit.iterations) {
    cv::Mat H = cv::Mat::zeros(n, n, CV_64F), g = cv::Mat::zeros(n, 1, CV_64F);
    for (std::size_t r = 0; r < x.size(); ++r) {
      std::copy(x[r].begin(), x[r].end(), xi.begin());
      xi[d] = 1.0;
      double s = 0;
      for (int k = 0; k < n; ++k)
        s += theta.at<double>(k) * xi[static_cast<std::size_t>(k)];
      const double p = 1.0 / (1.0 + std::exp(-s)), w = std::max(p * (1 - p), 1e-12), e = (right[r] ? 1.0 : 0.0) - p;
      for (int a = 0; a < n; ++a) {
        g.at<double>(a) += e * xi[static_cast<std::size_t>(a)];
        for (int b = 0; b <= a; ++b)
          H.at<double>(a, b) += w * xi[static_cast<std::size_t>(a)] * xi[static_cast<std::size_t>(b)];
      }
    }
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        H.at<double>(a, b) = H.at<double>(b, a);
    for (int k = 0; k + 1 < n; ++k) { // the ridge on w, not on b
      H.at<double>(k, k) += l2 * static_cast<double>(x.size());
      g.at<double>(k) -= l2 * static_cast<double>(x.size()) * theta.at<double>(k);
    }
    cv::Mat step;
    if (!cv::solve(H, g, step, cv::DECOMP_CHOLESKY))
      cv::solve(H, g, step, cv::DECOMP_SVD);
    theta += step;
    if (cv::norm(step, cv::NORM_INF) < 1e-8)
      break;
  }
  fit.iterations = std::min(fit.iterations, maxIterations);
  fit.weights.assign(theta.begin<double>(), theta.begin<double>() + static_cast<long>(d));
  fit.bias = theta.at<double>(n - 1);
  return fit;
}

double LogisticFit::probability(const std::vector<double> &x) const
{
  if (x.size() != weights.size())
    throw core::Error("logistic model: a row of " + std::to_string(x.size()) + " features for a model of " + std::to_string(weights.size()));
  double s = bias;
  for (std::size_t i = 0; i < x.size(); ++i)
    s += weights[i] * x[i];
  return 1.0 / (1.0 + std::exp(-s));
}

std::vector<double> crossValidatedLogistic(const std::vector<std::vector<double>> &x, const std::vector<bool> &right,
                                           const std::vector<int> &fold, int folds, double l2)
{
  if (fold.size() != x.size() || right.size() != x.size() || folds < 2)
    throw core::Error("cross-validation: needs a fold and a label per row, and at least two folds");
  for (int f : fold)
    if (f < 0 || f >= folds)
      throw core::Error("cross-validation: a fold index out of 0.." + std::to_string(folds - 1));
  std::vector<double> held(x.size());
  for (int k = 0; k < folds; ++k) {
    std::vector<std::vector<double>> train;
    std::vector<bool> y;
    for (std::size_t r = 0; r < x.size(); ++r)
      if (fold[r] != k) {
        train.push_back(x[r]);
        y.push_back(right[r]);
      }
    if (std::count(y.begin(), y.end(), true) == 0 || std::count(y.begin(), y.end(), false) == 0)
      throw core::Error("cross-validation: the rows outside fold " + std::to_string(k) +
                  " hold only right or only wrong ones; each fold's training set needs both");
    const LogisticFit lf = fitLogistic(train, y, l2);
    for (std::size_t r = 0; r < x.size(); ++r)
      if (fold[r] == k)
        held[r] = lf.probability(x[r]);
  }
  return held;
}

} // namespace pm::compare
