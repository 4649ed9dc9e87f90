// The cantilever scene: built from its parameters by the toolkit, run, measured from the bodies.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "BeamBuilder.h"
#include "Cantilever.h"
#include "EnergyLedger.h"
#include "CollapseTest.h"
#include "Measures.h"

namespace structures
{
CantileverResult runCantilever(const CantileverParameters& p)
{
	const auto start = std::chrono::steady_clock::now();
	CantileverResult r;
	r.answer = cantileverAnswer(p);
	const double mp = r.answer.plastic_moment_nm;
	StructureRig rig(p.solver);
	// the support: the ground, the member along +x from the origin
	plastic::BeamSpec spec;
	spec.start_m = btVector3(0, 0, 0);
	spec.end_m = btVector3(btScalar(p.length_m), 0, 0);
	spec.segments = p.segments;
	spec.section = plastic::rectangle(p.section_width_m, p.section_depth_m);
	spec.material.yield_stress_pa = p.yield_stress_pa;
	spec.material.youngs_modulus_pa = p.youngs_modulus_pa;
	spec.material.density_kg_m3 = p.density_kg_m3;
	spec.bending_axis = btVector3(0, 0, 1);
	spec.method = p.solver.method;
	plastic::Beam beam(rig.world(), spec, &rig.ground());
	for (btRigidBody* b : beam.segments()) b->setCollisionFlags(b->getCollisionFlags() | btCollisionObject::CF_NO_CONTACT_RESPONSE);
	btRigidBody* tip = beam.segments().back();
	// the segment's local z is the member axis: the tip is half a segment out
	ScaledLoad load(*tip, btVector3(0, 0, btScalar(beam.segmentLength_m() / 2)), btVector3(0, btScalar(-r.answer.collapse_load_n), 0), p.follower_load);
	const bool ramp = p.ramp_rate_per_s > 0;
	CollapseTest test({p.ramp_rate_per_s, p.fast_ramp_rate_per_s, p.slow_from_fraction * r.answer.collapse_ratio, p.collapse_rate_rad_s,
					   p.rate_window_s, p.mechanism_rotation_rad, p.hold_s});
	load.setFactor(ramp ? 0.0 : p.load_ratio);
	std::vector<PlanarAngle> angles;  // the ground, then each segment
	angles.emplace_back(nullptr);
	for (btRigidBody* b : beam.segments()) angles.emplace_back(b);
	plastic::EnergyLedger ledger(btVector3(0, 0, 0));
	for (btRigidBody* b : beam.segments()) ledger.addBody(*b);

	rig.beforeEachStep([&](double step_s)
					   {
		if (ramp)
		{
			test.advance(step_s);
			load.setFactor(test.factor());
		}
		load.apply();
		beam.updateForStep(step_s); });
	rig.afterEachStep([&]
					  {
		load.afterStep();
		for (PlanarAngle& a : angles) a.update(); });
	auto jointRotation = [&](size_t j)
	{ return angles[j + 1].angle_rad() - angles[j].angle_rad(); };
	r.stop_rotation_rad = std::numeric_limits<double>::quiet_NaN();
	double maxKinetic = 0;
	std::vector<double> atThird;  // the rotations a third into the run: what they change by after it is creep
	auto allRotations = [&]
	{
		std::vector<double> x;
		for (size_t j = 0; j < beam.joints().size(); j++) x.push_back(jointRotation(j));
		return x;
	};
	while (rig.time_s() < p.duration_s - 1e-12)
	{
		rig.step();
		if (atThird.empty() && rig.time_s() >= p.duration_s / 3 - 1e-12) atThird = allRotations();
		const double root = -jointRotation(0);  // the tip going down is clockwise
		r.max_root_rotation_rad = std::max(r.max_root_rotation_rad, std::fabs(root));
		for (size_t j = 1; j < beam.joints().size(); j++) r.max_inner_rotation_rad = std::max(r.max_inner_rotation_rad, std::fabs(jointRotation(j)));
		if (!std::isfinite(root))
		{
			r.finite = false;
			break;
		}
		if (ramp)
		{
			std::vector<double> rotations;
			for (size_t j = 0; j < beam.joints().size(); j++) rotations.push_back(jointRotation(j));
			test.update(rig.time_s(), rotations);
			if (test.done())
			{
				r.mechanism = test.mechanism(rotations);
				break;
			}
		}
		else if (!p.follower_load && p.load_ratio > 1)
		{
			const double kinetic = ledger.measure().kinetic_j;
			maxKinetic = std::max(maxKinetic, kinetic);
			// stopped: (almost) no kinetic energy left, or turning back (elastic joints spring back)
			if (root > 0.01 && (kinetic < 1e-4 * maxKinetic || root < r.max_root_rotation_rad - 1e-3))
			{
				r.stop_rotation_rad = r.max_root_rotation_rad;
				break;
			}
		}
	}
	r.collapse_ratio = test.collapseFactor();
	r.holds = test.holds();
	r.root_rotation_rad = -jointRotation(0);
	for (size_t j = 0; j < atThird.size(); j++) r.creep_rad = std::max(r.creep_rad, std::fabs(jointRotation(j) - atThird[j]));
	r.load_work_j = load.work_j();
	r.kinetic_j = ledger.measure().kinetic_j;
	for (size_t j = 0; j < beam.joints().size(); j++) r.geometric_plastic_work_j += mp * std::fabs(jointRotation(j));
	r.booked_plastic_work_j = beam.plasticWork_j();
	r.energy_balance_error_pct = r.load_work_j > 0 ? 100.0 * (r.load_work_j - r.kinetic_j - r.geometric_plastic_work_j) / r.load_work_j : 0.0;
	r.solver_fallbacks = rig.solverFallbacks();
	r.solver_retries = rig.solverRetries();
	r.steps = rig.steps();
	r.simulated_s = rig.time_s();
	r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	return r;
}
}  // namespace structures
