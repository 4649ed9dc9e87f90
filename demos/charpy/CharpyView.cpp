#include "CharpyView.h"

#include <algorithm>
#include <cstdio>

#include "btBulletDynamicsCommon.h"
#include "CommonInterfaces/CommonGUIHelperInterface.h"
#include "CommonInterfaces/CommonGraphicsAppInterface.h"

#include "CharpyScene.h"
#include "TextLines.h"

const float kCharpySpecimenRgb[3] = {0.95f, 0.45f, 0.05f};
const float kCharpyAnvilRgb[3] = {0.55f, 0.55f, 0.58f};
const float kCharpyHammerRgb[3] = {0.2f, 0.35f, 0.75f};

CharpyCamera charpyCamera(const CharpyParameters& p)
{
	// Target: above the specimen, so that it sits in the lower half; far enough to see both anvils.
	const float span_m = float(std::max(p.specimen_length_m, p.anvil_gap_m + 2 * p.anvil_width_m));
	CharpyCamera camera{};
	camera.distance_m = 1.2f * span_m;
	camera.yaw_deg = 90.f;     // looking along -X (from the hammer's side)...
	camera.pitch_deg = -60.f;  // ...and from above: the specimen bends towards the far side
	camera.target_m[0] = float(-0.5 * p.specimen_width_m);
	camera.target_m[1] = float(p.specimen_bottom_y_m + 6 * p.specimen_width_m);  // above: the frame's upper part shows text
	camera.target_m[2] = 0.f;
	return camera;
}

void resetCharpyCamera(GUIHelperInterface* guiHelper, const CharpyParameters& parameters)
{
	const CharpyCamera camera = charpyCamera(parameters);
	guiHelper->resetCamera(camera.distance_m, camera.yaw_deg, camera.pitch_deg, camera.target_m[0], camera.target_m[1], camera.target_m[2]);
}

void showCharpyScene(GUIHelperInterface* guiHelper, CharpyScene& scene)
{
	guiHelper->removeAllGraphicsInstances();
	btDiscreteDynamicsWorld* world = &scene.world();
	const auto& parts = scene.specimenParts();
	for (int i = 0; i < world->getNumCollisionObjects(); i++)
	{
		btCollisionObject* object = world->getCollisionObjectArray()[i];
		const float* rgb = kCharpyAnvilRgb;
		if (std::find(parts.begin(), parts.end(), object) != parts.end()) rgb = kCharpySpecimenRgb;
		if (object == scene.hammer()) rgb = kCharpyHammerRgb;
		guiHelper->createCollisionShapeGraphicsObject(object->getCollisionShape());
		// alpha 1: btVector3(r, g, b) would leave w = 0, a fully transparent instance
		guiHelper->createCollisionObjectGraphicsObject(object, btVector4(rgb[0], rgb[1], rgb[2], 1));
	}
	resetCharpyCamera(guiHelper, scene.parameters());
}

std::string charpyEnergyPanel(const CharpyScene& scene)
{
	const CharpyEnergies e = scene.energies();
	const double loss_j = scene.initialEnergy_j() - e.total_j;
	char text[1024];
	std::snprintf(text, sizeof(text),
				  "%s   t = %.2f ms\n"
				  "E0 %.1f J   now %.1f J\n"
				  "energy loss %.1f J\n"
				  "plastic work %.1f J\n"
				  "analytic Mp*theta %.1f J\n"
				  "kinetic %.1f J   potential %.1f J\n"
				  "elastic %.2f J\n"
				  "bend %.3f rad   plastic %.3f rad\n"
				  "%s%s",
				  std::string(charpyMethodName(scene.parameters().method)).c_str(), scene.time_s() * 1e3, scene.initialEnergy_j(),
				  e.total_j, loss_j, scene.plasticWork_j(), scene.section().analytic_loss_j, e.kinetic_j, e.potential_j, e.elastic_j,
				  scene.bendAngle_rad(), scene.plasticRotation_rad(), scene.broken() ? "broken  " : "", scene.passedAnvils() ? "passed the anvils" : "");
	return text;
}

void drawCharpyPanel(CommonGraphicsApp* app, const std::string& text, int left_px, int top_px)
{
	drawTextLines(app, text, left_px, top_px);
}
