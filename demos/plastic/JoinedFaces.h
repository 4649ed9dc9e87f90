// Contacts on the joined faces of a member cut into boxes: a Charpy specimen in parts, a beam of segments. Where two
// boxes of a member are joined, the solid member has no surface; but Bullet's box contacts take the faces of each box
// as they are, and a body that slides along the member can meet the end face of the next box at the seam (the boxes
// are a hair's breadth out of line, or turned against each other) and catch on it: a striker's edge catching on a
// seam pins a part on the anvil while it pushes the next, and the joint between them slips. JoinedFaces removes the
// contacts that push on a joined face while its joint holds; the body meets the member through the faces beside the
// seam, which are its surface.
#pragma once

#include <vector>

#include "LinearMath/btVector3.h"

class btCollisionObject;
class btDispatcher;
class btTypedConstraint;

namespace plastic
{
// a box's faces, in its own frame: the +axis face and the -axis face of each axis
enum BoxFace
{
	kFacePlusX = 1,
	kFaceMinusX = 2,
	kFacePlusY = 4,
	kFaceMinusY = 8,
	kFacePlusZ = 16,
	kFaceMinusZ = 32
};

class JoinedFaces
{
public:
	// `box` is joined to `partner` through its face `face` (one BoxFace) by `joint`: while the joint is enabled
	// (btTypedConstraint::isEnabled; a broken joint is not), that face is no surface where the partner covers it. Both
	// are collision objects whose shape is a btBoxShape; the joint must outlive this object or be given again.
	// Returns false, and adds nothing, for a face that is not one BoxFace, a null joint, or an object that is null or
	// whose shape is not a btBoxShape.
	bool add(const btCollisionObject* box, int face, const btCollisionObject* partner, const btTypedConstraint* joint);

	// Removes the contacts of the dispatcher's manifolds whose normal on a box lies within 60 degrees of one of its
	// joined faces' normals (more than 30 degrees from its side faces, towards the joined face), while that face's
	// joint holds, whose point on the box lies in its partner's box (to within the contact's depth and, along each
	// of the partner's axes, 4 % of its half extent there), and whose depth is at most 4 % of the box's smaller half
	// extent across the face: a point on an end face that the partner does not cover (a seam out of line, or opened
	// on the outside of a fold) is a surface and stays, and so is a deeper contact (a body sinking into the member).
	// Call it after the collision detection of a step and before its solve (a world's
	// performDiscreteCollisionDetection). A pair that touches only through such points has no contact in that step:
	// contact-ended callbacks fire. Returns the contacts it removed.
	int removeContacts(btDispatcher& dispatcher) const;

private:
	struct Face
	{
		const btCollisionObject* box;
		int axis;  // 0-2 in the box's frame
		bool plus; // the +axis face
		const btCollisionObject* partner;
		const btTypedConstraint* joint;
	};
	std::vector<Face> m_faces;  // few: searched linearly
	// the joined face of `box` that a contact with normal `outOfBox` (out of the box) at `onBox` (its point on the box)
	// pushes on, and which its partner covers there
	bool onJoinedFace(const btCollisionObject* box, const btVector3& outOfBox, const btVector3& onBox, btScalar depth) const;
};
}  // namespace plastic
