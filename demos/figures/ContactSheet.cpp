#include "ContactSheet.h"

#include <algorithm>
#include <cstdio>

#include "stb_image/stb_image_write.h"

ContactSheet::ContactSheet(int columns, int rows, int tileWidth_px, int tileHeight_px)
	: m_tileWidth(tileWidth_px),
	  m_tileHeight(tileHeight_px),
	  m_image(columns * (tileWidth_px + kGap_px) + kGap_px, rows * (tileHeight_px + kGap_px) + kGap_px)
{
	std::fill(m_image.rgb.begin(), m_image.rgb.end(), 255);
}

void ContactSheet::place(int column, int row, const Image& frame)
{
	const int x0 = kGap_px + column * (m_tileWidth + kGap_px);
	const int y0 = kGap_px + row * (m_tileHeight + kGap_px);
	for (int y = 0; y < m_tileHeight; y++)
	{
		const int fy0 = y * frame.height / m_tileHeight;
		const int fy1 = std::max(fy0 + 1, (y + 1) * frame.height / m_tileHeight);
		for (int x = 0; x < m_tileWidth; x++)
		{
			const int fx0 = x * frame.width / m_tileWidth;
			const int fx1 = std::max(fx0 + 1, (x + 1) * frame.width / m_tileWidth);
			for (int c = 0; c < 3; c++)
			{
				int sum = 0;
				for (int fy = fy0; fy < fy1; fy++)
					for (int fx = fx0; fx < fx1; fx++) sum += frame.at(fx, fy, c);
				m_image.at(x0 + x, y0 + y, c) = (unsigned char)(sum / ((fy1 - fy0) * (fx1 - fx0)));
			}
		}
	}
}

bool writePngWhole(const Image& image, const std::string& file, std::string& error)
{
	const std::string tmp = file + ".tmp";
	if (!stbi_write_png(tmp.c_str(), image.width, image.height, 3, image.rgb.data(), image.width * 3) ||
		std::rename(tmp.c_str(), file.c_str()) != 0)
	{
		std::remove(tmp.c_str());
		error = "cannot write " + file;
		return false;
	}
	return true;
}
