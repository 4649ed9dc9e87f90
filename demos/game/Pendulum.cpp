#include "Pendulum.h"

#include <algorithm>
#include <cmath>

namespace game
{
namespace
{
std::unique_ptr<btRigidBody> makeBody(double mass_kg, btCollisionShape& shape, const btTransform& at)
{
	btVector3 inertia(0, 0, 0);
	shape.calculateLocalInertia(btScalar(mass_kg), inertia);
	btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass_kg), nullptr, &shape, inertia);
	info.m_startWorldTransform = at;
	auto body = std::make_unique<btRigidBody>(info);
	body->setActivationState(DISABLE_DEACTIVATION);
	return body;
}

// a basis whose y axis is dir (a capsule's axis), z the world's
btMatrix3x3 alongY(const btVector3& dir)
{
	const btVector3 z(0, 0, 1);
	const btVector3 x = dir.cross(z).normalized();
	btMatrix3x3 b;
	b.setValue(x.x(), dir.x(), z.x(), x.y(), dir.y(), z.y(), x.z(), dir.z(), z.z());
	return b;
}
}  // namespace

Pendulum::Pendulum(btDiscreteDynamicsWorld& world, const PendulumSpec& spec) : m_world(world)
{
	const btScalar R = btScalar(spec.chain_length_m + spec.ball_radius_m);
	const btVector3 pivot = spec.bottom_m + btVector3(0, R, 0);
	const double a = spec.release_angle_rad;
	const btVector3 dir(btScalar(spec.release_direction * std::sin(a)), btScalar(-std::cos(a)), 0);  // pivot -> ball
	m_ballShape = std::make_unique<btSphereShape>(btScalar(spec.ball_radius_m));
	m_ball = makeBody(spec.ball_mass_kg, *m_ballShape, btTransform(btMatrix3x3::getIdentity(), pivot + dir * R));
	m_ball->setFriction(btScalar(spec.ball_friction));
	m_ball->setRestitution(0);
	world.addRigidBody(m_ball.get());
	const btScalar link = btScalar(spec.chain_length_m / spec.chain_links);
	m_linkShape = std::make_unique<btCapsuleShape>(btScalar(std::min(0.04, 0.2 * double(link))), link);
	const btMatrix3x3 linkBasis = alongY(-dir);  // local +y points up the chain, towards the pivot
	for (int i = 0; i < spec.chain_links; i++)
	{
		m_links.push_back(makeBody(spec.chain_mass_kg / spec.chain_links, *m_linkShape, btTransform(linkBasis, pivot + dir * ((btScalar(i) + btScalar(0.5)) * link))));
		world.addRigidBody(m_links.back().get(), 0, 0);  // the chain collides with nothing
	}
	const btVector3 top(0, link / 2, 0), end(0, -link / 2, 0);
	m_chain.push_back(std::make_unique<btPoint2PointConstraint>(*m_links.front(), top));  // to the fixed pivot
	for (size_t i = 1; i < m_links.size(); i++) m_chain.push_back(std::make_unique<btPoint2PointConstraint>(*m_links[i - 1], *m_links[i], end, top));
	m_chain.push_back(std::make_unique<btPoint2PointConstraint>(*m_links.back(), *m_ball, end, -dir * btScalar(spec.ball_radius_m)));
	for (auto& c : m_chain) world.addConstraint(c.get(), true);
}

Pendulum::~Pendulum()
{
	for (auto& c : m_chain) m_world.removeConstraint(c.get());
	for (auto& l : m_links) m_world.removeRigidBody(l.get());
	m_world.removeRigidBody(m_ball.get());
}

std::vector<const btRigidBody*> Pendulum::links() const
{
	std::vector<const btRigidBody*> b;
	for (const auto& l : m_links) b.push_back(l.get());
	return b;
}
}  // namespace game
