// A wrecking ball on a chain: a sphere hung from a fixed pivot by a chain of capsule links joined by point-to-point
// constraints (the links collide with nothing), released from rest at an angle from the vertical. It puts its bodies
// and constraints into a world and takes them out again when it is destroyed.
#pragma once

#include <memory>
#include <vector>

#include "btBulletDynamicsCommon.h"

namespace game
{
struct PendulumSpec
{
	btVector3 bottom_m{0, 0, 0};  // the ball's centre at the bottom of its swing (the pivot is straight above)
	double ball_mass_kg = 2000;
	double ball_radius_m = 0.4;
	double ball_friction = 0.5;
	double chain_length_m = 5.0;  // pivot to the ball's surface
	int chain_links = 8;
	double chain_mass_kg = 80;
	double release_angle_rad = 1.0;   // about world z, from the vertical
	double release_direction = -1.0;  // -1: released towards -x, +1: towards +x
};

class Pendulum
{
public:
	Pendulum(btDiscreteDynamicsWorld& world, const PendulumSpec& spec);
	~Pendulum();
	Pendulum(const Pendulum&) = delete;
	Pendulum& operator=(const Pendulum&) = delete;
	btRigidBody& ball() { return *m_ball; }
	const btRigidBody& ball() const { return *m_ball; }
	std::vector<const btRigidBody*> links() const;

private:
	btDiscreteDynamicsWorld& m_world;
	std::unique_ptr<btSphereShape> m_ballShape;
	std::unique_ptr<btCapsuleShape> m_linkShape;
	std::unique_ptr<btRigidBody> m_ball;
	std::vector<std::unique_ptr<btRigidBody>> m_links;
	std::vector<std::unique_ptr<btPoint2PointConstraint>> m_chain;
};
}  // namespace game
