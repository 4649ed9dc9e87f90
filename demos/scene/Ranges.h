// The scenes' range checks of their parameters: one message per value out of its range, naming it, the range and
// the unit, as the runners print them.
#pragma once

#include <string>
#include <vector>

namespace scene
{
// "name: value is not in [low, high] unit" into errors when value is outside the range (or not finite)
void requireRange(std::vector<std::string>& errors, const char* name, double value, double low, double high, const char* unit);
// the same for a range open at its low end, (low, high]
void requireRangeAbove(std::vector<std::string>& errors, const char* name, double value, double low, double high, const char* unit);
void requireWhole(std::vector<std::string>& errors, const char* name, int value, int low, int high);
// a pushover's drifts in order: 1 to 100 of them, each in [-limit, limit] and not the one before it (the first not 0)
void requireDrifts(std::vector<std::string>& errors, const char* name, const std::vector<double>& drifts, double limit, const char* of);
}  // namespace scene
