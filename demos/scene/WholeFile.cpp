#include "WholeFile.h"

#include <cstdio>
#include <fstream>

namespace scene
{
bool writeWhole(const std::string& path, const std::string& text, std::string& error)
{
	const std::string tmp = path + ".tmp";
	{
		std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
		out << text;
		out.close();
		if (!out)
		{
			error = "cannot write " + tmp;
			std::remove(tmp.c_str());
			return false;
		}
	}
	if (std::rename(tmp.c_str(), path.c_str()) != 0)
	{
		error = "cannot rename " + tmp + " to " + path;
		std::remove(tmp.c_str());
		return false;
	}
	return true;
}
}  // namespace scene
