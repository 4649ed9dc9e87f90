// What the structures scenes measure, independently of the joints' own bookkeeping: the rotation of a body about
// the world z axis since it was made (unwrapped, for planar scenes). Their loads are plastic::PointLoad.
#pragma once

#include "btBulletDynamicsCommon.h"

namespace scene
{
// Rotation (rad, counter-clockwise about +z) of a body since construction; update() after every step keeps it
// continuous past +-pi. A null body (the ground) never turns.
class PlanarAngle
{
public:
	explicit PlanarAngle(const btRigidBody* body);
	void update();
	double angle_rad() const { return m_angle_rad; }

private:
	const btRigidBody* m_body;
	btMatrix3x3 m_initial;
	double m_angle_rad = 0;
};

}  // namespace scene
