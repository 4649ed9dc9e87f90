// bt6DofElasticPlastic2Constraint::setYieldSurface (patch 0022): two DOFs that yield together on a surface. A 100 kg
// box (0.2 m cube, the same inertia about every axis) is held to the world at its centre; DOFs 4 and 5 (bending
// about y and z) or 4 and 0 (bending about y, axial force along x) are rigid-plastic with the capacities below and
// the other DOFs locked far below their caps. A dead load of a chosen direction is applied for a while. Checked
// against answers that do not come from the constraint:
// - where it yields: the plastic interaction of the section (a round section's circle, the fully plastic
//   rectangle's biaxial curve integrated here over fibres, M/Mp + (N/Np)^2 = 1), each with a run just inside and
//   just outside, and a box (no surface) that holds the outside loads as a control;
// - the force the joint carries while it yields, measured from the body by Newton's law (load - inertia x
//   acceleration), lies on the surface;
// - the flow is normal to the surface at that force (associated plasticity);
// - the booked work equals the load's work less the kinetic energy, both measured from the body.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "PhysicsWorld.h"

namespace
{
using Surface = bt6DofElasticPlastic2Constraint::YieldSurface;

constexpr double kDt = 1.0 / 240.0;
constexpr double kMomentNm = 10.0;  // plastic moment of DOFs 4 and 5
constexpr double kAxialN = 100.0;   // plastic axial force of DOF 0

struct Load
{
	double forceXN = 0;      // along x (DOF 0)
	double momentYNm = 0;    // about y (DOF 4)
	double momentZNm = 0;    // about z (DOF 5)
};

struct Result
{
	double maxRotationRad = 0;    // of the body from its start
	double maxDisplacementM = 0;  // of the body's centre along x
	// measured in the last steps by Newton's law, the force the joint carries (N, N m)
	double jointForceXN = 0, jointMomentYNm = 0, jointMomentZNm = 0;
	// the body's velocities at the end (m/s, rad/s): the direction of the plastic flow
	double velocityX = 0, angularY = 0, angularZ = 0;
	double workJ = 0;     // of the load, from the body's motion
	double kineticJ = 0;  // of the body at the end
	double bookedJ = 0;   // the constraint's absorbed energy
	double elasticJ = 0;  // held by its springs
};

// stiffnessNmPerRad > 0: DOFs 4 and 5 are elastic-plastic springs of that stiffness instead of rigid-plastic locks;
// rampSteps > 0: the load grows linearly from 0 over that many steps, then stays (an undamped spring under a sudden
// load would swing to twice its static force)
// turnRadPerS: the bending moment's direction turns at this rate about x (a load that is not proportional)
Result run(Surface surface, int dof0, int dof1, const Load& load, int steps, double stiffnessNmPerRad = 0, int rampSteps = 0,
		   double turnRadPerS = 0)
{
	std::unique_ptr<bt6DofElasticPlastic2Constraint> owner;  // outlives the world, which removes it
	PhysicsWorld w;
	const double mass = 100.0;
	btRigidBody* body = w.addBox(btVector3(0.1, 0.1, 0.1), mass, btVector3(0, 0, 0));
	auto* c = new bt6DofElasticPlastic2Constraint(*body, btTransform::getIdentity());
	owner.reset(c);
	for (int i = 0; i < 6; i++)
	{
		c->setStiffness(i, 0, false);  // rigid-plastic
		c->setMaxForce(i, btScalar(1e6));
	}
	c->setMaxForce(0, btScalar(kAxialN));
	c->setMaxForce(4, btScalar(kMomentNm));
	c->setMaxForce(5, btScalar(kMomentNm));
	if (stiffnessNmPerRad > 0)
	{
		c->setStiffness(4, btScalar(stiffnessNmPerRad), false);
		c->setStiffness(5, btScalar(stiffnessNmPerRad), false);
	}
	if (surface != bt6DofElasticPlastic2Constraint::YIELD_BOX) c->setYieldSurface(surface, dof0, dof1);
	w.world.addConstraint(c);

	const btVector3 fullForce(btScalar(load.forceXN), 0, 0);
	const btVector3 fullTorque(0, btScalar(load.momentYNm), btScalar(load.momentZNm));
	const double inertia = body->getLocalInertia().y();
	Result r;
	btVector3 velocityBefore(0, 0, 0), angularBefore(0, 0, 0);
	for (int s = 0; s < steps; s++)
	{
		const btScalar share = rampSteps > 0 ? btScalar(std::min(1.0, double(s + 1) / rampSteps)) : btScalar(1.0);
		const btVector3 force = fullForce * share;
		const btVector3 torque = fullTorque.rotate(btVector3(1, 0, 0), btScalar(turnRadPerS * s * kDt)) * share;
		body->applyCentralForce(force);
		body->applyTorque(torque);
		w.world.stepSimulation(btScalar(kDt), 0, btScalar(kDt));
		btVector3 v1 = body->getLinearVelocity(), w1 = body->getAngularVelocity();
		// the load's work over the displacement the step made (the world integrates the velocities after the step)
		r.workJ += kDt * (force.dot(v1) + torque.dot(w1));
		btQuaternion q = body->getWorldTransform().getRotation();
		r.maxRotationRad = std::max(r.maxRotationRad, double(q.getAngle() > SIMD_PI ? SIMD_2_PI - q.getAngle() : q.getAngle()));
		r.maxDisplacementM = std::max(r.maxDisplacementM, std::fabs(double(body->getCenterOfMassPosition().x())));
		if (s == steps - 11)
		{
			velocityBefore = v1;
			angularBefore = w1;
		}
	}
	// the joint's force from the body's mean acceleration over the last 10 steps
	btVector3 acceleration = (body->getLinearVelocity() - velocityBefore) / btScalar(10 * kDt);
	btVector3 angularAcceleration = (body->getAngularVelocity() - angularBefore) / btScalar(10 * kDt);
	r.jointForceXN = load.forceXN - mass * acceleration.x();
	r.jointMomentYNm = load.momentYNm - inertia * angularAcceleration.y();
	r.jointMomentZNm = load.momentZNm - inertia * angularAcceleration.z();
	r.velocityX = body->getLinearVelocity().x();
	r.angularY = body->getAngularVelocity().y();
	r.angularZ = body->getAngularVelocity().z();
	r.kineticJ = w.kineticEnergy(body);
	r.bookedJ = c->getAbsorbedEnergy();
	r.elasticJ = c->getElasticEnergy();
	return r;
}

Load bending(double magnitudeNm, double angleRad) { return Load{0, magnitudeNm * std::cos(angleRad), magnitudeNm * std::sin(angleRad)}; }

// The fully plastic rectangle b x h under a moment about an axis at angle of its principal axes, integrated over
// n x n fibres: the neutral axis through the centre (no axial force) at angle beta, each fibre at +-fy. Returns
// (My/Mpy, Mz/Mpz) of the stress block.
void rectangleFibres(double beta, double& uy, double& uz)
{
	const int n = 400;
	const double b = 1.0, h = 1.0, fy = 1.0;
	double my = 0, mz = 0;
	for (int i = 0; i < n; i++)
		for (int j = 0; j < n; j++)
		{
			double y = (i + 0.5) / n * b - b / 2, z = (j + 0.5) / n * h - h / 2;
			double stress = (z * std::cos(beta) - y * std::sin(beta)) > 0 ? fy : -fy;
			double area = b * h / (double(n) * n);
			my += stress * z * area;
			mz -= stress * y * area;
		}
	const double mp = fy * b * h * h / 4;
	uy = my / mp;
	uz = mz / mp;
}

bool yields(const Result& r) { return r.maxRotationRad > 0.01 || r.maxDisplacementM > 0.001; }
}  // namespace

// The closed-form gauges against the section: the rectangle's interaction curve from fibres, the circle and the
// linear-quadratic curve at points worked by hand.
TEST(YieldSurface, GaugesAreOneOnTheSectionsInteractionCurves)
{
	for (double beta : {0.0, 0.2, 0.5, 0.785398, 1.1, 1.4})
	{
		double uy, uz;
		rectangleFibres(beta, uy, uz);
		EXPECT_NEAR(bt6DofElasticPlastic2Constraint::getYieldSurfaceGauge(bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, btScalar(uy), btScalar(uz)), 1.0, 0.002)
			<< "neutral axis at " << beta << " rad: (" << uy << ", " << uz << ")";
	}
	// a 45-degree moment on a square: 2/3 of Mp about each axis, 0.943 Mp in all
	EXPECT_NEAR(bt6DofElasticPlastic2Constraint::getYieldSurfaceGauge(bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, btScalar(2.0 / 3.0), btScalar(2.0 / 3.0)), 1.0, 1e-6);
	EXPECT_NEAR(bt6DofElasticPlastic2Constraint::getYieldSurfaceGauge(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, btScalar(0.6), btScalar(-0.8)), 1.0, 1e-6);
	// M = 0.8 Mp with N = 0.8 Np: interaction 0.8 + 0.64 = 1.44; the gauge scales both to the curve: 1.294
	btScalar g = bt6DofElasticPlastic2Constraint::getYieldSurfaceGauge(bt6DofElasticPlastic2Constraint::YIELD_LINEAR_QUADRATIC, btScalar(0.8), btScalar(0.8));
	EXPECT_NEAR(0.8 / g + (0.8 / g) * (0.8 / g), 1.0, 1e-6);
	EXPECT_NEAR(bt6DofElasticPlastic2Constraint::getYieldSurfaceGauge(bt6DofElasticPlastic2Constraint::YIELD_BOX, btScalar(0.8), btScalar(-0.9)), 0.9, 1e-6);
}

// The I section's moment-axial curve against its stress blocks, worked here from the dimensions of an IPE 300
// (h 300, b 150, t_w 7.1, t_f 10.7 mm; no fillets): with the neutral axis at z0 from the centre, everything between
// -z0 and z0 carries the axial force and everything outside it the moment. The constraint gets only the two fractions.
TEST(YieldSurface, ISectionGaugeIsOneOnItsStressBlocks)
{
	const double h = 0.3, b = 0.15, tw = 0.0071, tf = 0.0107, hw = h - 2 * tf;
	const double area = 2 * b * tf + tw * hw, plasticModulus = b * tf * (h - tf) + tw * hw * hw / 4;
	const double web = tw * hw / area, flange = b * tf * (h - tf) / plasticModulus;
	ASSERT_TRUE(bt6DofElasticPlastic2Constraint::isValidISectionShape(btScalar(web), btScalar(flange)));
	PhysicsWorld w;
	btRigidBody* fixed = w.addBox(btVector3(0.1, 0.1, 0.1), 1.0, btVector3(0, 0, 0));
	bt6DofElasticPlastic2Constraint c(*fixed, btTransform::getIdentity());
	c.setYieldSurfaceISection(btScalar(web), btScalar(flange));
	c.setYieldSurface(bt6DofElasticPlastic2Constraint::YIELD_I_SECTION_AXIAL, 4, 0);
	int points = 0;
	for (double z0 = 0; z0 < h / 2; z0 += h / 2 / 40)
	{
		double n, m;  // the blocks' axial force (per fy) and moment (per fy) outside +-z0
		if (z0 <= hw / 2)
		{
			n = 2 * z0 * tw;
			m = plasticModulus - tw * z0 * z0;
		}
		else
		{
			n = tw * hw + 2 * b * (z0 - hw / 2);
			m = b * (h / 2 - z0) * (h / 2 + z0);
		}
		const double u0 = m / plasticModulus, u1 = n / area;
		EXPECT_NEAR(double(c.getYieldSurfaceGauge(btScalar(u0), btScalar(u1))), 1.0, 1e-5) << "z0 = " << z0 << ": (" << u0 << ", " << u1 << ")";
		EXPECT_NEAR(double(c.getYieldSurfaceGauge(btScalar(-0.5 * u0), btScalar(0.5 * u1))), 0.5, 1e-5) << "half of it, any sign";
		points++;
	}
	EXPECT_EQ(points, 40);
	// the static gauge without a shape is the rectangle's: u0 + u1^2 = 1
	EXPECT_NEAR(bt6DofElasticPlastic2Constraint::getYieldSurfaceGauge(bt6DofElasticPlastic2Constraint::YIELD_I_SECTION_AXIAL, btScalar(0.64), btScalar(0.6)), 1.0, 1e-6);
	// the pairs that are no section's are refused: no flanges with a flange moment, flanges without one, a web share
	// too small for the flanges' moment (r < 0), NaN
	const double refused[][2] = {{1.0, 0.3}, {0.5, 0.0}, {0.2, 0.2}, {0.0, 0.5}, {1.2, 0.5}, {0.5, 1.0}, {std::nan(""), 0.5}};
	for (const auto& pair : refused)
	{
		EXPECT_FALSE(bt6DofElasticPlastic2Constraint::isValidISectionShape(btScalar(pair[0]), btScalar(pair[1]))) << pair[0] << ", " << pair[1];
#ifdef NDEBUG
		c.setYieldSurfaceISection(btScalar(pair[0]), btScalar(pair[1]));
		EXPECT_EQ(double(c.getWebAxialFraction()), double(btScalar(web))) << "release builds keep the previous shape";
#endif
	}
	EXPECT_TRUE(bt6DofElasticPlastic2Constraint::isValidISectionShape(btScalar(1.0), btScalar(0.0))) << "the rectangle";
}

// A round section's moment at 45 degrees yields at Mp (the box held it to 1.41 Mp).
TEST(YieldSurface, CircleYieldsAtThePlasticMomentInEveryDirection)
{
	for (double angle : {0.0, 0.3, 0.785398, 1.2})
	{
		Result inside = run(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5, bending(0.97 * kMomentNm, angle), 240);
		Result outside = run(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5, bending(1.03 * kMomentNm, angle), 120);
		EXPECT_LT(inside.maxRotationRad, 1e-3) << angle;
		EXPECT_TRUE(yields(outside)) << angle << ": " << outside.maxRotationRad;
	}
	// control: without the surface the 45-degree moment of 1.3 Mp holds
	Result box = run(bt6DofElasticPlastic2Constraint::YIELD_BOX, 4, 5, bending(1.3 * kMomentNm, 0.785398), 240);
	EXPECT_LT(box.maxRotationRad, 1e-3);
}

// While it yields the joint carries a moment on the circle, the flow is along it, and the booked work is the load's
// work less the kinetic energy.
TEST(YieldSurface, CircleFlowIsNormalAndTheWorkBalances)
{
	const double angle = 0.5;
	Result r = run(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5, bending(1.1 * kMomentNm, angle), 60);
	ASSERT_TRUE(yields(r));
	EXPECT_NEAR(std::hypot(r.jointMomentYNm, r.jointMomentZNm) / kMomentNm, 1.0, 0.005);
	// normal to a circle at the moment: the flow is parallel to the joint's moment
	double flowAngle = std::atan2(r.angularZ, r.angularY);
	double momentAngle = std::atan2(r.jointMomentZNm, r.jointMomentYNm);
	EXPECT_NEAR(flowAngle, momentAngle, 0.01) << "flow " << flowAngle;
	EXPECT_NEAR(r.bookedJ, r.workJ - r.kineticJ, 0.01 * r.workJ);
}

// The rectangle's biaxial curve: a 45-degree moment on a square yields at 0.943 Mp; at 0.3 rad off its axis the
// force lies on the fibre curve and the flow is normal to it there (not along the load).
TEST(YieldSurface, RectangleBiaxialYieldsOnItsCurveWithNormalFlow)
{
	Result inside = run(bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, 4, 5, bending(0.92 * kMomentNm, 0.785398), 240);
	Result outside = run(bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, 4, 5, bending(0.97 * kMomentNm, 0.785398), 120);
	Result box = run(bt6DofElasticPlastic2Constraint::YIELD_BOX, 4, 5, bending(0.97 * kMomentNm, 0.785398), 240);
	EXPECT_LT(inside.maxRotationRad, 1e-3);
	EXPECT_TRUE(yields(outside));
	EXPECT_LT(box.maxRotationRad, 1e-3);  // control

	Result r = run(bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, 4, 5, bending(1.1 * kMomentNm, 0.3), 60);
	ASSERT_TRUE(yields(r));
	double uy = r.jointMomentYNm / kMomentNm, uz = r.jointMomentZNm / kMomentNm;
	ASSERT_GT(uy, uz);
	// on the curve uy + 3/4 uz^2 = 1 (the fibre test above checks that curve)
	EXPECT_NEAR(uy + 0.75 * uz * uz, 1.0, 0.005);
	// the normal there, (1, 3/2 uz), against the flow (and the load's direction, which differs by 0.15 rad)
	double normalAngle = std::atan2(1.5 * uz, 1.0);
	double flowAngle = std::atan2(r.angularZ, r.angularY);
	EXPECT_NEAR(flowAngle, normalAngle, 0.01) << "flow " << flowAngle;
	EXPECT_GT(std::fabs(normalAngle - 0.3), 0.06);
	EXPECT_NEAR(r.bookedJ, r.workJ - r.kineticJ, 0.01 * r.workJ);
}

// Bending with axial force, M/Mp + (N/Np)^2 = 1: (0.7, 0.5) = 0.95 holds, (0.8, 0.5) = 1.05 and (0.8, 0.8) = 1.44
// yield; the box held (0.8, 0.8). The flow (rotation rate, axial velocity) is normal to the curve.
TEST(YieldSurface, BendingWithAxialForceYieldsOnTheInteractionCurve)
{
	auto load = [](double m, double n) { return Load{n * kAxialN, m * kMomentNm, 0}; };
	EXPECT_FALSE(yields(run(bt6DofElasticPlastic2Constraint::YIELD_LINEAR_QUADRATIC, 4, 0, load(0.7, 0.5), 240)));
	EXPECT_TRUE(yields(run(bt6DofElasticPlastic2Constraint::YIELD_LINEAR_QUADRATIC, 4, 0, load(0.8, 0.5), 240)));
	EXPECT_TRUE(yields(run(bt6DofElasticPlastic2Constraint::YIELD_LINEAR_QUADRATIC, 4, 0, load(0.8, 0.8), 120)));
	EXPECT_FALSE(yields(run(bt6DofElasticPlastic2Constraint::YIELD_BOX, 4, 0, load(0.8, 0.8), 240)));  // control

	Result r = run(bt6DofElasticPlastic2Constraint::YIELD_LINEAR_QUADRATIC, 4, 0, load(0.9, 0.7), 60);
	ASSERT_TRUE(yields(r));
	double um = r.jointMomentYNm / kMomentNm, un = r.jointForceXN / kAxialN;
	EXPECT_NEAR(um + un * un, 1.0, 0.005);
	// normal: (df/dM, df/dN) = (1 / Mp, 2 un / Np) against (angular rate, axial velocity)
	double normalAngle = std::atan2(2.0 * un / kAxialN, 1.0 / kMomentNm);
	double flowAngle = std::atan2(r.velocityX, r.angularY);
	EXPECT_NEAR(flowAngle, normalAngle, 0.01) << "flow " << flowAngle;
	EXPECT_NEAR(r.bookedJ, r.workJ - r.kineticJ, 0.01 * r.workJ);
}

// Elastic-plastic springs (100 kg m^2/s^2 per rad: 0.5 s natural period, elastic at this step) on the circle: they
// spring below it and return to it above it; the booked work is the load's work less kinetic and elastic energy.
TEST(YieldSurface, ElasticSpringsReturnToTheCircle)
{

	const double k = 100.0;
	Result inside = run(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5, bending(0.9 * kMomentNm, 0.785398), 720, k, 480);
	EXPECT_LT(inside.bookedJ, 1e-6);
	EXPECT_LT(inside.maxRotationRad, 1.1 * 0.9 * kMomentNm / k);
	Result box = run(bt6DofElasticPlastic2Constraint::YIELD_BOX, 4, 5, bending(1.2 * kMomentNm, 0.785398), 720, k, 480);
	EXPECT_LT(box.bookedJ, 1e-6);  // control: the box keeps it elastic
	Result r = run(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5, bending(1.1 * kMomentNm, 0.785398), 540, k, 480);
	EXPECT_GT(r.bookedJ, 0.1);
	EXPECT_NEAR(std::hypot(r.jointMomentYNm, r.jointMomentZNm) / kMomentNm, 1.0, 0.01);
	EXPECT_NEAR(r.bookedJ, r.workJ - r.kineticJ - r.elasticJ, 0.01 * r.workJ);
}

// Every quadrant: the surfaces are symmetric in each force, so a moment with negative or mixed components yields at
// the same magnitude, and the flow has the signs of the moment's components.
TEST(YieldSurface, NegativeAndMixedSignMomentsYieldAlike)
{
	for (double angle : {0.5 + M_PI, -0.8, 2.2})
	{
		Result inside = run(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5, bending(0.97 * kMomentNm, angle), 240);
		Result outside = run(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5, bending(1.03 * kMomentNm, angle), 120);
		EXPECT_LT(inside.maxRotationRad, 1e-3) << angle;
		EXPECT_TRUE(yields(outside)) << angle;
	}
	// the rectangle at -0.3 rad: on its curve and normal to it, with uz < 0
	Result r = run(bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, 4, 5, bending(1.1 * kMomentNm, -0.3), 60);
	ASSERT_TRUE(yields(r));
	double uy = r.jointMomentYNm / kMomentNm, uz = r.jointMomentZNm / kMomentNm;
	EXPECT_LT(uz, 0);
	EXPECT_NEAR(uy + 0.75 * uz * uz, 1.0, 0.005);
	EXPECT_NEAR(std::atan2(r.angularZ, r.angularY), std::atan2(1.5 * uz, 1.0), 0.01);
}

// Elastic-plastic springs on the rectangle's curve under a moment that turns (not proportional: the point slides
// along the surface and each DOF's cap changes from step to step): every bit of flow is booked, the books balance.
TEST(YieldSurface, SpringsUnderATurningMomentBookAllTheirFlow)
{
	const double k = 100.0;
	Result r = run(bt6DofElasticPlastic2Constraint::YIELD_RECTANGLE_BIAXIAL, 4, 5, bending(1.02 * kMomentNm, 0.0), 720, k, 240, 0.5);
	EXPECT_GT(r.bookedJ, 0.1);
	EXPECT_NEAR(r.bookedJ, r.workJ - r.kineticJ - r.elasticJ, 0.01 * r.workJ) << "work " << r.workJ << " J, kinetic " << r.kineticJ << " J, elastic " << r.elasticJ << " J";
}

// Switched off again (YIELD_BOX, any DOFs), a constraint steps bit for bit as one that never had a surface.
TEST(YieldSurface, SwitchedOffIsTheBoxBitForBit)
{
	auto final = [](bool withSurface) {
		std::unique_ptr<bt6DofElasticPlastic2Constraint> owner;
		PhysicsWorld w;
		btRigidBody* body = w.addBox(btVector3(0.1, 0.1, 0.1), 100.0, btVector3(0, 0, 0));
		auto* c = new bt6DofElasticPlastic2Constraint(*body, btTransform::getIdentity());
		owner.reset(c);
		for (int i = 0; i < 6; i++)
		{
			c->setStiffness(i, 0, false);
			c->setMaxForce(i, btScalar(i == 4 || i == 5 ? kMomentNm : 1e6));
		}
		if (withSurface)
		{
			c->setYieldSurface(bt6DofElasticPlastic2Constraint::YIELD_CIRCLE, 4, 5);
			c->setYieldSurface(bt6DofElasticPlastic2Constraint::YIELD_BOX, -1, -1);
		}
		w.world.addConstraint(c);
		for (int s = 0; s < 120; s++)
		{
			body->applyTorque(btVector3(0, btScalar(1.2 * kMomentNm), btScalar(0.6 * kMomentNm)));
			w.world.stepSimulation(btScalar(kDt), 0, btScalar(kDt));
		}
		EXPECT_EQ(c->getYieldSurface(), bt6DofElasticPlastic2Constraint::YIELD_BOX);
		EXPECT_EQ(c->getYieldSurfaceDof(0), -1);
		const btTransform t = body->getWorldTransform();
		return std::vector<double>{t.getOrigin().x(), t.getRotation().x(), t.getRotation().y(), t.getRotation().z(), t.getRotation().w(), double(c->getAbsorbedEnergy())};
	};
	const std::vector<double> never = final(false), off = final(true);
	EXPECT_GT(never[5], 0.0);  // it yielded
	for (size_t i = 0; i < never.size(); i++) EXPECT_EQ(never[i], off[i]) << i;
}

// A constraint that never calls setYieldSurface is the box: the same numbers as a YIELD_BOX one.
TEST(YieldSurface, WithoutASurfaceEachDofYieldsAlone)
{
	Result r = run(bt6DofElasticPlastic2Constraint::YIELD_BOX, 4, 5, bending(1.1 * kMomentNm, 0.0), 60);
	ASSERT_TRUE(yields(r));
	EXPECT_NEAR(r.jointMomentYNm / kMomentNm, 1.0, 0.005);
	EXPECT_NEAR(r.bookedJ, r.workJ - r.kineticJ, 0.01 * r.workJ);
}
