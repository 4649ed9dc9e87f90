// What the structures scenes measure, independently of the joints' own bookkeeping: the rotation of a body about
// the world z axis since it was made (unwrapped, for planar scenes), and loads whose work is their force times
// the displacement of their point.
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

// A force at a point fixed in a body: reference_force_n times a factor the scene sets (a ramp), either fixed in
// the world (dead load) or turning with the body (follower load). Its work is the force of each step times the
// displacement of its point in that step.
class ScaledLoad
{
public:
	ScaledLoad(btRigidBody& body, const btVector3& localPoint_m, const btVector3& referenceForce_n, bool follower);
	void setFactor(double factor) { m_factor = factor; }
	double factor() const { return m_factor; }
	void apply();      // before a step
	void afterStep();  // after it
	double work_j() const { return m_work_j; }
	btVector3 point_m() const { return m_body.getWorldTransform() * m_localPoint_m; }
	btVector3 force_n() const;

private:
	btRigidBody& m_body;
	btVector3 m_localPoint_m;
	btVector3 m_referenceForce_n;  // world at construction
	btMatrix3x3 m_initialBasis;
	bool m_follower;
	double m_factor = 1;
	btVector3 m_before_m;
	btVector3 m_applied_n;
	double m_work_j = 0;
};
}  // namespace scene
