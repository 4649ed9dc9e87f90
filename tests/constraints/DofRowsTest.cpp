// Which rows a 6-DOF constraint filled for each DOF (getDofFirstRow / getDofNumRows: patch 0004 for
// btGeneric6DofSpring2Constraint, patch 0024 for btGeneric6DofConstraint), checked against the rows themselves: the
// solver hands a constraint its solved rows (processSolvedRows), and a DOF's row acts along that DOF's axis (its
// linear Jacobian is the axis for a linear DOF, its angular Jacobian the axis for an angular one). The frame is turned
// off the world axes, so that no two DOFs share an axis.
#include <gtest/gtest.h>

#include <vector>

#include "PhysicsWorld.h"

namespace
{
template <class Base>
class RowRecorder : public Base
{
public:
	using Base::Base;
	struct Row
	{
		btVector3 linear;
		btVector3 angular;
	};
	std::vector<Row> rows;

	void processSolvedRows(const btSolverConstraint* solved, int numRows, const btSolverBody& bodyA, const btSolverBody& bodyB, btScalar timeStep) override
	{
		rows.clear();
		for (int i = 0; i < numRows; i++) rows.push_back(Row{solved[i].m_contactNormal1, solved[i].m_relpos1CrossNormal});
		Base::processSolvedRows(solved, numRows, bodyA, bodyB, timeStep);
	}
};

btTransform turnedFrame()
{
	btTransform frame;
	frame.setIdentity();
	frame.setRotation(btQuaternion(btVector3(1, 1, 1).normalized(), btScalar(0.4)));
	frame.setOrigin(btVector3(0.5, 0, 0));
	return frame;
}

// each DOF's rows act along its axis; DOFs without rows report -1 and 0; the counts add up to the rows
template <class Constraint>
void expectRowsAlongTheirDofs(const Constraint& c, const std::vector<int>& expectedRows)
{
	const btMatrix3x3 basis = c.getCalculatedTransformA().getBasis();
	int total = 0;
	for (int i = 0; i < 6; i++)
	{
		EXPECT_EQ(expectedRows[size_t(i)], c.getDofNumRows(i)) << "DOF " << i;
		if (c.getDofNumRows(i) == 0)
		{
			EXPECT_EQ(-1, c.getDofFirstRow(i)) << "DOF " << i;
			continue;
		}
		total += c.getDofNumRows(i);
		const btVector3 axis = i < 3 ? basis.getColumn(i) : c.getAxis(i - 3);
		for (int r = c.getDofFirstRow(i); r < c.getDofFirstRow(i) + c.getDofNumRows(i); r++)
		{
			ASSERT_LT(r, int(c.rows.size()));
			const btVector3 along = i < 3 ? c.rows[size_t(r)].linear : c.rows[size_t(r)].angular;
			EXPECT_NEAR(1.0, std::fabs(double(along.normalized().dot(axis))), 1e-5) << "DOF " << i << ", row " << r;
		}
	}
	EXPECT_EQ(int(c.rows.size()), total);
}
}  // namespace

TEST(DofRows, Generic6DofRecordsTheRowOfEachDofInBothFrameOrders)
{
	for (bool offset : {true, false})
	{
		PhysicsWorld w;
		btRigidBody* a = w.addBox(btVector3(0.1, 0.1, 0.1), 0, btVector3(0, 0, 0));
		btRigidBody* b = w.addBox(btVector3(0.1, 0.1, 0.1), 1, btVector3(1, 0, 0));
		const btTransform frameA = turnedFrame();
		const btTransform frameB = b->getWorldTransform().inverse() * frameA;
		RowRecorder<btGeneric6DofConstraint> c(*a, *b, frameA, frameB, true);
		c.setUseFrameOffset(offset);
		c.setLinearLowerLimit(btVector3(1, 1, 1));  // free
		c.setLinearUpperLimit(btVector3(-1, -1, -1));
		c.setAngularLowerLimit(btVector3(1, 1, 1));
		c.setAngularUpperLimit(btVector3(-1, -1, -1));
		// motors on linear y, angular x and angular z: one row each (a 6DOF motor and limit share a row)
		c.getTranslationalLimitMotor()->m_enableMotor[1] = true;
		c.getTranslationalLimitMotor()->m_targetVelocity[1] = btScalar(0.1);
		c.getTranslationalLimitMotor()->m_maxMotorForce[1] = btScalar(10);
		for (int i : {0, 2})
		{
			c.getRotationalLimitMotor(i)->m_enableMotor = true;
			c.getRotationalLimitMotor(i)->m_targetVelocity = btScalar(0.1);
			c.getRotationalLimitMotor(i)->m_maxMotorForce = btScalar(10);
		}
		w.world.addConstraint(&c);
		w.world.stepSimulation(btScalar(1.0 / 60), 0);
		expectRowsAlongTheirDofs(c, {0, 1, 0, 1, 0, 1});
		// the frame order: angular rows first with the frame offset, linear first without
		EXPECT_EQ(offset ? 2 : 0, c.getDofFirstRow(1)) << "offset " << offset;
		w.world.removeConstraint(&c);
	}
}

TEST(DofRows, Spring2RecordsALimitAndAMotorOfOneDof)
{
	PhysicsWorld w;
	btRigidBody* a = w.addBox(btVector3(0.1, 0.1, 0.1), 0, btVector3(0, 0, 0));
	btRigidBody* b = w.addBox(btVector3(0.1, 0.1, 0.1), 1, btVector3(1, 0, 0));
	const btTransform frameA = turnedFrame();
	const btTransform frameB = b->getWorldTransform().inverse() * frameA;
	RowRecorder<btGeneric6DofSpring2Constraint> c(*a, *b, frameA, frameB);
	c.setLinearLowerLimit(btVector3(0, 1, 1));  // x locked, y and z free
	c.setLinearUpperLimit(btVector3(0, -1, -1));
	c.setAngularLowerLimit(btVector3(1, 1, 0));  // z locked, x and y free
	c.setAngularUpperLimit(btVector3(-1, -1, 0));
	for (int i : {1, 3, 5})
	{
		c.enableMotor(i, true);
		c.setTargetVelocity(i, btScalar(0.1));
		c.setMaxMotorForce(i, btScalar(10));
	}
	w.world.addConstraint(&c);
	w.world.stepSimulation(btScalar(1.0 / 60), 0);
	// angular z has its lock and its motor: two rows (Spring2 solves them apart)
	expectRowsAlongTheirDofs(c, {1, 1, 0, 1, 0, 2});
	w.world.removeConstraint(&c);
}
