#include "StructureView.h"

#include <algorithm>

#include "CommonInterfaces/CommonGUIHelperInterface.h"
#include "CommonInterfaces/CommonGraphicsAppInterface.h"
#include "CommonInterfaces/CommonRenderInterface.h"

const float kSteelRgba[4] = {0.45f, 0.55f, 0.7f, 1};
const float kYieldedRgba[4] = {1.0f, 0.55f, 0.05f, 1};
const float kBrokenRgba[4] = {0.85f, 0.08f, 0.08f, 1};
const float kElasticMarkerRgba[4] = {0.1f, 0.75f, 0.2f, 1};
const float kOtherBodyRgba[4] = {0.25f, 0.25f, 0.3f, 1};
const float kStaticBodyRgba[4] = {0.75f, 0.75f, 0.72f, 1};
const float kMarkerOffset_m = 0.15f;

namespace
{
const float* rgbaOf(JointColour c) { return c == JointColour::Broken ? kBrokenRgba : c == JointColour::Yielded ? kYieldedRgba
																											   : kSteelRgba; }

const float* colourOf(const btCollisionObject* object, const std::map<const btRigidBody*, JointColour>& states,
					 const std::vector<const btCollisionObject*>& wholeStructures)
{
	if (std::find(wholeStructures.begin(), wholeStructures.end(), object) != wholeStructures.end()) return kSteelRgba;
	const btRigidBody* body = btRigidBody::upcast(object);
	if (!body || body->getInvMass() == 0) return kStaticBodyRgba;
	const auto it = states.find(body);
	return it == states.end() ? kOtherBodyRgba : rgbaOf(it->second);
}
}  // namespace

std::map<const btRigidBody*, JointColour> bodyStates(const std::vector<scene::JointView>& joints)
{
	std::map<const btRigidBody*, JointColour> states;
	for (const scene::JointView& j : joints)
	{
		const JointColour c = j.broken ? JointColour::Broken : j.yielded ? JointColour::Yielded
																		 : JointColour::Elastic;
		for (const btRigidBody* b : {j.body_a, j.body_b})
		{
			if (!b || b->getInvMass() == 0) continue;
			auto it = states.find(b);
			if (it == states.end() || int(c) > int(it->second)) states[b] = c;
		}
	}
	return states;
}

void showStructure(GUIHelperInterface* guiHelper, scene::SteppedScene& scene)
{
	guiHelper->removeAllGraphicsInstances();
	btDiscreteDynamicsWorld& world = scene.world();
	const auto states = bodyStates(scene.joints());
	const std::vector<const btCollisionObject*> whole = scene.wholeStructures();
	// the graphics shapes and instances went with removeAllGraphicsInstances: a body shown before (a scene whose bodies
	// enter and leave the world) gets new ones
	for (int i = 0; i < world.getNumCollisionObjects(); i++)
	{
		btCollisionObject* object = world.getCollisionObjectArray()[i];
		object->setUserIndex(-1);
		object->getCollisionShape()->setUserIndex(-1);
	}
	for (int i = 0; i < world.getNumCollisionObjects(); i++)
	{
		btCollisionObject* object = world.getCollisionObjectArray()[i];
		const float* rgba = colourOf(object, states, whole);
		guiHelper->createCollisionShapeGraphicsObject(object->getCollisionShape());
		guiHelper->createCollisionObjectGraphicsObject(object, btVector4(rgba[0], rgba[1], rgba[2], rgba[3]));
	}
}

void colourStructure(GUIHelperInterface* guiHelper, scene::SteppedScene& scene)
{
	const std::vector<scene::JointView> joints = scene.joints();
	const auto states = bodyStates(joints);
	const std::vector<const btCollisionObject*> whole = scene.wholeStructures();
	btDiscreteDynamicsWorld& world = scene.world();
	for (int i = 0; i < world.getNumCollisionObjects(); i++)
	{
		const btCollisionObject* object = world.getCollisionObjectArray()[i];
		if (object->getUserIndex() < 0) continue;
		const float* rgba = colourOf(object, states, whole);
		const double colour[4] = {rgba[0], rgba[1], rgba[2], rgba[3]};
		guiHelper->changeRGBAColor(object->getUserIndex(), colour);
	}
}

void drawJointMarkers(GUIHelperInterface* guiHelper, scene::SteppedScene& scene, float size_px)
{
	const std::vector<scene::JointView> joints = scene.joints();
	CommonRenderInterface* renderer = guiHelper->getRenderInterface();
	if (!renderer) return;
	for (const scene::JointView& j : joints)
	{
		if (j.body_b && !j.body_b->getBroadphaseHandle()) continue;  // out of the world: a whole structure's
		const float* rgba = j.broken ? kBrokenRgba : j.yielded ? kYieldedRgba
															   : kElasticMarkerRgba;
		// in front of the member (the cameras look along -z), so the depth test does not hide it inside the body
		const float position[4] = {float(j.pivot_m.x()), float(j.pivot_m.y()), float(j.pivot_m.z() + kMarkerOffset_m), 1};
		renderer->drawPoint(position, rgba, size_px);
	}
}
