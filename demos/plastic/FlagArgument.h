// One command-line argument in the runners' flag style (charpy, structures, wrecking_ball): --name or --name=value.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace plastic
{
struct FlagArgument
{
	std::string name;
	std::string value;
	bool hasValue = false;
};

// The flag in argument, or nothing (with the runners' error text added to errors) when it does not start with "--".
inline std::optional<FlagArgument> splitFlagArgument(const std::string& argument, std::vector<std::string>& errors)
{
	if (argument.rfind("--", 0) != 0)
	{
		errors.push_back("unexpected argument '" + argument + "' (flags look like --name=value)");
		return std::nullopt;
	}
	FlagArgument flag;
	flag.name = argument.substr(2);
	const size_t eq = flag.name.find('=');
	if (eq != std::string::npos)
	{
		flag.value = flag.name.substr(eq + 1);
		flag.name = flag.name.substr(0, eq);
		flag.hasValue = true;
	}
	return flag;
}
}  // namespace plastic
