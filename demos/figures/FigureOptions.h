// Command line of charpy_figures: strict, every bad value named with its valid range.
#pragma once

#include <string>
#include <vector>

#include "CharpyMethod.h"

struct FigureOptions
{
	std::string out_dir = "charpy-figures";  // created if missing
	int width_px = 480;                      // of each frame; the contact sheet uses half size tiles
	int height_px = 360;
	std::vector<CharpyMethod> methods;       // default: all eight in thesis order
};

bool parseFigureOptions(int argc, char* argv[], FigureOptions& options, std::string& error);
