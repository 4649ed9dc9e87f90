// How an example frames its scene: the free viewport (the window minus the browser's GUI panels and the ledger's
// rectangle) and the camera that keeps a box of the world (the scene's view envelope: its bounds through its collapse)
// inside it with a margin. One piece for every example; it reads no world and draws nothing. The projection is the
// browser's own (SimpleCamera: the up axis y, a 90 degree vertical field of view, the window's aspect ratio).
#pragma once

#include <string>

#include "scene/SteppedScene.h"
#include "TextLines.h"

struct CommonCameraInterface;
struct CommonGraphicsApp;

struct ScreenRect  // pixels, y down, [left, right) x [top, bottom)
{
	int left = 0;
	int top = 0;
	int right = 0;
	int bottom = 0;
	int width() const { return right - left; }
	int height() const { return bottom - top; }
	bool contains(const ScreenRect& r) const { return r.left >= left && r.right <= right && r.top >= top && r.bottom <= bottom; }
	bool overlaps(const ScreenRect& r) const { return r.left < right && left < r.right && r.top < bottom && top < r.bottom; }
};

// The browser's GUI (upstream ExampleBrowser/GwenGUISupport/gwenUserInterface.cpp): the explorer docked left and the
// parameters docked right, 250 px wide each; the menu bar at the top; the console (100 px) and the status bar at the
// bottom. tests/render/gui_panels.py checks these against a rendered browser frame.
constexpr int kBrowserSidePanel_px = 250;
constexpr int kBrowserMenuBar_px = 22;
constexpr int kBrowserBottomPanels_px = 100 + 22;

// Whether the browser draws its GUI (plasticity_browser_main: not with --nogui). Default: it does.
void setBrowserGuiShown(bool shown);
bool browserGuiShown();

// The part of a width x height window the GUI leaves free (the whole window without it).
ScreenRect guiFreeRect(int width_px, int height_px, bool gui_shown);

// On-screen text as the examples draw it (app->drawText at size 0.4 from (left_px, top_px), lines kTextLine_px apart):
// the rectangle lines x characters cover; a line's ink (accents to descenders) lies within kTextLineHeight_px of the y
// drawText takes. kTextChar_px bounds the font's widest advance at that size. tests/render/FramingRenderTest.cpp checks
// that the drawn text stays inside.
constexpr int kTextLineHeight_px = 24;
constexpr int kTextChar_px = 10;
ScreenRect textRect(int lines, int characters, int left_px, int top_px);
ScreenRect textRect(const std::string& text, int left_px, int top_px);  // its lines and longest line

struct ViewCamera
{
	float distance_m = 5;
	float yaw_deg = 0;
	float pitch_deg = 0;
	float target_m[3] = {0, 0, 0};
};

struct SceneFraming
{
	ViewCamera camera;
	ScreenRect ledger;                          // where the ledger goes: the top left of the GUI's free rectangle
	int ledger_left_px = 0, ledger_top_px = 0;  // what drawText takes for its first line
	ScreenRect view;                            // the free viewport the envelope is framed in: beside or below the ledger
};

// The reserved size of a ledger and the margin kept around the envelope.
struct FramingRequest
{
	scene::WorldBox envelope;
	float yaw_deg = 180;  // from +z: the scenes are built in the x-y plane
	float pitch_deg = 0;
	int ledger_lines = 12;
	int ledger_characters = 40;
	int margin_px = 12;
};

// The camera that shows the envelope as large as it fits inside the free viewport, margin_px from its edges, with the
// ledger beside or below it (whichever shows the envelope larger).
SceneFraming frameScene(const FramingRequest& request, int width_px, int height_px, bool gui_shown);

// A world point's window pixel (x right, y down) through a camera's view and projection matrices; false behind it.
bool projectToWindow(const CommonCameraInterface& camera, int width_px, int height_px, const btVector3& p, float& x_px, float& y_px);
// The window rectangle a box's eight corners cover; false if one is behind the camera.
bool projectBox(const CommonCameraInterface& camera, int width_px, int height_px, const scene::WorldBox& box, float& left, float& top, float& right, float& bottom);
