#include "TextLines.h"

#include <sstream>

#include "CommonInterfaces/CommonGraphicsAppInterface.h"

void drawTextLines(CommonGraphicsApp* app, const std::string& text, int left_px, int top_px)
{
	std::istringstream lines(text);
	std::string line;
	int y = top_px;
	while (std::getline(lines, line))
	{
		app->drawText(line.c_str(), left_px, y, 0.4f);
		y += kTextLine_px;
	}
}
