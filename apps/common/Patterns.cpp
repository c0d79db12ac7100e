#include "pm/app/Patterns.h"

#include <cmath>

#include "pm/app/App.h"

namespace pm::app {

namespace {
//! v as a whole number, else a usage error about --board.
int wholeNumber(double v, const char *what)
{
  if (v != std::floor(v))
    throw CLI::ValidationError("--board", std::string("the ") + what + " must be whole numbers");
  return static_cast<int>(v);
}

} // namespace

std::unique_ptr<calib::Pattern> makePattern(const std::string &kind, const std::string &layout)
{
  std::unique_ptr<calib::Pattern> pattern;
  if (kind == "chessboard") {
    auto b = std::make_unique<calib::ChessBoard>();
    if (!layout.empty()) {
      const auto v = parseNumbers(layout, 3, "--board");
      b->innerRows = wholeNumber(v[0], "inner corner counts");
      b->innerCols = wholeNumber(v[1], "inner corner counts");
      b->squareMm = b->marginMm = v[2];
    }
    pattern = std::move(b);
  } else {
    auto b = std::make_unique<calib::TagBoard>();
    if (!layout.empty()) {
      const auto v = parseNumbers(layout, 4, "--board");
      b->rows = wholeNumber(v[0], "tag counts");
      b->cols = wholeNumber(v[1], "tag counts");
      b->tagSizeMm = v[2];
      b->pitchMm = v[3];
    }
    pattern = std::move(b);
  }
  pattern->validate();
  return pattern;
}


} // namespace pm::app
