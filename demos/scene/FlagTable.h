// The runners' flags of a parameter struct P (charpy, structures, wrecking_ball): a table from each flag's name to how
// it sets P from its text, its help (the value's form and the default) and whether it takes a value; one way to apply
// a flag with the runners' messages, and the table's usage lines.
#pragma once

#include <functional>
#include <initializer_list>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "FlagArgument.h"

namespace scene
{
template <class P>
struct Flag
{
	std::function<bool(P&, const std::string&)> set;  // false: the text is not a valid value
	std::string help;
	bool takesValue = true;
};

template <class P>
using Flags = std::map<std::string, Flag<P>>;

// --name=NUMBER into a double field
template <class P>
Flag<P> numberFlag(double P::*field, const char* help)
{
	return {[field](P& p, const std::string& t) { return parseNumber(t, p.*field); }, help};
}

// --name=N into an int field (a whole number)
template <class P>
Flag<P> wholeFlag(int P::*field, const char* help)
{
	return {[field](P& p, const std::string& t) { return parseInteger(t, p.*field); }, help};
}

// --name (no value) sets a bool field
template <class P>
Flag<P> switchFlag(bool P::*field, const char* help)
{
	return {[field](P& p, const std::string&) { return (p.*field = true); }, help, false};
}

// Applies one flag of the table to p, or says why not: unknown (context follows the flag's name, e.g. " for
// --scene=portal"), a value where it takes none, no value where it needs one, a value that is not valid.
template <class P>
void applyFlag(const Flags<P>& flags, P& p, const FlagArgument& flag, std::vector<std::string>& errors, const std::string& context = "")
{
	auto it = flags.find(flag.name);
	if (it == flags.end())
		errors.push_back("unknown flag --" + flag.name + context + " (see --help)");
	else if (!it->second.takesValue && flag.hasValue)
		errors.push_back("--" + flag.name + " takes no value");
	else if (it->second.takesValue && !flag.hasValue)
		errors.push_back("--" + flag.name + " needs a value: --" + flag.name + "=" + it->second.help);
	else if (!it->second.set(p, flag.value))
		errors.push_back("--" + flag.name + ": '" + flag.value + "' is not valid; expected " + it->second.help);
}

// A flag without a value outside the table (--json, --help): sets target, or says it takes none.
inline void setSwitch(const FlagArgument& flag, bool& target, std::vector<std::string>& errors)
{
	if (flag.hasValue)
		errors.push_back("--" + flag.name + " takes no value");
	else
		target = true;
}

// If flag is one of switches (flags without a value outside the table: --help, --json, ...), sets its target (or says
// it takes no value) and returns true; false for any other flag.
inline bool takeSwitch(const FlagArgument& flag, std::initializer_list<std::pair<const char*, bool*>> switches, std::vector<std::string>& errors)
{
	for (const auto& [name, target] : switches)
	{
		if (flag.name == name)
		{
			setSwitch(flag, *target, errors);
			return true;
		}
	}
	return false;
}

// If flag is --name, a file the runner writes, stores its value in target (or says it needs one) and returns true.
inline bool takePath(const FlagArgument& flag, const char* name, std::string& target, std::vector<std::string>& errors)
{
	if (flag.name != name)
		return false;
	if (flag.value.empty())
		errors.push_back("--" + flag.name + " needs a file name: --" + flag.name + "=FILE");
	else
		target = flag.value;
	return true;
}

// one line per flag: "  --name=HELP" ("  --name  HELP" for a flag without a value)
template <class P>
std::string usageOf(const Flags<P>& flags)
{
	std::string text;
	for (const auto& [name, flag] : flags) text += "  --" + name + (flag.takesValue ? "=" : "  ") + flag.help + "\n";
	return text;
}
}  // namespace scene
