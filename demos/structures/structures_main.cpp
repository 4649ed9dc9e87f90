// build/bin/structures: structures with textbook answers (cantilever, portal frame, drop weight, paper clip), headless, no
// OpenGL. See --help.
#include <iostream>
#include <stdexcept>

#include "StructuresCommandLine.h"
#include "StructuresOutput.h"
#include "scene/WholeFile.h"

int main(int argc, char** argv)
{
	using namespace structures;
	const StructuresCommandLine cl = parseStructuresCommandLine(std::vector<std::string>(argv + 1, argv + argc));
	if (!cl.errors.empty())
	{
		for (const std::string& e : cl.errors) std::cerr << "structures: " << e << "\n";
		return 2;
	}
	if (cl.help)
	{
		std::cout << structuresUsage();
		return 0;
	}
	try
	{
		bool finite = true;
		if (cl.scene == "cantilever")
		{
			const CantileverResult r = runCantilever(cl.cantilever);
			std::cout << (cl.json ? toJson(cl.cantilever, r) + "\n" : toSummary(cl.cantilever, r));
			finite = r.finite;
		}
		else if (cl.scene == "portal")
		{
			const PortalResult r = runPortal(cl.portal);
			std::cout << (cl.json ? toJson(cl.portal, r) + "\n" : toSummary(cl.portal, r));
			finite = r.finite;
		}
		else if (cl.scene == "paper-clip")
		{
			const PaperClipResult r = runPaperClip(cl.paperClip);
			if (!cl.hysteresisPath.empty())
			{
				std::string error;
				if (!scene::writeWhole(cl.hysteresisPath, hysteresisSvg(cl.paperClip, r), error))
				{
					std::cerr << "structures: --hysteresis: " << error << "\n";
					return 2;
				}
			}
			std::cout << (cl.json ? toJson(cl.paperClip, r) + "\n" : toSummary(cl.paperClip, r));
			finite = r.finite;
		}
		else
		{
			const DropWeightResult r = runDropWeight(cl.dropWeight);
			std::cout << (cl.json ? toJson(cl.dropWeight, r) + "\n" : toSummary(cl.dropWeight, r));
			finite = r.finite;
		}
		return finite ? 0 : 3;
	}
	catch (const std::invalid_argument& e)
	{
		std::cerr << "structures: " << e.what() << "\n";
		return 2;
	}
}
