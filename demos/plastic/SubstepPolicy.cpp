#include "SubstepPolicy.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "btBulletDynamicsCommon.h"

namespace plastic
{
namespace
{
void reach(const btCollisionObject* object, double horizon_s, double clearance_m, btVector3& lo, btVector3& hi)
{
	object->getCollisionShape()->getAabb(object->getWorldTransform(), lo, hi);
	const btRigidBody* body = btRigidBody::upcast(object);
	if (!body || object->isStaticObject())
	{
		return;  // static objects keep their boxes
	}
	const double radius = double((hi - lo).length()) / 2;
	const double travel = (double(body->getLinearVelocity().length()) + double(body->getAngularVelocity().length()) * radius) * horizon_s;
	const btScalar grow = btScalar(travel + clearance_m);
	lo -= btVector3(grow, grow, grow);
	hi += btVector3(grow, grow, grow);
}

bool overlap(const btVector3& aLo, const btVector3& aHi, const btVector3& bLo, const btVector3& bHi)
{
	return aLo.x() <= bHi.x() && bLo.x() <= aHi.x() && aLo.y() <= bHi.y() && bLo.y() <= aHi.y() && aLo.z() <= bHi.z() && bLo.z() <= aHi.z();
}
}  // namespace

bool mayTouchWithin(const std::vector<const btCollisionObject*>& movers, const std::vector<const btCollisionObject*>& others,
					double horizon_s, double clearance_m)
{
	// no allocation: a scene asks this several times per frame
	for (const btCollisionObject* mover : movers)
	{
		btVector3 mLo, mHi;
		reach(mover, horizon_s, clearance_m, mLo, mHi);
		for (const btCollisionObject* other : others)
		{
			if (other == mover)
			{
				continue;
			}
			btVector3 oLo, oHi;
			reach(other, horizon_s, clearance_m, oLo, oHi);
			if (overlap(mLo, mHi, oLo, oHi))
			{
				return true;
			}
		}
	}
	return false;
}

std::vector<std::string> validate(const ContactSubstepSettings& settings)
{
	std::vector<std::string> errors;
	const double h = settings.contact_substep_s;
	if (!(std::isfinite(h) && (h == 0 || (h >= 1e-7 && h <= 0.05))))
	{
		std::ostringstream out;
		out << "contact-substep: " << h << " is not in [1e-07, 0.05] s (or 0 = off)";
		errors.push_back(out.str());
	}
	return errors;
}

ContactSubstepPolicy::ContactSubstepPolicy(const ContactSubstepSettings& settings) : m_settings(settings), m_errors(validate(settings)) {}

int ContactSubstepPolicy::advance(double frame_s, const NearContact& nearContact, const Step& step) const
{
	if (!(std::isfinite(frame_s) && frame_s > 0) || !m_errors.empty())
	{
		return -1;
	}
	const double h = m_settings.contact_substep_s;
	int steps = 0;
	double remaining = frame_s;
	while (remaining > 1e-12 * frame_s)
	{
		double piece = remaining;
		if (h > 0)
		{
			// cut in halves until a piece reaches no contact within its own length; where even a contact
			// substep reaches one, the step is a contact substep
			while (piece > h && nearContact(piece))
			{
				piece /= 2;
			}
			if (piece < h)
			{
				piece = std::min(remaining, h);
			}
		}
		step(piece);
		steps++;
		remaining -= piece;
	}
	return steps;
}
}  // namespace plastic
