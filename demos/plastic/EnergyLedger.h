// The energies of a scene, read from the world (the ledger changes nothing): kinetic and potential energy of
// the bodies, elastic and plastic energy of the joints (through the plastic bookkeeping all plastic joints share),
// and the work of the loads the scene applies through PointLoad. A scene whose books balance has
// load work + initial total = total + plastic work (+ what contacts and the solver lost).
#pragma once

#include <vector>

#include "JointFactory.h"

namespace plastic
{
struct Energies
{
	double kinetic_j = 0;
	double potential_j = 0;  // m g h, h along -gravity from the origin
	double elastic_j = 0;
	double plastic_j = 0;
	double load_work_j = 0;
	double mechanical_j() const { return kinetic_j + potential_j + elastic_j; }
};

// A constant world force (N) at a point fixed in a body (m, body frame): apply() before a step, afterStep()
// after it adds the force times the displacement of the point to its work.
class PointLoad
{
public:
	PointLoad(btRigidBody& body, const btVector3& localPoint_m, const btVector3& force_n);
	void apply();
	void afterStep();
	double work_j() const { return m_work_j; }

private:
	btRigidBody& m_body;
	btVector3 m_localPoint_m;
	btVector3 m_force_n;
	btVector3 m_before_m;
	double m_work_j = 0;
};

class EnergyLedger
{
public:
	explicit EnergyLedger(const btVector3& gravity_m_s2) : m_gravity_m_s2(gravity_m_s2) {}
	void addBody(const btRigidBody& body) { m_bodies.push_back(&body); }
	void addJoint(const Joint& joint) { m_joints.push_back(&joint); }
	void addLoad(const PointLoad& load) { m_loads.push_back(&load); }
	Energies measure() const;

private:
	btVector3 m_gravity_m_s2;
	std::vector<const btRigidBody*> m_bodies;
	std::vector<const Joint*> m_joints;
	std::vector<const PointLoad*> m_loads;
};
}  // namespace plastic
