#include "CharpyScene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "plastic/JointFactory.h"
#include "plastic/Section.h"
#include "plastic/SolverSettings.h"
#include "plastic/JoinedFaces.h"
#include "plastic/SubstepPolicy.h"
#include "btBulletDynamicsCommon.h"
#include "BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h"
#include "BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h"
#include "scene/Errors.h"

namespace
{
constexpr double kGravity_m_s2 = 9.81;
constexpr double kMargin_m = 0.0005;      // collision margin of the small boxes (Bullet's default 0.04 m is 4x the specimen)
constexpr double kNoseHeight_m = 0.02;    // striker nose along Y
constexpr double kAnvilDepth_m = 0.04;    // anvils along X, behind the specimen
constexpr double kStartGap_m = 0.003;     // the hammer nose starts this far in front of the specimen
constexpr double kPoisson = 0.3;
// The near-contact test's allowance for what forces add within a step (joints, contacts, the torque that turns the
// hammer), a part of the specimen's width: 0.1 mm for the 10 mm specimen. From the toolkit's default 1 mm to this, no
// loss of methods 5-8 in REPORT.md's sweep (576 runs), STABILITY.md or FRICTION.md moved by more than 0.5 %, and the
// parts flying off after the fold, a millimetre from the nose and the anvils, no longer hold the world at the substep.
constexpr double kNearClearanceWidths = 0.01;
// the shortest internal step the world's contact stepping takes (--world-contact-travel) [s]
constexpr double kMinimumWorldStep_s = 1e-6;

double nearClearance_m(const CharpyParameters& p) { return kNearClearanceWidths * p.specimen_width_m; }

btTransform translation(double x, double y, double z)
{
	btTransform t;
	t.setIdentity();
	t.setOrigin(btVector3(btScalar(x), btScalar(y), btScalar(z)));
	return t;
}

// The toolkit's joint method for a Charpy method (rigid: no joint).
plastic::JointMethod jointMethod(CharpyMethod method)
{
	switch (method)
	{
		case CharpyMethod::BrittleZeroLimits: return plastic::JointMethod::Brittle;
		case CharpyMethod::Spring: return plastic::JointMethod::Spring;
		case CharpyMethod::Spring2: return plastic::JointMethod::Spring2;
		case CharpyMethod::HingeMotor: return plastic::JointMethod::HingeMotor;
		case CharpyMethod::ElasticPlastic: return plastic::JointMethod::ElasticPlastic;
		case CharpyMethod::ElasticPlastic2: return plastic::JointMethod::ElasticPlastic2;
		case CharpyMethod::RigidBody:
		case CharpyMethod::PlasticHinge: break;
	}
	return plastic::JointMethod::PlasticHinge;
}

// GJK's tolerances scaled to the specimen, as its collision margins are (patch 0018), for this scene's steps and its
// distance tests; a process-wide setting, so it is put back when the scope ends
class SpecimenLengthScale
{
public:
	explicit SpecimenLengthScale(double width_m) : m_saved(gVoronoiSimplexLengthScale) { gVoronoiSimplexLengthScale = btScalar(width_m); }
	~SpecimenLengthScale() { gVoronoiSimplexLengthScale = m_saved; }
	SpecimenLengthScale(const SpecimenLengthScale&) = delete;
	SpecimenLengthScale& operator=(const SpecimenLengthScale&) = delete;

private:
	btScalar m_saved;
};
}  // namespace

// The scene's world: after the collision detection of a step, the contacts on the faces through which the specimen's
// parts are joined are removed where the neighbouring part covers them, while their joints hold (plastic::JoinedFaces),
// before the solve
class CharpyWorld : public btDiscreteDynamicsWorld
{
public:
	using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
	plastic::JoinedFaces joinedFaces;
	void performDiscreteCollisionDetection() override
	{
		btDiscreteDynamicsWorld::performDiscreteCollisionDetection();
		joinedFaces.removeContacts(*getDispatcher());
	}
};

struct CharpyScene::Impl
{
	explicit Impl(plastic::SolverKind kind) : solver(kind) {}
	btDefaultCollisionConfiguration collisionConfiguration;
	btCollisionDispatcher dispatcher{&collisionConfiguration};
	btDbvtBroadphase broadphase;
	plastic::OwnedSolver solver;
	btAlignedObjectArray<btCollisionShape*> shapes;
	btAlignedObjectArray<btRigidBody*> bodies;
	btAlignedObjectArray<btTypedConstraint*> constraints;
	btAlignedObjectArray<btMotionState*> motionStates;
	btHingeConstraint* hammerPivot = nullptr;
	btVector3 pivot_m;
	std::vector<plastic::Joint> joints;      // the specimen's joints, made by the toolkit's joint factory
	std::vector<plastic::JointSpec> specs;   // what each was made from (the per-step caps follow it)
	std::vector<btVector3> pivotsInA;        // each joint's pivot in its first part's frame (m)

	// collisionGroup / collisionMask 0: Bullet's defaults for a static or a dynamic body
	btRigidBody* addBody(btDiscreteDynamicsWorld* world, btCollisionShape* shape, double mass_kg, const btVector3& inertia,
						 const btTransform& transform, double friction, double restitution, int collisionGroup = 0, int collisionMask = 0)
	{
		shapes.push_back(shape);
		auto* motionState = new btDefaultMotionState(transform);
		motionStates.push_back(motionState);
		btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass_kg), motionState, shape, inertia);
		info.m_friction = btScalar(friction);
		info.m_restitution = btScalar(restitution);
		auto* body = new btRigidBody(info);
		if (mass_kg > 0)
		{
			body->setActivationState(DISABLE_DEACTIVATION);
		}
		if (collisionGroup != 0)
		{
			world->addRigidBody(body, collisionGroup, collisionMask);
		}
		else
		{
			world->addRigidBody(body);
		}
		bodies.push_back(body);
		return body;
	}

	btBoxShape* box(double hx, double hy, double hz)
	{
		auto* shape = new btBoxShape(btVector3(btScalar(hx), btScalar(hy), btScalar(hz)));
		shape->setMargin(btScalar(kMargin_m));
		return shape;
	}
};

CharpyScene::CharpyScene(const CharpyParameters& parameters)
	: m_parameters(parameters)
{
	std::vector<std::string> errors = validateCharpyParameters(parameters);
	if (!errors.empty())
	{
		std::string text;
		for (const std::string& e : errors)
		{
			text += (text.empty() ? "" : "\n") + e;
		}
		throw std::invalid_argument(text);
	}
	plastic::ContactSubstepSettings substeps;
	substeps.contact_substep_s = parameters.contact_substep_s;
	substeps.free_step_s = parameters.free_step_s;
	substeps.contact_travel_m = parameters.contact_travel_m;
	m_substeps = plastic::ContactSubstepPolicy(substeps);
	scene::throwIfAny(m_substeps.errors());
	m_section = computeCharpySection(parameters);
	m_impl = std::make_unique<Impl>(parameters.solver);
	try
	{
		createWorld();
		createAnvils();
		createSpecimen();
		for (const btRigidBody* anvil : m_anvils)
		{
			btVector3 lo, hi;
			anvil->getAabb(lo, hi);
			m_anvilTop_m = std::max(m_anvilTop_m, double(hi.y()));
		}
		m_partPassed.assign(m_parts.size(), false);
		createJoints();
		createHammer();  // throws when the hammer cannot reach the specimen
	}
	catch (...)
	{
		destroy();  // the destructor does not run for a constructor that throws
		throw;
	}
	m_contactMovers.assign(m_parts.begin(), m_parts.end());
	m_contactOthers.assign(m_anvils.begin(), m_anvils.end());
	m_contactAnvils.assign(m_anvils.begin(), m_anvils.end());
	if (m_hammer)
	{
		m_contactOthers.push_back(m_hammer);
	}
	for (btRigidBody* part : m_parts)
	{
		part->setCcdMotionThreshold(btScalar(parameters.ccd_motion_threshold_m));
		part->setCcdSweptSphereRadius(btScalar(parameters.ccd_swept_sphere_radius_m));
	}
	if (parameters.ccd_motion_threshold_m > 0)
	{
		// a sweep's hit counts only if the step moves the part more than this into the surface: Bullet's 0.04 m is
		// four specimen widths, which no part here moves in a step, so the sweeps would never stop one. The parts'
		// margin is what their contacts hold anyway
		m_world->getDispatchInfo().m_allowedCcdPenetration = btScalar(kMargin_m);
	}
	m_initialEnergy_j = energies().total_j;
	m_previousBend_rad = bendAngle_rad();
}

CharpyScene::~CharpyScene() { destroy(); }

void CharpyScene::destroy()
{
	for (auto it = m_impl->joints.rbegin(); it != m_impl->joints.rend(); ++it)
	{
		m_world->removeConstraint(it->constraint.get());
	}
	m_impl->joints.clear();
	m_joints.clear();
	m_middleJoint = nullptr;
	for (int i = m_impl->constraints.size() - 1; i >= 0; i--)
	{
		m_world->removeConstraint(m_impl->constraints[i]);
		delete m_impl->constraints[i];
	}
	for (int i = m_impl->bodies.size() - 1; i >= 0; i--)
	{
		m_world->removeRigidBody(m_impl->bodies[i]);
		delete m_impl->bodies[i];
	}
	for (int i = 0; i < m_impl->motionStates.size(); i++) delete m_impl->motionStates[i];
	for (int i = 0; i < m_impl->shapes.size(); i++) delete m_impl->shapes[i];
	m_impl->constraints.clear();
	m_impl->bodies.clear();
	m_impl->motionStates.clear();
	m_impl->shapes.clear();
	m_world.reset();
}

void CharpyScene::createWorld()
{
	m_world = std::make_unique<CharpyWorld>(&m_impl->dispatcher, &m_impl->broadphase, m_impl->solver.get(),
											&m_impl->collisionConfiguration);
	m_world->setGravity(btVector3(0, btScalar(-kGravity_m_s2), 0));
	m_world->getSolverInfo().m_numIterations = m_parameters.solver_iterations;
	m_world->getDispatchInfo().m_speculativeBoxBoxContacts = m_parameters.speculative_contacts;
	m_world->getDispatchInfo().m_boxBoxEdgesAcrossFaces = m_parameters.box_edges_across_faces || m_parameters.speculative_contacts;
	// and a capsule (the striker's edge, an ISO anvil's rounded edge) lying along a part's face touches it at both ends
	// (patch 0051): with GJK's one point a step the far end's point slid off, and the striker and an anvil held a half
	// at opposite ends of its face and spun it off the anvil
	m_world->getDispatchInfo().m_capsuleFaceLineContacts = m_parameters.speculative_contacts;
	// contact rows aim at the gap with the bodies' turns (patch 0055); setContactStepping turns it on too
	m_world->getSolverInfo().m_contactTurnPrediction = m_parameters.contact_turn_prediction;
	if (m_parameters.world_contact_travel_m > 0)
	{
		// the world cuts each step into its own (patch 0053), and its tick callbacks set up and track each of them
		m_world->setContactStepping(btScalar(m_parameters.world_contact_travel_m), btScalar(kMinimumWorldStep_s));
		m_world->setInternalTickCallback(&CharpyScene::beforeWorldStep, this, true);
		m_world->setInternalTickCallback(&CharpyScene::afterWorldStep, this, false);
	}
}

void CharpyScene::createAnvils()
{
	const CharpyParameters& p = m_parameters;
	const double y0 = p.specimen_bottom_y_m, b = p.specimen_width_m;
	const double zCentre = p.anvil_gap_m / 2.0 + p.anvil_width_m / 2.0;
	for (double side : {-1.0, 1.0})
	{
		// the anvil behind the specimen (x < 0) and a ledge under it that carries its weight
		btTransform anvil = translation(-kAnvilDepth_m / 2.0, y0 + b / 2.0, side * zCentre);
		btTransform ledge = translation(b, y0 - 0.01, side * zCentre);
		btCollisionShape* shape = p.anvil_radius_m > 0 ? roundedAnvil(side) : m_impl->box(kAnvilDepth_m / 2.0, 2.0 * b, p.anvil_width_m / 2.0);
		if (p.anvil_radius_m > 0)
		{
			anvil = translation(0, y0 + b / 2.0, 0);  // the compound's children are placed in world X and Z
		}
		m_anvils.push_back(m_impl->addBody(m_world.get(), shape, 0, btVector3(0, 0, 0), anvil, 1.0, 0.0));
		m_anvils.push_back(m_impl->addBody(m_world.get(), m_impl->box(b, 0.01, p.anvil_width_m / 2.0), 0, btVector3(0, 0, 0),
										   ledge, 1.0, 0.0));
	}
}

btCollisionShape* CharpyScene::roundedAnvil(double side)
{
	// ISO 148-1 anvil, in the X-Z plane (extruded along Y): the front face x = 0 for |z| >= gz + r, the inner edge a
	// circle of radius r centred at (-r, gz + r) (the gap is anvil_gap_m at its narrowest, x = -r), and behind it the
	// inner face leaves the circle tapered by anvil_taper_rad (0: parallel to X) back to x = -depth. Children: the
	// edge is a capsule (exact in GJK; a btCylinderShape is not), the faces are boxes (exact box-box contacts).
	const CharpyParameters& p = m_parameters;
	const double r = p.anvil_radius_m, taper = p.anvil_taper_rad, gz = p.anvil_gap_m / 2.0, hy = 2.0 * p.specimen_width_m;
	const double outer = gz + p.anvil_width_m;
	auto* compound = new btCompoundShape();
	auto add = [&](const btTransform& t, btCollisionShape* child) {
		compound->addChildShape(t, child);
		m_impl->shapes.push_back(child);
	};
	// the edge: a capsule along Y as tall as the anvil
	add(translation(-r, 0, side * (gz + r)), new btCapsuleShape(btScalar(r), btScalar(2.0 * hy - 2.0 * r)));
	// where the tapered face leaves the circle (normal (-sin, -cos) in (x, |z|)), and where it crosses |z| = gz + r
	const double s = std::sin(taper), c = std::cos(taper);
	const double leaveX = -r - r * s, leaveZ = gz + r - r * c;
	const double blockBack = taper > 0 ? -r - r / s : -kAnvilDepth_m;  // the front block ends where the taper cuts it
	// the front block: x in [blockBack, 0], |z| in [gz + r, outer]
	add(translation(blockBack / 2.0, 0, side * (gz + r + outer) / 2.0), m_impl->box(-blockBack / 2.0, hy, (outer - gz - r) / 2.0));
	// the inner face behind the edge: a box whose inner face runs from the leaving point back to x = -depth along
	// (-cos, sin), thick enough to close the anvil but with its front end hidden in the edge and the block
	const double length = (leaveX + kAnvilDepth_m) / c;
	double thickness = 5.0 * r;
	if (taper > 0)
	{
		thickness = std::min(thickness, 0.9 * -leaveX / s);
	}
	const double cx = leaveX - 0.5 * length * c + 0.5 * thickness * s;
	const double cz = leaveZ + 0.5 * length * s + 0.5 * thickness * c;
	btTransform face = translation(cx, 0, side * cz);
	face.setRotation(btQuaternion(btVector3(0, 1, 0), btScalar(side * taper)));
	btBoxShape* faceBox = m_impl->box(length / 2.0, hy, thickness / 2.0);
	faceBox->setMargin(btScalar(std::min(kMargin_m, thickness / 4.0)));
	add(face, faceBox);
	return compound;
}

void CharpyScene::createSpecimen()
{
	const CharpyParameters& p = m_parameters;
	const double b = p.specimen_width_m, L = p.specimen_length_m;
	const int n = p.method == CharpyMethod::RigidBody ? 1 : p.parts;
	const double partLength = L / n;
	const double mass = p.density_kg_m3 * b * b * partLength;
	// The parts are one specimen: they collide with the anvils and the hammer, not with each other. Each is a box of
	// the full section, and a hinge's pivot lies inside the section (mid-ligament, 4 mm behind the struck face), so as
	// a hinge folds the corners of its parts swing into the parts beyond their neighbours where the material would flow:
	// with parts shorter than that (16 parts and more) they locked the middle hinge at asin(part length / 4 mm).
	const int specimenGroup = btBroadphaseProxy::CharacterFilter << 1;
	const int specimenMask = btBroadphaseProxy::AllFilter ^ specimenGroup;
	for (int i = 0; i < n; i++)
	{
		btBoxShape* shape = m_impl->box(b / 2.0, b / 2.0, partLength / 2.0);
		btVector3 inertia;
		shape->calculateLocalInertia(btScalar(mass), inertia);
		double z = -L / 2.0 + (i + 0.5) * partLength;
		m_parts.push_back(m_impl->addBody(m_world.get(), shape, mass, inertia, translation(b / 2.0, p.specimen_bottom_y_m + b / 2.0, z),
										  p.friction, 0.0, specimenGroup, specimenMask));
	}
}

void CharpyScene::createJoints()
{
	const CharpyParameters& p = m_parameters;
	const int n = static_cast<int>(m_parts.size());
	if (p.method == CharpyMethod::RigidBody)
	{
		return;
	}
	plastic::Material material;
	material.youngs_modulus_pa = p.youngs_modulus_pa;
	material.poisson_ratio = kPoisson;
	material.yield_stress_pa = p.yield_stress_pa;
	const double width = p.specimen_width_m;
	for (int i = 0; i + 1 < n; i++)
	{
		const double z = -p.specimen_length_m / 2.0 + (i + 1) * p.specimen_length_m / n;
		const bool notched = (i + 1) * 2 == n;
		// the section left at the interface: the ligament at the notch, the whole width elsewhere; the hinge at
		// its centre. The toolkit's member axis is the specimen axis (world Z), the section's width is the
		// specimen width (world Y) and its depth h the impact direction (world X): the impact bends the joint
		// about world Y (its bending axis 1), the other bending axis is world -X.
		const double h = notched ? m_section.ligament_m : width;
		plastic::JointSpec spec;
		spec.method = jointMethod(p.method);
		spec.pivot_m = btVector3(btScalar(notched ? m_section.hinge_offset_m : width / 2.0),
								 btScalar(p.specimen_bottom_y_m + width / 2.0), btScalar(z));
		spec.basis.setValue(0, -1, 0,  // columns: world Y, world -X, world Z
							1, 0, 0,   //
							0, 0, 1);
		spec.section = plastic::rectangle(width, h);
		spec.material = material;
		spec.segment_length_m = p.specimen_length_m / p.parts;
		spec.max_plastic_rotation_rad = p.max_plastic_rotation_rad;
		spec.min_steps_per_period = p.min_steps_per_period;
		spec.breaking_force_n = p.brittle_breaking_force_n;
		m_impl->joints.push_back(plastic::makeJoint(scene::requireValid(spec), *m_parts[i], *m_parts[i + 1]));
		m_impl->specs.push_back(spec);
		m_impl->pivotsInA.push_back(m_parts[i]->getWorldTransform().inverse() * spec.pivot_m);
		btTypedConstraint* joint = m_impl->joints.back().constraint.get();
		m_world->addConstraint(joint, true);
		m_joints.push_back(joint);
		if (notched)
		{
			m_middleJoint = joint;
		}
		// the parts are joined through their end faces (the specimen's axis is their Z): while the joint holds, a
		// contact there is no contact with the specimen's surface
		CharpyWorld& world = static_cast<CharpyWorld&>(*m_world);
		world.joinedFaces.add(m_parts[i], plastic::kFacePlusZ, m_parts[i + 1], joint);
		world.joinedFaces.add(m_parts[i + 1], plastic::kFaceMinusZ, m_parts[i], joint);
	}
}

void CharpyScene::createHammer()
{
	const CharpyParameters& p = m_parameters;
	if (p.hammer_thickness_m <= 0)
	{
		return;
	}
	const double L = p.hammer_length_m, H = p.hammer_height_m, T = p.hammer_thickness_m;
	// Local frame at the head's centre of mass. The striker nose tip is at (-(L/2 + draft), 0, 0); the pivot is
	// straight above it, so the impact is horizontal. The arm and nose take no part in mass and inertia (thesis 2.2.5).
	auto* compound = new btCompoundShape();
	btBoxShape* head = m_impl->box(L / 2.0, H / 2.0, T / 2.0);
	head->setMargin(btScalar(0.001));
	compound->addChildShape(translation(0, 0, 0), head);
	m_impl->shapes.push_back(head);
	if (p.hammer_draft_m > 0 && p.striker_radius_m > 0)
	{
		// the standard's striker: an edge rounded to striker_radius_m along Y at mid-span (a capsule), carried by
		// a blade thinner than the edge
		const double r = p.striker_radius_m;
		btBoxShape* blade = m_impl->box((p.hammer_draft_m - r) / 2.0, kNoseHeight_m / 2.0, r / 2.0);
		compound->addChildShape(translation(-(L / 2.0 + (p.hammer_draft_m - r) / 2.0), 0, 0), blade);
		m_impl->shapes.push_back(blade);
		auto* edge = new btCapsuleShape(btScalar(r), btScalar(kNoseHeight_m));
		compound->addChildShape(translation(-(L / 2.0 + p.hammer_draft_m - r), 0, 0), edge);
		m_impl->shapes.push_back(edge);
	}
	else if (p.hammer_draft_m > 0)
	{
		btBoxShape* nose = m_impl->box(p.hammer_draft_m / 2.0, kNoseHeight_m / 2.0, T / 2.0);
		compound->addChildShape(translation(-(L / 2.0 + p.hammer_draft_m / 2.0), 0, 0), nose);
		m_impl->shapes.push_back(nose);
	}
	btVector3 inertia;
	head->calculateLocalInertia(btScalar(p.hammer_mass_kg), inertia);

	const double tipX = L / 2.0 + p.hammer_draft_m;  // tip is at local x = -tipX
	const double armDrop = H / 2.0 + p.hammer_arm_length_m;
	const double yImpact = p.specimen_bottom_y_m + p.specimen_width_m / 2.0;
	const btVector3 pivot(btScalar(p.specimen_width_m), btScalar(yImpact + armDrop), 0);
	const btVector3 pivotLocal(btScalar(-tipX), btScalar(armDrop), 0);
	m_impl->pivot_m = pivot;

	// start rotated back about +Z so the tip is kStartGap_m in front of the specimen
	const double startAngle = std::asin(kStartGap_m / armDrop);
	btTransform atImpact = translation(pivot.x() - pivotLocal.x(), pivot.y() - pivotLocal.y(), 0);
	btTransform rotation;
	rotation.setIdentity();
	rotation.setRotation(btQuaternion(btVector3(0, 0, 1), btScalar(startAngle)));
	btTransform aroundPivot = translation(pivot.x(), pivot.y(), 0) * rotation * translation(-pivot.x(), -pivot.y(), 0);
	btTransform start = aroundPivot * atImpact;

	m_hammer = m_impl->addBody(m_world.get(), compound, p.hammer_mass_kg, inertia, start, 1.0, 0.0);
	auto* pivotJoint = new btHingeConstraint(*m_hammer, pivotLocal, btVector3(0, 0, 1));
	// the pivot's drift from a longer step is corrected without momentum in the much shorter steps after it (patch
	// 0044): the substep policy's steps vary, and Baumgarte's bias (ERP x drift / step) after a 1.3 ms step out of
	// contact gave the hammer 0.65 m/s in the 2 us contact step after it, 60 J (standard striker, friction 0, 0.1 ms
	// frames gathered); split in every step, the hammer struck through at 50 m/s lost 1356 J of its 31287 J against 354 J
	// with the bias (--full-duration --impact-speed=50)
	pivotJoint->setSplitPositionCorrectionAfterLongerSteps(true);
	m_world->addConstraint(pivotJoint, true);
	m_impl->constraints.push_back(pivotJoint);
	m_impl->hammerPivot = pivotJoint;

	// hammer energy above its hanging rest position: from the release angle or given directly
	const btVector3 comOffset = start.getOrigin() - pivot;  // pivot -> centre of mass
	const double Rc = comOffset.length();
	const double m = p.hammer_mass_kg;
	const double inertiaAboutPivot = inertia.z() + m * Rc * Rc;
	const double heightAboveRest = comOffset.y() + Rc;
	double releaseEnergy = m * kGravity_m_s2 * Rc * (1.0 - std::cos(p.release_angle_rad));
	if (p.initial_energy_j > 0)
	{
		releaseEnergy = p.initial_energy_j;
	}
	else if (p.impact_speed_m_s > 0)
	{
		const double omegaAtStart = p.impact_speed_m_s / armDrop;  // kStartGap_m before the impact
		releaseEnergy = 0.5 * inertiaAboutPivot * omegaAtStart * omegaAtStart + m * kGravity_m_s2 * heightAboveRest;
	}
	const double kinetic = releaseEnergy - m * kGravity_m_s2 * heightAboveRest;
	if (!(kinetic > 0))
	{
		throw std::invalid_argument("release-angle / initial-energy: the hammer does not reach the specimen (energy " +
									std::to_string(releaseEnergy) + " J, needs more than " +
									std::to_string(m * kGravity_m_s2 * heightAboveRest) + " J)");
	}
	const double omega = std::sqrt(2.0 * kinetic / inertiaAboutPivot);
	// swing towards -X: negative rotation about +Z
	const btVector3 angularVelocity(0, 0, btScalar(-omega));
	m_hammer->setAngularVelocity(angularVelocity);
	m_hammer->setLinearVelocity(angularVelocity.cross(comOffset));
	m_impactSpeed_m_s = omega * armDrop;
}

int CharpyScene::solverFallbacks() const { return m_impl->solver.fallbacks(); }

double CharpyScene::speculativeReach_m() const
{
	double reach = 1e300;
	for (const btRigidBody* part : m_parts)
	{
		reach = std::min(reach, double(part->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold)));
	}
	return reach;
}

std::string CharpyScene::speculativeReachWarning() const
{
	const CharpyParameters& p = m_parameters;
	if (!p.speculative_contacts)
	{
		return "";
	}
	const double step = p.contact_substep_s > 0 ? p.contact_substep_s : p.dt_s;
	const double reach = speculativeReach_m();
	const double closing = m_impactSpeed_m_s * step;
	std::string warning;
	char text[320];
	if (p.world_contact_travel_m > reach)
	{
		std::snprintf(text, sizeof text,
					  "the world's steps may let a pair move the %.3f mm world contact travel, more than the %.3f mm the "
					  "speculative contacts reach; use --world-contact-travel of at most %.3g",
					  1e3 * p.world_contact_travel_m, 1e3 * reach, reach);
		warning = text;
	}
	else if (closing > reach && p.world_contact_travel_m == 0)
	{
		std::snprintf(text, sizeof text,
					  "the hammer closes %.3f mm in a %.4g us internal step at %.2f m/s, more than the %.3f mm the speculative "
					  "contacts reach: parts can sink in and be thrown out; use --contact-substep of at most %.3g",
					  1e3 * closing, 1e6 * step, m_impactSpeed_m_s, 1e3 * reach, reach / m_impactSpeed_m_s);
		warning = text;
	}
	if (p.contact_travel_m > reach)
	{
		// a step the travel lengthens lets its pairs move that far: past the reach, a contact can be missed within it
		std::snprintf(text, sizeof text,
					  "a step in contact may let its pairs move the %.3f mm contact travel, more than the %.3f mm the "
					  "speculative contacts reach; use --contact-travel of at most %.3g",
					  1e3 * p.contact_travel_m, 1e3 * reach, reach);
		warning += (warning.empty() ? "" : "; ") + std::string(text);
	}
	return warning;
}

double CharpyScene::fastestSpin_rad_s() const
{
	double fastest = 0;
	for (const btRigidBody* part : m_parts)
	{
		fastest = std::max(fastest, double(part->getAngularVelocity().length()));
	}
	return fastest;
}

bool CharpyScene::nearContact(double horizon_s) const
{
	SpecimenLengthScale scale(m_parameters.specimen_width_m);
	if (!m_parameters.speculative_contacts)
	{
		return plastic::mayTouchWithin(m_contactMovers, m_contactOthers, horizon_s, nearClearance_m(m_parameters));
	}
	// After the fold the halves slide along the anvils' walls 30-80 um away, or ride on the hammer's nose, for 5-10
	// ms: left to the speculative contacts, these steps are no longer substeps. The substep holds while a part is
	// pressed against an anvil through a contact with friction (whose loss a longer step would change) or at rest,
	// while the hammer comes at the specimen (its gap is past the reach), and while a joint flows or holds elastic
	// energy (a longer step would change what it books: an elastic-plastic joint still ringing booked 5.3 J of flow in
	// one 86 us step); both are known after each step (m_holdSubstep). A part pressed against an anvil without friction
	// and sliding on it, its joint not flowing, is left to the speculative contacts as any other pair: after the fold a
	// frictionless specimen rides over the anvils pressed on them, and held at the substep there it took up to 26
	// substeps more (standard striker, 1 ms frames, 70 us substeps: 103-126 internal steps, 72-110 without them).
	return m_holdSubstep ||
		   plastic::mayTouchWithin(m_contactMovers, m_contactOthers, horizon_s, nearClearance_m(m_parameters), speculativeReach_m());
}

double CharpyScene::contactSpeed_m_s(double horizon_s) const
{
	if (m_jointFlowed)
	{
		// a joint that flowed in the last step keeps the substep whatever the contacts' speed: the contact forces that
		// bend it are not in the speed bound (a 0.73 ms step at 0.40 m/s during a slow fold met 0.97 m/s and sank the
		// half 0.2 mm into an ISO anvil, against 3 um in substeps), and the fold moved with the frame step (ISO
		// anvils, 3.5 m/s: 143.62-144.13 J against 143.30 J at every frame step in substeps)
		return std::numeric_limits<double>::infinity();
	}
	SpecimenLengthScale scale(m_parameters.specimen_width_m);
	return plastic::contactSpeed_m_s(*m_world->getDispatcher(), m_contactMovers, m_contactOthers, horizon_s,
									 nearClearance_m(m_parameters), m_parameters.speculative_contacts ? speculativeReach_m() : 0);
}

double CharpyScene::timeToTouch_s(double horizon_s) const
{
	// a pair within 1 % of the speculative reach touches
	SpecimenLengthScale scale(m_parameters.specimen_width_m);
	return plastic::timeToTouch_s(m_contactMovers, m_contactOthers, horizon_s, 0.01 * speculativeReach_m());
}

void CharpyScene::step()
{
	const CharpyParameters& p = m_parameters;
	double frame = p.dt_s;
	if (p.auto_dt)
	{
		// the longest of the coarse frame and its halves that reaches no contact: after the fold the halves ride on
		// the hammer's nose for 5-10 ms, near it within a coarse frame but not within a millisecond
		double coarse = p.auto_dt_coarse_s;
		while (coarse > frame && nearContact(coarse))
		{
			coarse /= 2;
		}
		if (coarse > frame)
		{
			// a coarse frame the scene chose itself ends at the duration, not past it (a frame of dt_s may, as every
			// frame of a fixed frame step does)
			frame = std::max(frame, std::min(coarse, p.duration_s - m_time_s - m_substeps.owed_s()));
		}
	}
	// with speculative contacts the striker's first step on the specimen, and a part's on an anvil or the hammer, starts
	// touching (plastic::timeToTouch_s): met within a step, the contact carries the section's collapse load across the gap
	plastic::ContactSubstepPolicy::TimeToTouch timeToTouch;
	if (p.speculative_contacts)
	{
		timeToTouch = [this](double horizon_s) { return this->timeToTouch_s(horizon_s); };
	}
	// and a step within which a part runs off an anvil ends there (plastic::timeToRelease_s): held to the step's end,
	// the fold went on past the pass angle (thesis, 60 us: 2.037 rad against 1.991, 5.8 J beyond the converged loss)
	plastic::ContactSubstepPolicy::TimeToRelease timeToRelease;
	if (p.speculative_contacts)
	{
		timeToRelease = [this](double horizon_s)
		{ return plastic::timeToRelease_s(*m_world->getDispatcher(), m_contactMovers, m_contactAnvils, horizon_s); };
	}
	// a run that ends once the specimen is clear ends at the internal step that leaves it so, not at the frame's end:
	// the frame step moves the end only as far as the clear test's horizon does (at most 1 ms). The rest of that frame
	// is owed; the frames after it (the browser steps on to the duration) step as any other
	plastic::ContactSubstepPolicy::Done ended;
	if (p.end_when_clear && !m_endedClear)
	{
		ended = [this] { return m_endedClear; };  // asked after every internal step (finishStep)
	}
	// the frame that reaches the duration is stepped whole, not gathered with frames past it
	const bool gather = m_time_s + m_substeps.owed_s() + frame < p.duration_s - 1e-12;
	// and with a contact travel, a slow contact (a hammer stalled in the specimen, the specimen at rest before the
	// hammer is near) is stepped as far as its pairs' speed allows (plastic::contactSpeed_m_s)
	plastic::ContactSubstepPolicy::ContactSpeed contactSpeed;
	if (p.contact_travel_m > 0)
	{
		contactSpeed = [this](double horizon_s) { return this->contactSpeed_m_s(horizon_s); };
	}
	m_substeps.advance(
		frame, [this](double horizon_s) { return nearContact(horizon_s); }, [this](double h_s) { internalStep(h_s); },
		[this] { return fastestSpin_rad_s(); }, timeToTouch, timeToRelease, ended, gather, contactSpeed);
	m_lastFrameStep_s = frame;
}

void CharpyScene::internalStep(double h_s)
{
	// with the world's contact stepping its tick callbacks (createWorld) set up and track each of its own steps
	const bool worldSteps = m_parameters.world_contact_travel_m > 0;
	if (!worldSteps)
	{
		prepareStep(h_s);
	}
	{
		SpecimenLengthScale scale(m_parameters.specimen_width_m);
		if (worldSteps && m_parameters.world_step_s > 0)
		{
			// upstream's fixed-step stepping: the frame and what the world owes of earlier ones in whole steps
			const int maxSteps = int(std::ceil(h_s / m_parameters.world_step_s)) + 1;
			m_world->stepSimulation(btScalar(h_s), maxSteps, btScalar(m_parameters.world_step_s));
		}
		else
		{
			m_world->stepSimulation(btScalar(h_s), 0);
		}
	}
	if (!worldSteps)
	{
		finishStep(h_s);
	}
	m_time_s += h_s;
	if (m_parameters.speculative_contacts)
	{
		// what nearContact holds the substep for, from this step: a joint flowed (the hinge motor's at its cap, as
		// trackAfterStep books it) or holds elastic energy, or a part was pressed against an anvil through a contact
		// with friction or at rest
		double elastic = 0;
		for (const plastic::Joint& joint : m_impl->joints)
		{
			elastic += joint.elasticEnergy_j();
		}
		const double rotation = plasticRotation_rad();
		m_jointFlowed = rotation != m_jointRotation_rad;
		// a frictionless contact whose part slides on it by more than 1 % of the speculative reach in a substep (what
		// counts as touching, timeToTouch_s) no longer holds it; one at rest (the specimen lying on its supports) does
		const double substep_s = m_parameters.contact_substep_s;
		const double slide_m_s = substep_s > 0 ? 0.01 * speculativeReach_m() / substep_s : std::numeric_limits<double>::infinity();
		m_holdSubstep = m_jointFlowed || elastic > 0 ||
						plastic::pressedContact(*m_world->getDispatcher(), m_contactMovers, m_contactAnvils, slide_m_s);
		m_jointRotation_rad = rotation;
	}
}

void CharpyScene::prepareStep(double step_s)
{
	// the upstream methods' caps are impulses: they follow the internal step
	for (size_t i = 0; i < m_impl->joints.size(); i++)
	{
		plastic::updateJointForStep(*m_impl->joints[i].constraint, m_impl->specs[i], step_s);
	}
}

void CharpyScene::finishStep(double step_s)
{
	m_internalSteps++;
	m_steppedTime_s += step_s;
	trackAfterStep(step_s);
	// the test ends at the internal step that leaves the specimen clear: the runner's substeps stop there (step()),
	// the world's own steps run on to the frame's end
	if (m_parameters.end_when_clear && !m_endedClear && clear())
	{
		recordEnd();
	}
}

void CharpyScene::recordEnd()
{
	m_endedClear = true;
	m_endState = currentState();
	// the world's state is at its own steps' time, which can lag the frames' (world_step_s); with the runner's substeps
	// it is the frames' own (m_time_s, the same sum of the same steps, is advanced after this step)
	m_endState.time_s = m_steppedTime_s;
}

CharpyEndState CharpyScene::endState() const { return m_endedClear ? m_endState : currentState(); }

CharpyEndState CharpyScene::currentState() const
{
	CharpyEndState state;
	state.time_s = m_time_s;
	state.internal_steps = m_internalSteps;
	state.energies = energies();
	state.plastic_work_j = plasticWork_j();
	state.plastic_rotation_rad = plasticRotation_rad();
	state.bend_angle_rad = bendAngle_rad();
	state.end_bend_angle_rad = endToEndBend_rad();
	state.hammer_angle_rad = hammerAngle_rad();
	state.kinetic_against_hammer_j = kineticAgainstHammer_j();
	state.broken = broken();
	return state;
}

void CharpyScene::beforeWorldStep(btDynamicsWorld* world, btScalar step_s)
{
	static_cast<CharpyScene*>(world->getWorldUserInfo())->prepareStep(double(step_s));
}

void CharpyScene::afterWorldStep(btDynamicsWorld* world, btScalar step_s)
{
	static_cast<CharpyScene*>(world->getWorldUserInfo())->finishStep(double(step_s));
}

void CharpyScene::trackAfterStep(double h_s)
{
	if (m_parameters.method == CharpyMethod::HingeMotor && m_middleJoint && m_middleJoint->isEnabled())
	{
		// the motor row is the hinge's last row: its impulse is getAppliedImpulse()
		double bend = bendAngle_rad();
		double rotation = std::fabs(bend - m_previousBend_rad);
		double cap = m_section.plastic_moment_nm * h_s;
		if (std::fabs(m_middleJoint->getAppliedImpulse()) >= cap * (1.0 - 1e-3))
		{
			m_motorWork_j += m_section.plastic_moment_nm * rotation;
			m_motorRotation_rad += rotation;
		}
		m_previousBend_rad = bend;
	}
	const double gain = energies().total_j - m_initialEnergy_j;
	m_maxEnergyGain_j = std::max(m_maxEnergyGain_j, gain);
	m_maxBookedExcess_j = std::max(m_maxBookedExcess_j, gain + plasticWork_j());
	for (int i = 0; i < m_impl->bodies.size(); i++)
	{
		const btRigidBody* body = m_impl->bodies[i];
		if (body->getInvMass() == 0) continue;
		m_maxSpeed_m_s = std::max(m_maxSpeed_m_s, double(body->getLinearVelocity().length()));
		m_maxDistance_m = std::max(m_maxDistance_m, double(body->getCenterOfMassPosition().length()));
	}

	// through the gap or over the top: where each part is when it gets behind the anvils' front plane
	for (size_t i = 0; i < m_parts.size(); i++)
	{
		btVector3 lo, hi;
		m_parts[i]->getAabb(lo, hi);
		if (!m_partPassed[i] && hi.x() < 0)
		{
			m_partPassed[i] = true;
			m_overTheTop = m_overTheTop || lo.y() > m_anvilTop_m;
		}
	}

	btDispatcher* dispatcher = m_world->getDispatcher();
	for (int i = 0; i < dispatcher->getNumManifolds(); i++)
	{
		btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(i);
		for (int j = 0; j < manifold->getNumContacts(); j++)
		{
			m_maxPenetration_m = std::max(m_maxPenetration_m, -double(manifold->getContactPoint(j).getDistance()));
		}
	}
}

CharpyEnergies CharpyScene::energies() const
{
	CharpyEnergies e;
	for (int i = 0; i < m_impl->bodies.size(); i++)
	{
		const btRigidBody* body = m_impl->bodies[i];
		if (body->getInvMass() == 0)
		{
			continue;
		}
		const double m = 1.0 / body->getInvMass();
		e.potential_j += m * kGravity_m_s2 * body->getCenterOfMassPosition().y();
		const btVector3& v = body->getLinearVelocity();
		const btVector3& w = body->getAngularVelocity();
		btVector3 localW = body->getWorldTransform().getBasis().transpose() * w;
		btVector3 inertia = body->getLocalInertia();
		e.kinetic_j += 0.5 * m * v.length2() + 0.5 * (inertia.x() * localW.x() * localW.x() + inertia.y() * localW.y() * localW.y() + inertia.z() * localW.z() * localW.z());
	}
	for (const plastic::Joint& joint : m_impl->joints)
	{
		e.elastic_j += joint.elasticEnergy_j();
	}
	e.total_j = e.potential_j + e.kinetic_j + e.elastic_j;
	return e;
}

double CharpyScene::plasticWork_j() const
{
	double work = 0;
	for (const plastic::Joint& joint : m_impl->joints)
	{
		work += joint.plasticWork_j();
	}
	return m_parameters.method == CharpyMethod::HingeMotor ? m_motorWork_j : work;
}

double CharpyScene::plasticRotation_rad() const
{
	double rotation = 0;
	for (const plastic::Joint& joint : m_impl->joints)
	{
		rotation += joint.plasticRotation_rad();
	}
	return m_parameters.method == CharpyMethod::HingeMotor ? m_motorRotation_rad : rotation;
}

double CharpyScene::bendAngle_rad() const
{
	if (m_parts.size() < 2)
	{
		return 0;
	}
	const size_t mid = m_parts.size() / 2;
	btQuaternion worldRelative = m_parts[mid]->getOrientation() * m_parts[mid - 1]->getOrientation().inverse();
	double angle = worldRelative.getAngleShortestPath();
	btVector3 axis = worldRelative.getAxis();
	return axis.y() < 0 ? -angle : angle;
}

double CharpyScene::endToEndBend_rad() const
{
	if (m_parts.size() < 2)
	{
		return 0;
	}
	btQuaternion relative = m_parts.back()->getOrientation() * m_parts.front()->getOrientation().inverse();
	return relative.getAngleShortestPath();
}

double CharpyScene::hammerAngle_rad() const
{
	if (!m_hammer)
	{
		return 0;
	}
	btQuaternion q = m_hammer->getOrientation();
	double angle = q.getAngleShortestPath();
	return q.getAxis().z() < 0 ? -angle : angle;
}

bool CharpyScene::broken() const
{
	for (btTypedConstraint* joint : m_joints)
	{
		if (!joint->isEnabled())
		{
			return true;
		}
	}
	return false;
}

bool CharpyScene::passedAnvils() const
{
	for (const btRigidBody* part : m_parts)
	{
		btVector3 lo, hi;
		part->getAabb(lo, hi);
		if (hi.x() > 0)
		{
			return false;
		}
	}
	return true;
}

bool CharpyScene::clear() const
{
	SpecimenLengthScale scale(m_parameters.specimen_width_m);
	// within a frame step, and no longer than 1 ms: the test is asked after every internal step (step()), and ends
	// there, so a 1/60 s frame step no longer holds it on to the frame's end and to a second frame, whose horizon its
	// spinning halves could reach (a 1 ms horizon was within 0.01 % of full-duration runs, CharpyTargetsTest)
	const double horizon_s = std::min(m_parameters.dt_s, kClearHorizon_s);
	return passedAnvils() && !plastic::mayTouchWithin(m_contactMovers, m_contactAnvils, horizon_s, nearClearance_m(m_parameters));
}

double CharpyScene::kineticAgainstHammer_j() const
{
	if (!m_hammer)
	{
		return 0;
	}
	double kinetic = 0;
	for (const btRigidBody* part : m_parts)
	{
		const double speed = plastic::relativeSpeedBound_m_s(part, m_hammer);
		kinetic += 0.5 * speed * speed / double(part->getInvMass());
	}
	return kinetic;
}

bool CharpyScene::finite() const
{
	for (int i = 0; i < m_impl->bodies.size(); i++)
	{
		const btRigidBody* body = m_impl->bodies[i];
		const btVector3& x = body->getCenterOfMassPosition();
		const btVector3& v = body->getLinearVelocity();
		const btVector3& w = body->getAngularVelocity();
		for (int k = 0; k < 3; k++)
		{
			if (!std::isfinite(double(x[k])) || !std::isfinite(double(v[k])) || !std::isfinite(double(w[k])))
			{
				return false;
			}
		}
	}
	return true;
}

bool CharpyScene::done() const { return !(m_time_s < m_parameters.duration_s - 1e-12) || !finite(); }

std::vector<scene::JointView> CharpyScene::joints() const
{
	std::vector<scene::JointView> views;
	for (size_t i = 0; i < m_impl->joints.size(); i++)
	{
		const plastic::Joint& joint = m_impl->joints[i];
		scene::JointView v;
		v.body_a = m_parts[i];
		v.body_b = m_parts[i + 1];
		v.pivot_m = m_parts[i]->getWorldTransform() * m_impl->pivotsInA[i];
		const bool motor = m_parameters.method == CharpyMethod::HingeMotor && joint.constraint.get() == m_middleJoint;
		v.plastic_rotation_rad = motor ? m_motorRotation_rad : joint.plasticRotation_rad();
		v.plastic_work_j = motor ? m_motorWork_j : joint.plasticWork_j();
		v.yielded = v.plastic_rotation_rad > scene::kYieldedRotation_rad;
		v.broken = !joint.constraint->isEnabled();
		views.push_back(v);
	}
	return views;
}

scene::SceneLedger CharpyScene::ledger() const
{
	const CharpyEnergies e = energies();
	scene::SceneLedger l;
	l.title = "charpy, " + std::string(charpyMethodName(m_parameters.method));
	l.time_s = m_time_s;
	// the hammer's energy at the start less the potential energy of every body now: what gravity and the swing gave
	l.load_work_j = m_initialEnergy_j - e.potential_j;
	l.kinetic_j = e.kinetic_j;
	l.plastic_booked_j = plasticWork_j();
	l.plastic_measured_j = m_section.plastic_moment_nm * std::fabs(bendAngle_rad());
	char line[160];
	std::snprintf(line, sizeof line, "analytic loss Mp x theta pass %.1f J", m_section.analytic_loss_j);
	l.answer.push_back(line);
	std::snprintf(line, sizeof line, "E0 %.1f J, loss %.1f J", m_initialEnergy_j, m_initialEnergy_j - e.total_j);
	l.status.push_back(line);
	std::snprintf(line, sizeof line, "bend %.3f rad, plastic %.3f rad", bendAngle_rad(), plasticRotation_rad());
	l.status.push_back(line);
	if (broken()) l.status.push_back("broken");
	if (passedAnvils()) l.status.push_back("passed the anvils");
	return l;
}

scene::WorldBox CharpyScene::viewEnvelope() const
{
	// The specimen (its back on the anvils' front plane x = 0, along z) and the anvils beside it; it bends away from
	// the hammer (-x) until its halves slip past the anvils' edges, about half its length behind them.
	const CharpyParameters& p = m_parameters;
	const double b = p.specimen_width_m;
	const double halfSpan = std::max(p.specimen_length_m, p.anvil_gap_m + 2 * p.anvil_width_m) / 2;
	scene::WorldBox box;
	box.min_m = btVector3(btScalar(-p.specimen_length_m / 2 - b), btScalar(p.specimen_bottom_y_m - b), btScalar(-halfSpan));
	box.max_m = btVector3(btScalar(2 * b), btScalar(p.specimen_bottom_y_m + 2 * b), btScalar(halfSpan));
	return box;
}
