#include "SteelFrame.h"

#include <algorithm>
#include <limits>


namespace game
{
plastic::BeamSpec SteelFrame::memberSpec(const SteelFrameSpec& spec, const btVector3& start, const btVector3& end, int segments)
{
	plastic::BeamSpec member;
	member.may_sleep = spec.may_sleep;
	member.start_m = start;
	member.end_m = end;
	member.segments = segments;
	member.joint = spec.joint;
	member.bending_axis = btVector3(0, 0, 1);
	return member;
}

SteelFrame::SteelFrame(btDiscreteDynamicsWorld& world, const SteelFrameSpec& spec, btRigidBody& ground, double internalStep_s) : m_world(world), m_spec(spec)
{
	const btScalar L = btScalar(spec.span_m), h = btScalar(spec.height_m);
	const btVector3 o = spec.origin_m;
	const int lines = spec.bays + 1;
	m_columns.resize(size_t(lines));
	m_beams.resize(size_t(spec.storeys));
	m_endSpecs.reserve(size_t(spec.storeys * spec.bays));
	m_endJoints.reserve(size_t(spec.storeys * spec.bays));
	for (int k = 0; k < spec.storeys; k++)
	{
		for (int c = 0; c < lines; c++)
		{
			btRigidBody* support = k == 0 ? &ground : m_columns[size_t(c)][size_t(k - 1)]->segments().back();
			m_columns[size_t(c)].push_back(std::make_unique<plastic::Beam>(
				world, memberSpec(spec, o + btVector3(L * btScalar(c), h * btScalar(k), 0), o + btVector3(L * btScalar(c), h * btScalar(k + 1), 0), spec.column_segments),
				support));
		}
		for (int b = 0; b < spec.bays; b++)
		{
			btRigidBody* left = m_columns[size_t(b)][size_t(k)]->segments().back();
			btRigidBody* right = m_columns[size_t(b + 1)][size_t(k)]->segments().back();
			const btVector3 end = o + btVector3(L * btScalar(b + 1), h * btScalar(k + 1), 0);
			m_beams[size_t(k)].push_back(std::make_unique<plastic::Beam>(world, memberSpec(spec, o + btVector3(L * btScalar(b), h * btScalar(k + 1), 0), end, spec.beam_segments), left));
			const plastic::Beam& beam = *m_beams[size_t(k)].back();
			if (beam.segments().empty()) continue;  // refused (errors())
			plastic::JointSpec joint = beam.jointSpecs().back();
			joint.pivot_m = end;
			m_endSpecs.push_back(joint);
			m_endJoints.push_back(plastic::makeJoint(joint, *beam.segments().back(), *right));
			if (m_endJoints.back().constraint) world.addConstraint(m_endJoints.back().constraint.get(), true);
		}
	}
	// every member once: its joints follow the step, and its bodies collide with everything but the frame
	for (const auto& group : {&m_columns, &m_beams})
		for (const auto& row : *group)
			for (const auto& member : row)
			{
				for (size_t j = 0; j < member->joints().size(); j++) plastic::updateJointForStep(*member->joints()[j].constraint, member->jointSpecs()[j], internalStep_s);
				for (btRigidBody* body : member->segments())
				{
					world.removeRigidBody(body);
					world.addRigidBody(body, kSteelFrameGroup, btBroadphaseProxy::AllFilter & ~kSteelFrameGroup);
				}
			}
	for (size_t i = 0; i < m_endJoints.size(); i++)
		if (m_endJoints[i].constraint) plastic::updateJointForStep(*m_endJoints[i].constraint, m_endSpecs[i], internalStep_s);
}

SteelFrame::~SteelFrame()
{
	for (plastic::Joint& j : m_endJoints)
		if (j.constraint) m_world.removeConstraint(j.constraint.get());
	m_endJoints.clear();
	for (auto floor = m_beams.rbegin(); floor != m_beams.rend(); ++floor)
		while (!floor->empty()) floor->pop_back();
	for (auto& line : m_columns)
		while (!line.empty()) line.pop_back();
}

std::vector<btRigidBody*> SteelFrame::bodies() const
{
	std::vector<btRigidBody*> all;
	for (const auto& group : {&m_columns, &m_beams})
		for (const auto& row : *group)
			for (const auto& member : row) all.insert(all.end(), member->segments().begin(), member->segments().end());
	return all;
}

std::vector<const plastic::Joint*> SteelFrame::joints() const
{
	std::vector<const plastic::Joint*> all;
	for (const auto& group : {&m_columns, &m_beams})
		for (const auto& row : *group)
			for (const auto& member : row)
				for (const plastic::Joint& j : member->joints()) all.push_back(&j);
	for (const plastic::Joint& j : m_endJoints) all.push_back(&j);
	return all;
}

std::vector<SteelFrameJoint> SteelFrame::frameJoints() const
{
	std::vector<SteelFrameJoint> all;
	auto addMember = [&all](const plastic::Beam& member, const btRigidBody* support, const std::string& prefix)
	{
		for (size_t j = 0; j < member.joints().size(); j++)
			all.push_back({&member.joints()[j], j == 0 ? support : member.segments()[j - 1], member.segments()[j], member.jointSpecs()[j].pivot_m,
						   prefix + "-" + std::to_string(j)});
	};
	const btScalar L = btScalar(m_spec.span_m), h = btScalar(m_spec.height_m);
	size_t end = 0;
	for (size_t k = 0; k < m_beams.size(); k++)
	{
		for (size_t c = 0; c < m_columns.size(); c++)
			addMember(*m_columns[c][k], k == 0 ? nullptr : m_columns[c][k - 1]->segments().back(),
					  "column-" + std::to_string(c) + "-" + std::to_string(k + 1));
		for (size_t b = 0; b < m_beams[k].size(); b++)
		{
			const plastic::Beam& beam = *m_beams[k][b];
			const std::string prefix = "beam-" + std::to_string(k + 1) + "-" + std::to_string(b + 1);
			addMember(beam, m_columns[b][k]->segments().back(), prefix);
			if (beam.segments().empty()) continue;  // refused: no end joint either
			all.push_back({&m_endJoints[end++], beam.segments().back(), m_columns[b + 1][k]->segments().back(),
						   m_spec.origin_m + btVector3(L * btScalar(b + 1), h * btScalar(k + 1), 0), prefix + "-end"});
		}
	}
	return all;
}

std::vector<btTypedConstraint*> SteelFrame::constraints() const
{
	std::vector<btTypedConstraint*> all;
	for (const plastic::Joint* j : joints())
		if (j->constraint) all.push_back(j->constraint.get());
	return all;
}

double SteelFrame::yieldEnergy_j() const
{
	double least = std::numeric_limits<double>::infinity();
	for (const auto& group : {&m_columns, &m_beams})
		for (const auto& row : *group)
			for (const auto& member : row)
				for (const plastic::JointSpec& j : member->jointSpecs()) least = std::min(least, plastic::jointYieldEnergy_j(j));
	for (const plastic::JointSpec& j : m_endSpecs) least = std::min(least, plastic::jointYieldEnergy_j(j));
	return least;
}

std::vector<std::vector<btRigidBody*>> SteelFrame::memberBodies() const
{
	std::vector<std::vector<btRigidBody*>> all;
	for (const auto& group : {&m_columns, &m_beams})
		for (const auto& row : *group)
			for (const auto& member : row) all.push_back(member->segments());
	return all;
}

std::vector<plastic::JitJoint> SteelFrame::jitJoints() const
{
	std::vector<plastic::JitJoint> all;
	for (const auto& group : {&m_columns, &m_beams})
		for (const auto& row : *group)
			for (const auto& member : row)
				for (size_t j = 0; j < member->joints().size(); j++)
					if (member->joints()[j].constraint) all.push_back(plastic::jitJoint(member->joints()[j], member->jointSpecs()[j]));
	for (size_t j = 0; j < m_endJoints.size(); j++)
		if (m_endJoints[j].constraint) all.push_back(plastic::jitJoint(m_endJoints[j], m_endSpecs[j]));
	return all;
}

double SteelFrame::plasticWork_j() const
{
	double w = 0;
	for (const plastic::Joint* j : joints()) w += j->plasticWork_j();
	return w;
}
}  // namespace game
