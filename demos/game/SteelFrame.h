// A steel frame on the ground: column lines of every storey and beams of every bay, each member a plastic::Beam of
// segments, the beams' ends joined to the next column line's node, the feet joined to the ground; its bodies collide
// with everything but each other (members meet at the nodes, where segments of members that are not joined overlap).
// It puts its bodies and joints into a world and takes them out again when it is destroyed.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "plastic/BeamBuilder.h"
#include "plastic/JitStructure.h"

namespace game
{
struct SteelFrameSpec
{
	btVector3 origin_m{0, 0, 0};  // the left foot; the frame stands in the x-y plane through it, bays along +x
	int storeys = 1;
	int bays = 1;
	double span_m = 6.0;
	double height_m = 4.0;
	int column_segments = 4;
	int beam_segments = 4;
	// every member's: its section, material, joint method, limits (BeamSpec::joint); and whether its segments may sleep
	plastic::JointSpec joint;
	bool may_sleep = false;
};

// the collision group of every frame's bodies (they collide with other groups, not with each other)
const int kSteelFrameGroup = 1 << 6;

// One joint of a frame: the bodies it joins (a null: the ground), where it was built and its name: column-C-K-J (column
// line C from 0, storey K from 1, joint J of the member from its foot; J = 0 at a foot is the base), beam-K-B-J (floor
// K, bay B from 1, J from the left node), beam-K-B-end (at the right node)
struct SteelFrameJoint
{
	const plastic::Joint* joint = nullptr;
	const btRigidBody* a = nullptr;
	const btRigidBody* b = nullptr;
	btVector3 pivot_m{0, 0, 0};
	std::string name;
};

class SteelFrame
{
public:
	// ground: the static body the feet are joined to. Check a column's and a beam's spec with
	// plastic::validate(memberSpec(...)) first: a refused member is built without bodies, which the frame does not guard.
	SteelFrame(btDiscreteDynamicsWorld& world, const SteelFrameSpec& spec, btRigidBody& ground, double internalStep_s);
	~SteelFrame();
	SteelFrame(const SteelFrame&) = delete;
	SteelFrame& operator=(const SteelFrame&) = delete;

	// a member of the frame from start to end in segments
	static plastic::BeamSpec memberSpec(const SteelFrameSpec& spec, const btVector3& start, const btVector3& end, int segments);

	// columns()[c][k]: column line c (x = c span), storey k, from its foot up; beams()[k][b]: floor k + 1, bay b, left to
	// right; endJoints()[k * bays + b]: that beam's end joint to the right column's node (the top segment of that
	// column's storey)
	const std::vector<std::vector<std::unique_ptr<plastic::Beam>>>& columns() const { return m_columns; }
	const std::vector<std::vector<std::unique_ptr<plastic::Beam>>>& beams() const { return m_beams; }
	const std::vector<plastic::Joint>& endJoints() const { return m_endJoints; }
	// every segment, every joint (the members' own, the feet's, the beams' ends)
	std::vector<btRigidBody*> bodies() const;
	std::vector<btTypedConstraint*> constraints() const;
	std::vector<const plastic::Joint*> joints() const;
	// every joint with its bodies, storey by storey: the columns' (line by line, from the foot), then each bay's beam
	// (from the left) and its end joint
	std::vector<SteelFrameJoint> frameJoints() const;
	// the least energy that yields one of its joints (plastic::jointYieldEnergy_j)
	double yieldEnergy_j() const;
	// every member's segments (bodies() member by member) and every joint (joints()) with what yields it: the frame as a
	// plastic::JitStructure that subdivides member by member
	std::vector<std::vector<btRigidBody*>> memberBodies() const;
	std::vector<plastic::JitJoint> jitJoints() const;
	double plasticWork_j() const;

private:
	btDiscreteDynamicsWorld& m_world;
	SteelFrameSpec m_spec;
	std::vector<std::vector<std::unique_ptr<plastic::Beam>>> m_columns;
	std::vector<std::vector<std::unique_ptr<plastic::Beam>>> m_beams;
	std::vector<plastic::JointSpec> m_endSpecs;
	std::vector<plastic::Joint> m_endJoints;
};
}  // namespace game
