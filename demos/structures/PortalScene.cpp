// The portal frame scene: built from its parameters by the toolkit (three members, the right base joined to the
// ground by the factory), the load factor ramped quasi-statically, the collapse and its mechanism measured from
// the bodies.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "BeamBuilder.h"
#include "EnergyLedger.h"
#include "CollapseTest.h"
#include "Measures.h"
#include "Portal.h"

namespace structures
{
PortalResult runPortal(const PortalParameters& p)
{
	const auto start = std::chrono::steady_clock::now();
	PortalResult r;
	r.answer = portalAnswer(p);
	const double mp = r.answer.plastic_moment_nm;
	StructureRig rig(p.solver);
	plastic::BeamSpec spec;
	spec.section = plastic::rectangle(p.section_width_m, p.section_depth_m);
	spec.material.yield_stress_pa = p.yield_stress_pa;
	spec.material.youngs_modulus_pa = p.youngs_modulus_pa;
	spec.material.density_kg_m3 = p.density_kg_m3;
	spec.bending_axis = btVector3(0, 0, 1);
	spec.method = p.solver.method;
	const btScalar L = btScalar(p.span_m), h = btScalar(p.height_m);
	// left column from its base up, fixed to the ground
	plastic::BeamSpec left = spec;
	left.start_m = btVector3(0, 0, 0);
	left.end_m = btVector3(0, h, 0);
	left.segments = p.column_segments;
	plastic::Beam columnLeft(rig.world(), left, &rig.ground());
	// the beam from the left knee, joined to the left column's top
	plastic::BeamSpec top = spec;
	top.start_m = btVector3(0, h, 0);
	top.end_m = btVector3(L, h, 0);
	top.segments = p.beam_segments;
	plastic::Beam beam(rig.world(), top, columnLeft.segments().back());
	// the right column from the right knee down, joined to the beam's end; its base joined to the ground
	plastic::BeamSpec right = spec;
	right.start_m = btVector3(L, h, 0);
	right.end_m = btVector3(L, 0, 0);
	right.segments = p.column_segments;
	plastic::Beam columnRight(rig.world(), right, beam.segments().back());
	plastic::JointSpec baseSpec = columnRight.jointSpecs().back();
	baseSpec.pivot_m = btVector3(L, 0, 0);
	plastic::Joint base = plastic::makeJoint(baseSpec, *columnRight.segments().back(), rig.ground());
	ConstraintInWorld baseInWorld(rig.world(), *base.constraint);

	// the bodies in order along the frame, the ground at both ends; site i joins body i and body i + 1
	std::vector<const btRigidBody*> path = {nullptr};
	for (const plastic::Beam* member : {&columnLeft, &beam, &columnRight})
		for (btRigidBody* b : member->segments())
		{
			path.push_back(b);
			b->setCollisionFlags(b->getCollisionFlags() | btCollisionObject::CF_NO_CONTACT_RESPONSE);
		}
	path.push_back(nullptr);
	std::vector<PlanarAngle> angles;
	for (const btRigidBody* b : path) angles.emplace_back(b);
	std::vector<const plastic::Joint*> joints;
	for (const plastic::Beam* member : {&columnLeft, &beam, &columnRight})
		for (const plastic::Joint& j : member->joints()) joints.push_back(&j);
	joints.push_back(&base);

	// loads: H at the left knee (the top end of the left column), V at mid-span (the end of the beam's left half)
	btRigidBody& kneeBody = *columnLeft.segments().back();
	btRigidBody& midBody = *beam.segments()[size_t(p.beam_segments / 2 - 1)];
	ScaledLoad horizontal(kneeBody, btVector3(0, 0, btScalar(columnLeft.segmentLength_m() / 2)), btVector3(btScalar(p.horizontal_load_n), 0, 0), false);
	ScaledLoad vertical(midBody, btVector3(0, 0, btScalar(beam.segmentLength_m() / 2)), btVector3(0, btScalar(-p.vertical_load_n), 0), false);
	CollapseTest test({p.ramp_rate_per_s, p.fast_ramp_rate_per_s, p.slow_from_fraction * r.answer.collapse_factor, p.collapse_rate_rad_s,
					   p.rate_window_s, p.mechanism_rotation_rad, p.hold_s});
	plastic::EnergyLedger ledger(btVector3(0, 0, 0));
	for (size_t i = 1; i + 1 < path.size(); i++) ledger.addBody(*path[i]);

	const bool ramp = p.ramp_rate_per_s > 0;
	rig.beforeEachStep([&](double step_s)
					   {
		if (ramp) test.advance(step_s);
		for (ScaledLoad* load : {&horizontal, &vertical})
		{
			load->setFactor(ramp ? test.factor() : p.load_factor);
			load->apply();
		}
		columnLeft.updateForStep(step_s);
		beam.updateForStep(step_s);
		columnRight.updateForStep(step_s);
		plastic::updateJointForStep(*base.constraint, baseSpec, step_s); });
	rig.afterEachStep([&]
					  {
		horizontal.afterStep();
		vertical.afterStep();
		for (PlanarAngle& a : angles) a.update(); });
	auto rotations = [&]
	{
		std::vector<double> x;
		for (size_t i = 0; i + 1 < angles.size(); i++) x.push_back(angles[i + 1].angle_rad() - angles[i].angle_rad());
		return x;
	};
	std::vector<double> atThird;  // the rotations a third into the run: what they change by after it is creep
	while (rig.time_s() < p.duration_s - 1e-12)
	{
		rig.step();
		const std::vector<double> now = rotations();
		if (!std::all_of(now.begin(), now.end(), [](double x)
						 { return std::isfinite(x); }))
		{
			r.finite = false;
			break;
		}
		for (double x : now) r.max_rotation_rad = std::max(r.max_rotation_rad, std::fabs(x));
		if (atThird.empty() && rig.time_s() >= p.duration_s / 3 - 1e-12) atThird = now;
		if (!ramp) continue;
		test.update(rig.time_s(), now);
		if (test.done()) break;
	}
	r.rotations_rad = rotations();
	for (size_t i = 0; i < atThird.size(); i++) r.creep_rad = std::max(r.creep_rad, std::fabs(r.rotations_rad[i] - atThird[i]));
	r.collapse_factor = test.collapseFactor();
	r.holds = test.holds();
	r.mechanism_rotations_rad = test.mechanismRotations(r.rotations_rad);
	r.mechanism_sites = test.mechanism(r.rotations_rad);
	r.mechanism_matches = test.done() && r.mechanism_sites == r.answer.mechanism_sites;
	r.collapse_error_pct = 100.0 * (r.collapse_factor - r.answer.collapse_factor) / r.answer.collapse_factor;
	r.load_work_j = horizontal.work_j() + vertical.work_j();
	r.kinetic_j = ledger.measure().kinetic_j;
	for (const plastic::Joint* j : joints) r.booked_plastic_work_j += j->plasticWork_j();
	for (double x : r.rotations_rad) r.geometric_plastic_work_j += mp * std::fabs(x);
	r.solver_fallbacks = rig.solverFallbacks();
	r.solver_retries = rig.solverRetries();
	r.steps = rig.steps();
	r.simulated_s = rig.time_s();
	r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	return r;
}
}  // namespace structures
