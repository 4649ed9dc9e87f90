// build/bin/charpy: the Charpy impact test, headless, no OpenGL. See --help.
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "CharpyCommandLine.h"
#include "CharpyRun.h"
#include "scene/WholeFile.h"

int main(int argc, char** argv)
{
	std::vector<std::string> arguments(argv + 1, argv + argc);
	CharpyCommandLine cl = parseCharpyCommandLine(arguments);
	if (!cl.errors.empty())
	{
		for (const std::string& e : cl.errors)
		{
			std::cerr << "charpy: " << e << "\n";
		}
		return 2;
	}
	if (cl.help)
	{
		std::cout << charpyUsage();
		return 0;
	}
	if (cl.listMethods)
	{
		for (int i = 1; i <= kCharpyMethodCount; i++)
		{
			CharpyMethod m = charpyMethodByNumber(i);
			std::cout << charpyMethodName(m) << "\t" << i << "\t" << charpyMethodDescription(m) << "\n";
		}
		return 0;
	}
	const std::string warning = charpySelfLockWarning(cl.parameters);
	if (!warning.empty())
	{
		std::cerr << "charpy: warning: " << warning << "\n";
	}
	try
	{
		std::ostringstream history;
		CharpyResult result = runCharpy(cl.parameters, cl.historyPath.empty() ? nullptr : &history);
		if (!result.step_warning.empty())
		{
			std::cerr << "charpy: warning: " << result.step_warning << "\n";
		}
		if (!cl.historyPath.empty())
		{
			// written whole or not at all: to a temporary name, then renamed
			std::string error;
			if (!scene::writeWhole(cl.historyPath, history.str(), error))
			{
				std::cerr << "charpy: --history: " << error << "\n";
				return 1;
			}
		}
		std::cout << (cl.json ? toJson(result) + "\n" : toSummary(result));
		return result.finite ? 0 : 3;
	}
	catch (const std::invalid_argument& e)
	{
		std::cerr << "charpy: " << e.what() << "\n";
		return 2;
	}
}
