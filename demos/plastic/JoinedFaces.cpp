#include "JoinedFaces.h"

#include "btBulletDynamicsCommon.h"

namespace plastic
{
void JoinedFaces::add(const btCollisionObject* box, BoxFace face, const btTypedConstraint* joint)
{
	int bit = 0;
	while ((1 << bit) != int(face))
	{
		bit++;
	}
	m_faces.push_back({box, bit / 2, bit % 2 == 0, joint});
}

bool JoinedFaces::onJoinedFace(const btCollisionObject* box, const btVector3& outOfBox) const
{
	bool inBox = false;
	btVector3 local(0, 0, 0);
	for (const Face& f : m_faces)
	{
		if (f.box != box || !f.joint->isEnabled())
		{
			continue;
		}
		if (!inBox)
		{
			local = outOfBox * box->getWorldTransform().getBasis();
			inBox = true;
		}
		if ((f.plus ? local[f.axis] : -local[f.axis]) > SIMDSQRT12)
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
			const btVector3& n = manifold->getContactPoint(i).m_normalWorldOnB;
			if (onJoinedFace(a, -n) || onJoinedFace(b, n))
			{
				manifold->removeContactPoint(i);
				removed++;
			}
		}
	}
	return removed;
}
}  // namespace plastic
