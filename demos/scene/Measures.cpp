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

}  // namespace scene
