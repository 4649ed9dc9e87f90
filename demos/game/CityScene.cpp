// The city: the buildings (game::SteelFrame on one ground), a wrecking ball for each hit building, stepped one internal
// step at a time so that each step's wall time can be measured, with the just-in-time structures' checks before and
// after each step in jit mode. What is measured besides the costs (the ledger) is measured between the timed steps.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>

#include "City.h"
#include "Pendulum.h"
#include "SteelFrame.h"
#include "plastic/EnergyLedger.h"
#include "plastic/JitStructure.h"
#include "scene/JointSites.h"
#include "scene/Measures.h"
#include "scene/Ranges.h"

namespace game
{
const char* cityModeName(CityMode mode)
{
	switch (mode)
	{
		case CityMode::JustInTime:
			return "jit";
		case CityMode::Jointed:
			return "jointed";
		default:
			return "rigid";
	}
}

bool parseCityMode(const std::string& text, CityMode& mode)
{
	for (CityMode m : {CityMode::JustInTime, CityMode::Jointed, CityMode::Rigid})
		if (text == cityModeName(m))
		{
			mode = m;
			return true;
		}
	return false;
}

std::vector<std::string> validateCityParameters(const CityParameters& p)
{
	std::vector<std::string> e = validateWreckingBallParameters(p.building);
	scene::requireWhole(e, "buildings", p.buildings, 1, 100000);
	scene::requireWhole(e, "hit", p.hit, 0, p.buildings);
	// room for a frame and a ball's swing between two buildings
	const double width_m = p.building.span_m * p.building.bays + p.building.section_depth_m;
	scene::requireRange(e, "spacing", p.spacing_m, width_m + 2 * p.building.ball_radius_m + 0.1, 1000, "m");
	return e;
}

namespace
{
double median(std::vector<double> v)
{
	if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
	std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
	return v[v.size() / 2];
}

int dynamicBodies(const btDiscreteDynamicsWorld& world)
{
	int n = 0;
	const btCollisionObjectArray& objects = world.getCollisionObjectArray();
	for (int i = 0; i < objects.size(); i++)
		if (!objects[i]->isStaticOrKinematicObject()) n++;
	return n;
}
}  // namespace

struct CityScene::State
{
	explicit State(const CityParameters& parameters) : p(parameters), structure(parameters.building.solver) {}
	void internalStep();
	bool ballPushesABuilding() const;

	CityParameters p;
	plastic::StructureWorld structure;
	std::unique_ptr<btBoxShape> groundShape;
	std::unique_ptr<btRigidBody> ground;
	std::vector<std::unique_ptr<SteelFrame>> frames;
	std::vector<std::unique_ptr<plastic::JitStructure>> jit;
	std::unique_ptr<plastic::JitStructureSet> set;
	std::vector<std::unique_ptr<Pendulum>> balls;
	plastic::EnergyLedger swing{btVector3(0, 0, 0)};  // the balls and their chains (their descent is the load's work)
	double initialSwingPotential_j = 0;
	// every building's joints, for the view; the hit buildings' with their bodies' rotations (Mp x rotations)
	std::vector<scene::JointSite> sites;
	std::vector<std::unique_ptr<scene::PlanarAngle>> bodyAngles;
	std::vector<std::pair<const scene::PlanarAngle*, const scene::PlanarAngle*>> hitAngles;  // per hit building's joint
	std::vector<const plastic::Joint*> hitJoints;
	std::vector<double> rotationAtBreak_rad;  // per hit building's joint: its rotation when it broke (NaN: not broken)
	double hitRotation(size_t i) const { return hitAngles[i].second->angle_rad() - hitAngles[i].first->angle_rad(); }
	double plasticMoment_nm = 0;
	double dt = 0;
	int perFrame = 1;
	CityResult r;
	std::vector<double> idle_us, all_us;
};

void CityScene::State::internalStep()
{
	btDiscreteDynamicsWorld& world = structure.world();
	const auto start = std::chrono::steady_clock::now();
	if (p.mode == CityMode::JustInTime) set->subdivideThreatened(dt);
	structure.stepOnce();
	if (p.mode == CityMode::JustInTime) set->mergeAtRest();
	const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
	r.wall_s += us * 1e-6;
	all_us.push_back(us);
	r.internal_steps++;
	r.simulated_s += dt;
	for (auto& a : bodyAngles) a->update();
	for (size_t i = 0; i < hitJoints.size(); i++)
		if (std::isnan(rotationAtBreak_rad[i]) && !hitJoints[i]->constraint->isEnabled()) rotationAtBreak_rad[i] = hitRotation(i);
	if (std::isnan(r.first_impact_s))
	{
		idle_us.push_back(us);
		if (ballPushesABuilding()) r.first_impact_s = r.simulated_s;
	}
	const int bodies = dynamicBodies(world);
	r.bodies_max = std::max(r.bodies_max, bodies);
	r.joints_max = std::max(r.joints_max, world.getNumConstraints());
	if (std::isnan(r.first_impact_s))
	{
		r.idle_bodies_max = std::max(r.idle_bodies_max, bodies);
		r.idle_joints_max = std::max(r.idle_joints_max, world.getNumConstraints());
	}
}

// a contact of a ball with anything but the ground or a chain that pushed in the last step
bool CityScene::State::ballPushesABuilding() const
{
	btDispatcher& d = *const_cast<plastic::StructureWorld&>(structure).world().getDispatcher();
	for (int m = 0; m < d.getNumManifolds(); m++)
	{
		const btPersistentManifold* manifold = d.getManifoldByIndexInternal(m);
		for (const auto& ball : balls)
		{
			const btCollisionObject* other = manifold->getBody0() == &ball->ball() ? manifold->getBody1()
											 : manifold->getBody1() == &ball->ball() ? manifold->getBody0()
																					 : nullptr;
			if (!other || other == ground.get()) continue;
			for (int c = 0; c < manifold->getNumContacts(); c++)
				if (manifold->getContactPoint(c).getAppliedImpulse() > 0) return true;
		}
	}
	return false;
}

CityScene::CityScene(const CityParameters& p)
{
	const std::vector<std::string> errors = validateCityParameters(p);
	if (!errors.empty())
	{
		std::string text = "city parameters:";
		for (const std::string& e : errors) text += " " + e + ";";
		throw std::invalid_argument(text);
	}
	m = std::make_unique<State>(p);
	State& s = *m;
	s.r.first_impact_s = std::numeric_limits<double>::quiet_NaN();
	const WreckingBallParameters& b = p.building;
	btDiscreteDynamicsWorld& world = s.structure.world();
	world.setGravity(btVector3(0, btScalar(-b.gravity_m_s2), 0));
	world.setForceUpdateAllAabbs(false);  // static buildings keep their boxes
	s.swing = plastic::EnergyLedger(world.getGravity());
	const int perRow = int(std::ceil(std::sqrt(double(p.buildings))));
	const btScalar pitch = btScalar(p.spacing_m);
	// the ground: one slab under the grid, its top at y = 0
	const btScalar half = btScalar(perRow) * pitch / 2 + 20;
	s.groundShape = std::make_unique<btBoxShape>(btVector3(half, 0.5, half));
	s.ground = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, s.groundShape.get()));
	s.ground->setWorldTransform(btTransform(btMatrix3x3::getIdentity(), btVector3(half - 20, -0.5, half - 20)));
	world.addRigidBody(s.ground.get());

	SteelFrameSpec frame = steelFrameSpec(b);
	frame.may_sleep = true;  // a city at rest sleeps
	s.set = std::make_unique<plastic::JitStructureSet>(world);
	for (int i = 0; i < p.buildings; i++)
	{
		frame.origin_m = btVector3(btScalar(i % perRow) * pitch, 0, btScalar(i / perRow) * pitch);
		s.frames.push_back(std::make_unique<SteelFrame>(world, frame, *s.ground, b.solver.internal_step_s));
		const SteelFrame& steel = *s.frames.back();
		std::vector<const btRigidBody*> bodies = {nullptr};  // this building's, with their angles last in bodyAngles
		if (i < p.hit) s.bodyAngles.push_back(std::make_unique<scene::PlanarAngle>(nullptr));  // the ground's: 0
		for (const SteelFrameJoint& j : steel.frameJoints())
		{
			s.sites.push_back(scene::jointSite(*j.joint, j.a, *j.b, j.pivot_m));
			if (i >= p.hit) continue;
			for (const btRigidBody* body : {j.a, j.b})
				if (std::find(bodies.begin(), bodies.end(), body) == bodies.end())
				{
					bodies.push_back(body);
					s.bodyAngles.push_back(std::make_unique<scene::PlanarAngle>(body));
				}
			auto angleOf = [&](const btRigidBody* body)
			{ return s.bodyAngles[s.bodyAngles.size() - bodies.size() + size_t(std::find(bodies.begin(), bodies.end(), body) - bodies.begin())].get(); };
			s.hitAngles.push_back({angleOf(j.a), angleOf(j.b)});
			s.hitJoints.push_back(j.joint);
			s.rotationAtBreak_rad.push_back(std::nan(""));
		}
		if (p.mode != CityMode::Jointed)
		{
			s.jit.push_back(std::make_unique<plastic::JitStructure>(world, steel.memberBodies(), steel.jitJoints()));
			s.jit.back()->merge();
			s.set->add(*s.jit.back());
		}
	}
	for (int i = 0; i < p.hit; i++)
	{
		const PendulumSpec ball = pendulumSpec(b, s.frames[size_t(i)]->columns()[0][0]->segments().front()->getCenterOfMassPosition() * btVector3(1, 0, 1));
		s.balls.push_back(std::make_unique<Pendulum>(world, ball));
		s.swing.addBody(s.balls.back()->ball());
		for (const btRigidBody* link : s.balls.back()->links()) s.swing.addBody(*link);
	}
	s.initialSwingPotential_j = s.swing.measure().potential_j;
	const WreckingBallEstimate estimate = wreckingBallEstimate(b);
	s.plasticMoment_nm = estimate.plastic_moment_nm;
	s.r.impact_energy_j = p.hit * estimate.release_energy_j;
	s.dt = b.solver.internal_step_s;
	s.perFrame = std::max(1, int(std::lround(1.0 / (b.frame_rate_hz * s.dt))));
}

CityScene::~CityScene()
{
	if (!m) return;
	m->balls.clear();
	m->jit.clear();
	m->frames.clear();
	m->structure.world().removeRigidBody(m->ground.get());
}

void CityScene::step()
{
	for (int k = 0; k < m->perFrame; k++) m->internalStep();
	m->r.frames++;
}

bool CityScene::done() const { return m->r.frames >= long(std::lround(m->p.building.duration_s * m->p.building.frame_rate_hz)); }

double CityScene::time_s() const { return double(m->r.frames) / m->p.building.frame_rate_hz; }

btDiscreteDynamicsWorld& CityScene::world() { return m->structure.world(); }

const CityParameters& CityScene::parameters() const { return m->p; }

std::vector<scene::JointView> CityScene::joints() const
{
	std::vector<scene::JointView> views;
	views.reserve(m->sites.size());
	for (const scene::JointSite& site : m->sites) views.push_back(scene::jointView(site, 0));
	return views;
}

long CityScene::worldChanges() const
{
	long changes = 0;
	for (const auto& s : m->jit) changes += s->subdivisions() + s->merges();
	return changes;
}

std::vector<const btCollisionObject*> CityScene::wholeStructures() const
{
	std::vector<const btCollisionObject*> whole;
	for (const auto& s : m->jit)
		if (s->wholeBody()) whole.push_back(s->wholeBody());
	return whole;
}

CityResult CityScene::result() const
{
	CityResult r = m->r;
	r.idle_step_us = median(m->idle_us);
	r.step_us = median(m->all_us);
	for (const auto& f : m->frames) r.plastic_energy_j += f->plasticWork_j();
	for (const auto& s : m->jit)
	{
		r.subdivisions += s->subdivisions();
		r.merges += s->merges() - s->members();  // not the ones that made each member whole at the start
	}
	for (const auto& f : m->frames)
		for (const btRigidBody* body : f->bodies()) r.finite = r.finite && std::isfinite(double(body->getCenterOfMassPosition().length()));
	return r;
}

scene::SceneLedger CityScene::ledger() const
{
	const CityResult r = result();
	const State& s = *m;
	scene::SceneLedger l;
	l.title = std::string("city, ") + cityModeName(s.p.mode) + ", " + plastic::jointMethodName(s.p.building.method);
	l.time_s = time_s();
	l.load_work_j = s.initialSwingPotential_j - s.swing.measure().potential_j;
	// every body in the world now (a whole building's are out of it, and without mass)
	btDiscreteDynamicsWorld& world = const_cast<plastic::StructureWorld&>(s.structure).world();
	plastic::EnergyLedger moving(world.getGravity());
	const btCollisionObjectArray& objects = world.getCollisionObjectArray();
	for (int i = 0; i < objects.size(); i++)
		if (const btRigidBody* body = btRigidBody::upcast(objects[i])) moving.addBody(*body);
	l.kinetic_j = moving.measure().kinetic_j;
	l.plastic_booked_j = r.plastic_energy_j;
	// a rigid-plastic joint absorbs Mp over its rotation up to its limit: a broken joint's bodies then turn freely
	for (size_t i = 0; i < s.hitJoints.size(); i++)
		l.plastic_measured_j += s.plasticMoment_nm * (std::isnan(s.rotationAtBreak_rad[i])
														 ? std::fabs(s.hitRotation(i))
														 : std::min(std::fabs(s.rotationAtBreak_rad[i]), s.p.building.max_plastic_rotation_rad));
	char line[200];
	std::snprintf(line, sizeof line, "%d buildings, %d hit: %.0f J released", s.p.buildings, s.p.hit, r.impact_energy_j);
	l.answer.push_back(line);
	l.answer.push_back("load: balls' descent; Mp x rot.: hit ones");
	std::snprintf(line, sizeof line, "bodies %d, joints %d in the world now", dynamicBodies(world), world.getNumConstraints());
	l.status.push_back(line);
	if (s.p.mode == CityMode::JustInTime)
	{
		std::snprintf(line, sizeof line, "%d members subdivided, %d merged", r.subdivisions, r.merges);
		l.status.push_back(line);
	}
	// no wall-clock figure on screen: the frames are the same bytes run to run (the runner reports the costs)
	std::snprintf(line, sizeof line, "%ld frames, %ld internal steps", r.frames, r.internal_steps);
	l.status.push_back(line);
	return l;
}

scene::WorldBox CityScene::viewEnvelope() const
{
	// the grid of frames (each bays x span wide, storeys x height tall, in the x-y plane at its grid place) and the
	// balls' swings from their release (left of their frames) up to the chains' pivots
	const CityParameters& p = m->p;
	const WreckingBallParameters& b = p.building;
	const int perRow = int(std::ceil(std::sqrt(double(p.buildings))));
	const int rows = (p.buildings + perRow - 1) / perRow;
	const double radius_m = b.chain_length_m + b.ball_radius_m;
	const double release_x_m = -(b.section_depth_m / 2 + b.ball_radius_m + 0.02) - radius_m * std::sin(std::min(b.release_angle_rad, 1.5707963));
	const double pad_m = b.section_depth_m;
	scene::WorldBox box;
	box.min_m = btVector3(btScalar((p.hit > 0 ? release_x_m - b.ball_radius_m : -b.height_m) - pad_m), 0, btScalar(-b.ball_radius_m - pad_m));
	box.max_m = btVector3(btScalar(p.spacing_m * (std::min(perRow, p.buildings) - 1) + b.span_m * b.bays + b.height_m + pad_m),
						  btScalar(std::max(p.hit > 0 ? b.impact_height_m + radius_m : 0.0, b.height_m * b.storeys) + pad_m),
						  btScalar(p.spacing_m * (rows - 1) + b.ball_radius_m + pad_m));
	return box;
}

CityResult runCity(const CityParameters& p) { return scene::runToEnd<CityScene>(p); }
}  // namespace game
