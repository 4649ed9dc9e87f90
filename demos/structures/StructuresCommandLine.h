// Command line of build/bin/structures: --scene=NAME picks the scene; every field of its parameter struct has
// a flag (the solver's too: --method, --dt, --iterations). Strict like the Charpy runner: an unknown flag, a
// value that is not wholly a number or one out of range is an error naming the parameter and its range.
#pragma once

#include <string>
#include <vector>

#include "Cantilever.h"
#include "DropWeight.h"
#include "PaperClip.h"
#include "Portal.h"

namespace structures
{
struct StructuresCommandLine
{
	std::string scene;  // cantilever, portal, drop-weight, paper-clip
	CantileverParameters cantilever;
	PortalParameters portal;
	DropWeightParameters dropWeight;
	PaperClipParameters paperClip;
	std::string hysteresisPath;  // paper-clip: --hysteresis=FILE.svg, the moment-rotation loops
	bool help = false;
	bool json = false;
	std::vector<std::string> errors;
};

StructuresCommandLine parseStructuresCommandLine(const std::vector<std::string>& arguments);
std::string structuresUsage();
}  // namespace structures
