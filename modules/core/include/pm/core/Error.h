#pragma once
/*!
  \file Error.h
  The one exception type of visp-photomodel. Its message is written for the user:
  what went wrong, with which file or value, and what to do.
*/
#include <stdexcept>
#include <string>

namespace pm {

class Error : public std::runtime_error
{
public:
  explicit Error(const std::string &what) : std::runtime_error(what) {}
};

} // namespace pm
