// The hinge law (HingeLaw.h) against the section's moment-curvature relation, and a cantilever of hardening joints
// (JointSpec::stress_strain, patch 0028's layers) against beam theory: the tip deflection is the curvature integrated
// along the member, delta = integral of kappa(M(x)) (L - x) dx, with M(x) = P (L - x) and kappa(M) the section's
// (SectionResponse, checked against the closed forms in SectionResponseTest), so for a root moment M0
// delta = (L / M0)^2 x integral from 0 to M0 of kappa(m) m dm. Linear geometry: at the loads used the tip turns less
// than 0.1 rad, and the rigid segments' large-displacement kinematics change P L by less than 0.5 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "CantileverRig.h"
#include "plastic/HingeLaw.h"
#include "plastic/SectionResponse.h"

using namespace plastic;

namespace
{
const double kLength_m = 2.0;

// kappa(M) of the section under the curve, by bisection on the section's moment (M below the largest it reaches)
double curvatureAt_1_m(const std::vector<SectionLayer>& layers, const StressStrainCurve& curve, double moment_nm, double upTo_1_m)
{
	double lo = 0, hi = upTo_1_m;
	for (int i = 0; i < 60; i++)
	{
		const double mid = 0.5 * (lo + hi);
		(sectionForces(layers, curve, 0.0, mid).moment_nm < moment_nm ? lo : hi) = mid;
	}
	return 0.5 * (lo + hi);
}

// beam theory's tip deflection of the cantilever under a tip load whose root moment is M0
double beamTheoryDeflection_m(const SectionProperties& section, const StressStrainCurve& curve, double rootMoment_nm)
{
	const std::vector<SectionLayer> layers = sectionLayers(section);
	const double upTo = 200 * yieldStrain(curve) / (section.depth_m / 2);
	const int n = 400;
	double integral = 0;  // of kappa(m) m dm, midpoint rule
	for (int i = 0; i < n; i++)
	{
		const double m = rootMoment_nm * (i + 0.5) / n;
		integral += curvatureAt_1_m(layers, curve, m, upTo) * m * rootMoment_nm / n;
	}
	return kLength_m * kLength_m / (rootMoment_nm * rootMoment_nm) * integral;
}

// the energies at the end of the ramp: while the load is held the elastic energy the joints report drifts up with the
// member's small vibration (at 0.6 Mp / L without layers, 374.5 to 380.6 J over 1 s at a constant load's work of
// 371 J), a bookkeeping error of elastic springs in a chain that the layers do not cause (CHANGES.md)
struct Pushed
{
	double deflection_m = 0;  // of the tip, averaged over the last 0.2 s of the hold
	double plasticWork_j = 0;     // at the end of the ramp
	double plasticWorkEnd_j = 0;  // at the end of the hold
	double loadWork_j = 0;
	double rampWork_j = 0;  // the load's work to the end of the ramp
	double kinetic_j = 0;
	double elastic_j = 0;
};

// the member in `segments` EP2 segments, the tip load ramped over ramp_s to the root moment ratio x Mp and held
Pushed push(const SectionProperties& section, const StressStrainCurve* curve, int segments, bool halfLengthSupport, double ratio, double step_s,
			double ramp_s = 2.0, double hold_s = 1.0)
{
	CantileverRig rig(10, true);  // btDirectJointSolver: the chain's elastic springs solved exactly
	BeamSpec spec = cantileverSpec(section, JointMethod::ElasticPlastic2);
	spec.end_m = btVector3(btScalar(kLength_m), 0, 0);
	spec.segments = segments;
	spec.may_sleep = false;
	spec.support_joint_half_length = halfLengthSupport;
	if (curve) spec.joint.stress_strain = *curve;
	Beam beam(rig.world, spec, &rig.support);
	EXPECT_TRUE(beam.errors().empty()) << (beam.errors().empty() ? "" : beam.errors().front());
	btRigidBody* tip = beam.segments().back();
	const btVector3 tipEnd(0, 0, btScalar(beam.segmentLength_m() / 2));
	const double Mp = capacities(section, steel()).plastic_moment_y_nm;
	const double P = ratio * Mp / kLength_m;
	Pushed r;
	const int ramp = int(ramp_s / step_s), hold = int(hold_s / step_s), averaged = int(0.2 / step_s);
	double sum = 0;
	btVector3 before = tip->getWorldTransform() * tipEnd;
	for (int i = 1; i <= ramp + hold; i++)
	{
		const btVector3 force(0, btScalar(-P * std::min(1.0, double(i) / ramp)), 0);
		tip->applyForce(force, tip->getWorldTransform().getBasis() * tipEnd);
		beam.updateForStep(step_s);
		rig.world.stepSimulation(btScalar(step_s), 0);
		const btVector3 after = tip->getWorldTransform() * tipEnd;
		r.loadWork_j += double(force.dot(after - before));
		before = after;
		if (i > ramp + hold - averaged) sum += -double(after.y());
		if (i != ramp) continue;
		r.plasticWork_j = beam.plasticWork_j();
		for (const Joint& j : beam.joints()) r.elastic_j += double(j.plasticState->getElasticEnergy());
		for (btRigidBody* b : beam.segments())
		{
			const btVector3 w = b->getAngularVelocity();
			r.kinetic_j += 0.5 * double(b->getLinearVelocity().length2()) / double(b->getInvMass()) +
						   0.5 * double(w.dot(b->getInvInertiaTensorWorld().inverse() * w));
		}
		r.rampWork_j = r.loadWork_j;
	}
	r.deflection_m = sum / averaged;
	r.plasticWorkEnd_j = beam.plasticWork_j();
	return r;
}
}  // namespace

// The layers follow the section's moment-curvature curve (theta = kappa L_p) within 1 % of its largest moment, from
// first yield to 50 times it, for the rectangle, the tube and the I section under an elastic-perfectly plastic and a
// bilinear curve; their elastic stiffness is E I / L_p.
TEST(HingeLaw, LayersFollowTheSectionsMomentCurvature)
{
	const Material s = steel();
	struct Case
	{
		const char* name;
		SectionProperties section;
		StressStrainCurve curve;
	};
	const Case cases[] = {{"rectangle, EPP", rectangle(0.05, 0.10), elasticPerfectlyPlastic(s)},
						  {"rectangle, b = 0.01", rectangle(0.05, 0.10), bilinear(s.youngs_modulus_pa, s.yield_stress_pa, 0.01)},
						  {"rectangle, b = 0.05", rectangle(0.05, 0.10), bilinear(s.youngs_modulus_pa, s.yield_stress_pa, 0.05)},
						  {"tube, b = 0.05", tube(0.1, 0.008), bilinear(s.youngs_modulus_pa, s.yield_stress_pa, 0.05)},
						  {"I section, EPP", iSection(0.2, 0.1, 0.0056, 0.0085), elasticPerfectlyPlastic(s)}};
	const double hinge_m = 0.25;
	for (const Case& c : cases)
	{
		const HingeLaw law = hingeLaw(c.section, c.curve, hinge_m);
		ASSERT_TRUE(law.error.empty()) << c.name << ": " << law.error;
		EXPECT_LE(law.layers.size(), 16u);
		double stiffness = 0;
		for (const HingeLayer& l : law.layers) stiffness += l.stiffness_nm_rad;
		const double EI = c.curve.pairs.front().stress_pa / c.curve.pairs.front().strain * c.section.second_moment_y_m4;
		EXPECT_NEAR(stiffness, EI / hinge_m, 0.005 * EI / hinge_m) << c.name;
		const std::vector<SectionLayer> layers = sectionLayers(c.section);
		const double ky = yieldStrain(c.curve) / (c.section.depth_m / 2);
		double worst = 0, largest = 0;
		for (double mu = 0.2; mu <= 50; mu *= 1.07)
		{
			const double section = sectionForces(layers, c.curve, 0.0, mu * ky).moment_nm;
			largest = std::max(largest, section);
			worst = std::max(worst, std::fabs(hingeMoment_nm(law, mu * ky * hinge_m) - section));
		}
		EXPECT_LT(worst / largest, 0.01) << c.name;
		std::printf("[ info     ] %s: %zu layers, EI/Lp %.4g (%.4g) N m/rad, largest error %.3f %% of %.4g N m\n", c.name, law.layers.size(), stiffness,
					EI / hinge_m, 100 * worst / largest, largest);
	}
}

TEST(HingeLaw, ItRefusesWhatLayersCannotFollow)
{
	const Material s = steel();
	EXPECT_NE(hingeLaw(rectangle(0.05, 0.10), elasticPerfectlyPlastic(s), 0.0).error.find("hinge_length_m"), std::string::npos);
	// a yield plateau, then hardening: the moment-curvature tangent rises again
	StressStrainCurve plateau{{{0.002, 400e6}, {0.02, 400e6}, {0.1, 500e6}}};
	const HingeLaw law = hingeLaw(rectangle(0.05, 0.10), plateau, 0.25);
	EXPECT_NE(law.error.find("tangent rises"), std::string::npos) << law.error;
	EXPECT_TRUE(law.layers.empty());
	JointSpec spec;
	spec.method = JointMethod::PlasticHinge;
	spec.section = rectangle(0.05, 0.10);
	spec.stress_strain = elasticPerfectlyPlastic(s);
	ASSERT_FALSE(validate(spec).empty());
	EXPECT_NE(validate(spec).front().find("stress_strain: only an elastic-plastic2"), std::string::npos) << validate(spec).front();
}

// The support joint's length: with each joint standing for the member around it (the support's for half a segment)
// the elastic tip deflection of 4 segments is the trapezoid sum of the curvature, (1/n) (1/2 + sum_k>0 (1 - k/n)^2)
// = 0.34375 against beam theory's 1/3 (+3.1 %); with a whole segment at the support it is the left-point sum
// (1/n) sum (1 - k/n)^2 = 0.46875 (+40.6 %). At 1/40000 s the joints' bending springs are elastic (25 steps per
// period); at game steps they are rigid-plastic and the member does not deflect elastically at all.
TEST(HingeLaw, TheSupportJointStandsForHalfASegment)
{
	const SectionProperties section = rectangle(0.05, 0.10);
	const double EI = steel().youngs_modulus_pa * section.second_moment_y_m4;
	const double ratio = 0.3, P = ratio * capacities(section, steel()).plastic_moment_y_nm / kLength_m;
	const double exact = P * std::pow(kLength_m, 3) / (3 * EI);
	const double step = 1.0 / 40000;
	const double half = push(section, nullptr, 4, true, ratio, step, 1.0, 0.5).deflection_m;
	const double whole = push(section, nullptr, 4, false, ratio, step, 1.0, 0.5).deflection_m;
	EXPECT_NEAR(half, exact * 3 * 0.34375, 0.01 * exact);
	EXPECT_NEAR(whole, exact * 3 * 0.46875, 0.01 * exact);
	std::printf("[ info     ] elastic tip deflection at P L = 0.3 Mp, 4 segments: %.5f m with the support's half segment (%.5f), %.5f m with a "
				"whole one (%.5f); P L^3 / 3EI = %.5f m\n",
				half, exact * 3 * 0.34375, whole, exact * 3 * 0.46875, exact);
}

// Patch 0029: the springs of a chain of 8 elastic-plastic joints (1/50000 s, every joint elastic) apply their force,
// so at 0.3 Mp / L the member deflects as its joints say, the left-point sum (1/8) sum (1 - k/8)^2 = 0.3984 of
// P L^3 / E I, and nothing yields; before, the out-of-plane bending no load drove grew until it yielded (12612 J booked
// after 3 s, the tip where it should be).
TEST(HingeLaw, TheSpringsOfAChainApplyTheirForce)
{
	const SectionProperties section = rectangle(0.05, 0.10);
	const double EI = steel().youngs_modulus_pa * section.second_moment_y_m4;
	const double P = 0.3 * capacities(section, steel()).plastic_moment_y_nm / kLength_m;
	const double expected = P * std::pow(kLength_m, 3) / EI * 204.0 / 512.0;
	const Pushed r = push(section, nullptr, 8, false, 0.3, 1.0 / 50000, 2.0, 1.0);
	EXPECT_NEAR(r.deflection_m, expected, 0.01 * expected);
	EXPECT_LT(r.plasticWorkEnd_j, 1e-3) << "nothing yields at 0.3 Mp / L";
	std::printf("[ info     ] 8 elastic segments at 0.3 Mp / L: tip %.5f m (%.5f), plastic work %.3g J\n", r.deflection_m, expected, r.plasticWorkEnd_j);
}

// A cantilever of hardening joints (4 segments, the support's joint half a segment long, 1/40000 s): under a tip load
// above Mp / L (1.05 and 1.15 on bilinear steel, b = 0.05) it bends and stops; the load's work to the end of the ramp
// balances the joints' plastic and elastic energy and the kinetic energy (each measured apart) within 1 %. The same
// member of elastic-perfectly plastic joints runs away at 1.05. Against beam theory (the curvature integrated along
// the member) the 4 segments are too flexible, +24 % at 1.05 and +26 % at 1.15 Mp / L: the support's joint takes the
// root's curvature over its whole 0.25 m, where the moment falls by 12 %. Printed, not asserted: more segments converge
// (report/HARDENING.md: 8 segments at 1/50000 s against OpenSees).
TEST(HingeLaw, AHardeningCantileverHoldsAboveMpWithItsBooksBalanced)
{
	const SectionProperties section = rectangle(0.05, 0.10);
	const Material s = steel();
	const double step = 1.0 / 40000;
	const StressStrainCurve curve = bilinear(s.youngs_modulus_pa, s.yield_stress_pa, 0.05);
	const Pushed epp = push(section, nullptr, 4, true, 1.05, step, 1.0, 0.5);
	EXPECT_GT(epp.deflection_m, 0.3) << "elastic-perfectly plastic joints do not hold 1.05 Mp / L";
	double previous = 0;
	for (double ratio : {1.05, 1.15})
	{
		const double M0 = ratio * capacities(section, s).plastic_moment_y_nm;
		const double theory = beamTheoryDeflection_m(section, curve, M0);
		const Pushed r = push(section, &curve, 4, true, ratio, step);
		EXPECT_GT(r.deflection_m, previous) << ratio;
		EXPECT_LT(r.deflection_m, 0.3) << "hardening joints hold " << ratio << " Mp / L";
		EXPECT_NEAR(r.rampWork_j, r.plasticWork_j + r.elastic_j + r.kinetic_j, 0.01 * r.rampWork_j) << "the books balance at " << ratio;
		previous = r.deflection_m;
		std::printf("[ info     ] b = 0.05, P L = %.2f Mp: tip %.5f m (beam theory %.5f m, %+.1f %%); load work %.1f J, plastic %.1f J, elastic "
					"%.1f J, kinetic %.3f J\n",
					ratio, r.deflection_m, theory, 100 * (r.deflection_m / theory - 1), r.rampWork_j, r.plasticWork_j, r.elastic_j, r.kinetic_j);
	}
	std::printf("[ info     ] elastic-perfectly plastic joints at 1.05 Mp / L: tip %.3f m after 1.5 s\n", epp.deflection_m);
}
