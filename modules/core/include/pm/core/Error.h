#pragma once
/*!
  \file Error.h
  The one exception type of visp-photomodel. Its message is written for the user:
  what went wrong, with which file or value, and what to do.
*/
#include <stdexcept>
#include <string>

namespace pm::core {

/*!
  The exception visp-photomodel throws (see Error.h); what() is the message for the user.
*/
class Error : public std::runtime_error
{
public:
  //! \e what: the message, saying what went wrong, with which file or value, and what to do.
  explicit Error(const std::string &what) : std::runtime_error(what) {}
};

} // namespace pm::core
