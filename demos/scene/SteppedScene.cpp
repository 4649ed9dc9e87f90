#include "SteppedScene.h"

#include <cstdio>

namespace scene
{
std::string ledgerText(const SceneLedger& l)
{
	char line[256];
	std::string text = l.title + "\n";
	std::snprintf(line, sizeof line, "t = %.3f s\n", l.time_s);
	text += line;
	std::snprintf(line, sizeof line, "load work %.1f J\nkinetic %.1f J\nplastic (booked) %.1f J\nplastic (Mp x rotations) %.1f J\n", l.load_work_j,
				  l.kinetic_j, l.plastic_booked_j, l.plastic_measured_j);
	text += line;
	for (const std::string& s : l.answer) text += s + "\n";
	for (const std::string& s : l.status) text += s + "\n";
	return text;
}
}  // namespace scene
