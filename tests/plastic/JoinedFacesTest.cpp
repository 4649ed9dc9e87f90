// plastic::JoinedFaces against a seam with a step: two boxes of a member joined end to end, the second 0.2 mm higher,
// and a cube whose edge sits at the seam, in the first's top face and against the second's end face. Bullet's
// box-box contact pushes the cube back along the member through that end face; while the joint holds, that face is no
// surface and the contact is removed, and once the joint is broken it is a surface again.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "plastic/JoinedFaces.h"
#include "btBulletDynamicsCommon.h"

namespace
{
struct Seam
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	btCollisionWorld world{&dispatcher, &broadphase, &configuration};
	btBoxShape memberShape{btVector3(btScalar(0.05), btScalar(0.005), btScalar(0.005))};
	btBoxShape cubeShape{btVector3(btScalar(0.005), btScalar(0.005), btScalar(0.005))};
	std::unique_ptr<btRigidBody> first, second;
	btCollisionObject cube;
	std::unique_ptr<btPoint2PointConstraint> joint;

	Seam()
	{
		// the member along x: the first box ends at x = 0, the second starts there, 0.2 mm higher
		first = std::make_unique<btRigidBody>(btScalar(0), nullptr, &memberShape);
		first->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(-0.05), 0, 0)));
		second = std::make_unique<btRigidBody>(btScalar(0), nullptr, &memberShape);
		second->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(0.05), btScalar(0.0002), 0)));
		joint = std::make_unique<btPoint2PointConstraint>(*first, *second, btVector3(btScalar(0.05), 0, 0), btVector3(btScalar(-0.05), 0, 0));
		// the cube on the first box's top face (in it by 0.01 mm), its leading face 0.05 mm into the second's end face
		cube.setCollisionShape(&cubeShape);
		cube.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(-0.00495), btScalar(0.00999), 0)));
		world.addCollisionObject(first.get());
		world.addCollisionObject(second.get());
		world.addCollisionObject(&cube);
	}
	~Seam()
	{
		// out of the world before the objects go (the members are destroyed after this body, the world last)
		world.removeCollisionObject(&cube);
		world.removeCollisionObject(second.get());
		world.removeCollisionObject(first.get());
	}
	// the cube's contacts with `box` whose normal lies along `axis` (within 45 degrees), at a height above aboveY
	int contacts(const btCollisionObject* box, int axis, btScalar aboveY = -BT_LARGE_FLOAT)
	{
		int count = 0;
		for (int m = 0; m < dispatcher.getNumManifolds(); m++)
		{
			btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
			const bool pair = (manifold->getBody0() == &cube && manifold->getBody1() == box) ||
							  (manifold->getBody1() == &cube && manifold->getBody0() == box);
			for (int i = 0; pair && i < manifold->getNumContacts(); i++)
			{
				const btManifoldPoint& cp = manifold->getContactPoint(i);
				if (btFabs(cp.m_normalWorldOnB[axis]) > SIMDSQRT12 && cp.getPositionWorldOnA().y() > aboveY) count++;
			}
		}
		return count;
	}
	// the cube's contacts through the second box's end face (normal along the member, x)
	int endFaceContacts(btScalar aboveY = -BT_LARGE_FLOAT) { return contacts(second.get(), 0, aboveY); }
};
}  // namespace

TEST(JoinedFaces, ContactsOnAJoinedFaceAreRemovedWhileItsJointHolds)
{
	Seam s;
	s.world.performDiscreteCollisionDetection();
	ASSERT_GT(s.endFaceContacts(), 0) << "the seam must catch the cube without JoinedFaces";

	plastic::JoinedFaces joined;
	ASSERT_TRUE(joined.add(s.first.get(), plastic::kFacePlusX, s.second.get(), s.joint.get()));
	ASSERT_TRUE(joined.add(s.second.get(), plastic::kFaceMinusX, s.first.get(), s.joint.get()));
	const int removed = joined.removeContacts(s.dispatcher);
	EXPECT_GT(removed, 0);
	EXPECT_EQ(s.endFaceContacts(), 0);

	// the cube's contacts with the first box's top face are the member's surface: they stay
	EXPECT_GT(s.contacts(s.first.get(), 1), 0);

	// a broken joint leaves two bodies whose end faces are surfaces
	s.joint->setEnabled(false);
	s.world.performDiscreteCollisionDetection();
	ASSERT_GT(s.endFaceContacts(), 0);
	EXPECT_EQ(joined.removeContacts(s.dispatcher), 0);
	EXPECT_GT(s.endFaceContacts(), 0);
}

TEST(JoinedFaces, AnEndFaceThePartnerDoesNotCoverIsASurface)
{
	// the first box moved 2 mm down: the second's end face stands 2.2 mm above the first's top (at y = 3 mm), bare,
	// and the cube against it is a real contact there; only where the first box covers the face (its top edge, to
	// within the contact's depth and 0.2 mm) is a point removed
	Seam s;
	s.first->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(-0.05), btScalar(-0.002), 0)));
	s.cube.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(-0.00495), btScalar(0.00799), 0)));
	s.world.performDiscreteCollisionDetection();
	const btScalar bare = btScalar(0.0035);
	const int onTheBareFace = s.endFaceContacts(bare);
	ASSERT_GT(onTheBareFace, 0);
	plastic::JoinedFaces joined;
	joined.add(s.first.get(), plastic::kFacePlusX, s.second.get(), s.joint.get());
	joined.add(s.second.get(), plastic::kFaceMinusX, s.first.get(), s.joint.get());
	joined.removeContacts(s.dispatcher);
	EXPECT_EQ(s.endFaceContacts(bare), onTheBareFace);
}

TEST(JoinedFaces, AContactAtTheSeamsCornerIsRemovedUnlessItPushesOnTheSideFace)
{
	// hand-made contacts of the cube at the second box's top corner on the seam (x = 0, y = 5.2 mm: 0.2 mm above the
	// first box's top, which covers it within its 4 % of 5 mm and the contact's 0.05 mm depth), with normals out of
	// the second box turned from its end face's (-x) towards its top face's (+y): at 50 degrees (a box-box contact's
	// normal at a corner can be the other box's face normal) it pushes on the seam and goes; at 70 degrees it pushes on
	// the top face, the surface, and stays
	Seam s;
	plastic::JoinedFaces joined;
	joined.add(s.first.get(), plastic::kFacePlusX, s.second.get(), s.joint.get());
	joined.add(s.second.get(), plastic::kFaceMinusX, s.first.get(), s.joint.get());
	btPersistentManifold* manifold = s.dispatcher.getNewManifold(&s.cube, s.second.get());
	const btVector3 corner(0, btScalar(0.0052), 0);
	const auto addContact = [&](double fromEndFace_deg, btScalar depth = btScalar(5e-5))
	{
		const btScalar a = btScalar(fromEndFace_deg * SIMD_PI / 180);
		const btVector3 outOfSecond(-btCos(a), btSin(a), 0);  // the normal on B (the second box), towards A (the cube)
		btManifoldPoint cp(s.cube.getWorldTransform().invXform(corner), s.second->getWorldTransform().invXform(corner), outOfSecond, -depth);
		cp.m_positionWorldOnA = corner;
		cp.m_positionWorldOnB = corner;
		manifold->addManifoldPoint(cp);
	};
	addContact(50);
	EXPECT_EQ(joined.removeContacts(s.dispatcher), 1);
	EXPECT_EQ(manifold->getNumContacts(), 0);
	addContact(70);
	EXPECT_EQ(joined.removeContacts(s.dispatcher), 0);
	EXPECT_EQ(manifold->getNumContacts(), 1);
	manifold->clearManifold();
	// 0.3 mm deep, more than a seam's step (4 % of the 5 mm half section): a body sinking into the member stays
	addContact(50, btScalar(3e-4));
	EXPECT_EQ(joined.removeContacts(s.dispatcher), 0);
	EXPECT_EQ(manifold->getNumContacts(), 1);
	manifold->clearManifold();
	s.dispatcher.releaseManifold(manifold);
}

TEST(JoinedFaces, TheSeamsStepIsMeasuredAgainstTheSectionNotTheLengthOfTheParts)
{
	// two parts 1.7 mm long of a 10 mm section, joined end to end at x = 0, the second 0.15 mm lower (a joint's shear
	// at its cap): the first part's top edge at the seam stands 0.15 mm proud of the second's top face. A contact there
	// pushing towards the seam (normal 50 degrees from the first part's +x end face) is on the seam: across the section
	// the partner's box reaches 4 % of 5 mm = 0.2 mm further, where 4 % of the part's 0.85 mm half length would be 34 um
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher(&configuration);
	btBoxShape partShape(btVector3(btScalar(0.00085), btScalar(0.005), btScalar(0.005)));
	btRigidBody first(btScalar(0), nullptr, &partShape), second(btScalar(0), nullptr, &partShape);
	first.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(-0.00085), 0, 0)));
	second.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(0.00085), btScalar(-0.00015), 0)));
	btPoint2PointConstraint joint(first, second, btVector3(btScalar(0.00085), 0, 0), btVector3(btScalar(-0.00085), btScalar(0.00015), 0));
	btBoxShape noseShape(btVector3(btScalar(0.01), btScalar(0.01), btScalar(0.01)));
	btCollisionObject nose;
	nose.setCollisionShape(&noseShape);
	plastic::JoinedFaces joined;
	joined.add(&first, plastic::kFacePlusX, &second, &joint);
	joined.add(&second, plastic::kFaceMinusX, &first, &joint);
	btPersistentManifold* manifold = dispatcher.getNewManifold(&nose, &first);
	const btVector3 edge(0, btScalar(0.005), 0);
	const btScalar a = btScalar(50 * SIMD_PI / 180);
	btManifoldPoint cp(nose.getWorldTransform().invXform(edge), first.getWorldTransform().invXform(edge), btVector3(btCos(a), btSin(a), 0), btScalar(-1e-5));
	cp.m_positionWorldOnA = edge;
	cp.m_positionWorldOnB = edge;
	manifold->addManifoldPoint(cp);
	EXPECT_EQ(joined.removeContacts(dispatcher), 1);
	// 0.3 mm proud it is a step of the surface, and stays
	second.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(btScalar(0.00085), btScalar(-0.0003), 0)));
	manifold->addManifoldPoint(cp);
	EXPECT_EQ(joined.removeContacts(dispatcher), 0);
	manifold->clearManifold();
	dispatcher.releaseManifold(manifold);
}

TEST(JoinedFaces, AFaceThatIsNotOneBoxFaceIsRefused)
{
	Seam s;
	plastic::JoinedFaces joined;
	EXPECT_FALSE(joined.add(s.first.get(), 0, s.second.get(), s.joint.get()));
	EXPECT_FALSE(joined.add(s.first.get(), plastic::kFacePlusX | plastic::kFaceMinusX, s.second.get(), s.joint.get()));
	EXPECT_FALSE(joined.add(s.first.get(), 64, s.second.get(), s.joint.get()));
	btSphereShape ballShape(btScalar(0.005));
	btCollisionObject ball;
	ball.setCollisionShape(&ballShape);
	EXPECT_FALSE(joined.add(&ball, plastic::kFacePlusX, s.second.get(), s.joint.get()));
	EXPECT_FALSE(joined.add(s.first.get(), plastic::kFacePlusX, &ball, s.joint.get()));
	EXPECT_FALSE(joined.add(s.first.get(), plastic::kFacePlusX, nullptr, s.joint.get()));
	EXPECT_FALSE(joined.add(s.first.get(), plastic::kFacePlusX, s.second.get(), nullptr));
	s.world.performDiscreteCollisionDetection();
	EXPECT_EQ(joined.removeContacts(s.dispatcher), 0);
}
