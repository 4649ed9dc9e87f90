// What a narrow-phase detector reports (btDiscreteCollisionDetectorInterface::Result): each point's normal on B,
// position on B and signed distance, in the order given. Used by the box-box detector tests.
#pragma once

#include <vector>

#include "BulletCollision/NarrowPhaseCollision/btDiscreteCollisionDetectorInterface.h"

struct DetectedPoints : public btDiscreteCollisionDetectorInterface::Result
{
	std::vector<btVector3> normals, points;
	std::vector<double> distances;
	void setShapeIdentifiersA(int, int) override {}
	void setShapeIdentifiersB(int, int) override {}
	void addContactPoint(const btVector3& normalOnBInWorld, const btVector3& pointInWorld, btScalar depth) override
	{
		normals.push_back(normalOnBInWorld);
		points.push_back(pointInWorld);
		distances.push_back(double(depth));
	}
};
