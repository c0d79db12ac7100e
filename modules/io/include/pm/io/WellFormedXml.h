#pragma once
/*!
  \file WellFormedXml.h
  A check that a text is well-formed XML, made with libxml2 before a more fragile parser sees it:
  OpenCV 4.6's FileStorage reads past the end of a file cut inside a tag (fuzzing found it).
*/
#include <string>

namespace pm::io {

/*!
  Throws pm::core::Error ("it is not well-formed XML (line N: what libxml2 says)") unless \e text is a
  well-formed XML document. No network access, no external entity is loaded, no entity expanded.
  \code
    pm::io::requireWellFormedXml("<opencv_storage><a>1</a></opencv_storage>"); // fine
    pm::io::requireWellFormedXml("<opencv_storage><a type_id=");                // throws
  \endcode
*/
void requireWellFormedXml(const std::string &text);

} // namespace pm::io
