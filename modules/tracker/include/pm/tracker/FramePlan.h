#pragma once
/*!
  \file FramePlan.h
  What a frame will do, decided before its search starts: whether it is a steady frame (the steady
  budget, SteadyFramePolicy), whether its hue planes hold only the steady windows, whether the lock
  verifier's challenger runs (LockVerifier), and the budgets of the main search and of the
  challenger, out of the whole frame budget (SearchParams::budget()). A value: nothing in it changes
  once the frame has started.

  \code
    pm::tracker::FramePlan plan = steady.plan(verifier.verifying(state));
    plan.hueMs = hueMs;
    plan.setBudgets(params.search, params.steady, params.verifier);
    const pm::rmga::FrameResult r = ga.evolve(objective, plan.main);
  \endcode
*/
#include "pm/rmga/RmGa.h"

namespace pm::tracker {

struct SearchParams;
struct SteadyParams;
struct VerifierParams;

//! A frame's plan (see the file's description).
struct FramePlan
{
  bool verifying = false;       //!< the challenger searches this frame (on the whole images)
  bool steady = false;          //!< the main search gets the steady budget (SteadyParams::budgetFraction)
  bool windowed = false;        //!< the hue planes are computed only in the steady windows
  double hueMs = 0;             //!< the time the hue planes took (ms; a wall-time budget is what remains)
  rmga::FrameBudget main;       //!< the main search's budget
  rmga::FrameBudget mainWhole;  //!< the main search's budget on a frame that is not steady (an escalation's total)
  rmga::FrameBudget challenger; //!< the challenger's budget (when verifying)

  /*!
    The budgets: the whole frame budget, less the hue planes' time (hueMs) when it is wall time; the
    challenger's share of it while verifying (VerifierParams::budgetFraction), the main search the
    rest, or the steady budget on a steady frame (never under one population's evaluations).
  */
  void setBudgets(const SearchParams &search, const SteadyParams &steadyParams, const VerifierParams &verifier);
};

//! The part \e fraction of \e b; never under \e population evaluations.
rmga::FrameBudget budgetPart(const rmga::FrameBudget &b, double fraction, int population);

} // namespace pm::tracker
