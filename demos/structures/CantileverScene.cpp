// The cantilever scene: built from its parameters by the toolkit, stepped, measured from the bodies.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "plastic/BeamBuilder.h"
#include "Cantilever.h"
#include "CollapseTest.h"
#include "plastic/EnergyLedger.h"
#include "scene/JointSites.h"
#include "scene/Measures.h"
#include "scene/DriftActuator.h"
#include "scene/Errors.h"

namespace structures
{
struct CantileverScene::State
{
	explicit State(const CantileverParameters& params)
		: p(params),
		  start(std::chrono::steady_clock::now()),
		  answer(cantileverAnswer(p)),
		  rig(p.solver),
		  beam(rig.world(), scene::requireValid(beamSpec(p)), &rig.ground()),
		  load(*beam.segments().back(), tipPoint(beam), btVector3(0, btScalar(-answer.collapse_load_n), 0), p.follower_load),
		  actuator(*beam.segments().back(), tipPoint(beam), btVector3(0, -1, 0), btVector3(btScalar(p.length_m), 0, 0), driftPath(p), actuatorStiffness(p, beam), tipMass_kg(beam)),
		  test(p, p.ramp_rate_per_s, answer.collapse_ratio),
		  ledger(btVector3(0, 0, 0))
	{
	}

	static plastic::BeamSpec beamSpec(const CantileverParameters& p)
	{
		// the support: the ground, the member along +x from the origin
		plastic::BeamSpec spec = scene::memberBeamSpec(p, btVector3(0, 0, 0), btVector3(btScalar(p.length_m), 0, 0), p.segments, p.solver.method);
		spec.support_joint_half_length = p.support_joint_half_length;
		if (p.stress_strain)
		{
			// the curve's first pair is the material's E and fy
			spec.joint.stress_strain = *p.stress_strain;
			spec.joint.material.yield_stress_pa = plastic::yieldStress_pa(*p.stress_strain);
			spec.joint.material.youngs_modulus_pa = plastic::yieldStress_pa(*p.stress_strain) / plastic::yieldStrain(*p.stress_strain);
		}
		return spec;
	}

	double jointRotation(size_t j) const { return angles[j + 1].angle_rad() - angles[j].angle_rad(); }
	// the segment's local z is the member axis: the tip is half a segment out
	static btVector3 tipPoint(const plastic::Beam& beam) { return btVector3(0, 0, btScalar(beam.segmentLength_m() / 2)); }
	static double tipMass_kg(const plastic::Beam& beam) { return 1.0 / double(beam.segments().back()->getInvMass()); }
	// a pushover's path: to tip_drift, or through the cyclic drifts in order (none: a load, not a pushover)
	static scene::DriftPath driftPath(const CantileverParameters& p)
	{
		scene::DriftPath path;
		if (!p.cyclic_drifts.empty())
			path.drifts = p.cyclic_drifts;
		else if (p.tip_drift > 0)
			path.drifts = {p.tip_drift};
		path.length_m = p.length_m;
		path.rate_per_s = p.drift_rate_per_s;
		return path;
	}
	// a stiff spring on the tip (100 times the member's elastic tip stiffness 3 E I / L^3), soft enough to be stable
	// with the tip segment's mass at the step, critically damped; its integral action takes away the spring's lag, so
	// that the tip reaches its drift also when the spring is soft
	static double actuatorStiffness(const CantileverParameters& p, const plastic::Beam& beam)
	{
		const plastic::BeamSpec spec = beamSpec(p);
		const double EI = spec.joint.material.youngs_modulus_pa * spec.joint.section.second_moment_y_m4;
		return scene::DriftActuator::stableStiffness_n_m(3.0 * EI / std::pow(p.length_m, 3), tipMass_kg(beam), p.solver.world.internal_step_s);
	}
	bool pushover() const { return actuator.active(); }
	double pushoverEnd_s() const { return actuator.end_s() + p.settle_s; }

	CantileverParameters p;
	std::chrono::steady_clock::time_point start;
	CantileverAnswer answer;
	scene::StructureRig rig;
	plastic::Beam beam;
	plastic::PointLoad load;
	// the pushover's: its force down along y
	scene::DriftActuator actuator;
	CollapseTest test;
	std::vector<scene::PlanarAngle> angles;  // the ground, then each segment
	plastic::EnergyLedger ledger;
	std::vector<scene::JointSite> sites;
	bool ramp = false;
	bool finished = false;
	bool finite = true;
	std::vector<int> mechanism;
	double stop_rotation_rad = std::numeric_limits<double>::quiet_NaN();
	double max_root_rotation_rad = 0;
	double max_inner_rotation_rad = 0;
	double maxKinetic = 0;
	std::vector<double> atThird;  // the rotations a third into the run: what they change by after it is creep
};

CantileverScene::CantileverScene(const CantileverParameters& p) : m(std::make_unique<State>(p))
{
	State& s = *m;
	for (btRigidBody* b : s.beam.segments()) b->setCollisionFlags(b->getCollisionFlags() | btCollisionObject::CF_NO_CONTACT_RESPONSE);
	s.ramp = p.ramp_rate_per_s > 0;
	s.load.setFactor(s.ramp || s.pushover() ? 0.0 : p.load_ratio);
	s.angles.emplace_back(nullptr);
	for (btRigidBody* b : s.beam.segments()) s.angles.emplace_back(b);
	for (btRigidBody* b : s.beam.segments()) s.ledger.addBody(*b);
	for (size_t j = 0; j < s.beam.joints().size(); j++)
		s.sites.push_back(scene::jointSite(s.beam.joints()[j], j ? s.beam.segments()[j - 1] : nullptr, *s.beam.segments()[j], s.beam.jointSpecs()[j].pivot_m));
	State* state = m.get();
	s.rig.beforeEachStep([state](double step_s)
						 {
		if (state->ramp)
		{
			state->test.advance(step_s);
			state->load.setFactor(state->test.factor());
		}
		state->load.apply();
		state->actuator.beforeStep(state->rig.time_s(), step_s);
		state->beam.updateForStep(step_s); });
	s.rig.afterEachStep([state]
						{
		state->load.afterStep();
		state->actuator.afterStep();
		for (scene::PlanarAngle& a : state->angles) a.update(); });
}

CantileverScene::~CantileverScene() = default;

bool CantileverScene::done() const
{
	const double end_s = m->pushover() ? std::min(m->p.duration_s, m->pushoverEnd_s()) : m->p.duration_s;
	return m->finished || m->rig.time_s() >= end_s - 1e-12;
}
double CantileverScene::time_s() const { return m->rig.time_s(); }
btDiscreteDynamicsWorld& CantileverScene::world() { return m->rig.world(); }

void CantileverScene::step()
{
	State& s = *m;
	if (done()) return;
	s.rig.step();
	if (s.atThird.empty() && s.rig.time_s() >= s.p.duration_s / 3 - 1e-12)
	{
		for (size_t j = 0; j < s.beam.joints().size(); j++) s.atThird.push_back(s.jointRotation(j));
	}
	const double root = -s.jointRotation(0);  // the tip going down is clockwise
	s.max_root_rotation_rad = std::max(s.max_root_rotation_rad, std::fabs(root));
	for (size_t j = 1; j < s.beam.joints().size(); j++) s.max_inner_rotation_rad = std::max(s.max_inner_rotation_rad, std::fabs(s.jointRotation(j)));
	if (!std::isfinite(root))
	{
		s.finite = false;
		s.finished = true;
		return;
	}
	if (s.ramp)
	{
		std::vector<double> rotations;
		for (size_t j = 0; j < s.beam.joints().size(); j++) rotations.push_back(s.jointRotation(j));
		s.test.update(s.rig.time_s(), rotations);
		if (s.test.done())
		{
			s.mechanism = s.test.mechanism(rotations);
			s.finished = true;
		}
	}
	else if (!s.p.follower_load && s.p.load_ratio > 1 && !s.pushover())
	{
		const double kinetic = s.ledger.measure().kinetic_j;
		s.maxKinetic = std::max(s.maxKinetic, kinetic);
		// stopped: (almost) no kinetic energy left, or turning back (elastic joints spring back)
		if (root > 0.01 && (kinetic < 1e-4 * s.maxKinetic || root < s.max_root_rotation_rad - 1e-3))
		{
			s.stop_rotation_rad = s.max_root_rotation_rad;
			s.finished = true;
		}
	}
}

CantileverResult CantileverScene::result() const
{
	const State& s = *m;
	CantileverResult r;
	r.answer = s.answer;
	const double mp = s.answer.plastic_moment_nm;
	r.mechanism = s.mechanism;
	r.stop_rotation_rad = s.stop_rotation_rad;
	r.max_root_rotation_rad = s.max_root_rotation_rad;
	r.max_inner_rotation_rad = s.max_inner_rotation_rad;
	r.collapse_ratio = s.test.collapseFactor();
	r.holds = s.test.holds();
	r.root_rotation_rad = -s.jointRotation(0);
	for (size_t j = 0; j < s.atThird.size(); j++) r.creep_rad = std::max(r.creep_rad, std::fabs(s.jointRotation(j) - s.atThird[j]));
	r.load_work_j = s.load.work_j() + s.actuator.work_j();
	r.cyclic_measured_drifts = s.actuator.meanDrifts();
	for (double force_n : s.actuator.meanForces_n()) r.cyclic_load_ratios.push_back(force_n * s.p.length_m / s.answer.plastic_moment_nm);
	// the last target's
	r.measured_tip_drift = r.cyclic_measured_drifts.empty() ? 0.0 : r.cyclic_measured_drifts.back();
	r.drift_load_ratio = r.cyclic_load_ratios.empty() ? 0.0 : r.cyclic_load_ratios.back();
	if (s.p.cyclic_drifts.empty())
	{
		r.cyclic_load_ratios.clear();
		r.cyclic_measured_drifts.clear();
	}
	r.kinetic_j = s.ledger.measure().kinetic_j;
	for (size_t j = 0; j < s.beam.joints().size(); j++) r.geometric_plastic_work_j += mp * std::fabs(s.jointRotation(j));
	r.booked_plastic_work_j = s.beam.plasticWork_j();
	r.energy_balance_error_pct = r.load_work_j > 0 ? 100.0 * (r.load_work_j - r.kinetic_j - r.geometric_plastic_work_j) / r.load_work_j : 0.0;
	static_cast<scene::RunStats&>(r) = s.rig.runStats(s.start, s.finite);
	return r;
}

std::vector<scene::JointView> CantileverScene::joints() const
{
	std::vector<scene::JointView> views;
	for (size_t j = 0; j < m->sites.size(); j++) views.push_back(scene::jointView(m->sites[j], m->jointRotation(j)));
	return views;
}

scene::SceneLedger CantileverScene::ledger() const
{
	const CantileverResult r = result();
	const CantileverParameters& p = m->p;
	scene::SceneLedger l;
	l.title = std::string("cantilever, ") + plastic::jointMethodName(p.solver.method);
	l.time_s = r.simulated_s;
	l.load_work_j = r.load_work_j;
	l.kinetic_j = r.kinetic_j;
	l.plastic_booked_j = r.booked_plastic_work_j;
	l.plastic_measured_j = r.geometric_plastic_work_j;
	char line[160];
	std::snprintf(line, sizeof line, "analytic: collapse at P = Mp / L = %.0f N", r.answer.collapse_load_n);
	l.answer.push_back(line);
	if (p.ramp_rate_per_s > 0)
	{
		std::snprintf(line, sizeof line, "load P L / Mp %.3f", m->load.factor());
		l.status.push_back(line);
		if (std::isfinite(r.collapse_ratio))
		{
			std::snprintf(line, sizeof line, "collapsed at P L / Mp = %.3f (analytic 1)", r.collapse_ratio);
			l.status.push_back(line);
		}
	}
	else
	{
		std::snprintf(line, sizeof line, "analytic stop (P L sin t = Mp t): %.3f rad", r.answer.stop_rotation_rad);
		l.answer.push_back(line);
		std::snprintf(line, sizeof line, "load P L / Mp %.2f, root rotation %.3f rad", p.load_ratio, r.root_rotation_rad);
		l.status.push_back(line);
		if (std::isfinite(r.stop_rotation_rad))
		{
			std::snprintf(line, sizeof line, "stopped at %.3f rad", r.stop_rotation_rad);
			l.status.push_back(line);
		}
	}
	return l;
}

CantileverResult runCantilever(const CantileverParameters& p) { return scene::runToEnd<CantileverScene>(p); }

scene::WorldBox CantileverScene::viewEnvelope() const
{
	// The member turns about its root (the origin), the tip down, through the arc its length sweeps: to the analytic
	// stop of a dead load (and 10 % past it), a little past the collapse under a ramp (held there, the lever shortens as
	// it turns), all the way round under a follower load above collapse (it never stops).
	const CantileverParameters& p = m->p;
	const double pi = 3.14159265358979;
	const double stop_rad = m->answer.stop_rotation_rad;
	double turn_rad = pi;
	if (p.ramp_rate_per_s > 0)
		turn_rad = 0.3;
	else if (std::isfinite(stop_rad))
		turn_rad = std::min(pi, 1.1 * stop_rad + 0.05);
	const double L = p.length_m;
	const double pad_m = p.section_depth_m;  // the member's depth, half on each side, and as much again
	scene::WorldBox box;
	box.min_m = btVector3(btScalar(std::min(0.0, L * std::cos(turn_rad)) - pad_m), btScalar(-L * (turn_rad < pi / 2 ? std::sin(turn_rad) : 1.0) - pad_m),
						  btScalar(-p.section_width_m));
	box.max_m = btVector3(btScalar(L + pad_m), btScalar(pad_m), btScalar(p.section_width_m));
	return box;
}
}  // namespace structures
