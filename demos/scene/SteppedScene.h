// What a scene shows while it runs, one step at a time: the console runners loop over step() until done();
// the ExampleBrowser examples step it to the browser's clock, draw its world, colour its joints by their state and
// print its ledger. Nothing here draws (no OpenGL): the examples read it.
#pragma once

#include <string>
#include <vector>

#include "RunStats.h"
#include "btBulletDynamicsCommon.h"

namespace scene
{
// One plastic joint as it is shown: where it is (world pivot), which bodies it joins, how far it has yielded.
struct JointView
{
	btVector3 pivot_m{0, 0, 0};
	const btRigidBody* body_a = nullptr;
	const btRigidBody* body_b = nullptr;  // may be static (a support)
	double plastic_rotation_rad = 0;      // booked by the joint (the hinge-motor stand-in: measured from the bodies)
	double plastic_work_j = 0;            // booked by the joint (0 for the hinge-motor stand-in)
	bool yielded = false;                 // it has turned plastically (more than kYieldedRotation_rad)
	bool broken = false;                  // disabled by its plastic rotation limit
};

// A joint counts as yielded once it has turned plastically this far (rad).
constexpr double kYieldedRotation_rad = 1e-4;

// The energies of a run as far as it has come, measured from the bodies and the loads, beside the analytic answer.
struct SceneLedger
{
	std::string title;  // scene, method
	double time_s = 0;
	double load_work_j = 0;           // work of the applied loads (or of gravity), from the loads' points
	double kinetic_j = 0;             // of every moving body
	double plastic_booked_j = 0;      // what the joints booked
	double plastic_measured_j = 0;    // Mp x |rotations| measured from the bodies
	std::vector<std::string> answer;  // the analytic answer, one line each
	std::vector<std::string> status;  // what the run has found so far (collapse, stop, broken joints)
};

// A box in the world (m).
struct WorldBox
{
	btVector3 min_m{0, 0, 0};
	btVector3 max_m{0, 0, 0};
};

// The ledger as text lines (J, rad, s) for the screen.
std::string ledgerText(const SceneLedger& ledger);

class SteppedScene
{
public:
	virtual ~SteppedScene() = default;
	virtual void step() = 0;  // one step of the scene's clock: an internal step (structures), a 60 Hz frame (the game scene)
	virtual bool done() const = 0;
	virtual double time_s() const = 0;
	virtual btDiscreteDynamicsWorld& world() = 0;
	virtual std::vector<JointView> joints() const = 0;
	virtual SceneLedger ledger() const = 0;
	// The box every body stays in over the whole run, collapse and after (from the parameters: the structure's bounds
	// and the reach of its mechanism): what the examples keep in view. Not the ground slab.
	virtual WorldBox viewEnvelope() const = 0;
	// A count that changes whenever bodies have entered or left the world since the scene was built (a structure made
	// one body or its jointed self again): the examples then show the world's bodies again. 0 for a scene whose world
	// keeps its bodies.
	virtual long worldChanges() const { return 0; }
	// Static bodies that stand for whole structures (shown in the structure's colour, not the supports'): none here.
	virtual std::vector<const btCollisionObject*> wholeStructures() const { return {}; }
};

// SteppedScene's interface as a scene's class declares it (each scene defines these in its .cpp), in one line of the
// class: SCENE_STEPPED_SCENE_OVERRIDES;
#define SCENE_STEPPED_SCENE_OVERRIDES                      \
	void step() override;                                  \
	bool done() const override;                            \
	double time_s() const override;                        \
	btDiscreteDynamicsWorld& world() override;             \
	std::vector<scene::JointView> joints() const override; \
	scene::SceneLedger ledger() const override;            \
	scene::WorldBox viewEnvelope() const override

// A scene of Parameters stepped until it is done, and its result() then (what the console runners print).
template <class Scene, class Parameters>
auto runToEnd(const Parameters& parameters)
{
	Scene scene(parameters);
	while (!scene.done()) scene.step();
	return scene.result();
}
}  // namespace scene
