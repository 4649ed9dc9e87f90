// Renders the thesis' figures 3.1-3.7 headless through OSMesa: for every method, frames before
// impact, at mid-bend and after the pass, plus one contact sheet (methods as rows, moments as
// columns). The scene is CharpyScene with default parameters; rendering only reads it.
//
//   build/bin/charpy_figures [--out=DIR] [--width=PX] [--height=PX] [--method=NAME]
#include <cstdio>
#include <string>

#include "CharpyMoments.h"
#include "CharpyRenderer.h"
#include "CharpyScene.h"
#include "CharpyView.h"
#include "ContactSheet.h"
#include "FigureOptions.h"

int main(int argc, char* argv[])
{
	FigureOptions options;
	std::string error;
	if (!parseFigureOptions(argc, argv, options, error))
	{
		std::fprintf(stderr, "charpy_figures: %s\n", error.c_str());
		return 2;
	}
	CharpyRenderer renderer(options.width_px, options.height_px);
	const int width = renderer.width();
	const int height = renderer.height();

	ContactSheet sheet(kCharpyMomentCount, int(options.methods.size()), width / 2, height / 2);
	for (size_t row = 0; row < options.methods.size(); row++)
	{
		CharpyParameters parameters;
		parameters.method = options.methods[row];
		CharpyScene scene(parameters);
		renderer.show(scene);
		const std::string method(charpyMethodName(parameters.method));
		CharpyMomentTracker tracker(scene);
		CharpyMoment moment;
		while (!tracker.done())
		{
			if (tracker.reached(scene, moment))
			{
				char label[256];
				std::snprintf(label, sizeof(label), "%d %s: %s", int(parameters.method), method.c_str(), charpyMomentName(moment));
				const Image frame = renderer.render(scene, std::string(label) + "\n" + charpyEnergyPanel(scene));
				const std::string file = options.out_dir + "/" + method + "_" + std::to_string(int(moment)) + ".png";
				if (!writePngWhole(frame, file, error))
				{
					std::fprintf(stderr, "charpy_figures: %s\n", error.c_str());
					return 1;
				}
				sheet.place(int(moment), int(row), frame);
				std::printf("%s  t = %.2f ms  bend %.3f rad\n", file.c_str(), scene.time_s() * 1e3, scene.bendAngle_rad());
				continue;
			}
			scene.step();
		}
	}
	const std::string sheetFile = options.out_dir + "/contact-sheet.png";
	if (!writePngWhole(sheet.image(), sheetFile, error))
	{
		std::fprintf(stderr, "charpy_figures: %s\n", error.c_str());
		return 1;
	}
	std::printf("%s: %zu methods x %d moments\n", sheetFile.c_str(), options.methods.size(), kCharpyMomentCount);
	return 0;
}
