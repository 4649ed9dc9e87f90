// The drop weight scene: the beam from the toolkit, its supports (pin or plastic clamp at the left, roller or
// sliding plastic clamp at the right on a carriage), the ball in contact; measured from the bodies.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "plastic/BeamBuilder.h"
#include "DropWeight.h"
#include "plastic/EnergyLedger.h"
#include "scene/JointSites.h"
#include "scene/Measures.h"
#include "scene/Errors.h"

namespace structures
{
namespace
{
// a free pin about world z at a world point
std::unique_ptr<btHingeConstraint> pin(btRigidBody& a, btRigidBody& b, const btVector3& point_m)
{
	const btTransform frame(btMatrix3x3::getIdentity(), point_m);
	return std::make_unique<btHingeConstraint>(a, b, a.getCenterOfMassTransform().inverse() * frame, b.getCenterOfMassTransform().inverse() * frame);
}

plastic::BeamSpec beamSpec(const DropWeightParameters& p)
{
	return scene::memberBeamSpec(p, btVector3(0, 0, 0), btVector3(btScalar(p.span_m), 0, 0), p.segments, p.solver.method);
}

std::unique_ptr<btRigidBody> makeBody(btScalar mass, btCollisionShape& shape, const btTransform& at)
{
	btVector3 inertia(0, 0, 0);
	shape.calculateLocalInertia(mass, inertia);
	btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, &shape, inertia);
	info.m_startWorldTransform = at;
	return std::make_unique<btRigidBody>(info);
}
}  // namespace

struct DropWeightScene::State
{
	explicit State(const DropWeightParameters& params)
		: p(params),
		  start(std::chrono::steady_clock::now()),
		  answer(dropWeightAnswer(p)),
		  rig(p.solver),
		  beam(rig.world(), scene::requireValid(beamSpec(p)), p.clamped ? &rig.ground() : nullptr),
		  rightEnd(btScalar(p.span_m), 0, 0),
		  carriageShape(btVector3(btScalar(p.section_width_m / 2), btScalar(p.section_depth_m / 2), btScalar(p.section_width_m / 2))),
		  ballShape(btScalar(p.weight_radius_m))
	{
	}

	double site(size_t i) const { return angles[i + 1].angle_rad() - angles[i].angle_rad(); }
	double geometricPlasticWork() const
	{
		double w = 0;
		const size_t sites = angles.size() - 1;
		for (size_t i = 0; i < sites; i++)
			if (p.clamped || (i != 0 && i + 1 != sites)) w += answer.plastic_moment_nm * std::fabs(site(i));
		return w;
	}

	DropWeightParameters p;
	std::chrono::steady_clock::time_point start;
	DropWeightAnswer answer;
	scene::StructureRig rig;
	plastic::Beam beam;
	btVector3 rightEnd;
	btBoxShape carriageShape;
	btSphereShape ballShape;
	// the right end's carriage: a body of one segment's mass that slides along x only
	std::unique_ptr<btRigidBody> carriage;
	std::unique_ptr<scene::BodyInWorld> carriageInWorld;
	std::unique_ptr<btGeneric6DofConstraint> slide;
	std::unique_ptr<scene::ConstraintInWorld> slideInWorld;
	std::unique_ptr<btHingeConstraint> leftPin;
	std::unique_ptr<scene::ConstraintInWorld> leftPinInWorld;
	plastic::JointSpec rightSpec;
	plastic::Joint rightClamp;
	std::unique_ptr<btHingeConstraint> rightPin;
	std::unique_ptr<scene::ConstraintInWorld> rightInWorld;
	std::unique_ptr<btRigidBody> ball;
	std::unique_ptr<scene::BodyInWorld> ballInWorld;
	// the bodies along the beam, site i joins body i and i + 1: the left support, the inner joints, the right support
	std::vector<scene::PlanarAngle> angles;
	std::unique_ptr<plastic::EnergyLedger> ledger;
	std::vector<scene::JointSite> sites;   // the plastic joints
	std::vector<size_t> siteIndex;  // their sites in angles
	size_t mid = 0;
	btVector3 midLocal{0, 0, 0};
	double kinetic_after_impact_j = std::numeric_limits<double>::quiet_NaN();
	double deepest = 0;
	bool finished = false;
	bool finite = true;
};

DropWeightScene::DropWeightScene(const DropWeightParameters& p) : m(std::make_unique<State>(p))
{
	State& s = *m;
	const std::vector<btRigidBody*>& segments = s.beam.segments();
	s.carriage = makeBody(segments.front()->getMass(), s.carriageShape, btTransform(btMatrix3x3::getIdentity(), s.rightEnd));
	s.carriage->setActivationState(DISABLE_DEACTIVATION);
	s.rig.world().addRigidBody(s.carriage.get(), 0, 0);
	s.carriageInWorld.reset(new scene::BodyInWorld{s.rig.world(), *s.carriage});  // in place: a temporary would take the body out
	s.slide = std::make_unique<btGeneric6DofConstraint>(s.rig.ground(), *s.carriage,
														s.rig.ground().getCenterOfMassTransform().inverse() * btTransform::getIdentity(), btTransform::getIdentity(), true);
	s.slide->setLinearLowerLimit(btVector3(1, 0, 0));  // lower > upper: free along x
	s.slide->setLinearUpperLimit(btVector3(-1, 0, 0));
	s.slide->setAngularLowerLimit(btVector3(0, 0, 0));
	s.slide->setAngularUpperLimit(btVector3(0, 0, 0));
	s.slideInWorld = std::make_unique<scene::ConstraintInWorld>(s.rig.world(), *s.slide);

	// the supports: pins, or the method's plastic joints (the left one is the beam's first joint)
	if (!p.clamped)
	{
		s.leftPin = pin(s.rig.ground(), *segments.front(), btVector3(0, 0, 0));
		s.leftPinInWorld = std::make_unique<scene::ConstraintInWorld>(s.rig.world(), *s.leftPin);
	}
	s.rightSpec = s.beam.jointSpecs().empty() ? plastic::JointSpec{} : s.beam.jointSpecs().back();
	s.rightSpec.pivot_m = s.rightEnd;
	if (p.clamped)
		s.rightClamp = plastic::makeJoint(scene::requireValid(s.rightSpec), *segments.back(), *s.carriage);
	else
		s.rightPin = pin(*segments.back(), *s.carriage, s.rightEnd);
	s.rightInWorld = std::make_unique<scene::ConstraintInWorld>(s.rig.world(), p.clamped ? *s.rightClamp.constraint : static_cast<btTypedConstraint&>(*s.rightPin));

	// the ball, just above the middle of the top face
	btVector3 ballInertia;
	s.ballShape.calculateLocalInertia(btScalar(p.weight_mass_kg), ballInertia);
	btRigidBody::btRigidBodyConstructionInfo ballInfo(btScalar(p.weight_mass_kg), nullptr, &s.ballShape, ballInertia);
	ballInfo.m_startWorldTransform.setOrigin(btVector3(btScalar(p.span_m / 2), btScalar(p.section_depth_m / 2 + p.weight_radius_m + 1e-3), 0));
	ballInfo.m_friction = 0;
	ballInfo.m_restitution = 0;
	s.ball = std::make_unique<btRigidBody>(ballInfo);
	s.ball->setActivationState(DISABLE_DEACTIVATION);
	s.ball->setLinearVelocity(btVector3(0, btScalar(-p.impact_speed_m_s), 0));
	s.rig.world().addRigidBody(s.ball.get());
	s.ballInWorld.reset(new scene::BodyInWorld{s.rig.world(), *s.ball});
	for (btRigidBody* b : segments) b->setFriction(0);

	s.angles.emplace_back(nullptr);
	for (btRigidBody* b : segments) s.angles.emplace_back(b);
	s.angles.emplace_back(s.carriage.get());
	s.ledger = std::make_unique<plastic::EnergyLedger>(btVector3(0, 0, 0));
	for (btRigidBody* b : segments) s.ledger->addBody(*b);
	s.ledger->addBody(*s.carriage);
	s.ledger->addBody(*s.ball);
	// and the plastic joints: their booked work and their springs' elastic energy
	for (const plastic::Joint& joint : s.beam.joints()) s.ledger->addJoint(joint);
	if (p.clamped) s.ledger->addJoint(s.rightClamp);
	// the plastic joints: the beam's (with the left clamp first when clamped), then the right clamp
	const size_t first = p.clamped ? 0 : 1;  // site of the beam's first joint
	for (size_t j = 0; j < s.beam.joints().size(); j++)
	{
		const btRigidBody* a = (p.clamped && j == 0) ? nullptr : segments[j + (p.clamped ? 0 : 1) - 1];
		const btRigidBody& b = *segments[j + (p.clamped ? 0 : 1)];
		s.sites.push_back(scene::jointSite(s.beam.joints()[j], a, b, s.beam.jointSpecs()[j].pivot_m));
		s.siteIndex.push_back(first + j);
	}
	if (p.clamped)
	{
		s.sites.push_back(scene::jointSite(s.rightClamp, s.carriage.get(), *segments.back(), s.rightEnd));
		s.siteIndex.push_back(s.angles.size() - 2);
	}
	s.mid = size_t(p.segments / 2);
	s.midLocal = btVector3(0, 0, btScalar(s.beam.segmentLength_m() / 2));

	State* state = m.get();
	s.rig.beforeEachStep([state](double step_s)
						 {
		state->beam.updateForStep(step_s);
		if (state->p.clamped) plastic::updateJointForStep(*state->rightClamp.constraint, state->rightSpec, step_s); });
	s.rig.afterEachStep([state]
						{
		for (scene::PlanarAngle& a : state->angles) a.update(); });
}

DropWeightScene::~DropWeightScene() = default;

bool DropWeightScene::done() const { return m->finished || m->rig.time_s() >= m->p.duration_s - 1e-12; }
double DropWeightScene::time_s() const { return m->rig.time_s(); }
btDiscreteDynamicsWorld& DropWeightScene::world() { return m->rig.world(); }
const btRigidBody& DropWeightScene::ball() const { return *m->ball; }

void DropWeightScene::step()
{
	State& s = *m;
	if (done()) return;
	s.rig.step();
	const plastic::Energies energies = s.ledger->measure();
	const double kinetic = energies.kinetic_j;
	if (!std::isfinite(kinetic))
	{
		s.finite = false;
		s.finished = true;
		return;
	}
	btRigidBody& leftHalfEnd = *s.beam.segments()[s.mid - 1];
	const double midspanVelocity = leftHalfEnd.getVelocityInLocalPoint(leftHalfEnd.getWorldTransform().getBasis() * s.midLocal).y();
	// what the hinges have to absorb once the ball and the middle move together: the kinetic energy then, plus
	// what the joints took during the impact, as plastic work and as elastic energy (Mp times the rotation counts an
	// elastic joint's spring at Mp: 124 J too much for elastic-plastic at 1/3840 s)
	if (std::isnan(s.kinetic_after_impact_j) && std::fabs(s.ball->getLinearVelocity().y() - midspanVelocity) < 0.01 * s.p.impact_speed_m_s)
		s.kinetic_after_impact_j = kinetic + energies.plastic_j + energies.elastic_j;
	const double midspan = s.site(s.mid);
	s.deepest = std::max(s.deepest, midspan);
	// stopped: the middle no longer moves (the ball may drift off), or it springs back
	if (!s.p.run_to_duration && !std::isnan(s.kinetic_after_impact_j) && midspan > 0 &&
		(std::fabs(midspanVelocity) < 1e-3 * s.p.impact_speed_m_s || midspan < s.deepest - 1e-3))
		s.finished = true;
}

DropWeightResult DropWeightScene::result() const
{
	const State& s = *m;
	DropWeightResult r;
	r.answer = s.answer;
	r.kinetic_after_impact_j = s.kinetic_after_impact_j;
	const size_t sites = s.angles.size() - 1;
	r.midspan_rotation_rad = s.site(s.mid);
	r.left_support_rotation_rad = -s.site(0);
	r.right_support_rotation_rad = -s.site(sites - 1);
	for (size_t i = 1; i + 1 < sites; i++)
		if (i != s.mid) r.max_inner_rotation_rad = std::max(r.max_inner_rotation_rad, std::fabs(s.site(i)));
	const plastic::Energies end = s.ledger->measure();
	r.kinetic_end_j = end.kinetic_j;
	r.geometric_plastic_work_j = s.geometricPlasticWork();
	r.booked_plastic_work_j = end.plastic_j;
	r.elastic_end_j = end.elastic_j;
	const DropWeightAnswer& a = r.answer;
	r.midspan_error_pct = 100 * (r.midspan_rotation_rad - a.midspan_rotation_rad) / a.midspan_rotation_rad;
	r.plastic_work_error_pct = 100 * (r.geometric_plastic_work_j - a.kinetic_after_impact_j) / a.kinetic_after_impact_j;
	r.balance_error_pct = 100 * (r.kinetic_after_impact_j - r.kinetic_end_j - r.booked_plastic_work_j - r.elastic_end_j) / r.kinetic_after_impact_j;
	static_cast<scene::RunStats&>(r) = s.rig.runStats(s.start, s.finite);
	return r;
}

std::vector<scene::JointView> DropWeightScene::joints() const
{
	std::vector<scene::JointView> views;
	for (size_t i = 0; i < m->sites.size(); i++) views.push_back(scene::jointView(m->sites[i], m->site(m->siteIndex[i])));
	return views;
}

scene::SceneLedger DropWeightScene::ledger() const
{
	const DropWeightResult r = result();
	const DropWeightAnswer& a = r.answer;
	scene::SceneLedger l;
	l.title = std::string("drop weight, ") + (m->p.clamped ? "clamped, " : "simply supported, ") + plastic::jointMethodName(m->p.solver.method);
	l.time_s = r.simulated_s;
	l.load_work_j = a.initial_kinetic_j;  // the ball's kinetic energy is the load
	l.kinetic_j = r.kinetic_end_j;
	l.plastic_booked_j = r.booked_plastic_work_j;
	l.plastic_measured_j = r.geometric_plastic_work_j;
	char line[200];
	std::snprintf(line, sizeof line, "analytic: after impact %.1f J, mid-span %.3f rad", a.kinetic_after_impact_j, a.midspan_rotation_rad);
	l.answer.push_back(line);
	std::snprintf(line, sizeof line, "mid-span rotation %.3f rad", r.midspan_rotation_rad);
	l.status.push_back(line);
	if (std::isfinite(r.kinetic_after_impact_j))
	{
		std::snprintf(line, sizeof line, "after impact %.1f J", r.kinetic_after_impact_j);
		l.status.push_back(line);
	}
	if (done()) l.status.push_back("stopped");
	return l;
}

DropWeightResult runDropWeight(const DropWeightParameters& p) { return scene::runToEnd<DropWeightScene>(p); }

scene::WorldBox DropWeightScene::viewEnvelope() const
{
	// The beam (0..L along x), the weight on its top face at mid-span, and the mechanism: the halves turn by the
	// analytic half rotation (half as much again, for the estimate's error) and the middle goes down L/2 sin of it.
	const DropWeightParameters& p = m->p;
	const double pi = 3.14159265358979;
	const double theta_rad = std::min(pi / 2, 1.5 * m->answer.half_rotation_rad + 0.05);
	const double pad_m = p.section_depth_m;
	scene::WorldBox box;
	box.min_m = btVector3(btScalar(-pad_m), btScalar(-p.span_m / 2 * std::sin(theta_rad) - pad_m), btScalar(-p.section_width_m));
	box.max_m = btVector3(btScalar(p.span_m + pad_m), btScalar(pad_m + 2 * p.weight_radius_m), btScalar(p.section_width_m));
	return box;
}
}  // namespace structures
