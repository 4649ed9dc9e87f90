// Command line of build/bin/wrecking_ball: a flag for every field of WreckingBallParameters (units in the help), strict
// like the other runners: an unknown flag, a value that is not wholly a number, or one out of its range is an error
// naming the parameter and its range.
#pragma once

#include <string>
#include <vector>

#include "WreckingBall.h"

namespace game
{
struct WreckingBallCommandLine
{
	WreckingBallParameters parameters;
	bool help = false;
	bool json = false;
	std::string joints_csv;   // per-joint energies, written whole
	std::string history_csv;  // per frame energies, written whole
	std::vector<std::string> errors;
};

WreckingBallCommandLine parseWreckingBallCommandLine(const std::vector<std::string>& arguments);
std::string wreckingBallUsage();
}  // namespace game
