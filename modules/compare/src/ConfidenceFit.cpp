#include "pm/compare/ConfidenceFit.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pm/compare/Roc.h"
#include "pm/core/Error.h"

namespace pm::compare {

namespace {

//! The features of \e f that \e used selects.
std::vector<double> usedFeatures(const LabelledFrame &f, const std::array<bool, tracker::ConfidenceCues::kFeatures> &used)
{
  const auto x = f.cues.features();
  std::vector<double> row;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (used[i])
      row.push_back(x[i]);
  return row;
}

double logit(double p) { return std::log(p / (1.0 - p)); }

} // namespace

ConfidenceFit fitConfidence(const ConfidenceStudy &study, tracker::ConfidenceKind kind, double maxFalseAccept)
{
  if (kind == tracker::ConfidenceKind::Auto || kind == tracker::ConfidenceKind::Custom)
    throw core::Error("fitConfidence: fit a kind of model (flat, stereo or all-around)");
  const std::vector<LabelledFrame> &set = study.frames;
  if (set.empty())
    throw core::Error("fitConfidence: no frame");
  const auto used = tracker::ConfidenceModel::featuresUsed(kind);
  std::vector<std::vector<double>> rows;
  std::vector<bool> right;
  std::vector<int> fold;
  for (std::size_t k = 0; k < set.size(); ++k) {
    rows.push_back(usedFeatures(set[k], used));
    right.push_back(set[k].right);
    fold.push_back(static_cast<int>(study.runOf.at(k) % 2));
  }
  ConfidenceFit out;
  try {
    out.aurocCrossValidated = auroc(crossValidatedLogistic(rows, right, fold, 2), right);
  } catch (const core::Error &e) {
    throw core::Error(std::string("fitConfidence (folds: runs of even and odd index): ") + e.what());
  }
  const LogisticFit fit = fitLogistic(rows, right);
  out.iterations = fit.iterations;
  // The operating point: a frame is trusted only when tracking and verified, so the others score 0.
  std::vector<double> p(set.size()), gated(set.size());
  for (std::size_t k = 0; k < set.size(); ++k) {
    p[k] = fit.probability(rows[k]);
    gated[k] = set[k].cues.tracking && set[k].cues.verified ? p[k] : 0.0;
  }
  const RocPoint op = thresholdFor(rocCurve(gated, right), maxFalseAccept);
  out.operatingThreshold = std::clamp(op.threshold, 1e-9, 1.0 - 1e-9);
  tracker::ConfidenceModel &m = out.model;
  m.kind = kind;
  m.threshold = 0.95;
  m.weights.fill(0.0);
  for (std::size_t i = 0, j = 0; i < used.size(); ++i)
    if (used[i])
      m.weights[i] = fit.weights[j++];
  m.bias = fit.bias + logit(m.threshold) - logit(out.operatingThreshold);
  std::vector<double> shipped(set.size());
  for (std::size_t k = 0; k < set.size(); ++k) {
    shipped[k] = m.confidence(set[k].cues);
    const bool trusted = set[k].cues.tracking && set[k].cues.verified && shipped[k] >= m.threshold;
    out.trustedRight += trusted && set[k].right ? 1 : 0;
    out.trustedWrong += trusted && !set[k].right ? 1 : 0;
  }
  out.auroc = auroc(shipped, right);
  return out;
}

} // namespace pm::compare
