// The portal frame scene: built from its parameters by the toolkit (three members, the right base joined to the
// ground by the factory), the load factor ramped quasi-statically, the collapse and its mechanism measured from
// the bodies.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "plastic/BeamBuilder.h"
#include "CollapseTest.h"
#include "plastic/EnergyLedger.h"
#include "scene/JointSites.h"
#include "scene/Measures.h"
#include "Portal.h"
#include "scene/DriftActuator.h"
#include "scene/Errors.h"

namespace structures
{
namespace
{
plastic::BeamSpec memberSpec(const PortalParameters& p, const btVector3& start, const btVector3& end, int segments)
{
	return scene::memberBeamSpec(p, start, end, segments, p.solver.method);
}
}  // namespace

struct PortalScene::State
{
	explicit State(const PortalParameters& params)
		: p(params),
		  start(std::chrono::steady_clock::now()),
		  answer(portalAnswer(p)),
		  rig(p.solver),
		  L(btScalar(p.span_m)),
		  h(btScalar(p.height_m)),
		  // left column from its base up, fixed to the ground
		  columnLeft(rig.world(), scene::requireValid(memberSpec(p, btVector3(0, 0, 0), btVector3(0, h, 0), p.column_segments)), &rig.ground()),
		  // the beam from the left knee, joined to the left column's top
		  beam(rig.world(), scene::requireValid(memberSpec(p, btVector3(0, h, 0), btVector3(L, h, 0), p.beam_segments)), columnLeft.segments().back()),
		  // the right column from the right knee down, joined to the beam's end; its base joined to the ground
		  columnRight(rig.world(), scene::requireValid(memberSpec(p, btVector3(L, h, 0), btVector3(L, 0, 0), p.column_segments)), beam.segments().back()),
		  baseSpec(baseOf(columnRight, L)),
		  base(plastic::makeJoint(scene::requireValid(baseSpec), *columnRight.segments().back(), rig.ground())),
		  baseInWorld(rig.world(), *base.constraint),
		  // loads: H at the left knee (the top end of the left column), V at mid-span (the end of the beam's left half)
		  horizontal(*columnLeft.segments().back(), btVector3(0, 0, btScalar(columnLeft.segmentLength_m() / 2)),
					 btVector3(btScalar(p.horizontal_load_n), 0, 0), false),
		  vertical(*beam.segments()[size_t(p.beam_segments / 2 - 1)], btVector3(0, 0, btScalar(beam.segmentLength_m() / 2)),
				   btVector3(0, btScalar(-p.vertical_load_n), 0), false),
		  kneeLeft(*columnLeft.segments().back(), btVector3(0, 0, btScalar(columnLeft.segmentLength_m() / 2)), btVector3(0, btScalar(-p.knee_load_n), 0), false),
		  kneeRight(*columnRight.segments().front(), btVector3(0, 0, btScalar(-columnRight.segmentLength_m() / 2)), btVector3(0, btScalar(-p.knee_load_n), 0), false),
		  actuator(*columnLeft.segments().back(), btVector3(0, 0, btScalar(columnLeft.segmentLength_m() / 2)), btVector3(1, 0, 0), btVector3(0, h, 0), swayPath(p),
				   actuatorStiffness(p, columnLeft), kneeMass_kg(columnLeft)),
		  test(p, p.ramp_rate_per_s, answer.collapse_factor),
		  ledger(btVector3(0, 0, 0))
	{
	}

	static plastic::JointSpec baseOf(const plastic::Beam& columnRight, btScalar L)
	{
		plastic::JointSpec s = columnRight.jointSpecs().back();
		s.pivot_m = btVector3(L, 0, 0);
		return s;
	}

	// the sway pushover's path: from 0 once the knee loads are on
	static scene::DriftPath swayPath(const PortalParameters& p)
	{
		scene::DriftPath path;
		path.drifts = p.sway_drifts;
		path.length_m = p.height_m;
		path.rate_per_s = p.drift_rate_per_s;
		path.start_s = p.knee_load_ramp_s;
		return path;
	}
	static double kneeMass_kg(const plastic::Beam& columnLeft) { return 1.0 / double(columnLeft.segments().back()->getInvMass()); }
	// 100 times the sway stiffness of two fixed-base columns under a rigid beam (24 E I / h^3, more than the frame's),
	// as far as it is stable with the knee segment's mass at the step
	static double actuatorStiffness(const PortalParameters& p, const plastic::Beam& columnLeft)
	{
		const double EI = p.youngs_modulus_pa * plastic::rectangle(p.section_width_m, p.section_depth_m).second_moment_y_m4;
		return scene::DriftActuator::stableStiffness_n_m(24.0 * EI / std::pow(p.height_m, 3), kneeMass_kg(columnLeft), p.solver.world.internal_step_s);
	}
	bool pushover() const { return actuator.active(); }
	// the knee loads' factor at time t: raised from 0 to 1 over knee_load_ramp_s
	double kneeFactor(double t) const { return std::min(1.0, t / p.knee_load_ramp_s); }

	std::vector<double> rotations() const
	{
		std::vector<double> x;
		for (size_t i = 0; i + 1 < angles.size(); i++) x.push_back(angles[i + 1].angle_rad() - angles[i].angle_rad());
		return x;
	}

	PortalParameters p;
	std::chrono::steady_clock::time_point start;
	PortalAnswer answer;
	scene::StructureRig rig;
	btScalar L, h;
	plastic::Beam columnLeft, beam, columnRight;
	plastic::JointSpec baseSpec;
	plastic::Joint base;
	scene::ConstraintInWorld baseInWorld;
	plastic::PointLoad horizontal, vertical;
	plastic::PointLoad kneeLeft, kneeRight;  // gravity
	scene::DriftActuator actuator;           // the sway pushover's, at the left knee along x
	CollapseTest test;
	plastic::EnergyLedger ledger;
	std::vector<const btRigidBody*> path;  // the bodies in order along the frame, the ground at both ends
	std::vector<scene::PlanarAngle> angles;
	std::vector<const plastic::Joint*> joints;  // site i joins body i and body i + 1
	std::vector<scene::JointSite> sites;
	bool finished = false;
	bool finite = true;
	bool ramp = true;               // ramp the load factor (collapse test) or hold it at p.load_factor
	double max_rotation_rad = 0;    // the largest joint rotation seen
	std::vector<double> atThird;    // the rotations a third into the run: what they change by after it is creep
};

PortalScene::PortalScene(const PortalParameters& p) : m(std::make_unique<State>(p))
{
	State& s = *m;
	s.path = {nullptr};
	for (const plastic::Beam* member : {&s.columnLeft, &s.beam, &s.columnRight})
		for (btRigidBody* b : member->segments())
		{
			s.path.push_back(b);
			b->setCollisionFlags(b->getCollisionFlags() | btCollisionObject::CF_NO_CONTACT_RESPONSE);
		}
	s.path.push_back(nullptr);
	for (const btRigidBody* b : s.path) s.angles.emplace_back(b);
	std::vector<btVector3> pivots;
	for (const plastic::Beam* member : {&s.columnLeft, &s.beam, &s.columnRight})
		for (size_t j = 0; j < member->joints().size(); j++)
		{
			s.joints.push_back(&member->joints()[j]);
			pivots.push_back(member->jointSpecs()[j].pivot_m);
		}
	s.joints.push_back(&s.base);
	pivots.push_back(s.baseSpec.pivot_m);
	for (size_t i = 0; i < s.joints.size(); i++)
	{
		// site i joins path[i] and path[i + 1]; the last one (the right base) joins the last segment and the ground
		const btRigidBody* a = s.path[i];
		const btRigidBody* b = s.path[i + 1] ? s.path[i + 1] : s.path[i];
		if (!s.path[i + 1]) a = nullptr;
		s.sites.push_back(scene::jointSite(*s.joints[i], a, *b, pivots[i]));
	}
	for (size_t i = 1; i + 1 < s.path.size(); i++) s.ledger.addBody(*s.path[i]);
	for (const plastic::Joint* joint : s.joints) s.ledger.addJoint(*joint);
	s.ramp = p.ramp_rate_per_s > 0 && !s.pushover();
	State* state = m.get();
	s.rig.beforeEachStep([state](double step_s)
						 {
		const double t = state->rig.time_s();
		// with knee loads the load factor rises once they are on
		if (state->ramp && (state->p.knee_load_n == 0 || t >= state->p.knee_load_ramp_s)) state->test.advance(step_s);
		for (plastic::PointLoad* load : {&state->horizontal, &state->vertical})
		{
			load->setFactor(state->pushover() ? 0.0 : state->ramp ? state->test.factor()
																  : state->p.load_factor);
			load->apply();
		}
		if (state->p.knee_load_n > 0)
			for (plastic::PointLoad* load : {&state->kneeLeft, &state->kneeRight})
			{
				load->setFactor(state->kneeFactor(t));
				load->apply();
			}
		state->actuator.beforeStep(t, step_s);
		state->columnLeft.updateForStep(step_s);
		state->beam.updateForStep(step_s);
		state->columnRight.updateForStep(step_s);
		plastic::updateJointForStep(*state->base.constraint, state->baseSpec, step_s); });
	s.rig.afterEachStep([state]
						{
		for (plastic::PointLoad* load : {&state->horizontal, &state->vertical, &state->kneeLeft, &state->kneeRight}) load->afterStep();
		state->actuator.afterStep();
		for (scene::PlanarAngle& a : state->angles) a.update(); });
}

PortalScene::~PortalScene() = default;

bool PortalScene::done() const
{
	const double end_s = m->pushover() ? std::min(m->p.duration_s, m->actuator.end_s() + m->p.settle_s) : m->p.duration_s;
	return m->finished || m->rig.time_s() >= end_s - 1e-12;
}
double PortalScene::time_s() const { return m->rig.time_s(); }
btDiscreteDynamicsWorld& PortalScene::world() { return m->rig.world(); }

void PortalScene::step()
{
	State& s = *m;
	if (done()) return;
	s.rig.step();
	const std::vector<double> now = s.rotations();
	if (!std::all_of(now.begin(), now.end(), [](double x)
					 { return std::isfinite(x); }))
	{
		s.finite = false;
		s.finished = true;
		return;
	}
	for (double x : now) s.max_rotation_rad = std::max(s.max_rotation_rad, std::fabs(x));
	if (s.atThird.empty() && s.rig.time_s() >= s.p.duration_s / 3 - 1e-12) s.atThird = now;
	if (!s.ramp) return;
	s.test.update(s.rig.time_s(), now);
	if (s.test.done()) s.finished = true;
}

PortalResult PortalScene::result() const
{
	const State& s = *m;
	PortalResult r;
	r.answer = s.answer;
	const double mp = s.answer.plastic_moment_nm;
	r.rotations_rad = s.rotations();
	r.max_rotation_rad = s.max_rotation_rad;
	for (size_t i = 0; i < s.atThird.size(); i++) r.creep_rad = std::max(r.creep_rad, std::fabs(r.rotations_rad[i] - s.atThird[i]));
	r.collapse_factor = s.test.collapseFactor();
	r.holds = s.test.holds();
	r.mechanism_rotations_rad = s.test.mechanismRotations(r.rotations_rad);
	r.mechanism_sites = s.test.mechanism(r.rotations_rad);
	r.mechanism_matches = s.test.done() && r.mechanism_sites == r.answer.mechanism_sites;
	r.collapse_error_pct = 100.0 * (r.collapse_factor - r.answer.collapse_factor) / r.answer.collapse_factor;
	r.load_work_j = s.horizontal.work_j() + s.vertical.work_j() + s.kneeLeft.work_j() + s.kneeRight.work_j() + s.actuator.work_j();
	if (s.pushover())
	{
		r.sway_measured_drifts = s.actuator.meanDrifts();
		for (double force_n : s.actuator.meanForces_n()) r.sway_load_ratios.push_back(force_n * s.p.height_m / (4 * mp));
		for (double d : r.sway_measured_drifts) r.second_order_load_ratios.push_back(swaySecondOrderRatio(s.p, d));
	}
	const plastic::Energies energies = s.ledger.measure();
	r.kinetic_j = energies.kinetic_j;
	r.booked_plastic_work_j = energies.plastic_j;
	r.elastic_j = energies.elastic_j;
	for (double x : r.rotations_rad) r.geometric_plastic_work_j += mp * std::fabs(x);
	if (r.load_work_j > 0) r.energy_balance_error_pct = 100.0 * (r.load_work_j - r.kinetic_j - r.booked_plastic_work_j - r.elastic_j) / r.load_work_j;
	static_cast<scene::RunStats&>(r) = s.rig.runStats(s.start, s.finite);
	return r;
}

std::vector<scene::JointView> PortalScene::joints() const
{
	const std::vector<double> rotations = m->rotations();
	std::vector<scene::JointView> views;
	for (size_t i = 0; i < m->sites.size(); i++) views.push_back(scene::jointView(m->sites[i], rotations[i]));
	return views;
}

scene::SceneLedger PortalScene::ledger() const
{
	const PortalResult r = result();
	const PortalAnswer& a = r.answer;
	scene::SceneLedger l;
	l.title = std::string("portal frame, ") + plastic::jointMethodName(m->p.solver.method);
	l.time_s = r.simulated_s;
	l.load_work_j = r.load_work_j;
	l.kinetic_j = r.kinetic_j;
	l.plastic_booked_j = r.booked_plastic_work_j;
	l.plastic_measured_j = r.geometric_plastic_work_j;
	char line[200];
	std::snprintf(line, sizeof line, "analytic: beam %.3f, sway %.3f, combined %.3f", a.beam_factor, a.sway_factor, a.combined_factor);
	l.answer.push_back(line);
	std::snprintf(line, sizeof line, "collapse factor %.3f (%s)", a.collapse_factor, a.mechanism.c_str());
	l.answer.push_back(line);
	if (m->pushover())
	{
		std::snprintf(line, sizeof line, "sway drift %.4f, H h / 4 Mp %.3f", m->actuator.drift(), m->actuator.force_n() * m->p.height_m / (4 * a.plastic_moment_nm));
		l.status.push_back(line);
		std::snprintf(line, sizeof line, "rigid-plastic, second order: %.3f", swaySecondOrderRatio(m->p, m->actuator.drift()));
		l.answer.push_back(line);
		return l;
	}
	std::snprintf(line, sizeof line, "load factor %.3f", m->test.factor());
	l.status.push_back(line);
	if (std::isfinite(r.collapse_factor))
	{
		std::snprintf(line, sizeof line, "collapsed at %.3f (%+.2f %%), mechanism %s", r.collapse_factor, r.collapse_error_pct,
					  r.mechanism_matches ? "as predicted" : "NOT as predicted");
		l.status.push_back(line);
	}
	return l;
}

PortalResult runPortal(const PortalParameters& p) { return scene::runToEnd<PortalScene>(p); }

scene::WorldBox PortalScene::viewEnvelope() const
{
	// The frame (columns 0..h at x = 0 and L, the beam at h) and its mechanism: the columns sway and the beam sags by
	// turns of a few mechanism rotations (the run holds the load once the collapse is seen and stops soon after).
	const PortalParameters& p = m->p;
	double turn_rad = std::max(0.2, 4 * p.mechanism_rotation_rad);
	for (double d : p.sway_drifts) turn_rad = std::max(turn_rad, std::fabs(d) + 0.05);
	const double pad_m = p.section_depth_m;
	scene::WorldBox box;
	box.min_m = btVector3(btScalar(-turn_rad * p.height_m - pad_m), btScalar(-pad_m), btScalar(-p.section_width_m));
	box.max_m = btVector3(btScalar(p.span_m + turn_rad * p.height_m + pad_m), btScalar(p.height_m + pad_m), btScalar(p.section_width_m));
	return box;
}
}  // namespace structures
