// Command line of the console runner: every CharpyParameters field has a flag.
#pragma once

#include <string>
#include <vector>

#include "CharpyParameters.h"

struct CharpyCommandLine
{
	CharpyParameters parameters;
	bool listMethods = false;
	bool help = false;
	bool json = false;
	std::string historyPath;  // empty: no history
	std::vector<std::string> errors;  // unknown flags, malformed or out-of-range values
};

// Parses argv[1..]; never throws. Strict: an unknown flag or a value that is not wholly a number is an error.
CharpyCommandLine parseCharpyCommandLine(const std::vector<std::string>& arguments);
std::string charpyUsage();
