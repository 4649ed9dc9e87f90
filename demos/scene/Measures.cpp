#include "Measures.h"

#include <cmath>

namespace scene
{
PlanarAngle::PlanarAngle(const btRigidBody* body) : m_body(body)
{
	m_initial = body ? body->getWorldTransform().getBasis() : btMatrix3x3::getIdentity();
}

void PlanarAngle::update()
{
	if (!m_body) return;
	// the rotation since construction, applied to the world x axis, projected on the x-y plane
	const btVector3 x = m_body->getWorldTransform().getBasis() * (m_initial.transpose() * btVector3(1, 0, 0));
	const double wrapped = std::atan2(double(x.y()), double(x.x()));
	double delta = wrapped - std::remainder(m_angle_rad, 2 * M_PI);
	delta = std::remainder(delta, 2 * M_PI);
	m_angle_rad += delta;
}

ScaledLoad::ScaledLoad(btRigidBody& body, const btVector3& localPoint_m, const btVector3& referenceForce_n, bool follower)
	: m_body(body),
	  m_localPoint_m(localPoint_m),
	  m_referenceForce_n(referenceForce_n),
	  m_initialBasis(body.getWorldTransform().getBasis()),
	  m_follower(follower),
	  m_before_m(point_m()),
	  m_applied_n(0, 0, 0)
{
}

btVector3 ScaledLoad::force_n() const
{
	btVector3 f = m_referenceForce_n * btScalar(m_factor);
	if (m_follower) f = m_body.getWorldTransform().getBasis() * (m_initialBasis.transpose() * f);
	return f;
}

void ScaledLoad::apply()
{
	m_before_m = point_m();
	m_applied_n = force_n();
	m_body.applyForce(m_applied_n, m_body.getWorldTransform().getBasis() * m_localPoint_m);
}

void ScaledLoad::afterStep() { m_work_j += double(m_applied_n.dot(point_m() - m_before_m)); }
}  // namespace scene
