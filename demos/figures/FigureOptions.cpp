#include "FigureOptions.h"

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <string_view>

namespace
{
bool parsePixels(std::string_view name, const std::string& text, int& value, std::string& error)
{
	char* end = nullptr;
	errno = 0;
	const long parsed = std::strtol(text.c_str(), &end, 10);
	if (text.empty() || *end != 0 || errno != 0 || parsed < 64 || parsed > 4096)
	{
		error = std::string(name) + ": '" + text + "' is not a whole number of pixels in [64, 4096]";
		return false;
	}
	value = int(parsed);
	return true;
}
}  // namespace

bool parseFigureOptions(int argc, char* argv[], FigureOptions& options, std::string& error)
{
	for (int i = 1; i < argc; i++)
	{
		const std::string arg = argv[i];
		const size_t eq = arg.find('=');
		const std::string name = arg.substr(0, eq);
		const std::string value = eq == std::string::npos ? "" : arg.substr(eq + 1);
		if (name == "--out" && !value.empty())
			options.out_dir = value;
		else if (name == "--width")
		{
			if (!parsePixels(name, value, options.width_px, error)) return false;
		}
		else if (name == "--height")
		{
			if (!parsePixels(name, value, options.height_px, error)) return false;
		}
		else if (name == "--method")
		{
			const auto method = parseCharpyMethod(value);
			if (!method)
			{
				error = "--method: '" + value + "' is not one of the eight method names (charpy --list-methods)";
				return false;
			}
			options.methods.push_back(*method);
		}
		else
		{
			error = "unknown flag " + arg + " (valid: --out=DIR, --width=PX, --height=PX, --method=NAME)";
			return false;
		}
	}
	if (options.methods.empty())
		for (int n = 1; n <= kCharpyMethodCount; n++) options.methods.push_back(charpyMethodByNumber(n));
	std::error_code ec;
	std::filesystem::create_directories(options.out_dir, ec);
	if (ec)
	{
		error = "--out: cannot create " + options.out_dir + ": " + ec.message();
		return false;
	}
	return true;
}
