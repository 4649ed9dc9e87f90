// How the thesis figures show the Charpy scene (demos/figures): camera, body colours, the energy panel. The browser
// shows it as every scene (demos/examples/SceneExample.cpp). Reads the scene; never changes its physics.
#pragma once

#include <string>

#include "CharpyParameters.h"

class CharpyScene;
struct GUIHelperInterface;
struct CommonGraphicsApp;

struct CharpyCamera
{
	float distance_m;
	float yaw_deg;
	float pitch_deg;
	float target_m[3];
};

// Framed on the specimen and the anvils, from above and in front, so the bend is visible.
CharpyCamera charpyCamera(const CharpyParameters& parameters);

// RGB colours the renderer gives each kind of body (the render test looks for the specimen's).
extern const float kCharpySpecimenRgb[3];
extern const float kCharpyAnvilRgb[3];
extern const float kCharpyHammerRgb[3];

// Graphics objects for every body of the scene's world (replacing any there were) and the camera.
void showCharpyScene(GUIHelperInterface* guiHelper, CharpyScene& scene);

// The camera of charpyCamera(parameters).
void resetCharpyCamera(GUIHelperInterface* guiHelper, const CharpyParameters& parameters);

// The energy balance as text lines (J, rad, ms).
std::string charpyEnergyPanel(const CharpyScene& scene);

// Draws text lines from (left_px, top_px); the default clears the browser's explorer panel.
void drawCharpyPanel(CommonGraphicsApp* app, const std::string& text, int left_px = 255, int top_px = 45);
