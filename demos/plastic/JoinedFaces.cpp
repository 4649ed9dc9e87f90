#include "JoinedFaces.h"

#include "btBulletDynamicsCommon.h"

namespace plastic
{
bool JoinedFaces::add(const btCollisionObject* box, int face, const btCollisionObject* partner, const btTypedConstraint* joint)
{
	int bit = 0;
	while (bit < 6 && (1 << bit) != face)
	{
		bit++;
	}
	const auto isBox = [](const btCollisionObject* object)
	{ return object && object->getCollisionShape() && object->getCollisionShape()->getShapeType() == BOX_SHAPE_PROXYTYPE; };
	if (bit == 6 || !isBox(box) || !isBox(partner) || !joint)
	{
		return false;
	}
	m_faces.push_back({box, bit / 2, bit % 2 == 0, partner, joint});
	return true;
}

namespace
{
// the cover's tolerance: this fraction of the partner's half extent along each of its axes; a contact deeper than this
// fraction of the box's section (its smaller half extent across the joined face) is a real penetration, not a seam's
// step, and stays
const btScalar kCoverFraction = btScalar(0.04);

// cos 60 degrees: a contact whose normal out of the box leans more than 30 degrees from the box's side faces towards a
// joined face pushes on the seam, not on the member's surface. Bullet's box-box contact at a seam's corner takes the
// other box's face normal, which can lie anywhere between the side face's and the end face's: a flat nose's corner
// caught on a part whose corner stood 8 um out of line, with a normal 49.5 degrees from the part's end face
const btScalar kJoinedFaceCos = btScalar(0.5);

// the half extents of a registered object (add() takes boxes only)
btVector3 halfExtents(const btCollisionObject* box) { return static_cast<const btBoxShape*>(box->getCollisionShape())->getHalfExtentsWithMargin(); }

// whether `point` (world) lies in the box `object` grown by `extra` and, along each of its axes, `fraction` of its half
// extent there. Across a member the step a joint makes at its seam (its shear, a twist times the half width) goes with
// the section, not with the length of the parts: a part 1.7 mm long of a 10 mm section gets 0.2 mm across it, as a
// long one does
bool inBox(const btCollisionObject* object, const btVector3& point, btScalar extra, btScalar fraction)
{
	const btVector3 half = halfExtents(object);
	const btVector3 reach = half * (1 + fraction) + btVector3(extra, extra, extra);
	const btVector3 local = object->getWorldTransform().invXform(point).absolute();
	return local.x() <= reach.x() && local.y() <= reach.y() && local.z() <= reach.z();
}
}  // namespace

bool JoinedFaces::onJoinedFace(const btCollisionObject* box, const btVector3& outOfBox, const btVector3& onBox, btScalar depth) const
{
	bool inFrame = false;
	btVector3 local(0, 0, 0);
	for (const Face& f : m_faces)
	{
		if (f.box != box || !f.joint->isEnabled())
		{
			continue;
		}
		if (!inFrame)
		{
			local = outOfBox * box->getWorldTransform().getBasis();
			inFrame = true;
		}
		// a seam's step is a fraction of the section, and so is the depth of a body caught on it: a deeper contact is a
		// body sinking into the member, and removing it would let it sink further (32 parts under sequential
		// impulse sank 1.3 mm, its contacts removed up to 2.35 mm deep)
		const btVector3 half = halfExtents(box);
		const btScalar section = btMin(half[(f.axis + 1) % 3], half[(f.axis + 2) % 3]);
		if ((f.plus ? local[f.axis] : -local[f.axis]) > kJoinedFaceCos && depth <= kCoverFraction * section &&
			inBox(f.partner, onBox, depth, kCoverFraction))
		{
			return true;
		}
	}
	return false;
}

int JoinedFaces::removeContacts(btDispatcher& dispatcher) const
{
	if (m_faces.empty())
	{
		return 0;
	}
	int removed = 0;
	for (int m = 0; m < dispatcher.getNumManifolds(); m++)
	{
		btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
		const btCollisionObject* a = manifold->getBody0();
		const btCollisionObject* b = manifold->getBody1();
		for (int i = manifold->getNumContacts() - 1; i >= 0; i--)
		{
			// the normal on B points from B towards A: out of B, into A
			const btManifoldPoint& cp = manifold->getContactPoint(i);
			const btVector3& n = cp.m_normalWorldOnB;
			const btScalar depth = btMax(-cp.getDistance(), btScalar(0));
			if (onJoinedFace(a, -n, cp.getPositionWorldOnA(), depth) || onJoinedFace(b, n, cp.getPositionWorldOnB(), depth))
			{
				manifold->removeContactPoint(i);
				removed++;
			}
		}
	}
	return removed;
}
}  // namespace plastic
