// A load on a body: a force at a point fixed in the body, and the work it does. The one load class of the toolkit and
// of every scene (the energy ledger adds its work).
#pragma once

#include "btBulletDynamicsCommon.h"

namespace plastic
{
// force_n (N, in the world when made) times a factor the scene may set (a ramp; 1 by default) at localPoint_m (m, body
// frame), either fixed in the world (a dead load) or turning with the body (a follower load). apply() before a step
// applies it and wakes the body when the force it applies is not the one of the step before (a force on a sleeping
// body does nothing and does not wake it, so a load that grows would be lost on a structure at rest; a constant load
// lets it sleep); afterStep() after the step adds that force times the displacement of its point to the work.
class PointLoad
{
public:
	PointLoad(btRigidBody& body, const btVector3& localPoint_m, const btVector3& force_n, bool follower = false);
	void setFactor(double factor) { m_factor = factor; }
	double factor() const { return m_factor; }
	void apply();
	void afterStep();
	double work_j() const { return m_work_j; }
	btVector3 point_m() const { return m_body.getWorldTransform() * m_localPoint_m; }
	// the force apply() applies now (N, world)
	btVector3 force_n() const;

private:
	btRigidBody& m_body;
	btVector3 m_localPoint_m;
	btVector3 m_force_n;  // world, when made
	btMatrix3x3 m_initialBasis;
	bool m_follower;
	double m_factor = 1;
	btVector3 m_before_m;
	btVector3 m_applied_n;
	double m_work_j = 0;
};
}  // namespace plastic
