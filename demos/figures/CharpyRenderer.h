// Off-screen renderer of a Charpy scene: an OSMesa SimpleOpenGL3App (window type 3 of patch 0010)
// with the browser's OpenGLGuiHelper. Shared by charpy_figures and the render tests. It reads the
// scene's world and never changes it.
#pragma once

#include <memory>
#include <string>

#include "ContactSheet.h"

class CharpyScene;
class SimpleOpenGL3App;
struct OpenGLGuiHelper;
class btVector3;

class CharpyRenderer
{
public:
	CharpyRenderer(int width_px, int height_px);
	~CharpyRenderer();

	int width() const;
	int height() const;
	// Graphics objects for the scene's bodies (replacing the previous scene's) and the standard camera.
	void show(CharpyScene& scene);
	// The current state of the shown scene as an image (top row first); text lines at the top left.
	Image render(CharpyScene& scene, const std::string& text = "");
	// Pixel of a world point in the last rendered frame; false if it is behind the camera.
	bool project(const btVector3& point_m, int& x_px, int& y_px) const;

private:
	std::unique_ptr<SimpleOpenGL3App> m_app;
	std::unique_ptr<OpenGLGuiHelper> m_gui;
};
