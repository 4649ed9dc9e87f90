// A number as the runners write it in JSON: nine significant digits, null for NaN and infinity.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

namespace scene
{
inline std::string jsonNumber(double value)
{
	if (!std::isfinite(value))
	{
		return "null";
	}
	char text[64];
	std::snprintf(text, sizeof text, "%.9g", value);
	return text;
}
}  // namespace scene
