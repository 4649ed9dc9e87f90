// The energies of a scene, read from the world (the ledger changes nothing): kinetic and potential energy of
// the bodies, elastic and plastic energy of the joints (through the plastic bookkeeping all plastic joints share),
// and the work of the loads the scene applies through PointLoad. A scene whose books balance has
// load work + initial total = total + plastic work (+ what contacts and the solver lost).
#pragma once

#include <vector>

#include "JointFactory.h"
#include "PointLoad.h"

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

// 1/2 m v^2 + 1/2 w I w of a body (J); 0 for a static body
double kineticEnergy_j(const btRigidBody& body);

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
