// Patch 0018: GJK's simplex tolerances are absolute (tuned for metre-sized objects); gVoronoiSimplexLengthScale scales
// them. Millimetre shapes as in the Charpy scene: a 1 mm edge (capsule or cylinder along Y) against a
// 10 x 10 x 27.5 mm box whose face is tangent to it, then 0.2 mm into it, at angles through a half-turn of rolling.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "btBulletDynamicsCommon.h"
#include "BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h"
#include "BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h"
#include "BulletCollision/NarrowPhaseCollision/btPointCollector.h"
#include "BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h"

namespace
{
// signed distance GJK finds between the edge (radius r, centre at the origin, axis Y) and the box rotated by phi about Y
// whose face is `offset` beyond tangency (negative: penetrating)
double gjkDistance(const btConvexShape& edge, double r, double phi, double offset)
{
	const double b = 0.01, halfLength = 0.01375;
	btBoxShape box(btVector3(btScalar(b / 2), btScalar(b / 2), btScalar(halfLength)));
	box.setMargin(btScalar(0.0005));
	const btVector3 normal(btScalar(std::cos(phi)), 0, btScalar(-std::sin(phi)));  // from the edge towards the box
	const btVector3 along(btScalar(std::sin(phi)), 0, btScalar(std::cos(phi)));
	btTransform boxPose;
	boxPose.setIdentity();
	boxPose.setRotation(btQuaternion(btVector3(0, 1, 0), btScalar(phi)));
	boxPose.setOrigin(normal * btScalar(r + offset + b / 2) - along * btScalar(halfLength - 0.004));
	btTransform edgePose;
	edgePose.setIdentity();
	edgePose.setOrigin(btVector3(-0.001f, 0.205f, 0.021f));  // away from the origin, as in the scene
	boxPose.setOrigin(boxPose.getOrigin() + edgePose.getOrigin());
	btVoronoiSimplexSolver simplex;
	btGjkEpaPenetrationDepthSolver epa;
	btGjkPairDetector gjk(&edge, &box, &simplex, &epa);
	btGjkPairDetector::ClosestPointInput input;
	input.m_transformA = edgePose;
	input.m_transformB = boxPose;
	btPointCollector out;
	gjk.getClosestPoints(input, out, nullptr);
	return out.m_hasResult ? double(out.m_distance) : 1.0;
}

struct ScaleGuard
{
	btScalar saved = gVoronoiSimplexLengthScale;
	~ScaleGuard() { gVoronoiSimplexLengthScale = saved; }
};
}  // namespace

TEST(GjkLengthScale, DefaultIsOne)
{
	EXPECT_EQ(gVoronoiSimplexLengthScale, btScalar(1));
	EXPECT_EQ(btVoronoiSimplexSolver().getEqualVertexThreshold(), btScalar(VORONOI_DEFAULT_EQUAL_VERTEX_THRESHOLD));
}

TEST(GjkLengthScale, MillimetreCapsuleAndCylinderAgainstABoxAreExactWhenScaled)
{
	ScaleGuard guard;
	const double r = 0.001;
	btCapsuleShape capsule(btScalar(r), 0.02f);
	btCylinderShape cylinder(btVector3(btScalar(r), 0.02f, btScalar(r)));
	cylinder.setMargin(btScalar(r / 2));
	int capsuleWrongAtDefault = 0;
	for (double phi = 0.05; phi < 1.0; phi += 0.1)
	{
#ifndef BT_USE_DOUBLE_PRECISION  // the double-precision tolerances are smaller (1e-12 m^2, 1e-8 m^3)
		gVoronoiSimplexLengthScale = 1;
		capsuleWrongAtDefault += std::fabs(gjkDistance(capsule, r, phi, -0.0002) + 0.0002) > 1e-4;
		EXPECT_GT(gjkDistance(cylinder, r, phi, -0.0002), 0.001) << "upstream's tolerances: no contact at phi " << phi;
#else
		capsuleWrongAtDefault = 1;
#endif
		gVoronoiSimplexLengthScale = 0.01f;
		for (double offset : {0.0, -0.0002})
		{
			EXPECT_NEAR(gjkDistance(capsule, r, phi, offset), offset, 1e-6) << "capsule, phi " << phi;
			EXPECT_NEAR(gjkDistance(cylinder, r, phi, offset), offset, 1e-4) << "cylinder, phi " << phi;
		}
	}
	EXPECT_GT(capsuleWrongAtDefault, 0) << "upstream's tolerances stop GJK early on some of these";
}
