#include "ViewFraming.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "CommonInterfaces/CommonCameraInterface.h"
#include "CommonInterfaces/CommonGraphicsAppInterface.h"
#include "OpenGLWindow/SimpleCamera.h"

namespace
{
bool gGuiShown = true;

const int kTextLeft_px = 5;  // the ledger's first column, right of the free rectangle's left edge
const int kTextTop_px = 4;   // its first line, below the free rectangle's top edge
const int kLedgerGap_px = 4;

btVector3 corner(const scene::WorldBox& box, int i)
{
	return btVector3(i & 1 ? box.max_m.x() : box.min_m.x(), i & 2 ? box.max_m.y() : box.min_m.y(), i & 4 ? box.max_m.z() : box.min_m.z());
}

void setCamera(SimpleCamera& camera, const ViewCamera& v)
{
	camera.setCameraDistance(v.distance_m);
	camera.setCameraYaw(v.yaw_deg);
	camera.setCameraPitch(v.pitch_deg);
	camera.setCameraTargetPosition(v.target_m[0], v.target_m[1], v.target_m[2]);
}

// The camera at this distance with its target moved across the view until the envelope's projection is centred on
// the region; false if a corner is behind the camera or the projection does not fit inside the region's margins.
bool fitsCentred(float distance_m, const FramingRequest& r, const ScreenRect& region, int width_px, int height_px, SimpleCamera& camera, ViewCamera& v)
{
	v.distance_m = distance_m;
	const btVector3 centre = (r.envelope.min_m + r.envelope.max_m) / 2;
	for (int k = 0; k < 3; k++) v.target_m[k] = float(centre[k]);
	float left = 0, top = 0, right = 0, bottom = 0;
	for (int iteration = 0; iteration < 20; iteration++)
	{
		setCamera(camera, v);
		if (!projectBox(camera, width_px, height_px, r.envelope, left, top, right, bottom)) return false;
		const float dx_px = (left + right) / 2 - (region.left + region.right) / 2.f;
		const float dy_px = (top + bottom) / 2 - (region.top + region.bottom) / 2.f;
		if (std::fabs(dx_px) < 0.1f && std::fabs(dy_px) < 0.1f) break;
		// a pixel at the target's depth is 2 d / height metres (the vertical half field of view is 45 degrees);
		// moving the target along the view's right (up) axis moves the picture left (down)
		float view[16];
		camera.getCameraViewMatrix(view);
		const float metres_per_px = 2 * distance_m / float(height_px);
		for (int k = 0; k < 3; k++) v.target_m[k] += metres_per_px * (dx_px * view[4 * k] - dy_px * view[4 * k + 1]);
	}
	const int m = r.margin_px;
	return left >= float(region.left + m) && right <= float(region.right - m) && top >= float(region.top + m) && bottom <= float(region.bottom - m);
}

// The nearest camera whose centred projection fits (bisection on the distance); false if none does.
bool frameIn(const FramingRequest& r, const ScreenRect& region, int width_px, int height_px, ViewCamera& best)
{
	if (region.width() <= 2 * r.margin_px || region.height() <= 2 * r.margin_px) return false;
	SimpleCamera camera;
	camera.setCameraUpAxis(1);
	camera.setAspectRatio(float(width_px) / float(height_px));
	ViewCamera v;
	v.yaw_deg = r.yaw_deg;
	v.pitch_deg = r.pitch_deg;
	const float size_m = float((r.envelope.max_m - r.envelope.min_m).length()) + 1e-3f;
	float near_m = 0.01f * size_m, far_m = 1000 * size_m;
	if (!fitsCentred(far_m, r, region, width_px, height_px, camera, v)) return false;
	best = v;
	for (int i = 0; i < 40; i++)
	{
		const float d = std::sqrt(near_m * far_m);
		if (fitsCentred(d, r, region, width_px, height_px, camera, v))
		{
			far_m = d;
			best = v;
		}
		else
			near_m = d;
	}
	return true;
}
}  // namespace

void setBrowserGuiShown(bool shown) { gGuiShown = shown; }

bool browserGuiShown() { return gGuiShown; }

ScreenRect guiFreeRect(int width_px, int height_px, bool gui_shown)
{
	ScreenRect r{0, 0, width_px, height_px};
	if (!gui_shown) return r;
	r.left = kBrowserSidePanel_px;
	r.right = std::max(r.left, width_px - kBrowserSidePanel_px);
	r.top = kBrowserMenuBar_px;
	r.bottom = std::max(r.top, height_px - kBrowserBottomPanels_px);
	return r;
}

ScreenRect textRect(int lines, int characters, int left_px, int top_px)
{
	return ScreenRect{left_px, top_px, left_px + characters * kTextChar_px, top_px + std::max(lines - 1, 0) * kTextLine_px + kTextLineHeight_px};
}

ScreenRect textRect(const std::string& text, int left_px, int top_px)
{
	std::istringstream lines(text);
	std::string line;
	int n = 0;
	size_t longest = 0;
	while (std::getline(lines, line))
	{
		n++;
		longest = std::max(longest, line.size());
	}
	return textRect(n, int(longest), left_px, top_px);
}

SceneFraming frameScene(const FramingRequest& request, int width_px, int height_px, bool gui_shown)
{
	SceneFraming f;
	const ScreenRect free = guiFreeRect(std::max(width_px, 1), std::max(height_px, 1), gui_shown);
	f.ledger_left_px = free.left + kTextLeft_px;
	f.ledger_top_px = free.top + kTextTop_px;
	f.ledger = textRect(request.ledger_lines, request.ledger_characters, f.ledger_left_px, f.ledger_top_px);
	const ScreenRect below{free.left, std::min(free.bottom, f.ledger.bottom + kLedgerGap_px), free.right, free.bottom};
	const ScreenRect beside{std::min(free.right, f.ledger.right + kLedgerGap_px), free.top, free.right, free.bottom};
	ViewCamera a, b;
	const bool fitsBelow = frameIn(request, below, width_px, height_px, a);
	const bool fitsBeside = frameIn(request, beside, width_px, height_px, b);
	if (fitsBeside && (!fitsBelow || b.distance_m < a.distance_m))
	{
		f.camera = b;
		f.view = beside;
	}
	else if (fitsBelow)
	{
		f.camera = a;
		f.view = below;
	}
	else  // no room beside or below the ledger (a tiny window): the whole free rectangle, the text over it
	{
		f.view = free;
		if (!frameIn(request, free, width_px, height_px, f.camera))
		{
			const btVector3 centre = (request.envelope.min_m + request.envelope.max_m) / 2;
			for (int k = 0; k < 3; k++) f.camera.target_m[k] = float(centre[k]);
			f.camera.distance_m = 2 * float((request.envelope.max_m - request.envelope.min_m).length());
		}
	}
	f.camera.yaw_deg = request.yaw_deg;
	f.camera.pitch_deg = request.pitch_deg;
	return f;
}

bool projectToWindow(const CommonCameraInterface& camera, int width_px, int height_px, const btVector3& p, float& x_px, float& y_px)
{
	float view[16], projection[16];
	camera.getCameraViewMatrix(view);
	camera.getCameraProjectionMatrix(projection);
	// column-major 4x4 matrices, as OpenGL takes them
	float eye[4], clip[4];
	const float world[4] = {float(p.x()), float(p.y()), float(p.z()), 1.f};
	for (int r = 0; r < 4; r++) eye[r] = view[r] * world[0] + view[4 + r] * world[1] + view[8 + r] * world[2] + view[12 + r] * world[3];
	for (int r = 0; r < 4; r++) clip[r] = projection[r] * eye[0] + projection[4 + r] * eye[1] + projection[8 + r] * eye[2] + projection[12 + r] * eye[3];
	if (clip[3] <= 0) return false;
	x_px = (clip[0] / clip[3] * 0.5f + 0.5f) * float(width_px);
	y_px = (0.5f - clip[1] / clip[3] * 0.5f) * float(height_px);
	return true;
}

bool projectBox(const CommonCameraInterface& camera, int width_px, int height_px, const scene::WorldBox& box, float& left, float& top, float& right, float& bottom)
{
	for (int i = 0; i < 8; i++)
	{
		float x = 0, y = 0;
		if (!projectToWindow(camera, width_px, height_px, corner(box, i), x, y)) return false;
		left = i == 0 ? x : std::min(left, x);
		right = i == 0 ? x : std::max(right, x);
		top = i == 0 ? y : std::min(top, y);
		bottom = i == 0 ? y : std::max(bottom, y);
	}
	return true;
}
