// A member that is one rigid body until it must bend (thesis 4.2, just-in-time subdivision): a Beam of segments and
// plastic joints that, while nothing threatens it, is simulated as one body of the segments' shape and mass, and is
// replaced by its segments and joints just before an impact that can yield one of its joints; once its segments have
// come to rest it becomes one body again, of the shape they have then (a compound of the bent segments).
//
// The transitions keep the mechanics of the whole:
// - subdivide(): each segment moves as the point of the whole body it was (v + w x r, w), so the momentum, the angular
//   momentum and the kinetic energy are the whole's.
// - merge(): the body gets the segments' mass, centre of mass and inertia (parallel axes, principal frame), their
//   momentum and their angular momentum about the centre of mass; the kinetic energy of their motion relative to one
//   another is lost (rigid contact), never gained, and booked (mergeLoss_j).
// The segments and joints are the same objects throughout: while the member is whole they are out of the world and
// keep their plastic state (set, accumulated rotation, absorbed energy, fatigue damage). The whole body is the first
// segment's btRigidBody carrying the member's shape, so the joint to a support (if any) stays on it and keeps working:
// a whole cantilever can still yield at its root.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "BeamBuilder.h"

namespace plastic
{

class JitMember
{
public:
	// The member of spec (its segments and joints, its start fixed to support, or free), made whole at once. A spec that
	// validate(spec) refuses builds nothing (errors()).
	JitMember(btDiscreteDynamicsWorld& world, const BeamSpec& spec, btRigidBody* support);
	~JitMember();
	JitMember(const JitMember&) = delete;
	JitMember& operator=(const JitMember&) = delete;

	const std::vector<std::string>& errors() const { return m_beam.errors(); }
	bool whole() const { return m_whole; }
	// the body in the world while whole (the first segment's, with the member's shape), nullptr once subdivided
	btRigidBody* wholeBody() const { return m_whole ? m_beam.segments().front() : nullptr; }
	const Beam& beam() const { return m_beam; }

	// Replaces the whole body by the segments and joints (nothing when subdivided already).
	void subdivide();
	// Replaces the segments by one body (nothing when whole already, or when a joint from outside the member is on a
	// segment other than the first: join a member to others at its first segment).
	void merge();
	bool mergeable() const;
	// Before a step: subdivides the whole member when a body whose swept box reaches it within lookahead_s can bring more
	// than yieldEnergy_j to it: 1/2 m v^2, v the relative speed, m the other body's mass against a supported member (the
	// support takes what the member does not), the reduced mass of the two against a free one; a moving kinematic body
	// always can. Returns whether it subdivided.
	bool subdivideIfThreatened(double lookahead_s);
	// After a step: merges a subdivided member whose segments are all asleep (Bullet's deactivation, so a member that
	// may not sleep never merges). Returns whether it merged.
	bool mergeIfAtRest();

	double plasticWork_j() const { return m_beam.plasticWork_j(); }
	double mergeLoss_j() const { return m_mergeLoss_j; }  // kinetic energy of relative motion lost at merges
	double yieldEnergy_j() const { return m_yieldEnergy_j; }
	int subdivisions() const { return m_subdivisions; }
	int merges() const { return m_merges; }

private:
	void rebaseSupportJoint(const btTransform& from, const btTransform& to);
	bool isMemberBody(const btCollisionObject* object) const;
	bool isInnerJoint(const btTypedConstraint* c) const;

	btDiscreteDynamicsWorld& m_world;
	Beam m_beam;
	btRigidBody* m_support;
	btCollisionShape* m_segmentShape = nullptr;  // the beam's box, the first segment's own shape
	btScalar m_segmentMass = 0;
	btVector3 m_segmentInertia{0, 0, 0};
	std::unique_ptr<btCompoundShape> m_wholeShape;
	std::vector<btTransform> m_local;  // each segment in the whole body's frame, while whole
	std::vector<std::pair<int, int>> m_filters;  // each segment's collision group and mask in the world
	bool m_whole = false;
	double m_yieldEnergy_j = 0;
	double m_mergeLoss_j = 0;
	int m_subdivisions = 0;
	int m_merges = 0;
};
}  // namespace plastic
