#include "JointFactory.h"

#include "HingeLaw.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace plastic
{
namespace
{
// the joint's frame in a body: the world pivot and basis expressed in the body
btTransform frameIn(const btRigidBody& body, const JointSpec& spec)
{
	const btTransform world(spec.basis, spec.pivot_m);
	return body.getCenterOfMassTransform().inverse() * world;
}

// the plastic settings of a joint (makeJoint checked each field first)
btPlasticConstraintSettings plasticSettings(const JointSpec& spec)
{
	btPlasticConstraintSettings settings;
	settings.m_maxPlasticRotation = btScalar(spec.max_plastic_rotation_rad);
	settings.m_minStepsPerPeriod = btScalar(spec.min_steps_per_period);
	if (spec.fatigue)
	{
		settings.m_fatigueDuctilityRotation = btScalar(fatigueDuctilityRotation_rad(spec));
		settings.m_fatigueDuctilityExponent = btScalar(spec.fatigue->ductility_exponent);
	}
	return settings;
}

// 6DOF frame: X = bending axis 1, Y = bending axis 2, Z = member axis; linear DOFs 0-2 along them
template <class Constraint, class Stiffness>
void configureElasticPlastic(Constraint& c, const JointSpec& spec, Stiffness setStiffness)
{
	const SectionCapacities cap = jointCapacities(spec);
	const SegmentStiffness k = jointStiffness(spec);
	const double maxForce[6] = {cap.shear_n, cap.shear_n, cap.axial_n, cap.plastic_moment_y_nm, cap.plastic_moment_z_nm, cap.torque_nm};
	const double stiff[6] = {k.shear_n_m, k.shear_n_m, k.axial_n_m, k.bending_y_nm_rad, k.bending_z_nm_rad, k.torsion_nm_rad};
	for (int i = 0; i < 6; i++)
	{
		setStiffness(c, i, stiff[i]);
		c.setMaxForce(i, btScalar(maxForce[i]));
		if (!(btScalar(maxForce[i]) < SIMD_INFINITY))
		{
			// not plastic: the constraint leaves the DOF to its base's limits, and the base's angular DOFs are free
			// by default; an infinite capacity holds the DOF where it is made
			c.setLimit(i, btScalar(0), btScalar(0));
		}
	}
	c.setPlasticSettings(plasticSettings(spec));
	c.resetPlasticState();
}

// the upstream spring methods (thesis 2.5): linear DOFs locked, angular DOFs free with springs whose stiffness is the
// DOF's capacity per radian, at rest where they are made
template <class Constraint, class Stiffness>
void configureSprings(Constraint& c, const JointSpec& spec, Stiffness setStiffness)
{
	const SectionCapacities cap = jointCapacities(spec);
	const double moment[3] = {cap.plastic_moment_y_nm, cap.plastic_moment_z_nm, cap.torque_nm};
	c.setLinearLowerLimit(btVector3(0, 0, 0));
	c.setLinearUpperLimit(btVector3(0, 0, 0));
	c.setAngularLowerLimit(btVector3(1, 1, 1));  // free: the springs act
	c.setAngularUpperLimit(btVector3(-1, -1, -1));
	for (int i = 3; i < 6; i++)
	{
		c.enableSpring(i, true);
		setStiffness(c, i, moment[i - 3]);
	}
	c.setEquilibriumPoint();
}
}  // namespace

const char* jointMethodName(JointMethod method)
{
	switch (method)
	{
		case JointMethod::Brittle: return "brittle";
		case JointMethod::Spring: return "spring";
		case JointMethod::Spring2: return "spring2";
		case JointMethod::HingeMotor: return "hinge-motor";
		case JointMethod::PlasticHinge: return "plastic-hinge";
		case JointMethod::ElasticPlastic: return "elastic-plastic";
		case JointMethod::ElasticPlastic2: return "elastic-plastic2";
	}
	return "?";
}

// DOFs 2 (the axial force), 3 (moment about y, the main bending), 4 (about z) and 5 (the torque) as configureElasticPlastic
// caps them
static void setYieldSurface(bt6DofElasticPlastic2Constraint& c, const JointSpec& spec)
{
	using C = bt6DofElasticPlastic2Constraint;
	if (spec.yield_surface == YieldSurface::Biaxial)
	{
		switch (spec.section.biaxial_interaction)
		{
			case BiaxialInteraction::Circle: c.setYieldSurface(C::YIELD_CIRCLE, 3, 4); break;
			case BiaxialInteraction::Rectangle: c.setYieldSurface(C::YIELD_RECTANGLE_BIAXIAL, 3, 4); break;
			case BiaxialInteraction::ISection: c.setYieldSurface(C::YIELD_LINEAR_QUADRATIC, 4, 3); break;  // weak z, strong y
			case BiaxialInteraction::None: break;
		}
	}
	if (spec.yield_surface == YieldSurface::BendingAxial && spec.section.axial_interaction == AxialInteraction::Rectangle)
	{
		c.setYieldSurface(C::YIELD_LINEAR_QUADRATIC, 3, 2);  // u0 = My / Mp_y, u1 = N / Np
	}
	if (spec.yield_surface == YieldSurface::BendingAxial && spec.section.axial_interaction == AxialInteraction::ISection)
	{
		c.setYieldSurfaceISection(btScalar(webAxialFraction(spec.section)), btScalar(flangeMomentFraction(spec.section)));
		c.setYieldSurface(C::YIELD_I_SECTION_AXIAL, 3, 2);
	}
	if (spec.yield_surface == YieldSurface::BendingTorsion && spec.section.torsion_interaction == TorsionInteraction::Circle)
	{
		c.setYieldSurface(C::YIELD_CIRCLE, 3, 5);  // u0 = My / Mp_y, u1 = T / Tp
	}
}

SectionCapacities jointCapacities(const JointSpec& spec) { return spec.capacities ? *spec.capacities : capacities(spec.section, spec.material); }

SegmentStiffness jointStiffness(const JointSpec& spec)
{
	return spec.stiffness ? *spec.stiffness : stiffness(spec.section, spec.material, spec.segment_length_m);
}

namespace
{
// cap^2 / 2k: the elastic energy of a spring of stiffness k at the force cap (infinite for a rigid or uncapped DOF)
double energyAtCap(double cap, double stiffness)
{
	return cap > 0 && stiffness > 0 && std::isfinite(cap) ? cap * cap / (2 * stiffness) : std::numeric_limits<double>::infinity();
}
}  // namespace

double jointYieldEnergy_j(const JointSpec& spec)
{
	const SectionCapacities cap = jointCapacities(spec);
	const SegmentStiffness k = jointStiffness(spec);
	return std::min({energyAtCap(cap.plastic_moment_y_nm, k.bending_y_nm_rad), energyAtCap(cap.plastic_moment_z_nm, k.bending_z_nm_rad),
					 energyAtCap(cap.torque_nm, k.torsion_nm_rad), energyAtCap(cap.axial_n, k.axial_n_m), energyAtCap(cap.shear_n, k.shear_n_m)});
}

LowCycleFatigue universalSlopesFatigue(double reduction_of_area, double hinge_length_m)
{
	LowCycleFatigue f;
	const double ductility = std::log(1 / (1 - reduction_of_area));
	f.ductility_coefficient = std::pow(2.0, -0.4) * std::pow(ductility, 0.6);
	f.ductility_exponent = -0.6;
	f.hinge_length_m = hinge_length_m;
	return f;
}

double fatigueDuctilityRotation_rad(const JointSpec& spec)
{
	if (!spec.fatigue) return 0;
	return 2 * spec.fatigue->hinge_length_m * spec.fatigue->ductility_coefficient / spec.section.depth_m;
}

std::vector<std::string> validate(const JointSpec& spec)
{
	std::vector<std::string> errors = validate(spec.section);
	auto notIn = [&errors](const char* name, double value, const char* rangeAndUnit)
	{
		std::ostringstream out;
		out << name << ": " << value << " is not in " << rangeAndUnit;
		errors.push_back(out.str());
	};
	if (!(spec.segment_length_m > 0 && std::isfinite(spec.segment_length_m)))
	{
		notIn("segment length", spec.segment_length_m, "(0, inf) m");
	}
	if (!(spec.max_plastic_rotation_rad > 0))
	{
		notIn("max plastic rotation", spec.max_plastic_rotation_rad, "(0, inf) rad");
	}
	if (!(spec.min_steps_per_period >= 1 && std::isfinite(spec.min_steps_per_period)))
	{
		notIn("min_steps_per_period", spec.min_steps_per_period, "[1, inf) steps per period");
	}
	if (spec.capacities)
	{
		const SectionCapacities& c = *spec.capacities;
		const std::pair<const char*, double> given[] = {{"capacities.axial_n", c.axial_n}, {"capacities.shear_n", c.shear_n}, {"capacities.plastic_moment_y_nm", c.plastic_moment_y_nm}, {"capacities.plastic_moment_z_nm", c.plastic_moment_z_nm}, {"capacities.torque_nm", c.torque_nm}};
		for (const auto& g : given)
			if (!(g.second > 0)) notIn(g.first, g.second, "(0, inf] N or N m");
	}
	if (spec.stiffness)
	{
		const SegmentStiffness& k = *spec.stiffness;
		const std::pair<const char*, double> given[] = {{"stiffness.axial_n_m", k.axial_n_m}, {"stiffness.shear_n_m", k.shear_n_m}, {"stiffness.bending_y_nm_rad", k.bending_y_nm_rad}, {"stiffness.bending_z_nm_rad", k.bending_z_nm_rad}, {"stiffness.torsion_nm_rad", k.torsion_nm_rad}};
		for (const auto& g : given)
			if (!(g.second > 0 && std::isfinite(g.second))) notIn(g.first, g.second, "(0, inf) N/m or N m/rad");
	}
	if (spec.fatigue)
	{
		const LowCycleFatigue& f = *spec.fatigue;
		if (!(f.ductility_coefficient > 0 && std::isfinite(f.ductility_coefficient))) notIn("fatigue.ductility_coefficient", f.ductility_coefficient, "(0, inf)");
		if (!(f.ductility_exponent >= -1 && f.ductility_exponent <= -0.1)) notIn("fatigue.ductility_exponent", f.ductility_exponent, "[-1, -0.1]");
		if (!(f.hinge_length_m > 0 && std::isfinite(f.hinge_length_m))) notIn("fatigue.hinge_length_m", f.hinge_length_m, "(0, inf) m");
		if (spec.method != JointMethod::PlasticHinge && spec.method != JointMethod::ElasticPlastic && spec.method != JointMethod::ElasticPlastic2)
			errors.push_back("fatigue: only the plastic methods (plastic-hinge, elastic-plastic, elastic-plastic2) break by fatigue");
	}
	if (spec.method == JointMethod::Brittle && !(spec.breaking_force_n > 0))
	{
		notIn("breaking force", spec.breaking_force_n, "(0, inf) N");
	}
	if (spec.yield_surface != YieldSurface::PerDof && spec.method != JointMethod::ElasticPlastic2)
	{
		errors.push_back("yield_surface: only an elastic-plastic2 joint has one (per-dof for " + std::string(jointMethodName(spec.method)) + ")");
	}
	if (spec.yield_surface == YieldSurface::Biaxial && spec.section.biaxial_interaction == BiaxialInteraction::None)
	{
		errors.push_back("yield_surface: biaxial needs a section whose interaction is known (rectangle, round bar, tube, I section), not a " +
						 spec.section.shape);
	}
	if (spec.yield_surface == YieldSurface::BendingAxial && spec.section.axial_interaction == AxialInteraction::None)
	{
		errors.push_back("yield_surface: bending-axial needs a section whose interaction of moment and axial force is known (rectangle, I section), not a " +
						 (spec.section.shape.empty() ? std::string("section without a shape") : spec.section.shape));
	}
	if (spec.yield_surface == YieldSurface::BendingTorsion && spec.section.torsion_interaction == TorsionInteraction::None)
	{
		errors.push_back("yield_surface: bending-torsion needs a section whose interaction of moment and torque is known (tube, round bar), not a " +
						 (spec.section.shape.empty() ? std::string("section without a shape") : spec.section.shape));
	}
	if (std::string(jointMethodName(spec.method)) == "?")
	{
		errors.push_back("method: not one of brittle, spring, spring2, hinge-motor, plastic-hinge, elastic-plastic, elastic-plastic2");
	}
	if (spec.stress_strain && spec.method != JointMethod::ElasticPlastic2)
	{
		errors.push_back("stress_strain: only an elastic-plastic2 joint hardens (not " + std::string(jointMethodName(spec.method)) + ")");
	}
	else if (spec.stress_strain && spec.section.error.empty() && errors.empty())
	{
		const HingeLaw law = hingeLaw(spec.section, *spec.stress_strain, spec.segment_length_m);
		if (!law.error.empty()) errors.push_back("stress_strain: " + law.error);
	}
	for (const std::string& e : validate(spec.solver)) errors.push_back(e);
	return errors;
}

Joint makeJoint(const JointSpec& spec, btRigidBody& a, btRigidBody& b)
{
	if (!validate(spec).empty())
	{
		return Joint{};
	}
	// a hinge's axis is the frame's Z: turn the basis so that bending axis 1 becomes Z
	btMatrix3x3 hingeBasis;
	hingeBasis.setValue(spec.basis[0][1], spec.basis[0][2], spec.basis[0][0],  //
						spec.basis[1][1], spec.basis[1][2], spec.basis[1][0],  //
						spec.basis[2][1], spec.basis[2][2], spec.basis[2][0]);
	JointSpec hingeSpec = spec;
	hingeSpec.basis = hingeBasis;
	const SectionCapacities cap = jointCapacities(spec);
	switch (spec.method)
	{
		case JointMethod::Brittle:
		{
			auto c = std::make_unique<btGeneric6DofConstraint>(a, b, frameIn(a, spec), frameIn(b, spec), true);
			c->setLinearLowerLimit(btVector3(0, 0, 0));
			c->setLinearUpperLimit(btVector3(0, 0, 0));
			c->setAngularLowerLimit(btVector3(0, 0, 0));
			c->setAngularUpperLimit(btVector3(0, 0, 0));
			configureJoint(*c, spec.solver, true);
			return Joint{std::move(c), nullptr, spec.method};
		}
		case JointMethod::Spring:
		{
			auto c = std::make_unique<btGeneric6DofSpringConstraint>(a, b, frameIn(a, spec), frameIn(b, spec), true);
			configureSprings(*c, spec, [](btGeneric6DofSpringConstraint& j, int i, double k) { j.setStiffness(i, btScalar(k)); });
			configureJoint(*c, spec.solver, false);
			return Joint{std::move(c), nullptr, spec.method};
		}
		case JointMethod::Spring2:
		{
			auto c = std::make_unique<btGeneric6DofSpring2Constraint>(a, b, frameIn(a, spec), frameIn(b, spec));
			// limitIfNeeded = true, as upstream users get it
			configureSprings(*c, spec, [](btGeneric6DofSpring2Constraint& j, int i, double k) { j.setStiffness(i, btScalar(k)); });
			configureJoint(*c, spec.solver, false);
			return Joint{std::move(c), nullptr, spec.method};
		}
		case JointMethod::HingeMotor:
		{
			auto h = std::make_unique<btHingeConstraint>(a, b, frameIn(a, hingeSpec), frameIn(b, hingeSpec));
			h->enableAngularMotor(true, 0, 0);
			configureJoint(*h, spec.solver, false);  // a motor's row has a velocity target
			return Joint{std::move(h), nullptr, spec.method};
		}
		case JointMethod::PlasticHinge:
		{
			auto h = std::make_unique<btPlasticHingeConstraint>(a, b, frameIn(a, hingeSpec), frameIn(b, hingeSpec));
			h->setPlasticMoment(btScalar(cap.plastic_moment_y_nm));
			h->setPlasticSettings(plasticSettings(spec));
			configureJoint(*h, spec.solver, true);  // its rows hold position errors alone
			const btPlasticConstraintState* state = &h->getPlasticState();
			return Joint{std::move(h), state, spec.method};
		}
		case JointMethod::ElasticPlastic:
		{
			auto c = std::make_unique<bt6DofElasticPlasticConstraint>(a, b, frameIn(a, spec), frameIn(b, spec), true);
			configureElasticPlastic(*c, spec, [](bt6DofElasticPlasticConstraint& j, int i, double k) { j.setStiffness(i, btScalar(k)); });
			configureJoint(*c, spec.solver, false);  // springs
			const btPlasticConstraintState* state = &c->getPlasticState();
			return Joint{std::move(c), state, spec.method};
		}
		case JointMethod::ElasticPlastic2:
		{
			auto c = std::make_unique<bt6DofElasticPlastic2Constraint>(a, b, frameIn(a, spec), frameIn(b, spec));
			configureElasticPlastic(*c, spec, [](bt6DofElasticPlastic2Constraint& j, int i, double k) { j.setStiffness(i, btScalar(k), false); });
			setYieldSurface(*c, spec);
			if (spec.stress_strain)
			{
				const HingeLaw law = hingeLaw(spec.section, *spec.stress_strain, spec.segment_length_m);
				btScalar stiffness[16], maxMoment[16];
				for (size_t j = 0; j < law.layers.size(); j++)
				{
					stiffness[j] = btScalar(law.layers[j].stiffness_nm_rad);
					maxMoment[j] = std::isfinite(law.layers[j].max_moment_nm) ? btScalar(law.layers[j].max_moment_nm) : SIMD_INFINITY;
				}
				c->setHardeningLayers(3, int(law.layers.size()), stiffness, maxMoment);
				// a step in which the DOF is rigid-plastic (too stiff for it) yields at the section's plastic moment, as
				// a joint without a curve does, not at the layers' sum (the moment at 100 times first-yield curvature)
				c->setMaxForce(3, btScalar(yieldStress_pa(*spec.stress_strain) * spec.section.plastic_modulus_y_m3));
			}
			configureJoint(*c, spec.solver, false);  // springs
			const btPlasticConstraintState* state = &c->getPlasticState();
			return Joint{std::move(c), state, spec.method};
		}
	}
	return Joint{};  // not reached: validate names the method
}

void updateJointForStep(btTypedConstraint& joint, const JointSpec& spec, double step_s)
{
	if (spec.method == JointMethod::HingeMotor)
	{
		static_cast<btHingeConstraint&>(joint).setMaxMotorImpulse(btScalar(jointCapacities(spec).plastic_moment_y_nm * step_s));
	}
	else if (spec.method == JointMethod::Brittle)
	{
		joint.setBreakingImpulseThreshold(btScalar(spec.breaking_force_n * step_s));
	}
}

double Joint::elasticEnergy_j() const
{
	if (!constraint || !constraint->isEnabled())
	{
		return 0.0;  // a broken joint holds no elastic energy
	}
	if (plasticState)
	{
		return plasticState->getElasticEnergy();
	}
	double energy = 0;
	if (method == JointMethod::Spring)
	{
		auto* c = static_cast<btGeneric6DofSpringConstraint*>(constraint.get());
		c->calculateTransforms();
		for (int i = 0; i < 3; i++)
		{
			const double angle = c->getAngle(i) - c->getEquilibriumPoint(i + 3);
			energy += 0.5 * c->getStiffness(i + 3) * angle * angle;
		}
	}
	else if (method == JointMethod::Spring2)
	{
		auto* c = static_cast<btGeneric6DofSpring2Constraint*>(constraint.get());
		c->calculateTransforms();
		for (int i = 0; i < 3; i++)
		{
			const double angle = c->getAngle(i) - c->getRotationalLimitMotor(i)->m_equilibriumPoint;
			energy += 0.5 * c->getRotationalLimitMotor(i)->m_springStiffness * angle * angle;
		}
	}
	return energy;
}

}  // namespace plastic
