// The city: the buildings (game::SteelFrame on one ground), a wrecking ball for each hit building, stepped one internal
// step at a time so that each step's wall time can be measured, with the just-in-time structures' checks before and
// after each step in jit mode.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "City.h"
#include "Pendulum.h"
#include "SteelFrame.h"
#include "plastic/JitStructure.h"
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

CityResult runCity(const CityParameters& p)
{
	CityResult r;
	r.first_impact_s = std::numeric_limits<double>::quiet_NaN();
	const WreckingBallParameters& b = p.building;
	plastic::StructureWorld structure(b.solver);
	btDiscreteDynamicsWorld& world = structure.world();
	world.setGravity(btVector3(0, btScalar(-b.gravity_m_s2), 0));
	world.setForceUpdateAllAabbs(false);  // static buildings keep their boxes
	const int perRow = int(std::ceil(std::sqrt(double(p.buildings))));
	const btScalar pitch = btScalar(p.spacing_m);
	// the ground: one slab under the grid, its top at y = 0
	const btScalar half = btScalar(perRow) * pitch / 2 + 20;
	btBoxShape groundShape(btVector3(half, 0.5, half));
	btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &groundShape));
	ground.setWorldTransform(btTransform(btMatrix3x3::getIdentity(), btVector3(half - 20, -0.5, half - 20)));
	world.addRigidBody(&ground);

	SteelFrameSpec frame = steelFrameSpec(b);
	frame.may_sleep = true;  // a city at rest sleeps

	std::vector<std::unique_ptr<SteelFrame>> frames;
	std::vector<std::unique_ptr<plastic::JitStructure>> jit;
	plastic::JitStructureSet set(world);
	for (int i = 0; i < p.buildings; i++)
	{
		frame.origin_m = btVector3(btScalar(i % perRow) * pitch, 0, btScalar(i / perRow) * pitch);
		frames.push_back(std::make_unique<SteelFrame>(world, frame, ground, b.solver.internal_step_s));
		if (p.mode != CityMode::Jointed)
		{
			jit.push_back(std::make_unique<plastic::JitStructure>(world, frames.back()->bodies(), frames.back()->constraints(), frames.back()->yieldEnergy_j()));
			jit.back()->merge();
			set.add(*jit.back());
		}
	}
	std::vector<std::unique_ptr<Pendulum>> balls;
	for (int i = 0; i < p.hit; i++)
	{
		const PendulumSpec ball = pendulumSpec(b, frames[size_t(i)]->columns()[0][0]->segments().front()->getCenterOfMassPosition() * btVector3(1, 0, 1));
		balls.push_back(std::make_unique<Pendulum>(world, ball));
	}
	r.impact_energy_j = p.hit * wreckingBallEstimate(b).release_energy_j;

	const double dt = b.solver.internal_step_s;
	const int perFrame = std::max(1, int(std::lround(1.0 / (b.frame_rate_hz * dt))));
	r.frames = long(std::lround(b.duration_s * b.frame_rate_hz));
	std::vector<double> idle_us, all_us;
	for (long f = 0; f < r.frames; f++)
		for (int k = 0; k < perFrame; k++)
		{
			const auto start = std::chrono::steady_clock::now();
			if (p.mode == CityMode::JustInTime) set.subdivideThreatened(dt);
			structure.stepOnce();
			if (p.mode == CityMode::JustInTime) set.mergeAtRest();
			const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
			r.wall_s += us * 1e-6;
			all_us.push_back(us);
			r.internal_steps++;
			r.simulated_s += dt;
			// the first impact: a ball pushes a building (a contact with an impulse between a ball and anything but the
			// ground or a chain)
			if (std::isnan(r.first_impact_s))
			{
				idle_us.push_back(us);
				btDispatcher& d = *world.getDispatcher();
				for (int m = 0; m < d.getNumManifolds() && std::isnan(r.first_impact_s); m++)
				{
					const btPersistentManifold* manifold = d.getManifoldByIndexInternal(m);
					for (const auto& ball : balls)
					{
						const btCollisionObject* other = manifold->getBody0() == &ball->ball() ? manifold->getBody1()
														 : manifold->getBody1() == &ball->ball() ? manifold->getBody0()
																								 : nullptr;
						if (!other || other == &ground) continue;
						for (int c = 0; c < manifold->getNumContacts(); c++)
							if (manifold->getContactPoint(c).getAppliedImpulse() > 0) r.first_impact_s = r.simulated_s;
					}
				}
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
	r.idle_step_us = median(idle_us);
	r.step_us = median(all_us);
	for (const auto& f : frames) r.plastic_energy_j += f->plasticWork_j();
	for (const auto& s : jit)
	{
		r.subdivisions += s->subdivisions();
		r.merges += s->merges() - 1;  // not the one that made it whole at the start
	}
	for (const auto& f : frames)
		for (const btRigidBody* body : f->bodies()) r.finite = r.finite && std::isfinite(double(body->getCenterOfMassPosition().length()));
	balls.clear();
	jit.clear();
	frames.clear();
	world.removeRigidBody(&ground);
	return r;
}
}  // namespace game
