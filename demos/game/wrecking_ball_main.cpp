// build/bin/wrecking_ball: the game scene headless, no OpenGL. See --help.
#include <iostream>
#include <stdexcept>

#include "WreckingBallCommandLine.h"
#include "WreckingBallOutput.h"
#include "scene/WholeFile.h"

int main(int argc, char** argv)
{
	using namespace game;
	const WreckingBallCommandLine cl = parseWreckingBallCommandLine(std::vector<std::string>(argv + 1, argv + argc));
	if (!cl.errors.empty())
	{
		for (const std::string& e : cl.errors) std::cerr << "wrecking_ball: " << e << "\n";
		return 2;
	}
	if (cl.help)
	{
		std::cout << wreckingBallUsage();
		return 0;
	}
	try
	{
		WreckingBallScene scene(cl.parameters);
		std::string history = historyHeader();
		while (!scene.done())
		{
			scene.step();
			if (!cl.history_csv.empty()) history += historyRow(scene.time_s(), scene.result());
		}
		const WreckingBallResult r = scene.result();
		std::string error;
		if (!cl.joints_csv.empty() && !scene::writeWhole(cl.joints_csv, jointsCsv(r), error)) throw std::runtime_error(error);
		if (!cl.history_csv.empty() && !scene::writeWhole(cl.history_csv, history, error)) throw std::runtime_error(error);
		std::cout << (cl.json ? toJson(cl.parameters, r) + "\n" : toSummary(cl.parameters, r));
		return r.finite ? 0 : 3;
	}
	catch (const std::invalid_argument& e)
	{
		std::cerr << "wrecking_ball: " << e.what() << "\n";
		return 2;
	}
	catch (const std::runtime_error& e)
	{
		std::cerr << "wrecking_ball: " << e.what() << "\n";
		return 1;
	}
}
