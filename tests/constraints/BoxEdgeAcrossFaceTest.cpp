// Patch 0042: with btDispatcherInfo::m_boxBoxEdgesAcrossFaces, an edge of a box lying within 5 degrees of across
// another box's face touches it at both ends, where upstream's btBoxBoxDetector picks the edge pair and reports one
// point at the deeper end. Checked against the geometry: a 10 x 10 x 3.4 mm part twisted by 2 mrad about its axis,
// its face pressed onto a static box's edge, is as deep at the edge's two ends as the twist makes it (the Charpy
// specimen in 16 parts that this mends: tests/charpy/CharpyDirectSolveTest.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "btBulletDynamicsCommon.h"
#include "BulletCollision/CollisionDispatch/btBoxBoxDetector.h"
#include "DetectedPoints.h"

namespace
{
const double kHalfWidth_m = 0.005;  // the part's half width along the edge (world Y)

// A: a static box whose edge along Y lies at x = 0, z = 0 (the box fills x < 0, z > 0). B: a 10 x 10 x 3.4 mm part (its
// axis local Z) turned by bend_rad about Y and twisted by twist_rad about its own axis, its -X face pressed depth_m
// beyond the edge's midpoint.
struct EdgeOnFace
{
	btTransform a, b;
	btVector3 faceNormal;  // the part's -X face's outward normal in world
	EdgeOnFace(double bend_rad, double twist_rad, double depth_m)
	{
		a.setIdentity();
		a.setOrigin(btVector3(-0.01f, 0, 0.01f));
		b.setIdentity();
		b.setRotation(btQuaternion(btVector3(0, 1, 0), btScalar(bend_rad)) * btQuaternion(btVector3(0, 0, 1), btScalar(twist_rad)));
		faceNormal = b.getBasis() * btVector3(-1, 0, 0);
		b.setOrigin(-faceNormal * btScalar(kHalfWidth_m - depth_m));
	}
	DetectedPoints detect(bool edgesAcrossFaces) const
	{
		btBoxShape boxA(btVector3(0.01f, 0.02f, 0.01f)), boxB(btVector3(0.005f, 0.005f, 0.0017f));
		btBoxBoxDetector detector(&boxA, &boxB);
		detector.m_edgesAcrossFaces = edgesAcrossFaces;
		btDiscreteCollisionDetectorInterface::ClosestPointInput input;
		input.m_transformA = a;
		input.m_transformB = b;
		DetectedPoints out;
		detector.getClosestPoints(input, out, nullptr);
		return out;
	}
};
}  // namespace

TEST(BoxEdgeAcrossFace, ATwistedPartTouchesTheEdgeAtBothEndsAsDeepAsTheTwistMakesThem)
{
	const double twist = 0.002, depth = 2e-5;
	for (double bend : {0.2, 0.5, 0.8})
	{
		const EdgeOnFace pair(bend, twist, depth);
		const DetectedPoints upstream = pair.detect(false);
		ASSERT_EQ(1u, upstream.points.size()) << "upstream's detector picks the edge pair here (bend " << bend << ")";
		EXPECT_NEAR(kHalfWidth_m, std::fabs(upstream.points[0].y()), 1e-6);

		const DetectedPoints both = pair.detect(true);
		ASSERT_EQ(2u, both.points.size()) << "bend " << bend;
		// the face turned by the twist about the part's axis: at y the edge is depth + twist * y (the sign by which end
		// the twist lowers) into it
		for (size_t i = 0; i < 2; i++)
		{
			const double y = both.points[i].y();
			EXPECT_NEAR(kHalfWidth_m, std::fabs(y), 1e-6) << "an end of the edge";
			const double expected = depth + twist * y * (upstream.points[0].y() > 0 ? 1.0 : -1.0);
			EXPECT_NEAR(-expected, both.distances[i], 2e-7) << "the depth at y = " << y;
			EXPECT_NEAR(1.0, std::fabs(both.normals[i].dot(pair.faceNormal)), 1e-5) << "the normal is the part's face's";
		}
		EXPECT_LT(both.points[0].y() * both.points[1].y(), 0) << "one point at each end";
	}
}

TEST(BoxEdgeAcrossFace, AnEdgeFarFromAcrossTheFaceIsAsUpstreamHasIt)
{
	// twisted by 0.2 rad (11 degrees) the edge pair is no face's: the setting changes nothing
	for (double bend : {0.2, 0.5})
	{
		const EdgeOnFace pair(bend, 0.2, 2e-5);
		const DetectedPoints upstream = pair.detect(false), both = pair.detect(true);
		ASSERT_EQ(upstream.points.size(), both.points.size());
		for (size_t i = 0; i < both.points.size(); i++)
		{
			EXPECT_EQ(upstream.distances[i], both.distances[i]);
			EXPECT_EQ(upstream.points[i], both.points[i]);
		}
	}
}
