#include "EnergyLedger.h"

namespace plastic
{
PointLoad::PointLoad(btRigidBody& body, const btVector3& localPoint_m, const btVector3& force_n)
	: m_body(body), m_localPoint_m(localPoint_m), m_force_n(force_n), m_before_m(body.getWorldTransform() * localPoint_m)
{
}

void PointLoad::apply()
{
	m_before_m = m_body.getWorldTransform() * m_localPoint_m;
	m_body.applyForce(m_force_n, m_body.getWorldTransform().getBasis() * m_localPoint_m);
}

void PointLoad::afterStep()
{
	const btVector3 after = m_body.getWorldTransform() * m_localPoint_m;
	m_work_j += double(m_force_n.dot(after - m_before_m));
}

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
