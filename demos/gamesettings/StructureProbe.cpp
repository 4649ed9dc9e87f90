#include "StructureProbe.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "plastic/BeamBuilder.h"
#include "BulletDynamics/Featherstone/btMultiBody.h"
#include "BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h"
#include "BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h"
#include "BulletDynamics/Featherstone/btMultiBodyJointMotor.h"
#include "BulletDynamics/Featherstone/btMultiBodyLinkCollider.h"
#include "plastic/EnergyLedger.h"
#include "scene/Errors.h"

namespace plastic
{
namespace
{
constexpr double kMemberLength_m = 2.0;

SectionProperties beamSection() { return rectangle(0.05, 0.10); }
SectionProperties columnSection() { return rectangle(0.05, 0.14); }

// a member of the structure, from the support outwards
struct MemberPlan
{
	btVector3 start_m, end_m;
	SectionProperties section;
	int segments;
};

std::vector<MemberPlan> plan(const ProbeCase& c)
{
	if (c.segments < 1 || c.segments > 64) throw std::invalid_argument("segments: " + std::to_string(c.segments) + " is not in [1, 64]");
	if (c.structure == Structure::Cantilever) return {{btVector3(0, 0, 0), btVector3(btScalar(kMemberLength_m), 0, 0), beamSection(), c.segments}};
	return {{btVector3(0, 0, 0), btVector3(0, btScalar(kMemberLength_m), 0), columnSection(), c.segments},
			{btVector3(0, btScalar(kMemberLength_m), 0), btVector3(btScalar(kMemberLength_m), btScalar(kMemberLength_m), 0), beamSection(), c.segments}};
}

// index of the joint (from the support) plastic analysis puts the hinge in
int hingeJoint(const ProbeCase& c) { return c.structure == Structure::Cantilever ? 0 : c.segments; }

double wrap(double a)
{
	while (a > M_PI) a -= 2 * M_PI;
	while (a < -M_PI) a += 2 * M_PI;
	return a;
}

// the angle of a segment's member axis (its local z) in the x-y plane
double memberAngle(const btRigidBody& b)
{
	const btVector3 axis = b.getWorldTransform().getBasis().getColumn(2);
	return std::atan2(double(axis.y()), double(axis.x()));
}

void fillRotations(ProbeRun& run, const std::vector<double>& rotations, int hinge)
{
	run.hinge_rotation_rad = std::fabs(rotations[size_t(hinge)]);
	run.max_other_rotation_rad = 0;
	for (size_t i = 0; i < rotations.size(); i++)
		if (int(i) != hinge) run.max_other_rotation_rad = std::max(run.max_other_rotation_rad, std::fabs(rotations[i]));
	run.max_rotation_rad = std::max(run.hinge_rotation_rad, run.max_other_rotation_rad);
	if (!std::isfinite(run.hinge_rotation_rad) || !std::isfinite(run.max_other_rotation_rad)) run.finite = false;
}

ProbeRun runRigid(const ProbeCase& c, JointMethod method, const ProbeSetting& setting, double loadFactor, double seconds)
{
	StructureWorld structure(setting.world);
	btDiscreteDynamicsWorld& world = structure.world();
	btBoxShape supportShape(btVector3(0.1, 0.1, 0.1));
	btRigidBody support(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &supportShape));
	const std::vector<MemberPlan> members = plan(c);
	const btVector3 out = (members[0].end_m - members[0].start_m).normalized();
	support.setWorldTransform(btTransform(btQuaternion::getIdentity(), members[0].start_m - out * 0.1));
	world.addRigidBody(&support, 0, 0);

	std::vector<std::unique_ptr<Beam>> beams;
	std::vector<btRigidBody*> chain;
	btRigidBody* previous = &support;
	for (const MemberPlan& m : members)
	{
		BeamSpec spec;
		spec.may_sleep = false;  // its loads change on resting bodies
		spec.start_m = m.start_m;
		spec.end_m = m.end_m;
		spec.segments = m.segments;
		spec.joint.section = m.section;
		spec.joint.material = steel();
		spec.bending_axis = btVector3(0, 0, 1);
		spec.joint.method = method;
		spec.joint.solver = setting.joint;
		beams.push_back(std::make_unique<Beam>(world, scene::requireValid(spec), previous));
		for (const Joint& j : beams.back()->joints()) j.constraint->setWarmStartingFactor(btScalar(setting.warm_starting_factor));
		for (btRigidBody* b : beams.back()->segments()) chain.push_back(b);
		previous = chain.back();
	}
	const double P = loadFactor * collapseLoad_n(c);
	btRigidBody* tip = chain.back();
	PointLoad load(*tip, btVector3(0, 0, btScalar(beams.back()->segmentLength_m() / 2)), btVector3(0, btScalar(-P), 0));
	EnergyLedger ledger(world.getGravity());
	for (btRigidBody* b : chain) ledger.addBody(*b);
	for (const auto& beam : beams)
		for (const Joint& j : beam->joints()) ledger.addJoint(j);
	ledger.addLoad(load);

	// the joint angles at rest: body i's member angle minus its predecessor's (the support's is the first body's)
	std::vector<double> rest(chain.size());
	for (size_t i = 0; i < chain.size(); i++) rest[i] = memberAngle(*chain[i]) - (i == 0 ? memberAngle(*chain[0]) : memberAngle(*chain[i - 1]));
	const double support0 = memberAngle(*chain[0]);
	auto rotations = [&]() {
		std::vector<double> r(chain.size());
		for (size_t i = 0; i < chain.size(); i++)
			r[i] = wrap(memberAngle(*chain[i]) - (i == 0 ? support0 : memberAngle(*chain[i - 1])) - rest[i]);
		return r;
	};

	ProbeRun run;
	const double step_s = setting.world.internal_step_s;
	const int steps = int(std::lround(seconds / step_s));
	const int stepsPerSecond = int(std::lround(1.0 / step_s));
	double wall_s = 0;
	for (int i = 0; i < steps; i++)
	{
		load.apply();
		for (const auto& beam : beams) beam->updateForStep(step_s);
		const auto t0 = std::chrono::steady_clock::now();
		world.stepSimulation(btScalar(step_s), 0);
		wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		load.afterStep();
		run.internal_steps++;
		if (i + 1 == stepsPerSecond)
		{
			ProbeRun oneSecond;
			fillRotations(oneSecond, rotations(), hingeJoint(c));
			run.max_rotation_after_1s_rad = oneSecond.max_rotation_rad;
		}
		if (!std::isfinite(double(tip->getCenterOfMassPosition().x()))) break;
	}
	fillRotations(run, rotations(), hingeJoint(c));
	const Energies e = ledger.measure();
	run.load_work_j = e.load_work_j;
	run.kinetic_j = e.kinetic_j;
	run.plastic_j = e.plastic_j;
	run.elastic_j = e.elastic_j;
	run.books = method != JointMethod::HingeMotor;
	run.wall_s_per_step = run.internal_steps > 0 ? wall_s / run.internal_steps : 0;
	run.solver_fallbacks = structure.solverFallbacks();
	world.removeRigidBody(&support);
	// last built first: a later beam's first joint holds a body of the one before it
	while (!beams.empty()) beams.pop_back();
	return run;
}

// Reduced coordinates: one btMultiBody, a fixed base at the support, a revolute link per segment about world z,
// each joint driven by a btMultiBodyJointMotor at velocity 0 whose impulse is capped at Mp * dt.
ProbeRun runMultiBody(const ProbeCase& c, const ProbeSetting& setting, double loadFactor, double seconds)
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btDbvtBroadphase broadphase;
	btMultiBodyConstraintSolver solver;
	btMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
	world.setGravity(btVector3(0, 0, 0));
	configureWorld(world, setting.world);
	const std::vector<MemberPlan> members = plan(c);
	struct Link
	{
		btVector3 pivot, com, end, inertia, half;
		double mass, mp;
	};
	std::vector<Link> links;
	for (const MemberPlan& m : members)
	{
		const btVector3 axis = (m.end_m - m.start_m).normalized();
		const double L = (m.end_m - m.start_m).length() / m.segments;
		const double mass = steel().density_kg_m3 * m.section.area_m2 * L;
		// the box in world axes: the member along axis, depth across it in the plane, width along z
		const btVector3 half = axis.absolute() * btScalar(L / 2) + btVector3(0, 0, 1).cross(axis).absolute() * btScalar(m.section.depth_m / 2) +
							   btVector3(0, 0, btScalar(m.section.width_m / 2));
		btVector3 inertia;
		btBoxShape(half).calculateLocalInertia(btScalar(mass), inertia);
		const double mp = capacities(m.section, steel()).plastic_moment_y_nm;
		for (int i = 0; i < m.segments; i++)
		{
			const btVector3 pivot = m.start_m + axis * btScalar(i * L);
			links.push_back({pivot, pivot + axis * btScalar(L / 2), pivot + axis * btScalar(L), inertia, half, mass, mp});
		}
	}
	const int n = int(links.size());
	auto mb = std::make_unique<btMultiBody>(n, 0, btVector3(0, 0, 0), true, false);
	mb->setBaseWorldTransform(btTransform(btQuaternion::getIdentity(), links[0].pivot));
	for (int i = 0; i < n; i++)
	{
		const btVector3 parentCom = i == 0 ? links[0].pivot : links[size_t(i - 1)].com;
		mb->setupRevolute(i, btScalar(links[size_t(i)].mass), links[size_t(i)].inertia, i - 1, btQuaternion::getIdentity(), btVector3(0, 0, 1),
						  links[size_t(i)].pivot - parentCom, links[size_t(i)].com - links[size_t(i)].pivot, true);
	}
	mb->finalizeMultiDof();
	mb->setLinearDamping(0);
	mb->setAngularDamping(0);
	mb->setCanSleep(false);
	world.addMultiBody(mb.get());
	// a collider per link (colliding with nothing): the solver finds a motor's island through its link's collider
	std::vector<std::unique_ptr<btBoxShape>> shapes;
	std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
	for (int i = 0; i < n; i++)
	{
		shapes.push_back(std::make_unique<btBoxShape>(links[size_t(i)].half));
		colliders.push_back(std::make_unique<btMultiBodyLinkCollider>(mb.get(), i));
		colliders.back()->setCollisionShape(shapes.back().get());
		colliders.back()->setWorldTransform(btTransform(btQuaternion::getIdentity(), links[size_t(i)].com));
		world.addCollisionObject(colliders.back().get(), 0, 0);
		mb->getLink(i).m_collider = colliders.back().get();
	}
	const double step_s = setting.world.internal_step_s;
	std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors;
	for (int i = 0; i < n; i++)
	{
		motors.push_back(std::make_unique<btMultiBodyJointMotor>(mb.get(), i, btScalar(0), btScalar(links[size_t(i)].mp * step_s)));
		world.addMultiBodyConstraint(motors.back().get());
	}
	const double P = loadFactor * collapseLoad_n(c);
	const btVector3 force(0, btScalar(-P), 0);
	const btVector3 tipLocal = links.back().end - links.back().com;  // the link frame is world-aligned at rest
	ProbeRun run;
	const int steps = int(std::lround(seconds / step_s));
	const int stepsPerSecond = int(std::lround(1.0 / step_s));
	double wall_s = 0;
	for (int i = 0; i < steps; i++)
	{
		const btVector3 tip = mb->localPosToWorld(n - 1, tipLocal);
		const btVector3 com = mb->localPosToWorld(n - 1, btVector3(0, 0, 0));
		mb->addLinkForce(n - 1, force);
		mb->addLinkTorque(n - 1, (tip - com).cross(force));
		const auto t0 = std::chrono::steady_clock::now();
		world.stepSimulation(btScalar(step_s), 0);
		wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		mb->clearForcesAndTorques();
		run.load_work_j += double(force.dot(mb->localPosToWorld(n - 1, tipLocal) - tip));
		run.internal_steps++;
		if (i + 1 == stepsPerSecond)
			for (int j = 0; j < n; j++) run.max_rotation_after_1s_rad = std::max(run.max_rotation_after_1s_rad, std::fabs(double(mb->getJointPos(j))));
	}
	std::vector<double> r(static_cast<size_t>(n));
	for (int i = 0; i < n; i++) r[size_t(i)] = double(mb->getJointPos(i));
	fillRotations(run, r, hingeJoint(c));
	run.books = false;
	run.wall_s_per_step = run.internal_steps > 0 ? wall_s / run.internal_steps : 0;
	for (auto& m : motors) world.removeMultiBodyConstraint(m.get());
	for (auto& col : colliders) world.removeCollisionObject(col.get());
	world.removeMultiBody(mb.get());
	return run;
}
}  // namespace

std::string ProbeCase::name() const
{
	return (structure == Structure::Cantilever ? "cantilever " : "L-frame ") + std::to_string(segments) + (structure == Structure::Cantilever ? " seg" : "+" + std::to_string(segments) + " seg");
}

double restRotation_rad(double loadFactor)
{
	if (!(loadFactor > 1)) return 0;
	double lo = 1e-9, hi = M_PI;  // f(t) = factor sin t - t: positive just above 0, negative at pi
	for (int i = 0; i < 200; i++)
	{
		const double mid = 0.5 * (lo + hi);
		(loadFactor * std::sin(mid) - mid > 0 ? lo : hi) = mid;
	}
	return 0.5 * (lo + hi);
}

double collapseLoad_n(const ProbeCase& /*c*/)
{
	// both: the beam's Mp over its 2 m lever (the L-frame's column, Mp 1.96x, carries the same moment and stays)
	return capacities(beamSection(), steel()).plastic_moment_y_nm / kMemberLength_m;
}

ProbeRun runProbe(const ProbeCase& c, JointMethod method, const ProbeSetting& setting, double loadFactor, double seconds)
{
	// the settings are validated where the world is configured (StructureWorld, configureWorld)
	return setting.multibody ? runMultiBody(c, setting, loadFactor, seconds) : runRigid(c, method, setting, loadFactor, seconds);
}

double collapseFactor(const ProbeCase& c, JointMethod method, const ProbeSetting& setting, double lo, double hi, double tolerance, double threshold_rad)
{
	auto moves = [&](double f) {
		const ProbeRun r = runProbe(c, method, setting, f, 1.0);
		return !r.finite || r.max_rotation_rad > threshold_rad;
	};
	if (moves(lo)) return lo;
	if (!moves(hi)) return hi;
	while (hi - lo > tolerance)
	{
		const double mid = 0.5 * (lo + hi);
		(moves(mid) ? hi : lo) = mid;
	}
	return 0.5 * (lo + hi);
}
}  // namespace plastic
