// The wrecking ball scene: the frame from the toolkit (columns of every storey and beams of every bay, members of
// segments joined at their nodes; one storey and one bay is a fixed-base portal), the ball on a chain of links, the
// ground; stepped in 60 Hz frames; measured from the bodies after every internal
// step (a tick callback that only reads the world).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "plastic/BeamBuilder.h"
#include "plastic/EnergyLedger.h"
#include "scene/JointSites.h"
#include "scene/Measures.h"
#include "Pendulum.h"
#include "SteelFrame.h"
#include "scene/StructureRig.h"
#include "WreckingBall.h"
#include "scene/Errors.h"

namespace game
{
namespace
{
std::unique_ptr<btRigidBody> makeBody(double mass_kg, btCollisionShape& shape, const btTransform& at)
{
	btVector3 inertia(0, 0, 0);
	if (mass_kg > 0) shape.calculateLocalInertia(btScalar(mass_kg), inertia);
	btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass_kg), nullptr, &shape, inertia);
	info.m_startWorldTransform = at;
	return std::make_unique<btRigidBody>(info);
}
}  // namespace

struct WreckingBallScene::State
{
	explicit State(const WreckingBallParameters& params) : p(params), estimate(wreckingBallEstimate(p)), structure(p.solver), ledger(btVector3(0, btScalar(-p.gravity_m_s2), 0)), swing(btVector3(0, btScalar(-p.gravity_m_s2), 0)) {}

	// as the figures were made: the frame would sleep until the ball wakes it
	SteelFrameSpec frameSpec() const { return steelFrameSpec(p); }

	double relativeRotation(size_t i) const { return angles[i].second->angle_rad() - angles[i].first->angle_rad(); }
	double chainAndBallKinetic() const { return swing.measure().kinetic_j; }
	bool ballTouchesFrame() const;  // a contact between the ball and the frame pushed in the last step
	void afterInternalStep(double step_s);
	static void tick(btDynamicsWorld* world, btScalar step_s) { static_cast<State*>(world->getWorldUserInfo())->afterInternalStep(double(step_s)); }

	WreckingBallParameters p;
	WreckingBallEstimate estimate;
	plastic::StructureWorld structure;
	plastic::EnergyLedger ledger;  // every moving body and every joint
	plastic::EnergyLedger swing;   // the ball and its chain
	// the ground: a static slab whose top is y = 0, under the whole frame
	std::unique_ptr<btBoxShape> groundShape;
	std::unique_ptr<btRigidBody> ground;
	std::unique_ptr<SteelFrame> steel;  // the frame's members and joints
	std::vector<const plastic::Joint*> joints;  // one storey and bay: along the frame, base-left .. base-right
	std::vector<std::string> names;
	std::vector<scene::JointSite> sites;
	std::vector<std::unique_ptr<scene::PlanarAngle>> bodyAngles;
	std::vector<std::pair<const scene::PlanarAngle*, const scene::PlanarAngle*>> angles;  // per joint: body a, body b
	std::vector<double> measuredAtBreak;                                                            // per joint, the measured rotation when it broke (NaN: not broken)
	std::vector<double> brokenAt_s;
	std::unique_ptr<Pendulum> pendulum;  // the ball and its chain
	btRigidBody* ball = nullptr;
	std::vector<const btRigidBody*> frameBodies;
	double initial_mechanical_j = 0;  // kinetic + potential at the start
	double previousChainKinetic_j = 0;
	double previousBallSpeed_m_s = 0;
	double impact_kinetic_j = 0;
	double impact_speed_m_s = 0;
	bool impacted = false;
	double time_s = 0;          // frames x frame time
	double internalTime_s = 0;  // internal steps taken
	long frames = 0;
	long internalSteps = 0;
	double wall_s = 0;
	double maxFrameWall_s = 0;
	double maxGain_j = -1e300;
	bool finite = true;
};

bool WreckingBallScene::State::ballTouchesFrame() const
{
	btDispatcher* dispatcher = const_cast<plastic::StructureWorld&>(structure).world().getDispatcher();
	for (int i = 0; i < dispatcher->getNumManifolds(); i++)
	{
		const btPersistentManifold* m = dispatcher->getManifoldByIndexInternal(i);
		const btCollisionObject* other = m->getBody0() == ball ? m->getBody1() : m->getBody1() == ball ? m->getBody0()
																									   : nullptr;
		if (!other || std::find(frameBodies.begin(), frameBodies.end(), other) == frameBodies.end()) continue;
		for (int c = 0; c < m->getNumContacts(); c++)
			if (m->getContactPoint(c).getAppliedImpulse() > 0) return true;
	}
	return false;
}

void WreckingBallScene::State::afterInternalStep(double step_s)
{
	internalSteps++;
	internalTime_s += step_s;
	for (auto& a : bodyAngles) a->update();
	for (size_t i = 0; i < joints.size(); i++)
		if (std::isnan(measuredAtBreak[i]) && !joints[i]->constraint->isEnabled())
		{
			measuredAtBreak[i] = relativeRotation(i);
			brokenAt_s[i] = internalTime_s;
		}
	if (!impacted && ballTouchesFrame())
	{
		impacted = true;
		impact_kinetic_j = previousChainKinetic_j;
		impact_speed_m_s = previousBallSpeed_m_s;
	}
	previousChainKinetic_j = chainAndBallKinetic();
	previousBallSpeed_m_s = ball->getLinearVelocity().length();
}

WreckingBallScene::WreckingBallScene(const WreckingBallParameters& p)
{
	const std::vector<std::string> errors = validateWreckingBallParameters(p);
	if (!errors.empty()) throw std::invalid_argument(errors.front());
	m = std::make_unique<State>(p);
	State& s = *m;
	btDiscreteDynamicsWorld& world = s.structure.world();
	world.setGravity(btVector3(0, btScalar(-p.gravity_m_s2), 0));
	const btScalar L = btScalar(p.span_m), h = btScalar(p.height_m);
	s.groundShape = std::make_unique<btBoxShape>(btVector3(std::max(btScalar(20), L * btScalar(p.bays)), 0.5, 20));
	s.ground = makeBody(0, *s.groundShape, btTransform(btMatrix3x3::getIdentity(), btVector3(btScalar(p.span_m * p.bays / 2), -0.5, 0)));
	world.addRigidBody(s.ground.get());

	for (const plastic::BeamSpec& member : {SteelFrame::memberSpec(s.frameSpec(), btVector3(0, 0, 0), btVector3(0, h, 0), p.column_segments),
											 SteelFrame::memberSpec(s.frameSpec(), btVector3(0, h, 0), btVector3(L, h, 0), p.beam_segments)})
		scene::requireValid(member);
	s.steel = std::make_unique<SteelFrame>(world, s.frameSpec(), *s.ground, p.solver.internal_step_s);
	std::vector<SteelFrameJoint> frame = s.steel->frameJoints();
	const bool portal = p.storeys == 1 && p.bays == 1;
	if (portal)
	{
		// the portal's joints along the frame, named as the frame's joints always were: base-left, column-left-1..,
		// knee-left, beam-1.., knee-right, column-right-1.. (from the knee down), base-right
		const int n = p.column_segments, m = p.beam_segments;
		std::vector<SteelFrameJoint> along;
		for (int j = 0; j < n; j++) along.push_back(frame[size_t(j)]);
		for (int j = 0; j <= m; j++) along.push_back(frame[size_t(2 * n + j)]);
		for (int j = n - 1; j >= 0; j--) along.push_back(frame[size_t(n + j)]);
		auto portalName = [n, m](int k) -> std::string
		{
			if (k == 0) return "base-left";
			if (k < n) return "column-left-" + std::to_string(k);
			if (k == n) return "knee-left";
			if (k < n + m) return "beam-" + std::to_string(k - n);
			if (k == n + m) return "knee-right";
			if (k < 2 * n + m) return "column-right-" + std::to_string(k - n - m);
			return "base-right";
		};
		for (size_t i = 0; i < along.size(); i++) along[i].name = portalName(int(i));
		frame = along;
	}
	else
	{
		for (SteelFrameJoint& j : frame)
			if (j.name.size() > 2 && j.name.compare(0, 7, "column-") == 0 && j.a == nullptr) j.name = "base-" + j.name.substr(7, j.name.find('-', 7) - 7);
	}
	std::vector<const btRigidBody*> bodies = {nullptr};
	for (const SteelFrameJoint& j : frame)
	{
		s.joints.push_back(j.joint);
		s.names.push_back(j.name);
		for (const btRigidBody* body : {j.a, j.b})
			if (std::find(bodies.begin(), bodies.end(), body) == bodies.end()) bodies.push_back(body);
	}
	for (const btRigidBody* body : bodies) s.bodyAngles.push_back(std::make_unique<scene::PlanarAngle>(body));
	auto angleOf = [&](const btRigidBody* body)
	{ return s.bodyAngles[size_t(std::find(bodies.begin(), bodies.end(), body) - bodies.begin())].get(); };
	for (const SteelFrameJoint& j : frame)
	{
		s.angles.push_back({angleOf(j.a), angleOf(j.b)});
		s.sites.push_back(scene::jointSite(*j.joint, j.a, *j.b, j.pivot_m));
	}
	for (const plastic::Joint* j : s.joints) s.ledger.addJoint(*j);
	s.measuredAtBreak.assign(s.joints.size(), std::nan(""));
	s.brokenAt_s.assign(s.joints.size(), -1);
	for (size_t i = 1; i < bodies.size(); i++)
	{
		s.frameBodies.push_back(bodies[i]);
		s.ledger.addBody(*bodies[i]);
	}

	// the ball at the release angle, away from the frame (towards -x); at the bottom of its swing 2 cm from the column
	const PendulumSpec pendulum = pendulumSpec(p);
	s.pendulum = std::make_unique<Pendulum>(world, pendulum);
	s.ball = &s.pendulum->ball();
	s.ledger.addBody(*s.ball);
	s.swing.addBody(*s.ball);
	for (const btRigidBody* l : s.pendulum->links())
	{
		s.ledger.addBody(*l);
		s.swing.addBody(*l);
	}

	const plastic::Energies e = s.ledger.measure();
	s.initial_mechanical_j = e.kinetic_j + e.potential_j;
	s.previousChainKinetic_j = s.chainAndBallKinetic();
	world.setInternalTickCallback(State::tick, m.get());
}

WreckingBallScene::~WreckingBallScene()
{
	if (!m) return;
	State& s = *m;
	btDiscreteDynamicsWorld& world = s.structure.world();
	world.setInternalTickCallback(nullptr);
	s.pendulum.reset();
	s.steel.reset();
	world.removeRigidBody(s.ground.get());
}

bool WreckingBallScene::done() const { return !m->finite || m->time_s >= m->p.duration_s - 1e-9; }
double WreckingBallScene::time_s() const { return m->time_s; }
btDiscreteDynamicsWorld& WreckingBallScene::world() { return m->structure.world(); }
const btRigidBody& WreckingBallScene::ball() const { return *m->ball; }
const WreckingBallParameters& WreckingBallScene::parameters() const { return m->p; }
std::vector<const btRigidBody*> WreckingBallScene::frameBodies() const { return m->frameBodies; }
std::vector<const btRigidBody*> WreckingBallScene::chainBodies() const { return m->pendulum->links(); }

void WreckingBallScene::step()
{
	State& s = *m;
	if (done()) return;
	const double frame_s = 1.0 / s.p.frame_rate_hz;
	const auto start = std::chrono::steady_clock::now();
	s.structure.stepFrame(frame_s);
	const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	s.wall_s += wall;
	s.maxFrameWall_s = std::max(s.maxFrameWall_s, wall);
	s.frames++;
	s.time_s = s.frames * frame_s;
	// energy gained since the start: what the bodies and joints hold now, booked plastic work included, against
	// the mechanical energy at the start (the ball starts at rest: its potential energy)
	const plastic::Energies e = s.ledger.measure();
	const double balanceGain = e.kinetic_j + e.potential_j + e.elastic_j + e.plastic_j - s.initial_mechanical_j;
	s.maxGain_j = std::max(s.maxGain_j, balanceGain);
	if (!std::isfinite(balanceGain)) s.finite = false;
}

WreckingBallResult WreckingBallScene::result() const
{
	const State& s = *m;
	WreckingBallResult r;
	r.estimate = s.estimate;
	const double mp = s.estimate.plastic_moment_nm;
	for (size_t i = 0; i < s.joints.size(); i++)
	{
		FrameJointResult j;
		j.name = s.names[i];
		j.plastic_moment_nm = mp;
		j.booked_rotation_rad = s.joints[i]->plasticRotation_rad();
		j.broken = !s.joints[i]->constraint->isEnabled();
		j.measured_rotation_rad = std::isnan(s.measuredAtBreak[i]) ? s.relativeRotation(i) : s.measuredAtBreak[i];
		j.booked_work_j = s.joints[i]->plasticWork_j();
		// a rigid-plastic joint absorbs Mp over its rotation up to its limit: the rest of the step that broke it is
		// free motion
		j.measured_work_j = mp * (j.broken ? std::min(std::fabs(j.measured_rotation_rad), s.p.max_plastic_rotation_rad) : std::fabs(j.measured_rotation_rad));
		j.broken_at_s = j.broken ? s.brokenAt_s[i] : -1;
		r.plastic_booked_j += j.booked_work_j;
		r.plastic_measured_j += j.measured_work_j;
		if (j.broken) r.broken_joints++;
		if ((s.joints[i]->plasticState ? j.booked_rotation_rad : std::fabs(j.measured_rotation_rad)) > scene::kYieldedRotation_rad) r.yielded_joints++;
		r.joints.push_back(j);
	}
	const plastic::Energies e = s.ledger.measure();
	r.impact_kinetic_j = s.impact_kinetic_j;
	r.impact_speed_m_s = s.impact_speed_m_s;
	r.gravity_work_j = s.initial_mechanical_j - e.potential_j;  // the ball starts at rest: the initial mechanical energy is potential
	r.kinetic_j = e.kinetic_j;
	r.elastic_j = e.elastic_j;
	r.max_energy_gain_j = s.frames ? s.maxGain_j : 0.0;
	r.dissipated_j = r.gravity_work_j - (r.kinetic_j + r.elastic_j + r.plastic_booked_j);
	r.frames = s.frames;
	r.internal_steps = s.internalSteps;
	r.simulated_s = s.time_s;
	r.wall_s = s.wall_s;
	r.real_time_factor = s.wall_s > 0 ? s.time_s / s.wall_s : 0.0;
	r.max_frame_wall_s = s.maxFrameWall_s;
	r.solver_fallbacks = s.structure.solverFallbacks();
	r.finite = s.finite;
	return r;
}

std::vector<scene::JointView> WreckingBallScene::joints() const
{
	std::vector<scene::JointView> views;
	for (size_t i = 0; i < m->sites.size(); i++) views.push_back(scene::jointView(m->sites[i], m->relativeRotation(i)));
	return views;
}

scene::SceneLedger WreckingBallScene::ledger() const
{
	const WreckingBallResult r = result();
	scene::SceneLedger l;
	l.title = std::string("wrecking ball, ") + plastic::jointMethodName(m->p.method);
	l.time_s = r.simulated_s;
	l.load_work_j = r.gravity_work_j;
	l.kinetic_j = r.kinetic_j;
	l.plastic_booked_j = r.plastic_booked_j;
	l.plastic_measured_j = r.plastic_measured_j;
	char line[200];
	std::snprintf(line, sizeof line, "release: %.0f J, %.2f m/s at the bottom", r.estimate.release_energy_j, r.estimate.impact_speed_m_s);
	l.answer.push_back(line);
	std::snprintf(line, sizeof line, "Mp %.1f kN m, breaks past %.2f rad", r.estimate.plastic_moment_nm / 1e3, m->p.max_plastic_rotation_rad);
	l.answer.push_back(line);
	if (r.impact_kinetic_j > 0)
	{
		std::snprintf(line, sizeof line, "impact %.0f J; yielded %d, broken %d joints", r.impact_kinetic_j, r.yielded_joints, r.broken_joints);
		l.status.push_back(line);
	}
	// no wall-clock figure on screen: the frames are the same bytes run to run (the runner reports the real-time factor)
	std::snprintf(line, sizeof line, "%ld frames, %ld internal steps", r.frames, r.internal_steps);
	l.status.push_back(line);
	return l;
}

WreckingBallResult runWreckingBall(const WreckingBallParameters& p) { return scene::runToEnd<WreckingBallScene>(p); }

scene::WorldBox WreckingBallScene::viewEnvelope() const
{
	// The frame (bays x span by storeys x height on the ground), the ball's swing from its release (left of the frame)
	// up to the chain's pivot, and the debris: broken members fall over to the right, as far as a storey's height.
	const WreckingBallParameters& p = m->p;
	const double radius_m = p.chain_length_m + p.ball_radius_m;  // pivot to the ball's centre
	const double bottom_x_m = -(p.section_depth_m / 2 + p.ball_radius_m + 0.02);
	const double pivot_y_m = p.impact_height_m + radius_m;
	const double release_x_m = bottom_x_m - radius_m * std::sin(std::min(p.release_angle_rad, 1.5707963));
	const double pad_m = p.section_depth_m;
	scene::WorldBox box;
	box.min_m = btVector3(btScalar(release_x_m - p.ball_radius_m - pad_m), 0, btScalar(-p.ball_radius_m - pad_m));
	box.max_m = btVector3(btScalar(p.span_m * p.bays + p.height_m + pad_m), btScalar(std::max(pivot_y_m, p.height_m * p.storeys) + pad_m),
						  btScalar(p.ball_radius_m + pad_m));
	return box;
}
}  // namespace game
