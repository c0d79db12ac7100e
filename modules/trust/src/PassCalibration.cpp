#include "pm/trust/PassCalibration.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <thread>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "pm/core/Error.h"
#include "pm/model/PassRig.h"
#include "pm/tracker/PhotoModelTracker.h"
#include "pm/trust/HeldOutViews.h"
#include "pm/trust/RangeBias.h"
#include "pm/tracker/RangeCorrection.h"

namespace pm::trust {

namespace {

using Features = std::array<double, tracker::ConfidenceCues::kFeatures>;

/*!
  The features a camera changes at right poses, the only ones a calibration moves: the fit (q, the worse
  camera's q, its shares of S_in on the model's hue and of S_out on the background), the precise stage's
  residual and separation. Not the margin over the turned poses nor the lines' sigmas: those are the
  toy's shape (a head's nearly round outline has a small margin through any camera), and a small margin
  is a danger to keep seeing. Not the state's cues: those are the run's.
*/
constexpr std::array<bool, tracker::ConfidenceCues::kFeatures> kImageCues{true,  true,  true,  true,  false, false, false, false, false,
                                                                          false, false, false, false, true,  false, false, true,  false};

//! \e t's cues as a steady, verified lock reads them (the state's cues the tracker's at run time).
tracker::ConfidenceCues steady(const PassTry &t)
{
  tracker::ConfidenceCues c = t.cues;
  c.framesTracked = 30;
  c.verified = true;
  c.tracking = true;
  c.qualityDrop = 0;
  c.jumpMm = 0;
  c.jumpDeg = 0;
  return c;
}

double median(std::vector<double> v)
{
  if (v.empty())
    return 0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double quantile(std::vector<double> v, double q)
{
  if (v.empty())
    return 1;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  const double f = pos - static_cast<double>(i);
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

//! The area under the ROC of \e right scores against \e wrong ones (ties count half).
double auroc(std::vector<double> right, std::vector<double> wrong)
{
  if (right.empty() || wrong.empty())
    return 0;
  std::sort(wrong.begin(), wrong.end());
  double a = 0;
  for (double r : right) {
    const auto lo = std::lower_bound(wrong.begin(), wrong.end(), r), hi = std::upper_bound(wrong.begin(), wrong.end(), r);
    a += static_cast<double>(lo - wrong.begin()) + 0.5 * static_cast<double>(hi - lo);
  }
  return a / (static_cast<double>(right.size()) * static_cast<double>(wrong.size()));
}

//! The shifts that bring the right tries' medians \e rightMedian up to \e m's reference, where the weight counts them short.
Features deficits(const tracker::ConfidenceModel &m, const Features &rightMedian)
{
  Features s{};
  const bool referenced = std::any_of(m.reference.begin(), m.reference.end(), [](double r) { return r != 0; });
  for (std::size_t i = 0; i < s.size() && referenced; ++i) {
    if (!kImageCues[i] || m.weights[i] == 0)
      continue;
    const double d = m.reference[i] - rightMedian[i];
    s[i] = m.weights[i] > 0 ? std::max(0.0, d) : std::min(0.0, d);
  }
  return s;
}

//! \e m with \e shifts times \e a added.
tracker::ConfidenceModel shifted(const tracker::ConfidenceModel &m, const Features &shifts, double a)
{
  tracker::ConfidenceModel out = m;
  for (std::size_t i = 0; i < shifts.size(); ++i)
    out.shift[i] += a * shifts[i];
  return out;
}

double highest(const tracker::ConfidenceModel &m, const std::vector<tracker::ConfidenceCues> &cues)
{
  double h = 0;
  for (const auto &c : cues)
    h = std::max(h, m.confidence(c));
  return h;
}

/*!
  Each axis's gain: the sigmaShare quantile of |error| / sigma over the right tries whose sigma is known,
  never under 1: a pass whose errors exceed the sigmas widens them; one whose errors fall within them
  does not narrow them (a held-out view's model lacks that view, its sigma its own; a sigma too small is
  a danger, one too large a caution).
*/
std::array<double, 6> sigmaGains(const std::vector<const PassTry *> &right, const CalibrationParams &p)
{
  std::array<double, 6> gain{1, 1, 1, 1, 1, 1};
  for (std::size_t a = 0; a < 6; ++a) {
    std::vector<double> ratio;
    for (const PassTry *t : right) {
      if (!t->uncertainty.known)
        continue;
      const double s = a < 3 ? t->uncertainty.sigmaMm[a] : t->uncertainty.sigmaDeg[a - 3];
      if (s > 0 && std::isfinite(s))
        ratio.push_back(std::fabs(t->error[a]) / s);
    }
    if (ratio.size() >= 5)
      gain[a] = std::clamp(quantile(ratio, p.sigmaShare), std::max(1.0, p.minGain), p.maxGain);
  }
  return gain;
}

} // namespace

void CalibrationParams::validate() const
{
  auto check = [](bool ok, const char *what) {
    if (!ok)
      throw core::Error(std::string("trust calibration: ") + what);
  };
  check(heldOutViews >= 1 && heldOutViews <= 200, "the views held out must number 1 to 200");
  check(viewsPerModel >= 1 && viewsPerModel <= heldOutViews, "each model must hold out 1 to all of the views held out");
  check(tries.nearStarts >= 1 && tries.nearFrames >= 1 && tries.wrongFrames >= 1 && tries.searches >= 0 && tries.searchFrames >= 1,
        "at least one near start and one frame per try");
  check(wrongCeiling > 0 && wrongCeiling < 1, "the wrong tries' ceiling must lie in (0, 1)");
  check(plainlyWrongCeiling > 0 && plainlyWrongCeiling <= wrongCeiling, "the plainly wrong tries' ceiling must lie in (0, the wrong tries']");
  check(maxLogitGain >= 0, "the shifts' largest gain must not be negative");
  check(sigmaShare > 0 && sigmaShare < 1, "the share within 1 sigma must lie in (0, 1)");
  check(rangeMaxCameras >= 0, "the range's largest rig must not be negative");
  check(minGain > 0 && maxGain >= minGain, "the sigmas' gains need 0 < min <= max");
}

core::TrustCalibration calibrateTrust(const std::vector<PassTry> &tries, const tracker::ConfidenceModel &shipped, const CalibrationParams &p)
{
  p.validate();
  core::TrustCalibration t;
  std::vector<const PassTry *> right;
  std::vector<tracker::ConfidenceCues> rightCues, wrongCues, plainlyWrongCues;
  std::vector<std::size_t> views;
  for (const PassTry &x : tries) {
    if (x.right()) {
      right.push_back(&x);
      rightCues.push_back(steady(x));
    } else if (x.wrong()) {
      wrongCues.push_back(steady(x));
      if (x.plainlyWrong())
        plainlyWrongCues.push_back(wrongCues.back());
    }
    if (std::find(views.begin(), views.end(), x.view) == views.end())
      views.push_back(x.view);
  }
  t.heldOutViews = static_cast<int>(views.size());
  t.rightExamples = static_cast<int>(right.size());
  t.wrongExamples = static_cast<int>(wrongCues.size());
  t.measured = !right.empty();
  if (!t.measured)
    return t;

  // 1. What right poses read here, and the shifts that read them as the lab's right poses.
  Features rightMedian{};
  const auto &names = tracker::ConfidenceCues::featureNames();
  for (std::size_t i = 0; i < rightMedian.size(); ++i) {
    std::vector<double> v;
    for (const auto &c : rightCues)
      if (c.measured(i))
        v.push_back(c.features()[i]);
    rightMedian[i] = v.empty() ? shipped.reference[i] : median(v);
    t.rightReadings.emplace_back(names[i], rightMedian[i]);
  }
  Features want = deficits(shipped, rightMedian);
  double gain = 0; // what the shifts add to the logit
  for (std::size_t i = 0; i < want.size(); ++i)
    gain += shipped.weights[i] * want[i];
  if (gain > p.maxLogitGain)
    for (double &w : want)
      w *= p.maxLogitGain / gain;
  // 2. The guard: no wrong try over its ceiling (or over the shipped confidence's own highest): a near
  //    miss's, and the lower one of a plainly wrong try.
  const double ceiling = std::max(p.wrongCeiling, highest(shipped, wrongCues));
  const double plainCeiling = std::max(p.plainlyWrongCeiling, highest(shipped, plainlyWrongCues));
  const auto guarded = [&](const tracker::ConfidenceModel &m) {
    return highest(m, wrongCues) <= ceiling && highest(m, plainlyWrongCues) <= plainCeiling;
  };
  double a = 1;
  while (a > 0 && !guarded(shifted(shipped, want, a)))
    a = std::max(0.0, a - 0.1);
  t.guard = a;
  tracker::ConfidenceModel m = shifted(shipped, want, a);
  // 3. No plainly wrong try trusted: where even the shipped confidence trusts one through this camera,
  //    every confidence is lowered on its logit until the highest sits at the plainly wrong tries'
  //    ceiling. (A near miss of 5-10 deg, a thin toy's roll, is the guard's business, as before.)
  const double worst = highest(m, plainlyWrongCues);
  if (worst >= m.threshold) {
    const auto logit = [](double q) { return std::log(q / (1 - q)); };
    t.confidenceOffset = logit(p.plainlyWrongCeiling) - logit(std::min(worst, 1 - 1e-12));
    m.bias += t.confidenceOffset;
  }
  for (std::size_t i = 0; i < want.size(); ++i)
    if (a * want[i] != 0)
      t.cueShifts.emplace_back(names[i], a * want[i]);
  // Its figures on the tries.
  std::vector<double> rs, ws;
  int trusted = 0, trustedShipped = 0;
  for (const auto &c : rightCues) {
    rs.push_back(m.confidence(c));
    trusted += rs.back() >= m.threshold;
    trustedShipped += shipped.confidence(c) >= shipped.threshold;
  }
  for (const auto &c : wrongCues) {
    ws.push_back(m.confidence(c));
    t.wrongTrusted += ws.back() >= m.threshold;
    t.wrongMaxConfidence = std::max(t.wrongMaxConfidence, ws.back());
  }
  t.auroc = auroc(rs, ws);
  t.rightTrusted = static_cast<double>(trusted) / static_cast<double>(rightCues.size());
  t.rightTrustedShipped = static_cast<double>(trustedShipped) / static_cast<double>(rightCues.size());
  // 4. The sigmas.
  t.sigmaGain = sigmaGains(right, p);
  for (std::size_t ax = 0; ax < 6; ++ax) {
    int n = 0, within = 0;
    for (const PassTry *x : right) {
      if (!x->uncertainty.known)
        continue;
      const double s = t.sigmaGain[ax] * (ax < 3 ? x->uncertainty.sigmaMm[ax] : x->uncertainty.sigmaDeg[ax - 3]);
      ++n;
      within += std::fabs(x->error[ax]) <= s;
    }
    t.withinSigma[ax] = n > 0 ? static_cast<double>(within) / n : 0;
  }
  return t;
}

std::size_t calibrationSteps(std::size_t views, const CalibrationParams &p)
{
  const std::vector<std::vector<std::size_t>> folds = heldOutFolds(views, p.heldOutViews, p.viewsPerModel);
  std::size_t steps = folds.size(); // a step a model built, and one a view tried
  for (const std::vector<std::size_t> &f : folds)
    steps += f.size();
  return steps;
}

namespace {

/*!
  The held-out models of \e folds, built two at a time (the builder runs on one core): the models, or for a
  fold that cannot be built its reason in \e errors. \e onStep after each model, on the calling thread.
*/
std::vector<std::optional<FoldModel>> buildFolds(const core::StereoRig &rig, const std::vector<model::PassView> &pass,
                                                 const model::AllAroundParams &params, const model::PassMeasurements &measured,
                                                 const std::vector<std::vector<std::size_t>> &folds,
                                                 std::vector<std::string> &errors, const std::function<void()> &onStep)
{
  std::vector<std::optional<FoldModel>> models(folds.size());
  std::vector<std::exception_ptr> failures(folds.size());
  errors.assign(folds.size(), "");
  std::atomic<std::size_t> next{0}, done{0};
  auto work = [&] {
    for (std::size_t i; (i = next++) < folds.size();) {
      try {
        models[i] = buildFoldModel(rig, pass, params, measured, folds[i]);
      } catch (const core::Error &e) {
        errors[i] = e.what();
      } catch (...) {
        failures[i] = std::current_exception();
      }
      ++done;
    }
  };
  std::thread helper;
  if (std::thread::hardware_concurrency() > 1 && folds.size() > 1)
    helper = std::thread(work);
  std::size_t reported = 0;
  work();
  if (helper.joinable()) {
    while (done < folds.size()) { // report the helper's models as they come
      for (; reported < done; ++reported)
        if (onStep)
          onStep();
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    helper.join();
  }
  for (; reported < folds.size(); ++reported)
    if (onStep)
      onStep();
  for (const std::exception_ptr &f : failures)
    if (f)
      std::rethrow_exception(f);
  return models;
}

} // namespace

core::TrustCalibration calibrateFromPass(const core::CameraRig &rig, const std::vector<model::PassView> &pass, const model::AllAroundParams &params,
                                         const model::PassMeasurements &measured, const tracker::TrackerParams &trackerParams, const CalibrationParams &p,
                                         const std::function<void()> &onStep, std::string *why, std::vector<PassTry> *triesOut)
{
  p.validate();
  const auto t0 = std::chrono::steady_clock::now();
  model::AllAroundParams foldParams = params;
  foldParams.carving.minViews = std::min(params.carving.minViews, pass.size() > 4 ? pass.size() - 4 : std::size_t{1});
  const std::vector<std::vector<std::size_t>> folds = heldOutFolds(pass.size(), p.heldOutViews, p.viewsPerModel);
  std::vector<std::string> errors;
  const core::StereoRig pair = model::passRig(rig);
  const core::CameraRig tried = rig.size() <= 2 ? rig : core::CameraRig(pair); // the cameras a pass view holds
  const std::vector<std::optional<FoldModel>> models = buildFolds(pair, pass, foldParams, measured, folds, errors, onStep);
  std::vector<PassTry> tries;
  std::string reason;
  for (std::size_t f = 0; f < folds.size(); ++f) {
    if (!models[f]) {
      reason = errors[f];
      for (std::size_t k = 0; k < folds[f].size() && onStep; ++k)
        onStep();
      continue;
    }
    tracker::PhotoModelTracker tracker(tried, models[f]->model, trackerParams);
    for (std::size_t k : folds[f]) {
      const std::vector<PassTry> v = tryView(tracker, pass[k], pass[k].fMh.inverse() * models[f]->fMm, p.tries, k, k);
      tries.insert(tries.end(), v.begin(), v.end());
      if (onStep)
        onStep();
    }
  }
  // The range the precise stage reads through this rig: measured, and the tries' errors corrected as the tracker will correct them.
  const std::array<double, 3> centre = tracker::cameraCentreMm(tried);
  const RangeBias range = measureRangeBias(tries, centre);
  const bool correctRange = range.measured() && static_cast<int>(tried.size()) <= p.rangeMaxCameras;
  if (correctRange)
    for (PassTry &x : tries)
      x = rangeCorrected(x, range.scale, centre);
  tracker::ConfidenceModel shipped = tracker::ConfidenceModel::shipped(tracker::ConfidenceKind::AllAround);
  shipped.threshold = trackerParams.judgement.confidence.threshold;
  core::TrustCalibration t = calibrateTrust(tries, shipped, p);
  t.rangeErrorPct = range.errorPct;
  t.rangeViews = range.views;
  if (t.measured && correctRange) {
    t.rangeScale = range.scale;
    t.rangeCameras = static_cast<int>(tried.size());
  }
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!t.measured && why)
    *why = tries.empty() ? "no model could be built without some of the views (" + reason + ")"
                         : "the tracker found no right pose on the held-out views";
  if (triesOut)
    *triesOut = std::move(tries);
  return t;
}

std::string triesCsv(const std::vector<PassTry> &tries, const core::TrustCalibration &calibrated)
{
  const tracker::ConfidenceModel shipped = tracker::ConfidenceModel::shipped(tracker::ConfidenceKind::AllAround);
  const tracker::ConfidenceModel m = shipped.calibrated(calibrated);
  std::ostringstream s;
  s << "view,start,error_mm,error_deg,err_x_mm,err_y_mm,err_z_mm,err_rx_deg,err_ry_deg,err_rz_deg,label,confidence_shipped,confidence,"
       "sigma_x_mm,sigma_y_mm,sigma_z_mm,sigma_rx_deg,sigma_ry_deg,sigma_rz_deg";
  for (const char *n : tracker::ConfidenceCues::featureNames())
    s << "," << n;
  s << "\n" << std::setprecision(6);
  for (const PassTry &t : tries) {
    const tracker::ConfidenceCues c = steady(t);
    s << t.view << "," << t.start << "," << t.errorMm << "," << t.errorDeg;
    for (double e : t.error)
      s << "," << e;
    s << "," << (t.right() ? "right" : t.wrong() ? "wrong" : "between") << "," << shipped.confidence(c) << "," << m.confidence(c);
    for (std::size_t a = 0; a < 6; ++a) {
      s << ",";
      if (t.uncertainty.known)
        s << calibrated.sigmaGain[a] * (a < 3 ? t.uncertainty.sigmaMm[a] : t.uncertainty.sigmaDeg[a - 3]);
    }
    for (double x : c.features())
      s << "," << x;
    s << "\n";
  }
  return s.str();
}

std::string describe(const core::TrustCalibration &t)
{
  std::ostringstream s;
  if (!t.measured)
    return "trust: not calibrated from the pass (the shipped confidence and sigmas)";
  s << std::fixed << std::setprecision(3) << "trust from the pass: on " << t.heldOutViews << " views held out of the model, right and wrong tries ("
    << t.rightExamples << " and " << t.wrongExamples << ") separate with AUROC " << t.auroc << "; cues read as the lab's by ";
  if (t.cueShifts.empty())
    s << "none (they read as well as there)";
  for (std::size_t i = 0; i < t.cueShifts.size(); ++i)
    s << (i ? ", " : "") << t.cueShifts[i].first << " " << std::showpos << std::setprecision(3) << t.cueShifts[i].second << std::noshowpos;
  if (t.guard < 1)
    s << std::setprecision(1) << " (" << 100 * t.guard << " % of it: wrong tries came near)";
  if (t.confidenceOffset < 0)
    s << std::setprecision(2) << "; every confidence lowered by " << -t.confidenceOffset << " on its logit (plainly wrong tries read right through this camera)";
  s << std::setprecision(0) << "; as steady locks it trusts " << 100 * t.rightTrusted << " % of the right tries (shipped "
    << 100 * t.rightTrustedShipped << " %; the lab's own passes 39-71 %), " << t.wrongTrusted << " wrong" << std::setprecision(2)
    << " (the highest " << t.wrongMaxConfidence << "); 1-sigma x";
  for (std::size_t i = 0; i < 6; ++i)
    s << (i ? "," : "") << std::setprecision(1) << t.sigmaGain[i];
  if (t.rangeScale != 1)
    s << std::setprecision(2) << "; the held-out views' poses " << std::fabs(t.rangeErrorPct) << " % of their range too "
      << (t.rangeErrorPct > 0 ? "far" : "near") << " (" << std::setprecision(1) << 5 * std::fabs(t.rangeErrorPct) << " mm at 500 mm), corrected";
  else if (t.rangeViews > 0)
    s << std::setprecision(2) << "; the range not corrected (the held-out views " << std::showpos << t.rangeErrorPct << std::noshowpos
      << " %; corrected through one camera only, from 0.1 % on which the views agree)";
  s << std::setprecision(1) << " (" << t.seconds << " s)";
  return s.str();
}

} // namespace pm::trust
