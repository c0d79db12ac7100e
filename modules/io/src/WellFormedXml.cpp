#include "pm/io/WellFormedXml.h"

#include <climits>

#include <libxml/parser.h>
#include <libxml/xmlerror.h>

#include "pm/core/Error.h"

namespace pm::io {

namespace {
//! libxml2 prints its errors on stderr by default: silenced, the first one is reported in the Error.
void quiet(void *, const char *, ...) {}
} // namespace

void requireWellFormedXml(const std::string &text)
{
  if (text.size() > static_cast<std::size_t>(INT_MAX))
    throw core::Error("it is too long to be an XML file");
  xmlSetGenericErrorFunc(nullptr, quiet);
  xmlResetLastError();
  xmlDocPtr doc = xmlReadMemory(text.data(), static_cast<int>(text.size()), "noname.xml", nullptr,
                                XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
  if (doc) {
    xmlFreeDoc(doc);
    return;
  }
  const xmlError *e = xmlGetLastError();
  std::string what = e && e->message ? e->message : "unknown error";
  while (!what.empty() && (what.back() == '\n' || what.back() == ' '))
    what.pop_back();
  throw core::Error("it is not well-formed XML (line " + std::to_string(e ? e->line : 0) + ": " + what + ")");
}

} // namespace pm::io
