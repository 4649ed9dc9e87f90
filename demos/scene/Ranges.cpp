#include "Ranges.h"

#include <cmath>
#include <sstream>

namespace scene
{
namespace
{
void requireRange(std::vector<std::string>& errors, const char* name, double value, double low, double high, bool lowInclusive, const char* unit)
{
	if (!(std::isfinite(value) && (lowInclusive ? value >= low : value > low) && value <= high))
	{
		std::ostringstream out;
		out << name << ": " << value << " is not in " << (lowInclusive ? "[" : "(") << low << ", " << high << "]" << (*unit ? " " : "") << unit;
		errors.push_back(out.str());
	}
}
}  // namespace

void requireRange(std::vector<std::string>& errors, const char* name, double value, double low, double high, const char* unit)
{
	requireRange(errors, name, value, low, high, true, unit);
}

void requireRangeAbove(std::vector<std::string>& errors, const char* name, double value, double low, double high, const char* unit)
{
	requireRange(errors, name, value, low, high, false, unit);
}

void requireWhole(std::vector<std::string>& errors, const char* name, int value, int low, int high)
{
	if (value < low || value > high)
	{
		errors.push_back(std::string(name) + ": " + std::to_string(value) + " is not in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
	}
}

void requireDrifts(std::vector<std::string>& errors, const char* name, const std::vector<double>& drifts, double limit, const char* of)
{
	if (drifts.size() > 100) errors.push_back(std::string(name) + ": " + std::to_string(drifts.size()) + " drifts is not in [1, 100]");
	double from = 0;
	for (size_t i = 0; i < drifts.size(); i++)
	{
		const double d = drifts[i];
		if (!(std::fabs(d) <= limit) || d == from)
		{
			std::ostringstream out;
			out << name << ": drift " << i + 1 << " (" << d << ") is not in [" << -limit << ", " << limit << "] " << of << " or is the drift before it";
			errors.push_back(out.str());
		}
		from = d;
	}
}
}  // namespace scene
