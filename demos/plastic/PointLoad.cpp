#include "PointLoad.h"

namespace plastic
{
PointLoad::PointLoad(btRigidBody& body, const btVector3& localPoint_m, const btVector3& force_n, bool follower)
	: m_body(body),
	  m_localPoint_m(localPoint_m),
	  m_force_n(force_n),
	  m_initialBasis(body.getWorldTransform().getBasis()),
	  m_follower(follower),
	  m_before_m(point_m()),
	  m_applied_n(0, 0, 0)
{
}

btVector3 PointLoad::force_n() const
{
	btVector3 f = m_force_n * btScalar(m_factor);
	if (m_follower) f = m_body.getWorldTransform().getBasis() * (m_initialBasis.transpose() * f);
	return f;
}

void PointLoad::apply()
{
	m_before_m = point_m();
	const btVector3 force = force_n();
	if (!(force == m_applied_n)) m_body.activate();
	m_applied_n = force;
	m_body.applyForce(m_applied_n, m_body.getWorldTransform().getBasis() * m_localPoint_m);
}

void PointLoad::afterStep() { m_work_j += double(m_applied_n.dot(point_m() - m_before_m)); }
}  // namespace plastic
