// The Charpy impact test scene (thesis section 2): built from CharpyParameters by this one piece of
// code for the GUI example, the console runner, the tests and the reports. Only the bodies, joints and
// per-step work that the chosen method needs are created. It is a scene of the shared scene layer
// (scene::SteppedScene): the one example class of every scene shows it (demos/examples/SceneExample.h).
#pragma once

#include <memory>
#include <vector>

#include "CharpyParameters.h"
#include "CharpySection.h"
#include "plastic/SubstepPolicy.h"
#include "scene/SteppedScene.h"

class btCollisionShape;
class btDiscreteDynamicsWorld;
class btDynamicsWorld;
class btRigidBody;
class btTypedConstraint;

struct CharpyEnergies
{
	double potential_j = 0;  // m g y of every dynamic body
	double kinetic_j = 0;    // linear and rotational
	double elastic_j = 0;    // held by springs / elastic-plastic joints
	double total_j = 0;      // the sum of the three above
};

// The test's state where it ended (CharpyScene::endState)
struct CharpyEndState
{
	double time_s = 0;  // simulated time: the world's own where the test ended within a frame, else the frames'
	long internal_steps = 0;  // taken up to it
	CharpyEnergies energies;
	double plastic_work_j = 0;
	double plastic_rotation_rad = 0;
	double bend_angle_rad = 0;
	double end_bend_angle_rad = 0;
	double hammer_angle_rad = 0;
	double kinetic_against_hammer_j = 0;
	bool broken = false;
};

class CharpyScene : public scene::SteppedScene
{
public:
	// Throws std::invalid_argument listing every invalid parameter.
	explicit CharpyScene(const CharpyParameters& parameters);
	~CharpyScene() override;
	CharpyScene(const CharpyScene&) = delete;
	CharpyScene& operator=(const CharpyScene&) = delete;

	// One frame: dt_s (or the coarse auto step far from contact), split into internal steps of at most
	// contact_substep_s while the specimen is in or near contact.
	void step() override;
	// at the run's duration, or when a body state is not finite
	bool done() const override;
	double time_s() const override { return m_time_s; }
	btDiscreteDynamicsWorld& world() override { return *m_world; }
	// the specimen's joints (none for the rigid body)
	std::vector<scene::JointView> joints() const override;
	scene::SceneLedger ledger() const override;
	// the anvils and the specimen as it bends through them (the hammer swings through it at the impact)
	scene::WorldBox viewEnvelope() const override;

	const CharpyParameters& parameters() const { return m_parameters; }
	const CharpySection& section() const { return m_section; }
	long internalSteps() const { return m_internalSteps; }
	// internal steps in which the direct or MLCP solver fell back to sequential impulse (0 for sequential impulse)
	int solverFallbacks() const;
	double lastFrameStep_s() const { return m_lastFrameStep_s; }

	CharpyEnergies energies() const;
	double initialEnergy_j() const { return m_initialEnergy_j; }
	double impactSpeed_m_s() const { return m_impactSpeed_m_s; }
	// How far speculative contacts reach [m]: the smallest contact breaking threshold of the specimen's parts (Bullet
	// gives a pair the smaller of its two shapes'; patch 0036 reports box pairs apart by less than it).
	double speculativeReach_m() const;
	// With speculative contacts, a warning when the hammer closes more than their reach in an internal step in
	// contact (the contact substep, or the frame step without substeps) at its impact speed, naming the largest
	// substep that does not, and when the contact travel is longer than their reach (a step it lengthens lets its
	// pairs move that far), naming the reach; empty otherwise. Such steps let parts sink in past the reach, and the
	// contacts' position correction can throw them out (report/REPORT.md's landscape of substeps).
	std::string speculativeReachWarning() const;
	double maxEnergyGain_j() const { return m_maxEnergyGain_j; }
	// The largest excess, after any internal step, of the plastic work booked so far over the energy the scene has
	// lost (E0 - E) [J]: every other loss (friction, contacts) is >= 0, so a positive excess is work booked that no
	// force paid for (a yielding joint turned by the contacts' position correction) or energy made
	double maxBookedExcess_j() const { return m_maxBookedExcess_j; }
	double plasticWork_j() const;
	double plasticRotation_rad() const;
	double bendAngle_rad() const;    // relative rotation of the two middle parts about Y
	double endToEndBend_rad() const; // rotation angle of the last part relative to the first, about any axis
	double hammerAngle_rad() const;  // pendulum rotation about Z from the impact position
	bool broken() const;
	bool passedAnvils() const;       // every part is behind the anvils' front plane (x < 0)
	// the test is over: every part is behind the anvils and none can touch an anvil within a frame step, or 1 ms if the
	// frame step is longer (plastic::mayTouchWithin); asked after every internal step. The parts may still meet the
	// hammer (kineticAgainstHammer_j).
	bool clear() const;
	static constexpr double kClearHorizon_s = 1e-3;
	// with end_when_clear, the test ended at an internal step that left the specimen clear
	bool endedClear() const { return m_endedClear; }
	// The state at that internal step, or now if it has not ended so. The runner's own substeps stop there; the world's
	// contact stepping (world_contact_travel_m) takes the frame whole, on to its end in steps as long as no pair near
	// contact limits them, where a pendulum's hinge loses energy (a 12 m/s hammer 25 J in a 1/60 s frame of 5.8 ms
	// steps): that is no part of the test, so its state is taken after the world's step that left it clear.
	CharpyEndState endState() const;
	// the parts' kinetic energy against the hammer, 1/2 sum m (plastic::relativeSpeedBound_m_s)^2 [J]: the most one
	// collision of them with the hammer could dissipate now. A scale of what ending at clear() leaves out, not a bound
	// over the rest of a run (gravity and the swing change the speeds, and they can meet again).
	double kineticAgainstHammer_j() const;
	bool overTheTop() const { return m_overTheTop; }  // a part got behind the anvils above their top, not through the gap
	double maxPenetration_m() const { return m_maxPenetration_m; }
	double maxSpeed_m_s() const { return m_maxSpeed_m_s; }        // fastest dynamic body, any step
	double maxDistance_m() const { return m_maxDistance_m; }      // farthest dynamic body centre from the origin
	bool finite() const;             // no NaN or infinity in any body state

	const std::vector<btRigidBody*>& specimenParts() const { return m_parts; }
	btRigidBody* hammer() const { return m_hammer; }

private:
	struct Impl;

	void destroy();  // removes and deletes everything created so far
	void createWorld();
	void createAnvils();
	btCollisionShape* roundedAnvil(double side);  // the anvil at side * z > 0 with a rounded (and tapered) inner edge
	void createSpecimen();
	void createJoints();
	void createHammer();
	// whether a part can touch an anvil or the hammer within horizon_s (plastic::mayTouchWithin); with speculative
	// contacts, a part within their reach counts only while it is pressed against an anvil or can move half the
	// reach, or a joint works
	bool nearContact(double horizon_s) const;
	// when the first part now apart from an anvil or the hammer touches it, within horizon_s [s]
	double timeToTouch_s(double horizon_s) const;
	// the fastest speed of a part against an anvil or the hammer in or near contact within horizon_s [m/s]
	double contactSpeed_m_s(double horizon_s) const;
	double fastestSpin_rad_s() const;  // of the specimen's parts
	void internalStep(double h_s);
	void trackAfterStep(double h_s);
	void prepareStep(double step_s);  // before an internal step: the joints' caps for its length
	void finishStep(double step_s);   // after it: counted and tracked
	// with the world's contact stepping, the same for each of its internal steps (its tick callbacks)
	static void beforeWorldStep(btDynamicsWorld* world, btScalar step_s);
	static void afterWorldStep(btDynamicsWorld* world, btScalar step_s);

	CharpyParameters m_parameters;
	bool m_endedClear = false;  // the test ended at the internal step that left the specimen clear (recordEnd)
	CharpyEndState m_endState;  // the state there
	double m_steppedTime_s = 0;  // the internal steps taken so far: the world's time (it can lag m_time_s)
	void recordEnd();            // ends the test now: m_endedClear, m_endState
	CharpyEndState currentState() const;
	plastic::ContactSubstepPolicy m_substeps{plastic::ContactSubstepSettings{0}};  // the frame's internal steps
	CharpySection m_section;
	std::unique_ptr<Impl> m_impl;  // Bullet's world objects, shapes and bodies
	std::unique_ptr<btDiscreteDynamicsWorld> m_world;
	std::vector<btRigidBody*> m_parts;
	std::vector<btRigidBody*> m_anvils;
	std::vector<const btCollisionObject*> m_contactMovers;  // the specimen's parts: what the substep policy asks about
	std::vector<const btCollisionObject*> m_contactOthers;  // the anvils and the hammer
	std::vector<const btCollisionObject*> m_contactAnvils;  // the anvils
	std::vector<btTypedConstraint*> m_joints;  // views of the toolkit joints m_impl owns
	btRigidBody* m_hammer = nullptr;
	btTypedConstraint* m_middleJoint = nullptr;

	double m_time_s = 0;
	// with speculative contacts: in the last step a joint flowed or held elastic energy, or a part was pressed against
	// an anvil through a contact with friction or at rest; true before the first step, when no contact has told its
	// load (the specimen lying on the anvils made 0.07-0.15 J in a first step of 0.5 ms)
	bool m_holdSubstep = true;
	bool m_jointFlowed = true;  // a joint flowed in the last internal step (with speculative contacts)
	double m_jointRotation_rad = 0;  // the joints' plastic rotation after the last step
	long m_internalSteps = 0;
	double m_lastFrameStep_s = 0;
	double m_initialEnergy_j = 0;
	double m_impactSpeed_m_s = 0;
	double m_maxEnergyGain_j = 0;
	double m_maxBookedExcess_j = 0;
	double m_maxPenetration_m = 0;
	double m_maxSpeed_m_s = 0;
	double m_maxDistance_m = 0;
	double m_anvilTop_m = 0;           // highest point of the anvils (AABB)
	std::vector<bool> m_partPassed;    // the part has got behind the anvils' front plane
	bool m_overTheTop = false;
	// hinge-motor method only: the motor's work and rotation while at its cap
	double m_motorWork_j = 0;
	double m_motorRotation_rad = 0;
	double m_previousBend_rad = 0;
};
