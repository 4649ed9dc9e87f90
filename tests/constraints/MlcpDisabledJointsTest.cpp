// Patch 0021: btMLCPSolver::createMLCPFast keeps one row offset per constraint it visits (disabled constraints, which
// have no rows, included) and per contact row, but sized that array by the number of rows: with more disabled joints
// than enabled rows the first step wrote past its end (AddressSanitizer: heap-buffer-overflow at `ofs[c] = rowOffset`;
// without ASan, malloc aborted). A double pendulum of two enabled hinges with 16 disabled hinges on the same links and a
// box resting on the ground, under btMLCPSolver + btDantzigSolver at 240 Hz: the scene must give more entries than rows,
// the enabled hinges must hold the links at their pivots and axes, the disabled ones must not stop the swing, the
// contact must hold the box, and the run must be bit-identical to the same world without the disabled hinges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "btBulletDynamicsCommon.h"
#include "BulletDynamics/MLCPSolvers/btDantzigSolver.h"
#include "BulletDynamics/MLCPSolvers/btMLCPSolver.h"

namespace
{
// Counts, before each direct solve, the rows and the entries createMLCPFast walks: a non-contact constraint is one entry
// with its own number of rows (0 if disabled), a contact row one entry (contacts and friction are not interleaved).
class EntryCountingMlcpSolver : public btMLCPSolver
{
public:
	using btMLCPSolver::btMLCPSolver;

	int solves = 0;
	int maxEntriesOverRows = 0;

protected:
	void createMLCPFast(const btContactSolverInfo& infoGlobal) override
	{
		const int rows = m_allConstraintPtrArray.size();
		const int nonContactRows = m_tmpSolverNonContactConstraintPool.size();
		int entries = 0;
		for (int i = 0; i < rows; entries++)
			i += i < nonContactRows ? m_tmpConstraintSizesPool[entries].m_numConstraintRows : 1;
		solves++;
		maxEntriesOverRows = std::max(maxEntriesOverRows, entries - rows);
		btMLCPSolver::createMLCPFast(infoGlobal);
	}
};

struct MlcpWorld
{
	btDefaultCollisionConfiguration configuration;
	btCollisionDispatcher dispatcher{&configuration};
	btDbvtBroadphase broadphase;
	btDantzigSolver dantzig;
	EntryCountingMlcpSolver solver{&dantzig};
	btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
	std::vector<std::unique_ptr<btBoxShape>> shapes;
	std::vector<std::unique_ptr<btRigidBody>> bodies;
	std::vector<std::unique_ptr<btTypedConstraint>> joints;

	MlcpWorld()
	{
		world.setGravity(btVector3(0, -10, 0));
		world.getSolverInfo().m_globalCfm = btScalar(1e-8);  // the four coplanar contacts of a box make A singular
	}
	~MlcpWorld()
	{
		for (auto& joint : joints) world.removeConstraint(joint.get());
		for (auto& body : bodies) world.removeRigidBody(body.get());
	}

	// a box of half extents h; collides with the others only if `collides`
	btRigidBody* addBox(const btVector3& h, double mass, const btVector3& position, bool collides)
	{
		shapes.push_back(std::make_unique<btBoxShape>(h));
		btVector3 inertia(0, 0, 0);
		if (mass > 0) shapes.back()->calculateLocalInertia(btScalar(mass), inertia);
		btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, shapes.back().get(), inertia);
		info.m_startWorldTransform.setIdentity();
		info.m_startWorldTransform.setOrigin(position);
		bodies.push_back(std::make_unique<btRigidBody>(info));
		bodies.back()->setActivationState(DISABLE_DEACTIVATION);
		if (collides)
			world.addRigidBody(bodies.back().get());
		else
			world.addRigidBody(bodies.back().get(), 0, 0);
		return bodies.back().get();
	}

	btHingeConstraint* addHinge(btHingeConstraint* hinge, bool enabled)
	{
		joints.emplace_back(hinge);
		hinge->setEnabled(enabled);
		world.addConstraint(hinge, true);
		return hinge;
	}
};

double distance(const btVector3& a, const btVector3& b) { return double((a - b).length()); }

struct PendulumRun
{
	int solves = 0, maxEntriesOverRows = 0, fallbacks = 0;
	double worstPivot = 0, worstAxis = 0;  // m; 1 - cos of the tilt of a link's Z axis
	double lowestLink1 = 0;                // y of link 1's long axis: -1 hanging straight down
	double lowestBox = 1, highestBox = 0;  // m
	btTransform link1, link2, box;
};

// two 0.5 m links, horizontal at the start, hinged about Z at the top and to each other, released for 2 s at 1/240 s;
// `disabledPerGroup` disabled hinges of link 1 to the world (about X, along the link: they would hold it horizontal)
// are added before the enabled hinges and as many of link 1 to link 2 (about Y) between them
PendulumRun runPendulum(int disabledPerGroup)
{
	MlcpWorld w;
	const btVector3 top(0, 3, 0), z(0, 0, 1);
	btRigidBody* link1 = w.addBox(btVector3(0.25f, 0.05f, 0.05f), 1.0, top + btVector3(0.25f, 0, 0), false);
	btRigidBody* link2 = w.addBox(btVector3(0.25f, 0.05f, 0.05f), 1.0, top + btVector3(0.75f, 0, 0), false);
	const btVector3 leftEnd(-0.25f, 0, 0), rightEnd(0.25f, 0, 0);
	for (int k = 0; k < disabledPerGroup; k++)
		w.addHinge(new btHingeConstraint(*link1, btVector3(btScalar(0.05 * k - 0.2), 0, 0), btVector3(1, 0, 0)), false);
	w.addHinge(new btHingeConstraint(*link1, leftEnd, z), true);
	for (int k = 0; k < disabledPerGroup; k++)
		w.addHinge(new btHingeConstraint(*link1, *link2, rightEnd, leftEnd, btVector3(0, 1, 0), btVector3(0, 1, 0)), false);
	w.addHinge(new btHingeConstraint(*link1, *link2, rightEnd, leftEnd, z, z), true);
	// a box resting on the ground beside them: contact and friction rows in the same solve
	w.addBox(btVector3(5, 0.5f, 5), 0, btVector3(0, -0.5f, 0), true);
	btRigidBody* box = w.addBox(btVector3(0.1f, 0.1f, 0.1f), 1.0, btVector3(2, 0.099f, 0), true);

	PendulumRun run;
	for (int step = 0; step < 480; step++)
	{
		w.world.stepSimulation(btScalar(1. / 240.), 0);
		const btTransform& t1 = link1->getWorldTransform();
		const btTransform& t2 = link2->getWorldTransform();
		run.worstPivot = std::max({run.worstPivot, distance(t1 * leftEnd, top), distance(t1 * rightEnd, t2 * leftEnd)});
		run.worstAxis = std::max({run.worstAxis, 1 - double(t1.getBasis().getColumn(2).dot(z)), 1 - double(t2.getBasis().getColumn(2).dot(z))});
		run.lowestLink1 = std::min(run.lowestLink1, double(t1.getBasis().getColumn(0).y()));
		run.lowestBox = std::min(run.lowestBox, double(box->getWorldTransform().getOrigin().y()));
		run.highestBox = std::max(run.highestBox, double(box->getWorldTransform().getOrigin().y()));
	}
	run.solves = w.solver.solves;
	run.maxEntriesOverRows = w.solver.maxEntriesOverRows;
	run.fallbacks = w.solver.getNumFallbacks();
	run.link1 = link1->getWorldTransform();
	run.link2 = link2->getWorldTransform();
	run.box = box->getWorldTransform();
	return run;
}

void expectSameTransform(const btTransform& a, const btTransform& b, const char* what)
{
	for (int i = 0; i < 3; i++)
	{
		EXPECT_EQ(a.getOrigin()[i], b.getOrigin()[i]) << what << " position " << i;
		for (int j = 0; j < 3; j++) EXPECT_EQ(a.getBasis()[i][j], b.getBasis()[i][j]) << what << " basis " << i << j;
	}
}
}  // namespace

TEST(MlcpDisabledJoints, EnabledHingesHoldBesideManyDisabledOnes)
{
	const PendulumRun run = runPendulum(8);
	ASSERT_EQ(run.solves, 480);
	EXPECT_GT(run.maxEntriesOverRows, 0) << "the scene must give createMLCPFast more entries than rows";
	EXPECT_EQ(run.fallbacks, 0) << "the direct solve failed";
	EXPECT_LT(run.worstPivot, 0.01) << "the enabled hinges let their pivots part (m)";
	EXPECT_LT(run.worstAxis, 1e-4) << "the enabled hinges let their axes tilt away from Z";
	EXPECT_LT(run.lowestLink1, -0.9) << "link 1 did not swing down: the disabled hinges held it";
	EXPECT_GT(run.lowestBox, 0.09) << "the box sank into the ground (m)";
	EXPECT_LT(run.highestBox, 0.11) << "the box jumped off the ground (m)";
}

TEST(MlcpDisabledJoints, DisabledHingesChangeNothing)
{
	const PendulumRun with = runPendulum(8), without = runPendulum(0);
	EXPECT_EQ(without.maxEntriesOverRows, 0);
	EXPECT_EQ(without.fallbacks, 0);
	expectSameTransform(with.link1, without.link1, "link 1");
	expectSameTransform(with.link2, without.link2, "link 2");
	expectSameTransform(with.box, without.box, "box");
}
