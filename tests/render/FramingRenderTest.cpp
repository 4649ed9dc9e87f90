// What a user sees in the examples: each example, run headless (OSMesa) through its whole run and after it at the
// common window sizes with the browser's GUI, keeps its structure inside the free viewport with the camera it set
// itself. Every frame, every body's AABB corners (not the ground slab) are projected with the active camera's view and
// projection matrices, as the browser renders them (its aspect ratio from the window), and the bounds must lie inside
// the window minus the GUI's panels (ViewFraming.h's constants, checked against a browser frame by gui_panels.py) and
// off the ledger's rectangle (the lines the example drew, at the positions it drew them). The cameras of f3f52bf are
// the control: with them the same check fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "btBulletDynamicsCommon.h"
#include "CommonInterfaces/CommonExampleInterface.h"
#include "OpenGLWindow/OpenGLInclude.h"
#include "OpenGLWindow/SimpleOpenGL3App.h"
#include "OpenGLGuiHelper.h"

#include "SceneExample.h"
#include "ViewFraming.h"

namespace
{
const int kWindowTypeOSMesa = 3;  // SimpleOpenGL3App window type of patch 0010

// The app: records every text line an example draws (where, what); draws it only when asked to.
class RecordingApp : public SimpleOpenGL3App
{
public:
	RecordingApp(int w, int h) : SimpleOpenGL3App("framing", w, h, false, kWindowTypeOSMesa) {}
	void drawText(const char* txt, int x, int y, float size, float rgba[4]) override
	{
		lines.push_back({txt, x, y});
		if (draw) SimpleOpenGL3App::drawText(txt, x, y, size, rgba);
	}
	struct Line
	{
		std::string text;
		int x, y;
	};
	std::vector<Line> lines;
	bool draw = false;
};

// The GUI helper: records the world the example renders instead of drawing it (the check needs no pixels).
struct RecordingGuiHelper : public OpenGLGuiHelper
{
	explicit RecordingGuiHelper(CommonGraphicsApp* app) : OpenGLGuiHelper(app, false) {}
	void render(const btDiscreteDynamicsWorld* w) override { world = w; }
	const btDiscreteDynamicsWorld* world = nullptr;
};

struct ExampleCase
{
	const char* name;
	CommonExampleInterface::CreateFunc* create;
	double browser_s;       // browser time at 60 Hz frames: the run, its collapse and a while after (the example stops stepping when the scene is done)
	ViewCamera old_camera;  // f3f52bf's camera (SceneControls.cpp, WreckingBallControls.cpp)
};

const ExampleCase kCases[] = {
	{"Cantilever", CantileverExampleCreateFunc, 5.0, {2.8f, 180, 0, {1.0f, 0.4f, 0}}},
	{"Portal", PortalExampleCreateFunc, 14.0, {3.6f, 180, 0, {2, 2.9f, 0}}},
	{"DropWeight", DropWeightExampleCreateFunc, 2.0, {1.2f, 180, 0, {1, 0.3f, 0}}},
	{"WreckingBall", WreckingBallExampleCreateFunc, 3.5, {5, 180, -8, {-0.3f, 3.6f, 0}}},
	{"Building", BuildingExampleCreateFunc, 3.5, {21, 180, -8, {22, 10.5f, 0}}},
	// the city had no camera at f3f52bf: the control is the wrecking ball's old one (its first building)
	{"City", CityExampleCreateFunc, 3.5, {5, 180, -8, {-0.3f, 3.6f, 0}}},
};

struct WindowSize
{
	int width, height;
};
const WindowSize kSizes[] = {{800, 600}, {1024, 768}, {1280, 720}, {1920, 1080}};

struct Bounds
{
	float left = 1e30f, top = 1e30f, right = -1e30f, bottom = -1e30f;
	void add(float l, float t, float r, float b)
	{
		left = std::min(left, l);
		top = std::min(top, t);
		right = std::max(right, r);
		bottom = std::max(bottom, b);
	}
	bool inside(const ScreenRect& s) const { return left >= s.left && right <= s.right && top >= s.top && bottom <= s.bottom; }
	bool overlaps(const ScreenRect& s) const { return left < s.right && s.left < right && top < s.bottom && s.top < bottom; }
	std::string str() const
	{
		char text[128];
		std::snprintf(text, sizeof text, "[%.0f, %.0f] x [%.0f, %.0f]", left, right, top, bottom);
		return text;
	}
};

std::string str(const ScreenRect& r)
{
	char text[128];
	std::snprintf(text, sizeof text, "[%d, %d] x [%d, %d]", r.left, r.right, r.top, r.bottom);
	return text;
}

// A ground slab: static and wider (x or z) than every moving body together; the structure is everything else.
std::vector<const btCollisionObject*> structureBodies(const btDiscreteDynamicsWorld& world)
{
	btVector3 lo(1e30f, 1e30f, 1e30f), hi(-1e30f, -1e30f, -1e30f);
	for (int i = 0; i < world.getNumCollisionObjects(); i++)
	{
		const btCollisionObject* o = world.getCollisionObjectArray()[i];
		if (o->isStaticOrKinematicObject()) continue;
		btVector3 a, b;
		o->getCollisionShape()->getAabb(o->getWorldTransform(), a, b);
		lo.setMin(a);
		hi.setMax(b);
	}
	std::vector<const btCollisionObject*> bodies;
	for (int i = 0; i < world.getNumCollisionObjects(); i++)
	{
		const btCollisionObject* o = world.getCollisionObjectArray()[i];
		btVector3 a, b;
		o->getCollisionShape()->getAabb(o->getWorldTransform(), a, b);
		if (o->isStaticOrKinematicObject() && (b.x() - a.x() > hi.x() - lo.x() || b.z() - a.z() > hi.z() - lo.z())) continue;
		bodies.push_back(o);
	}
	return bodies;
}

// One run of an example in a window of that size; what its structure covered and where its text went.
struct RunResult
{
	Bounds structure;  // over every frame
	Bounds text;       // every ledger line drawn, as textRect bounds it
	int frames = 0;
	int bad_frames = 0;  // frames whose structure left the free rectangle or met that frame's text
	std::string first_bad;
};

RunResult runExample(const ExampleCase& c, WindowSize size, bool old_camera)
{
	setBrowserGuiShown(true);
	RecordingApp app(size.width, size.height);
	app.setUpAxis(1);
	RecordingGuiHelper gui(&app);
	CommonExampleOptions options(&gui);
	std::unique_ptr<CommonExampleInterface> example(c.create(options));
	example->initPhysics();
	example->resetCamera();
	if (old_camera)
	{
		const ViewCamera& o = c.old_camera;
		gui.resetCamera(o.distance_m, o.yaw_deg, o.pitch_deg, o.target_m[0], o.target_m[1], o.target_m[2]);
	}
	const ScreenRect free = guiFreeRect(size.width, size.height, true);
	RunResult r;
	const int frames = int(c.browser_s * 60);
	for (int frame = 0; frame < frames; frame++)
	{
		example->stepSimulation(1.f / 60.f);
		app.m_instancingRenderer->updateCamera(app.getUpAxis());  // as the browser does before it renders: the aspect ratio
		app.lines.clear();
		example->renderScene();
		if (!gui.world) continue;
		const CommonCameraInterface* camera = app.m_instancingRenderer->getActiveCamera();
		Bounds frameBounds;
		for (const btCollisionObject* o : structureBodies(*gui.world))
		{
			scene::WorldBox box;
			o->getCollisionShape()->getAabb(o->getWorldTransform(), box.min_m, box.max_m);
			float left = 0, top = 0, right = 0, bottom = 0;
			if (!projectBox(*camera, size.width, size.height, box, left, top, right, bottom))
			{
				left = top = -1e6f;  // behind the camera: out of view
				right = bottom = 1e6f;
			}
			frameBounds.add(left, top, right, bottom);
		}
		bool ok = frameBounds.inside(free);
		std::string why = ok ? "" : "outside the free rectangle " + str(free);
		for (const RecordingApp::Line& line : app.lines)
		{
			const ScreenRect t = textRect(line.text, line.x, line.y);
			r.text.add(float(t.left), float(t.top), float(t.right), float(t.bottom));
			if (ok && frameBounds.overlaps(t))
			{
				ok = false;
				why = "under the text '" + line.text + "' " + str(t);
			}
		}
		r.structure.add(frameBounds.left, frameBounds.top, frameBounds.right, frameBounds.bottom);
		r.frames++;
		if (!ok && r.bad_frames++ == 0) r.first_bad = "frame " + std::to_string(frame) + ": structure " + frameBounds.str() + " " + why;
	}
	example->exitPhysics();
	return r;
}

class Framing : public ::testing::TestWithParam<std::tuple<int, int>>
{
};

std::string caseName(const ::testing::TestParamInfo<std::tuple<int, int>>& info)
{
	const WindowSize s = kSizes[std::get<1>(info.param)];
	return std::string(kCases[std::get<0>(info.param)].name) + "_" + std::to_string(s.width) + "x" + std::to_string(s.height);
}
}  // namespace

TEST_P(Framing, StructureStaysInTheFreeViewportOffTheLedger)
{
	const ExampleCase& c = kCases[std::get<0>(GetParam())];
	const WindowSize size = kSizes[std::get<1>(GetParam())];
	const RunResult r = runExample(c, size, false);
	const ScreenRect free = guiFreeRect(size.width, size.height, true);
	std::printf("%s %dx%d: %d frames, structure %s, text %s, free %s\n", c.name, size.width, size.height, r.frames, r.structure.str().c_str(),
				r.text.str().c_str(), str(free).c_str());
	ASSERT_GT(r.frames, 0) << "the example rendered no world";
	EXPECT_EQ(r.bad_frames, 0) << r.first_bad;
	// and it is not framed as a speck: its bounds span at least a third of the free rectangle's width or height
	EXPECT_TRUE(r.structure.right - r.structure.left >= free.width() / 3.f || r.structure.bottom - r.structure.top >= free.height() / 3.f) << r.structure.str();
}

INSTANTIATE_TEST_SUITE_P(Examples, Framing, ::testing::Combine(::testing::Range(0, int(sizeof kCases / sizeof kCases[0])), ::testing::Range(0, 4)), caseName);

// The control: f3f52bf's cameras fail the same check at 800 x 600 (the portal's beam edge-on with its columns under
// the console, the cantilever leaving the view as it bends, the wrecking ball's frame cut off, text over each).
class OldCamera : public ::testing::TestWithParam<int>
{
};

TEST_P(OldCamera, FailsTheCheck)
{
	const ExampleCase& c = kCases[GetParam()];
	const RunResult r = runExample(c, {800, 600}, true);
	std::printf("%s, old camera: %d of %d frames fail: %s\n", c.name, r.bad_frames, r.frames, r.first_bad.c_str());
	ASSERT_GT(r.frames, 0);
	EXPECT_GT(r.bad_frames, 0) << "the old camera passes: the check does not tell framings apart";
}

INSTANTIATE_TEST_SUITE_P(Examples, OldCamera, ::testing::Range(0, int(sizeof kCases / sizeof kCases[0])), [](const ::testing::TestParamInfo<int>& info)
						 { return std::string(kCases[info.param].name); });

// textRect bounds the ink drawText puts down: the ledger's widest lines and a line of the widest glyphs, drawn on the
// cleared frame, read back; every dark pixel lies inside the rectangle textRect gives for them.
TEST(FramingText, DrawnTextStaysInsideItsRectangle)
{
	RecordingApp app(800, 600);
	app.setUpAxis(1);
	app.draw = true;
	const std::string text = "plastic (Mp x rotations) 74445.8 J\nanalytic stop (P L sin t = Mp t): 1.496 rad\nMMMMWWWW@@@@mmmm\nyjgpq|()[]{}";
	const int left = 255, top = 30;
	app.m_instancingRenderer->init();
	app.m_instancingRenderer->updateCamera(app.getUpAxis());
	drawTextLines(&app, text, left, top);
	std::vector<unsigned char> rgba(size_t(800) * 600 * 4);
	glPixelStorei(GL_PACK_ALIGNMENT, 1);
	glReadPixels(0, 0, 800, 600, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
	app.swapBuffer();
	Bounds ink;
	int dark = 0;
	for (int y = 0; y < 600; y++)
		for (int x = 0; x < 800; x++)
		{
			const unsigned char* p = &rgba[(size_t(599 - y) * 800 + x) * 4];
			if (p[0] + p[1] + p[2] < 3 * 100)
			{
				ink.add(float(x), float(y), float(x + 1), float(y + 1));
				dark++;
			}
		}
	const ScreenRect rect = textRect(text, left, top);
	std::printf("ink %s (%d dark pixels), textRect %s\n", ink.str().c_str(), dark, str(rect).c_str());
	ASSERT_GT(dark, 500) << "no text was drawn";
	EXPECT_TRUE(ink.inside(rect)) << "ink " << ink.str() << " outside " << str(rect);
}
