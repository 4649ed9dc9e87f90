#include "EnergyLedger.h"

namespace plastic
{
Energies EnergyLedger::measure() const
{
	Energies e;
	for (const btRigidBody* body : m_bodies)
	{
		if (body->getInvMass() == 0) continue;
		const double mass = 1.0 / body->getInvMass();
		const btVector3 w = body->getWorldTransform().getBasis().transpose() * body->getAngularVelocity();
		const btVector3 I = body->getLocalInertia();
		e.kinetic_j += 0.5 * mass * body->getLinearVelocity().length2() +
					   0.5 * (I.x() * w.x() * w.x() + I.y() * w.y() * w.y() + I.z() * w.z() * w.z());
		e.potential_j -= mass * m_gravity_m_s2.dot(body->getCenterOfMassPosition());
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
