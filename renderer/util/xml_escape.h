#pragma once
// Text for XML and HTML pages (the JUnit file and HTML report of ochre-regress, the relighting page of
// ochre relight).

#include <string>

namespace ochre {

// XML text with &, <, >, " and ' escaped (for attribute values and text; also valid HTML).
std::string xml_escape(const std::string& text);

}  // namespace ochre
