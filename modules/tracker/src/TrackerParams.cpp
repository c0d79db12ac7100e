#include "pm/tracker/TrackerParams.h"

namespace pm::tracker {

void TrackerParams::validate() const
{
  fitness.validate();
  search.validate();
  lock.validate();
  steady.validate();
  verifier.validate();
  refinement.validate();
  judgement.validate();
  background.validate();
}

} // namespace pm::tracker
