#include "CharpyRenderer.h"

#include <vector>

#include "OpenGLWindow/OpenGLInclude.h"
#include "OpenGLWindow/SimpleOpenGL3App.h"
#include "OpenGLGuiHelper.h"
#include "btBulletDynamicsCommon.h"

#include "CharpyScene.h"
#include "CharpyView.h"

namespace
{
const int kWindowTypeOSMesa = 3;  // SimpleOpenGL3App window type of patch 0010
}

CharpyRenderer::CharpyRenderer(int width_px, int height_px)
	: m_app(std::make_unique<SimpleOpenGL3App>("Charpy", width_px, height_px, false, kWindowTypeOSMesa))
{
	m_app->setUpAxis(1);
	m_gui = std::make_unique<OpenGLGuiHelper>(m_app.get(), false);
}

CharpyRenderer::~CharpyRenderer()
{
	m_gui.reset();
	m_app.reset();
}

int CharpyRenderer::width() const { return m_app->m_window->getWidth(); }

int CharpyRenderer::height() const { return m_app->m_window->getHeight(); }

void CharpyRenderer::show(CharpyScene& scene) { showCharpyScene(m_gui.get(), scene); }

Image CharpyRenderer::render(CharpyScene& scene, const std::string& text)
{
	m_app->m_instancingRenderer->init();
	m_app->m_instancingRenderer->updateCamera(m_app->getUpAxis());
	m_gui->syncPhysicsToGraphics(&scene.world());
	m_gui->render(&scene.world());
	if (!text.empty()) drawCharpyPanel(m_app.get(), text, 10, 15);

	const int w = width();
	const int h = height();
	std::vector<unsigned char> rgba(size_t(w) * h * 4);
	glPixelStorei(GL_PACK_ALIGNMENT, 1);
	glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
	Image image(w, h);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++)
			for (int c = 0; c < 3; c++) image.at(x, y, c) = rgba[(size_t(h - 1 - y) * w + x) * 4 + c];
	m_app->swapBuffer();  // clears for the next frame
	return image;
}

bool CharpyRenderer::project(const btVector3& p, int& x_px, int& y_px) const
{
	const CommonCameraInterface* camera = m_app->m_instancingRenderer->getActiveCamera();
	float view[16], projection[16];
	camera->getCameraViewMatrix(view);
	camera->getCameraProjectionMatrix(projection);
	// column-major 4x4 matrices, as OpenGL takes them
	float eye[4], clip[4];
	const float world[4] = {float(p.x()), float(p.y()), float(p.z()), 1.f};
	for (int r = 0; r < 4; r++) eye[r] = view[r] * world[0] + view[4 + r] * world[1] + view[8 + r] * world[2] + view[12 + r] * world[3];
	for (int r = 0; r < 4; r++) clip[r] = projection[r] * eye[0] + projection[4 + r] * eye[1] + projection[8 + r] * eye[2] + projection[12 + r] * eye[3];
	if (clip[3] <= 0) return false;
	x_px = int((clip[0] / clip[3] * 0.5f + 0.5f) * width());
	y_px = int((0.5f - clip[1] / clip[3] * 0.5f) * height());
	return true;
}
