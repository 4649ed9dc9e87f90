// Command line of build/bin/structures: --scene=NAME picks the scene; every field of its parameter struct has
// a flag (the solver's too: --method, --dt, --iterations). Strict like the Charpy runner: an unknown flag, a
// value that is not wholly a number or one out of range is an error naming the parameter and its range.
#pragma once

#include <string>
#include <vector>

#include "Cantilever.h"
#include "DropWeight.h"
#include "Portal.h"

namespace structures
{
struct StructuresCommandLine
{
	std::string scene;  // cantilever, portal, drop-weight
	CantileverParameters cantilever;
	PortalParameters portal;
	DropWeightParameters dropWeight;
	bool help = false;
	bool json = false;
	std::vector<std::string> errors;
};

StructuresCommandLine parseStructuresCommandLine(const std::vector<std::string>& arguments);
std::string structuresUsage();
}  // namespace structures
