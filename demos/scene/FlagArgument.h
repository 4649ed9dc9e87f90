// One command-line argument in the runners' flag style (charpy, structures, wrecking_ball): --name or --name=value.
#pragma once

#include <cerrno>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace scene
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
// Every argument's flag, in order; an argument that is no flag is left out, with the runners' error text in errors.
inline std::vector<FlagArgument> splitFlagArguments(const std::vector<std::string>& arguments, std::vector<std::string>& errors)
{
	std::vector<FlagArgument> flags;
	for (const std::string& argument : arguments)
	{
		if (std::optional<FlagArgument> flag = splitFlagArgument(argument, errors))
		{
			flags.push_back(*flag);
		}
	}
	return flags;
}

// A flag's value as a number: the whole text must be a number strtod reads (the parameters' validation checks its range).
inline bool parseNumber(const std::string& text, double& value)
{
	if (text.empty())
	{
		return false;
	}
	char* end = nullptr;
	errno = 0;
	value = std::strtod(text.c_str(), &end);
	return end == text.c_str() + text.size() && errno == 0;
}

// A flag's value as a whole number in [-1e9, 1e9].
inline bool parseInteger(const std::string& text, int& value)
{
	double d;
	if (!parseNumber(text, d) || d != static_cast<double>(static_cast<long long>(d)) || d < -1e9 || d > 1e9)
	{
		return false;
	}
	value = static_cast<int>(d);
	return true;
}
}  // namespace scene
