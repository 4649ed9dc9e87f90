// The project's ExampleBrowser app: upstream's OpenGLExampleBrowser with the plasticity examples.
// Headless: --window_backend=osmesa --start_demo_name=Charpy --png_file=PREFIX --max_frames=N
// (flags of patch 0011; see README). The loop is upstream's main.cpp without the file importers.
#include <cstdio>

#include "OpenGLExampleBrowser.h"
#include "ExampleEntries.h"
#include "Bullet3Common/b3CommandLineArgs.h"
#include "Utils/b3Clock.h"

#include "ViewFraming.h"

int main(int argc, char* argv[])
{
	b3CommandLineArgs args(argc, argv);
	double minUpdateTime_us = 1000.;
	args.GetCmdLineArgument("minUpdateTimeMicroSecs", minUpdateTime_us);
	setBrowserGuiShown(!args.CheckCmdLineFlag("nogui"));  // the examples frame their scenes beside the GUI's panels

	ExampleEntriesAll examples;
	examples.initExampleEntries();
	OpenGLExampleBrowser* browser = new OpenGLExampleBrowser(&examples);
	const bool initialised = browser->init(argc, argv);
	b3Clock clock;
	clock.reset();
	if (initialised)
	{
		do
		{
			float deltaTime_s = clock.getTimeMicroseconds() / 1e6f;
			if (deltaTime_s > 0.1f) deltaTime_s = 0.1f;
			if (deltaTime_s < minUpdateTime_us / 1e6)
			{
				b3Clock::usleep(int(minUpdateTime_us / 10.));
			}
			else
			{
				clock.reset();
				browser->update(deltaTime_s);
			}
		} while (!browser->requestedExit());
	}
	delete browser;
	return initialised ? 0 : 2;
}
