#include "JointSites.h"

#include <cmath>

namespace scene
{
JointSite jointSite(const plastic::Joint& joint, const btRigidBody* a, const btRigidBody& b, const btVector3& worldPivot_m)
{
	JointSite s;
	s.joint = &joint;
	s.body_a = a;
	s.body_b = &b;
	s.pivot_in_b_m = b.getWorldTransform().inverse() * worldPivot_m;
	return s;
}

JointView jointView(const JointSite& site, double measuredRotation_rad)
{
	JointView v;
	v.pivot_m = site.body_b->getWorldTransform() * site.pivot_in_b_m;
	v.body_a = site.body_a;
	v.body_b = site.body_b;
	const plastic::Joint& j = *site.joint;
	v.plastic_rotation_rad = j.plasticState ? j.plasticRotation_rad() : std::fabs(measuredRotation_rad);
	v.plastic_work_j = j.plasticWork_j();
	v.yielded = v.plastic_rotation_rad > kYieldedRotation_rad;
	v.broken = !j.constraint->isEnabled();
	return v;
}
}  // namespace scene
