// Output files written whole or not at all: the runners' CSV, SVG and history files.
#pragma once

#include <string>

namespace scene
{
// writes text to path whole (a temporary file path + ".tmp", then renamed over path); false with a message naming the
// file in error ("cannot write PATH.tmp", "cannot rename PATH.tmp to PATH"), and no temporary file left
bool writeWhole(const std::string& path, const std::string& text, std::string& error);
}  // namespace scene
