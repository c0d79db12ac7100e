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

//! Whether \e f is trusted by \e m (tracking, verified, confident).
bool trustedBy(const tracker::ConfidenceModel &m, const LabelledFrame &f)
{
  return f.cues.tracking && f.cues.verified && m.confidence(f.cues) >= m.threshold;
}

//! The held-out runs' figures under \e m.
ConfidenceFit::HeldOut scoreHeldOut(const ConfidenceStudy &study, const std::vector<bool> &heldRun, const tracker::ConfidenceModel &m)
{
  ConfidenceFit::HeldOut h;
  std::vector<double> conf;
  std::vector<bool> right;
  std::vector<std::size_t> rightOf(heldRun.size(), 0), trustedOf(heldRun.size(), 0);
  for (std::size_t k = 0; k < study.frames.size(); ++k) {
    const std::size_t run = study.runOf.at(k);
    if (!heldRun[run])
      continue;
    const LabelledFrame &f = study.frames[k];
    const bool trusted = trustedBy(m, f);
    conf.push_back(m.confidence(f.cues));
    right.push_back(f.right);
    ++h.frames;
    h.wrong += f.right ? 0 : 1;
    h.trustedRight += trusted && f.right ? 1 : 0;
    h.trustedWrong += trusted && !f.right ? 1 : 0;
    rightOf[run] += f.right ? 1 : 0;
    trustedOf[run] += trusted && f.right ? 1 : 0;
  }
  for (std::size_t r = 0; r < heldRun.size(); ++r) {
    h.runs += heldRun[r] ? 1 : 0;
    if (heldRun[r] && rightOf[r] > 0)
      h.worstRunTrustedShare = std::min(h.worstRunTrustedShare, static_cast<double>(trustedOf[r]) / static_cast<double>(rightOf[r]));
  }
  if (h.wrong > 0 && h.wrong < h.frames)
    h.auroc = auroc(conf, right);
  return h;
}

} // namespace

ConfidenceFit fitConfidence(const ConfidenceStudy &study, tracker::ConfidenceKind kind, double maxFalseAccept, const std::string &heldOut)
{
  if (kind == tracker::ConfidenceKind::Auto || kind == tracker::ConfidenceKind::Custom)
    throw core::Error("fitConfidence: fit a kind of model (flat, stereo or all-around)");
  if (study.frames.empty())
    throw core::Error("fitConfidence: no frame");
  // The runs left out of the fit: those through the held-out camera.
  std::vector<bool> heldRun(study.runNames.size(), false);
  for (std::size_t r = 0; r < heldRun.size() && !heldOut.empty(); ++r)
    heldRun[r] = r < study.runVariation.size() && study.runVariation[r] == heldOut;
  if (!heldOut.empty() && std::find(heldRun.begin(), heldRun.end(), true) == heldRun.end())
    throw core::Error("fitConfidence: no run was filmed through the held-out camera '" + heldOut + "'");
  std::vector<LabelledFrame> set;
  std::vector<std::size_t> runOf;
  for (std::size_t k = 0; k < study.frames.size(); ++k)
    if (!heldRun[study.runOf.at(k)]) {
      set.push_back(study.frames[k]);
      runOf.push_back(study.runOf[k]);
    }
  if (set.empty())
    throw core::Error("fitConfidence: no frame left to fit on");
  const auto used = tracker::ConfidenceModel::featuresUsed(kind);
  std::vector<std::vector<double>> rows;
  std::vector<bool> right;
  std::vector<int> fold;
  for (std::size_t k = 0; k < set.size(); ++k) {
    rows.push_back(usedFeatures(set[k], used));
    right.push_back(set[k].right);
    fold.push_back(static_cast<int>(runOf[k] % 2));
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
    const bool trusted = trustedBy(m, set[k]);
    out.trustedRight += trusted && set[k].right ? 1 : 0;
    out.trustedWrong += trusted && !set[k].right ? 1 : 0;
  }
  out.auroc = auroc(shipped, right);
  if (!heldOut.empty()) {
    out.heldOut = scoreHeldOut(study, heldRun, m);
    out.heldOut.variation = heldOut;
  }
  return out;
}

} // namespace pm::compare
