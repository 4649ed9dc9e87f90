// Where a scene's plastic joints are, for showing them: each joint with the bodies it joins and its pivot fixed in
// its second body (always a moving one), so the pivot follows the structure as it bends.
#pragma once

#include "plastic/JointFactory.h"
#include "SteppedScene.h"

namespace scene
{
struct JointSite
{
	const plastic::Joint* joint = nullptr;
	const btRigidBody* body_a = nullptr;  // null: the ground
	const btRigidBody* body_b = nullptr;
	btVector3 pivot_in_b_m{0, 0, 0};
};

// the joint between a (null: the ground) and b at a world pivot, as the bodies stand now
JointSite jointSite(const plastic::Joint& joint, const btRigidBody* a, const btRigidBody& b, const btVector3& worldPivot_m);
// the view of a site; measuredRotation_rad (from the bodies) stands in for the booked rotation of a joint without
// plastic bookkeeping (the hinge-motor stand-in)
JointView jointView(const JointSite& site, double measuredRotation_rad);
}  // namespace scene
