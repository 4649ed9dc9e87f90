// Headless rendering through the OSMesa window (patch 0010): the Charpy scene is drawn where it is,
// frames change where the specimen moved, and llvmpipe reproduces a reference frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <algorithm>
#include <map>
#include <string>

#include "btBulletDynamicsCommon.h"

#include "CharpyMoments.h"
#include "CharpyRenderer.h"
#include "CharpyScene.h"
#include "CharpyView.h"

namespace
{
// The specimen's orange under the renderer's lighting: red well above blue, green in between.
bool looksLikeSpecimen(const Image& image, int x, int y)
{
	const int r = image.at(x, y, 0), g = image.at(x, y, 1), b = image.at(x, y, 2);
	return r > 120 && r - b > 90 && g < r && g > b;
}

// Specimen-coloured pixels within radius_px of (x, y).
int specimenPixelsNear(const Image& image, int x, int y, int radius_px)
{
	int count = 0;
	for (int dy = -radius_px; dy <= radius_px; dy++)
		for (int dx = -radius_px; dx <= radius_px; dx++)
		{
			const int px = x + dx, py = y + dy;
			if (px >= 0 && py >= 0 && px < image.width && py < image.height && looksLikeSpecimen(image, px, py)) count++;
		}
	return count;
}

btVector3 specimenCentre(const CharpyScene& scene)
{
	btVector3 sum(0, 0, 0);
	for (const btRigidBody* part : scene.specimenParts()) sum += part->getCenterOfMassPosition();
	return sum / btScalar(scene.specimenParts().size());
}

// Steps the scene to a moment of CharpyMomentTracker.
void stepTo(CharpyScene& scene, CharpyMomentTracker& tracker, CharpyMoment wanted)
{
	CharpyMoment moment;
	while (!tracker.done())
	{
		if (tracker.reached(scene, moment) && moment == wanted) return;
		scene.step();
	}
	FAIL() << "moment " << charpyMomentName(wanted) << " never reached";
}

bool readPpm(const std::string& file, Image& image)
{
	std::ifstream in(file, std::ios::binary);
	std::string magic;
	int w = 0, h = 0, max = 0;
	if (!(in >> magic >> w >> h >> max) || magic != "P6" || max != 255) return false;
	in.get();
	image = Image(w, h);
	return bool(in.read(reinterpret_cast<char*>(image.rgb.data()), std::streamsize(image.rgb.size())));
}

void writePpm(const std::string& file, const Image& image)
{
	std::ofstream out(file, std::ios::binary);
	out << "P6\n" << image.width << " " << image.height << "\n255\n";
	out.write(reinterpret_cast<const char*>(image.rgb.data()), std::streamsize(image.rgb.size()));
}

class CharpyRender : public ::testing::Test
{
protected:
	static CharpyRenderer& renderer()
	{
		static CharpyRenderer instance(320, 240);  // one OSMesa context for every test
		return instance;
	}
};
}  // namespace

TEST_F(CharpyRender, FrameHasTheRequestedSizeAndIsNotBlank)
{
	CharpyScene scene{CharpyParameters{}};
	renderer().show(scene);
	const Image frame = renderer().render(scene);
	ASSERT_EQ(frame.width, 320);
	ASSERT_EQ(frame.height, 240);
	// A flat-shaded scene has few colours, but not one: count them and the background's share.
	std::map<int, int> colours;
	for (int y = 0; y < frame.height; y++)
		for (int x = 0; x < frame.width; x++) colours[frame.at(x, y, 0) << 16 | frame.at(x, y, 1) << 8 | frame.at(x, y, 2)]++;
	int background = 0;
	for (const auto& colour : colours) background = std::max(background, colour.second);
	EXPECT_GT(colours.size(), 20u) << "a blank or nearly blank frame";
	EXPECT_LT(background, frame.width * frame.height * 97 / 100) << "the background covers almost everything";
}

TEST_F(CharpyRender, SpecimenColourIsWhereTheSpecimenIs)
{
	CharpyScene scene{CharpyParameters{}};
	renderer().show(scene);
	const Image frame = renderer().render(scene);
	int x = 0, y = 0;
	ASSERT_TRUE(renderer().project(specimenCentre(scene), x, y));
	ASSERT_TRUE(x >= 0 && y >= 0 && x < frame.width && y < frame.height) << x << ", " << y;
	EXPECT_GE(specimenPixelsNear(frame, x, y, 3), 10) << "no specimen colour at its projected centre " << x << ", " << y;
	// ...and only there: far from it (the frame's corners) there is none.
	EXPECT_EQ(specimenPixelsNear(frame, 10, 10, 8), 0);
	EXPECT_EQ(specimenPixelsNear(frame, frame.width - 10, frame.height - 10, 8), 0);
}

TEST_F(CharpyRender, FrameAfterThePassDiffersWhereTheSpecimenMoved)
{
	CharpyScene scene{CharpyParameters{}};  // plastic hinge: the specimen bends and passes the anvils
	CharpyMomentTracker tracker(scene);
	renderer().show(scene);
	stepTo(scene, tracker, CharpyMoment::BeforeImpact);
	const Image before = renderer().render(scene);
	int x0 = 0, y0 = 0;
	ASSERT_TRUE(renderer().project(specimenCentre(scene), x0, y0));
	stepTo(scene, tracker, CharpyMoment::After);
	ASSERT_TRUE(scene.passedAnvils());
	const Image after = renderer().render(scene);
	int x1 = 0, y1 = 0;
	ASSERT_TRUE(renderer().project(specimenCentre(scene), x1, y1));
	EXPECT_GE(specimenPixelsNear(before, x0, y0, 3), 10);
	EXPECT_EQ(specimenPixelsNear(after, x0, y0, 1), 0) << "the specimen is still drawn where it was";
	EXPECT_GT(std::hypot(x1 - x0, y1 - y0), 5.0) << "the specimen's centre did not move on screen";
	int changed = 0;
	for (int dy = -3; dy <= 3; dy++)
		for (int dx = -3; dx <= 3; dx++)
			for (int c = 0; c < 3; c++) changed += before.at(x0 + dx, y0 + dy, c) != after.at(x0 + dx, y0 + dy, c);
	EXPECT_GT(changed, 100) << "the pixels where the specimen was did not change";
}

// llvmpipe renders the same bytes run to run here; the tolerance allows another Mesa version's
// rounding, not another picture. BP_UPDATE_RENDER_REFERENCE=1 rewrites the reference.
TEST_F(CharpyRender, MidBendFrameMatchesTheReference)
{
	CharpyScene scene{CharpyParameters{}};
	CharpyMomentTracker tracker(scene);
	renderer().show(scene);
	stepTo(scene, tracker, CharpyMoment::MidBend);
	const Image frame = renderer().render(scene, charpyEnergyPanel(scene));
	const std::string reference_file = std::string(BP_RENDER_REFERENCE_DIR) + "/plastic-hinge-mid-bend-320x240.ppm";
	if (std::getenv("BP_UPDATE_RENDER_REFERENCE"))
	{
		writePpm(reference_file, frame);
		GTEST_SKIP() << "wrote " << reference_file;
	}
	Image reference(0, 0);
	ASSERT_TRUE(readPpm(reference_file, reference)) << reference_file;
	ASSERT_EQ(reference.width, frame.width);
	ASSERT_EQ(reference.height, frame.height);
	double sum = 0;
	int far_off = 0;
	for (size_t i = 0; i < frame.rgb.size(); i++)
	{
		const int d = std::abs(int(frame.rgb[i]) - int(reference.rgb[i]));
		sum += d;
		far_off += d > 40;
	}
	EXPECT_LT(sum / double(frame.rgb.size()), 2.0) << "mean difference per channel";
	EXPECT_LT(far_off, int(frame.rgb.size() / 200)) << "channels off by more than 40 levels";
}
