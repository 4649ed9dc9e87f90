// The paper clip scene: the wire's leg on a plastic joint at the vise, turned by a kinematic hand, measured from the
// hand's lock (its moment on the leg) and the leg's motion.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "PaperClip.h"
#include "plastic/EnergyLedger.h"
#include "scene/Errors.h"
#include "scene/JointSites.h"

namespace structures
{
namespace
{
const double kPi = 3.14159265358979323846;
}

struct PaperClipScene::State
{
	explicit State(const PaperClipParameters& params)
		: p((scene::throwIfAny(validatePaperClipParameters(params)), params)),
		  answer(paperClipAnswer(p)),
		  spec(paperClipJointSpec(p)),
		  rig(p.solver),
		  legShape(btVector3(btScalar(p.leg_length_m / 2), btScalar(p.wire_diameter_m / 2), btScalar(p.wire_diameter_m / 2))),
		  handShape(btVector3(btScalar(p.wire_diameter_m), btScalar(p.wire_diameter_m), btScalar(p.wire_diameter_m)))
	{
	}
	const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
	double drivenAngle(double t) const { return p.bend_amplitude_rad * std::sin(2 * kPi * t / p.cycle_period_s); }
	double legAngle() const
	{
		const btVector3 x = leg->getWorldTransform().getBasis().getColumn(0);
		return std::atan2(double(x.y()), double(x.x()));
	}

	PaperClipParameters p;
	PaperClipAnswer answer;
	plastic::JointSpec spec;  // the wire's joint
	scene::StructureRig rig;
	btCylinderShapeX legShape;
	btBoxShape handShape;
	std::unique_ptr<btRigidBody> leg;
	std::unique_ptr<btDefaultMotionState> handMotion;
	std::unique_ptr<btRigidBody> hand;
	plastic::Joint joint;
	std::unique_ptr<btGeneric6DofConstraint> lock;
	btJointFeedback feedback;
	std::unique_ptr<scene::BodyInWorld> legInWorld, handInWorld;
	std::unique_ptr<scene::ConstraintInWorld> jointInWorld, lockInWorld;
	scene::JointSite site;
	plastic::EnergyLedger ledger{btVector3(0, 0, 0)};  // the leg's kinetic energy
	PaperClipResult r;
	double startKinetic_j = 0;
	bool finished = false;
};

PaperClipScene::PaperClipScene(const PaperClipParameters& p) : m(std::make_unique<State>(p))
{
	State& s = *m;
	const double r = p.wire_diameter_m / 2;
	const double mass_kg = p.density_kg_m3 * kPi * r * r * p.leg_length_m;
	btVector3 inertia(0, 0, 0);
	s.legShape.calculateLocalInertia(btScalar(mass_kg), inertia);
	btRigidBody::btRigidBodyConstructionInfo legInfo(btScalar(mass_kg), nullptr, &s.legShape, inertia);
	legInfo.m_startWorldTransform.setIdentity();
	legInfo.m_startWorldTransform.setOrigin(btVector3(btScalar(p.leg_length_m / 2), 0, 0));
	s.leg = std::make_unique<btRigidBody>(legInfo);
	s.leg->setActivationState(DISABLE_DEACTIVATION);  // driven all the time
	s.rig.world().addRigidBody(s.leg.get(), 0, 0);
	s.legInWorld.reset(new scene::BodyInWorld{s.rig.world(), *s.leg});
	// the hand: kinematic, turning about the joint's axis (z through the origin)
	s.handMotion = std::make_unique<btDefaultMotionState>(btTransform::getIdentity());
	s.hand = std::make_unique<btRigidBody>(0, s.handMotion.get(), &s.handShape);
	s.hand->setCollisionFlags(s.hand->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
	s.hand->setActivationState(DISABLE_DEACTIVATION);
	s.rig.world().addRigidBody(s.hand.get(), 0, 0);
	s.handInWorld.reset(new scene::BodyInWorld{s.rig.world(), *s.hand});
	s.joint = plastic::makeJoint(s.spec, *s.leg, s.rig.ground());
	s.jointInWorld = std::make_unique<scene::ConstraintInWorld>(s.rig.world(), *s.joint.constraint);
	s.site = scene::jointSite(s.joint, nullptr, *s.leg, s.spec.pivot_m);
	// the hand's lock: the leg's rotation is the hand's, its position the joint's (linear DOFs free: lower above upper)
	const btTransform inHand(btQuaternion::getIdentity(), btVector3(btScalar(p.leg_length_m / 2), 0, 0));
	s.lock = std::make_unique<btGeneric6DofConstraint>(*s.hand, *s.leg, inHand, btTransform::getIdentity(), true);
	s.lock->setLinearLowerLimit(btVector3(1, 1, 1));
	s.lock->setLinearUpperLimit(btVector3(-1, -1, -1));
	s.lock->setAngularLowerLimit(btVector3(0, 0, 0));
	s.lock->setAngularUpperLimit(btVector3(0, 0, 0));
	s.lock->setJointFeedback(&s.feedback);
	s.lockInWorld = std::make_unique<scene::ConstraintInWorld>(s.rig.world(), *s.lock);
	// the leg starts turning with the hand (no impulsive start)
	const double spin = 2 * kPi * p.bend_amplitude_rad / p.cycle_period_s;
	s.leg->setAngularVelocity(btVector3(0, 0, btScalar(spin)));
	s.leg->setLinearVelocity(btVector3(0, btScalar(spin * p.leg_length_m / 2), 0));
	s.ledger.addBody(*s.leg);
	s.startKinetic_j = s.ledger.measure().kinetic_j;
	s.r.answer = s.answer;
	s.r.break_time_s = std::numeric_limits<double>::quiet_NaN();
	s.r.cycles_to_break = std::numeric_limits<double>::quiet_NaN();
	State* state = m.get();
	s.rig.beforeEachStep([state](double step_s)
						 {
		plastic::updateJointForStep(*state->joint.constraint, state->spec, step_s);
		state->handMotion->setWorldTransform(btTransform(btQuaternion(btVector3(0, 0, 1), btScalar(state->drivenAngle(state->rig.time_s() + step_s))))); });
	s.rig.afterEachStep([state]
						{
		State& s = *state;
		const double t = s.rig.time_s() + s.rig.step_s();  // the rig counts the step after this
		const double moment = double(s.feedback.m_appliedTorqueBodyB.z());
		s.r.hand_work_j += moment * (s.drivenAngle(t) - s.drivenAngle(t - s.rig.step_s()));
		s.r.peak_moment_nm = std::max(s.r.peak_moment_nm, std::fabs(moment));
		const double rotation = s.legAngle();
		if (!std::isfinite(rotation) || !std::isfinite(moment)) s.r.finite = false;
		if (!s.joint.constraint->isEnabled())
		{
			s.r.broken = true;
			s.r.break_time_s = t;
			s.r.cycles_to_break = t / s.p.cycle_period_s;
			s.finished = true;
			return;
		}
		s.r.hysteresis.push_back({t, rotation, moment}); });
}

PaperClipScene::~PaperClipScene() = default;

void PaperClipScene::step()
{
	if (m->finished) return;
	m->rig.step();
	if (!m->r.finite || m->rig.time_s() >= m->p.duration_s - 0.5 * m->rig.step_s()) m->finished = true;
}

bool PaperClipScene::done() const { return m->finished; }
double PaperClipScene::time_s() const { return m->rig.time_s(); }
btDiscreteDynamicsWorld& PaperClipScene::world() { return m->rig.world(); }

PaperClipResult PaperClipScene::result() const
{
	const State& s = *m;
	PaperClipResult r = s.r;
	if (s.joint.plasticState)
	{
		r.fatigue_damage = double(s.joint.plasticState->getFatigueDamage());
		r.plastic_rotation_rad = double(s.joint.plasticState->getCurrentPlasticRotation());
	}
	r.plastic_work_j = s.joint.plasticWork_j();
	r.elastic_j = s.joint.elasticEnergy_j();
	r.start_kinetic_j = s.startKinetic_j;
	r.kinetic_j = s.ledger.measure().kinetic_j;
	r.energy_balance_error_pct =
		r.hand_work_j > 0 ? 100 * (r.hand_work_j - r.plastic_work_j - r.elastic_j - (r.kinetic_j - r.start_kinetic_j)) / r.hand_work_j : 0.0;
	static_cast<scene::RunStats&>(r) = s.rig.runStats(s.start, s.r.finite);
	return r;
}

std::vector<scene::JointView> PaperClipScene::joints() const { return {scene::jointView(m->site, m->legAngle())}; }

scene::SceneLedger PaperClipScene::ledger() const
{
	const PaperClipResult r = result();
	scene::SceneLedger l;
	l.title = std::string("paper clip, ") + plastic::jointMethodName(m->p.solver.method);
	l.time_s = r.simulated_s;
	// the energy in: the hand's work and the leg's kinetic energy at the start
	l.load_work_j = r.hand_work_j + r.start_kinetic_j;
	l.kinetic_j = r.kinetic_j;
	l.plastic_booked_j = r.plastic_work_j;
	l.plastic_measured_j = r.plastic_work_j;
	char line[160];
	std::snprintf(line, sizeof line, "Coffin-Manson: %.2f cycles", r.answer.cycles_to_break);
	l.answer.push_back(line);
	std::snprintf(line, sizeof line, "cycles %.2f, fatigue damage %.3f", r.simulated_s / m->p.cycle_period_s, r.fatigue_damage);
	l.status.push_back(line);
	if (r.broken)
	{
		std::snprintf(line, sizeof line, "broke after %.2f cycles", r.cycles_to_break);
		l.status.push_back(line);
	}
	return l;
}

scene::WorldBox PaperClipScene::viewEnvelope() const
{
	// the leg sweeps +-A about the vise
	const PaperClipParameters& p = m->p;
	const double L = p.leg_length_m, pad = 4 * p.wire_diameter_m;
	const double reach = L * std::sin(p.bend_amplitude_rad);
	scene::WorldBox box;
	box.min_m = btVector3(btScalar(-pad), btScalar(-reach - pad), btScalar(-pad));
	box.max_m = btVector3(btScalar(L + pad), btScalar(reach + pad), btScalar(pad));
	return box;
}

PaperClipResult runPaperClip(const PaperClipParameters& p) { return scene::runToEnd<PaperClipScene>(p); }

}  // namespace structures
