// Text inside XML elements and attributes: the X3P's main.xml (x3p_writer.cpp) and the
// cutter pictures' SVG (tools/render/cutter_svg.cpp) write user text (comments, titles).
#pragma once

#include <string>

namespace scallop {

// `text` with &, < and > escaped and the control characters XML 1.0 forbids (all below
// 0x20 but tab and newline) dropped.
std::string xmlEscape(const std::string& text);

}  // namespace scallop
