#include "EnergyLedger.h"

namespace plastic
{
double kineticEnergy_j(const btRigidBody& body)
{
	if (body.getInvMass() == 0) return 0;
	const double mass = 1.0 / body.getInvMass();
	const btVector3 w = body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
	const btVector3 I = body.getLocalInertia();
	return 0.5 * mass * body.getLinearVelocity().length2() + 0.5 * (I.x() * w.x() * w.x() + I.y() * w.y() * w.y() + I.z() * w.z() * w.z());
}

Energies EnergyLedger::measure() const
{
	Energies e;
	for (const btRigidBody* body : m_bodies)
	{
		if (body->getInvMass() == 0) continue;
		e.kinetic_j += kineticEnergy_j(*body);
		e.potential_j -= (1.0 / body->getInvMass()) * m_gravity_m_s2.dot(body->getCenterOfMassPosition());
	}
	for (const Joint* joint : m_joints)
	{
		e.elastic_j += joint->elasticEnergy_j();
		e.plastic_j += joint->plasticWork_j();
	}
	for (const PointLoad* load : m_loads) e.load_work_j += load->work_j();
	return e;
}
}  // namespace plastic
