// A 20 kg box turning at 5.6 rad/s about a btHingeConstraint pivot 0.8 m from its centre, in a world without gravity
// (its kinetic energy stays what it was): the rig of the tests of setSplitPositionCorrectionAfterLongerSteps (patch
// 0044), whose pivot drifts by the square of its turn in a step. Any world and solver; the world's gravity is set to 0.
#pragma once

#include <algorithm>
#include <vector>

#include "btBulletDynamicsCommon.h"

enum class PivotCorrection
{
	Baumgarte,         // upstream: the rows' velocity bias in every step
	AfterLongerSteps,  // setSplitPositionCorrectionAfterLongerSteps(true)
	Split,             // setSplitPositionCorrection(true): the split pass in every step
};

struct TurningPendulum
{
	static constexpr double kMass_kg = 20;
	static constexpr double kArm_m = 0.8;
	static constexpr double kSpin_rad_s = 5.6;

	btDiscreteDynamicsWorld& world;
	btBoxShape shape{btVector3(0.05, 0.05, 0.05)};
	btRigidBody body;
	btHingeConstraint pivot;

	TurningPendulum(btDiscreteDynamicsWorld& w, PivotCorrection correction)
		: world(w), body(info(shape)), pivot(body, btVector3(btScalar(-kArm_m), 0, 0), btVector3(0, 0, 1))
	{
		world.setGravity(btVector3(0, 0, 0));
		body.setActivationState(DISABLE_DEACTIVATION);
		// turning about the world's origin: v = w x r
		body.setAngularVelocity(btVector3(0, 0, btScalar(kSpin_rad_s)));
		body.setLinearVelocity(btVector3(0, btScalar(kSpin_rad_s * kArm_m), 0));
		world.addRigidBody(&body, 0, 0);
		pivot.setSplitPositionCorrection(correction == PivotCorrection::Split);
		pivot.setSplitPositionCorrectionAfterLongerSteps(correction == PivotCorrection::AfterLongerSteps);
		world.addConstraint(&pivot, true);
	}
	~TurningPendulum()
	{
		world.removeConstraint(&pivot);
		world.removeRigidBody(&body);
	}

	double kineticEnergy_j() const
	{
		const btVector3 local = body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
		const btVector3 I = body.getLocalInertia();
		return 0.5 * kMass_kg * double(body.getLinearVelocity().length2()) +
			   0.5 * double(I.x() * local.x() * local.x() + I.y() * local.y() * local.y() + I.z() * local.z() * local.z());
	}
	double pivotDrift_m() const { return double(body.getCenterOfMassPosition().length()) - kArm_m; }

	// steps the world through the given steps; the largest rise of its kinetic energy over the one it started with [J]
	double largestRise_j(const std::vector<double>& steps_s)
	{
		const double start = kineticEnergy_j();
		double rise = 0;
		for (double h : steps_s)
		{
			world.stepSimulation(btScalar(h), 0);
			rise = std::max(rise, kineticEnergy_j() - start);
		}
		return rise;
	}

	// ten 0.1 ms steps, one of 1.3 ms, then twenty of 2 us: frames gathered out of contact, then contact substeps
	static std::vector<double> gatheredThenShortSteps()
	{
		std::vector<double> steps(10, 1e-4);
		steps.push_back(1.3e-3);
		steps.insert(steps.end(), 20, 2e-6);
		return steps;
	}

private:
	static btRigidBody::btRigidBodyConstructionInfo info(btBoxShape& shape)
	{
		btVector3 inertia;
		shape.calculateLocalInertia(btScalar(kMass_kg), inertia);
		btRigidBody::btRigidBodyConstructionInfo i(btScalar(kMass_kg), nullptr, &shape, inertia);
		i.m_startWorldTransform.setIdentity();
		i.m_startWorldTransform.setOrigin(btVector3(btScalar(kArm_m), 0, 0));
		return i;
	}
};
