// The drop weight scene: the beam from the toolkit, its supports (pin or plastic clamp at the left, roller or
// sliding plastic clamp at the right on a carriage), the ball in contact; measured from the bodies.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "BeamBuilder.h"
#include "DropWeight.h"
#include "EnergyLedger.h"
#include "Measures.h"

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
}  // namespace

DropWeightResult runDropWeight(const DropWeightParameters& p)
{
	const auto start = std::chrono::steady_clock::now();
	DropWeightResult r;
	r.answer = dropWeightAnswer(p);
	const double mp = r.answer.plastic_moment_nm;
	StructureRig rig(p.solver);
	plastic::BeamSpec spec;
	spec.start_m = btVector3(0, 0, 0);
	spec.end_m = btVector3(btScalar(p.span_m), 0, 0);
	spec.segments = p.segments;
	spec.section = plastic::rectangle(p.section_width_m, p.section_depth_m);
	spec.material.yield_stress_pa = p.yield_stress_pa;
	spec.material.youngs_modulus_pa = p.youngs_modulus_pa;
	spec.material.density_kg_m3 = p.density_kg_m3;
	spec.bending_axis = btVector3(0, 0, 1);
	spec.method = p.solver.method;
	plastic::Beam beam(rig.world(), spec, p.clamped ? &rig.ground() : nullptr);
	const std::vector<btRigidBody*>& segments = beam.segments();

	// the right end's carriage: a body of one segment's mass that slides along x only
	const btVector3 rightEnd(btScalar(p.span_m), 0, 0);
	btBoxShape carriageShape(btVector3(btScalar(p.section_width_m / 2), btScalar(p.section_depth_m / 2), btScalar(p.section_width_m / 2)));
	const btScalar carriageMass = segments.front()->getMass();
	btVector3 carriageInertia;
	carriageShape.calculateLocalInertia(carriageMass, carriageInertia);
	btRigidBody::btRigidBodyConstructionInfo carriageInfo(carriageMass, nullptr, &carriageShape, carriageInertia);
	carriageInfo.m_startWorldTransform = btTransform(btMatrix3x3::getIdentity(), rightEnd);
	btRigidBody carriage(carriageInfo);
	carriage.setActivationState(DISABLE_DEACTIVATION);
	rig.world().addRigidBody(&carriage, 0, 0);
	BodyInWorld carriageInWorld{rig.world(), carriage};
	btGeneric6DofConstraint slide(rig.ground(), carriage, rig.ground().getCenterOfMassTransform().inverse() * btTransform::getIdentity(),
								  btTransform::getIdentity(), true);
	slide.setLinearLowerLimit(btVector3(1, 0, 0));  // lower > upper: free along x
	slide.setLinearUpperLimit(btVector3(-1, 0, 0));
	slide.setAngularLowerLimit(btVector3(0, 0, 0));
	slide.setAngularUpperLimit(btVector3(0, 0, 0));
	ConstraintInWorld slideInWorld(rig.world(), slide);

	// the supports: pins, or the method's plastic joints (the left one is the beam's first joint)
	std::unique_ptr<btHingeConstraint> leftPin = p.clamped ? nullptr : pin(rig.ground(), *segments.front(), btVector3(0, 0, 0));
	std::unique_ptr<ConstraintInWorld> leftPinInWorld = leftPin ? std::make_unique<ConstraintInWorld>(rig.world(), *leftPin) : nullptr;
	plastic::JointSpec rightSpec = beam.jointSpecs().empty() ? plastic::JointSpec{} : beam.jointSpecs().back();
	rightSpec.pivot_m = rightEnd;
	plastic::Joint rightClamp;
	std::unique_ptr<btHingeConstraint> rightPin;
	if (p.clamped)
		rightClamp = plastic::makeJoint(rightSpec, *segments.back(), carriage);
	else
		rightPin = pin(*segments.back(), carriage, rightEnd);
	ConstraintInWorld rightInWorld(rig.world(), p.clamped ? *rightClamp.constraint : static_cast<btTypedConstraint&>(*rightPin));

	// the ball, just above the middle of the top face
	btSphereShape ballShape(btScalar(p.weight_radius_m));
	btVector3 ballInertia;
	ballShape.calculateLocalInertia(btScalar(p.weight_mass_kg), ballInertia);
	btRigidBody::btRigidBodyConstructionInfo ballInfo(btScalar(p.weight_mass_kg), nullptr, &ballShape, ballInertia);
	ballInfo.m_startWorldTransform.setOrigin(btVector3(btScalar(p.span_m / 2), btScalar(p.section_depth_m / 2 + p.weight_radius_m + 1e-3), 0));
	ballInfo.m_friction = 0;
	ballInfo.m_restitution = 0;
	btRigidBody ball(ballInfo);
	ball.setActivationState(DISABLE_DEACTIVATION);
	ball.setLinearVelocity(btVector3(0, btScalar(-p.impact_speed_m_s), 0));
	rig.world().addRigidBody(&ball);
	BodyInWorld ballInWorld{rig.world(), ball};
	for (btRigidBody* s : segments) s->setFriction(0);

	// the bodies along the beam, site i joins body i and i + 1: the left support, the inner joints, the right support
	std::vector<PlanarAngle> angles;
	angles.emplace_back(nullptr);
	for (btRigidBody* s : segments) angles.emplace_back(s);
	angles.emplace_back(&carriage);
	plastic::EnergyLedger ledger(btVector3(0, 0, 0));
	for (btRigidBody* s : segments) ledger.addBody(*s);
	ledger.addBody(carriage);
	ledger.addBody(ball);

	rig.beforeEachStep([&](double step_s)
					   {
		beam.updateForStep(step_s);
		if (p.clamped) plastic::updateJointForStep(*rightClamp.constraint, rightSpec, step_s); });
	rig.afterEachStep([&]
					  {
		for (PlanarAngle& a : angles) a.update(); });
	auto site = [&](size_t i)
	{ return angles[i + 1].angle_rad() - angles[i].angle_rad(); };
	const size_t sites = angles.size() - 1, mid = size_t(p.segments / 2);
	auto geometricPlasticWork = [&]
	{
		double w = 0;
		for (size_t i = 0; i < sites; i++)
			if (p.clamped || (i != 0 && i + 1 != sites)) w += mp * std::fabs(site(i));
		return w;
	};
	btRigidBody& leftHalfEnd = *segments[mid - 1];
	const btVector3 midLocal(0, 0, btScalar(beam.segmentLength_m() / 2));
	r.kinetic_after_impact_j = std::numeric_limits<double>::quiet_NaN();
	double deepest = 0;
	while (rig.time_s() < p.duration_s - 1e-12)
	{
		rig.step();
		const double kinetic = ledger.measure().kinetic_j;
		if (!std::isfinite(kinetic))
		{
			r.finite = false;
			break;
		}
		const double midspanVelocity = leftHalfEnd.getVelocityInLocalPoint(leftHalfEnd.getWorldTransform().getBasis() * midLocal).y();
		// what the hinges have to absorb once the ball and the middle move together: the kinetic energy then, plus
		// what the hinges took during the impact
		if (std::isnan(r.kinetic_after_impact_j) && std::fabs(ball.getLinearVelocity().y() - midspanVelocity) < 0.01 * p.impact_speed_m_s)
			r.kinetic_after_impact_j = kinetic + geometricPlasticWork();
		const double midspan = site(mid);
		deepest = std::max(deepest, midspan);
		// stopped: the middle no longer moves (the ball may drift off), or it springs back
		if (!std::isnan(r.kinetic_after_impact_j) && midspan > 0 && (std::fabs(midspanVelocity) < 1e-3 * p.impact_speed_m_s || midspan < deepest - 1e-3)) break;
	}
	r.midspan_rotation_rad = site(mid);
	r.left_support_rotation_rad = -site(0);
	r.right_support_rotation_rad = -site(sites - 1);
	for (size_t i = 1; i + 1 < sites; i++)
		if (i != mid) r.max_inner_rotation_rad = std::max(r.max_inner_rotation_rad, std::fabs(site(i)));
	r.kinetic_end_j = ledger.measure().kinetic_j;
	r.geometric_plastic_work_j = geometricPlasticWork();
	r.booked_plastic_work_j = beam.plasticWork_j() + rightClamp.plasticWork_j();
	const DropWeightAnswer& a = r.answer;
	r.midspan_error_pct = 100 * (r.midspan_rotation_rad - a.midspan_rotation_rad) / a.midspan_rotation_rad;
	r.plastic_work_error_pct = 100 * (r.geometric_plastic_work_j - a.kinetic_after_impact_j) / a.kinetic_after_impact_j;
	r.balance_error_pct = 100 * (r.kinetic_after_impact_j - r.kinetic_end_j - r.geometric_plastic_work_j) / r.kinetic_after_impact_j;
	r.solver_fallbacks = rig.solverFallbacks();
	r.solver_retries = rig.solverRetries();
	r.steps = rig.steps();
	r.simulated_s = rig.time_s();
	r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	return r;
}
}  // namespace structures
