#include "pm/lab/LoopTable.h"
#include "pm/lab/TrackingReport.h"

#include <iomanip>
#include <ostream>

namespace pm::lab {

void writeLoopCsvHeader(std::ostream &csv, unsigned dof)
{
  csv << std::setprecision(8) << "t,moving,true_x,true_y,true_z,true_e1,true_e2,true_e3,used_x,used_y,used_z,used_e1,used_e2,used_e3,"
         "translation_error_mm,rotation_error_deg,fitness,state,servoing,compute_ms,estimate_error_mm,estimate_error_deg,"
         "used_error_mm,used_error_deg,"
         "confidence,verified,trusted,held_by,visible_share,background_hue_deg"
      << uncertaintyCsvHeader() << cuesCsvHeader() << stepsCsvHeader();
  for (unsigned i = 1; i <= dof; ++i)
    csv << ",q" << i;
  for (unsigned i = 1; i <= dof; ++i)
    csv << ",qdot" << i;
  csv << "\n";
}

void writeLoopCsvRow(std::ostream &csv, const LoopFrame &f, bool oracle)
{
  const core::Phi a = core::fromHomogeneousMatrix(f.hMmTrue), b = core::fromHomogeneousMatrix(f.hMmUsed);
  csv << f.t << "," << (f.moving ? 1 : 0);
  for (std::size_t i = 0; i < 6; ++i)
    csv << "," << a[i];
  for (std::size_t i = 0; i < 6; ++i)
    csv << "," << b[i];
  csv << "," << f.translationErrorMm << "," << f.rotationErrorDeg << "," << f.track.fitness << ","
      << (oracle ? "oracle" : toString(f.track.state)) << "," << (f.servoing ? 1 : 0) << "," << f.track.computeMs << ","
      << f.estimateErrorMm << "," << f.estimateErrorDeg << "," << f.usedErrorMm << "," << f.usedErrorDeg << ","
      << f.track.confidence << "," << (f.track.verified ? 1 : 0) << "," << (f.track.trusted ? 1 : 0) << "," << (f.heldBy ? f.heldBy : "")
      << "," << f.track.visibleShare << ","
      << f.track.backgroundHueDeg;
  writeUncertaintyCells(csv, f.track.uncertainty);
  writeCueCells(csv, f.track.cues);
  writeStepCells(csv, f.track.steps);
  for (unsigned i = 0; i < f.q.size(); ++i)
    csv << "," << f.q[i];
  for (unsigned i = 0; i < f.qdot.size(); ++i)
    csv << "," << f.qdot[i];
  csv << "\n";
}

} // namespace pm::lab
