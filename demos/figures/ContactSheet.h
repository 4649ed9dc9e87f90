// RGB images, a grid of downscaled frames, and PNG files written whole (to a .tmp file, then renamed).
#pragma once

#include <string>
#include <vector>

struct Image
{
	Image(int width_px, int height_px) : width(width_px), height(height_px), rgb(size_t(width_px) * height_px * 3, 0) {}
	unsigned char& at(int x, int y, int channel) { return rgb[(size_t(y) * width + x) * 3 + channel]; }
	unsigned char at(int x, int y, int channel) const { return rgb[(size_t(y) * width + x) * 3 + channel]; }
	int width;
	int height;
	std::vector<unsigned char> rgb;
};

// columns x rows tiles of tileWidth x tileHeight pixels, white between them.
class ContactSheet
{
public:
	ContactSheet(int columns, int rows, int tileWidth_px, int tileHeight_px);
	// Scales frame into tile (column, row) by averaging the pixels that fall into each tile pixel.
	void place(int column, int row, const Image& frame);
	const Image& image() const { return m_image; }

private:
	static constexpr int kGap_px = 4;
	int m_tileWidth;
	int m_tileHeight;
	Image m_image;
};

// Writes file.tmp and renames it to file, so file is either complete or absent.
bool writePngWhole(const Image& image, const std::string& file, std::string& error);
