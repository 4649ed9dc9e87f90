// Joint events (issue 21, design review): gPlasticYieldStartedCallback and gPlasticConstraintBrokenCallback report,
// in the step it happens, every constraint that starts to yield and every one that breaks, so a game does not poll
// its joints. Checked against polling the same world step by step (the accumulated rotation grows: it yielded;
// isEnabled() turns false: it broke), on every plastic class, with loads that start, stop and start again.
#include <gtest/gtest.h>

#include <map>
#include <utility>
#include <vector>

#include "PhysicsWorld.h"

namespace
{
std::vector<std::pair<int, const btTypedConstraint*>> gYieldStarted, gBroken;
int gStep = 0;
void onYieldStarted(btTypedConstraint* c) { gYieldStarted.emplace_back(gStep, c); }
void onBroken(btTypedConstraint* c) { gBroken.emplace_back(gStep, c); }

struct Loaded
{
	btRigidBody* body;
	btTypedConstraint* constraint;
	int axis;  // the loaded axis (0 = x, 2 = z)
	double (*rotation)(const btTypedConstraint*);
	double (*moment)(int step);  // N m, in units of Mp
};

double hingeRotation(const btTypedConstraint* c) { return static_cast<const btPlasticHingeConstraint*>(c)->getCurrentPlasticRotation(); }
double ep2Rotation(const btTypedConstraint* c) { return static_cast<const bt6DofElasticPlastic2Constraint*>(c)->getCurrentPlasticRotation(); }
double epRotation(const btTypedConstraint* c) { return static_cast<const bt6DofElasticPlasticConstraint*>(c)->getCurrentPlasticRotation(); }

double never(int) { return 0.5; }                                    // holds
double always(int) { return 1.5; }                                   // yields from the first step
double startStopStart(int s) { return (s < 20 || s >= 60) ? 1.5 : -0.2; }  // yields, stops, yields again
double late(int s) { return s < 40 ? 0.3 : 3.0; }                    // yields from step 40, then breaks

constexpr double kMp = 2.0;

struct Scene
{
	PhysicsWorld w;
	std::vector<Loaded> joints;
	Scene()
	{
		double (*loads[])(int) = {never, always, startStopStart, late};
		for (int kind = 0; kind < 3; kind++)
		{
			for (auto* load : loads)
			{
				const btVector3 at(btScalar(2.0 * joints.size()), 0, 0);
				Loaded j;
				j.moment = load;
				if (kind == 0)
				{
					j.body = w.addBox(btVector3(0.5, 0.05, 0.05), 1.0, at);
					auto* h = new btPlasticHingeConstraint(*j.body, btVector3(0, 0, 0), btVector3(0, 0, 1));
					h->setPlasticMoment(btScalar(kMp));
					h->setMaxPlasticRotation(btScalar(0.5));
					j.constraint = h;
					j.axis = 2;
					j.rotation = hingeRotation;
				}
				else
				{
					j.body = w.addBox(btVector3(0.05, 0.05, 0.5), 1.0, at);
					if (kind == 1)
					{
						auto* c = new bt6DofElasticPlastic2Constraint(*j.body, btTransform::getIdentity());
						for (int i = 0; i < 6; i++)
						{
							c->setStiffness(i, btScalar(0.), false);
							c->setMaxForce(i, btScalar(i == 3 ? kMp : 1e6));
						}
						c->setMaxPlasticRotation(btScalar(0.5));
						j.constraint = c;
						j.rotation = ep2Rotation;
					}
					else
					{
						auto* c = new bt6DofElasticPlasticConstraint(*j.body, btTransform::getIdentity(), true);
						for (int i = 0; i < 6; i++)
						{
							c->setStiffness(i, btScalar(0.));
							c->setMaxForce(i, btScalar(i == 3 ? kMp : 1e6));
						}
						c->setMaxPlasticRotation(btScalar(0.5));
						j.constraint = c;
						j.rotation = epRotation;
					}
					j.axis = 0;
				}
				w.world.addConstraint(j.constraint);
				joints.push_back(j);
			}
		}
	}
	~Scene()
	{
		for (auto& j : joints)
		{
			w.world.removeConstraint(j.constraint);
			delete j.constraint;
		}
	}
	void step(int s)
	{
		for (auto& j : joints)
		{
			btVector3 m(0, 0, 0);
			m[j.axis] = btScalar(j.moment(s) * kMp);
			j.body->applyTorque(m);
		}
		w.world.stepSimulation(btScalar(1.0 / 240.0), 0);
	}
};
}  // namespace

TEST(PlasticEvents, CallbacksReportWhatPollingFindsInTheStepItHappens)
{
	gYieldStarted.clear();
	gBroken.clear();
	gPlasticYieldStartedCallback = onYieldStarted;
	gPlasticConstraintBrokenCallback = onBroken;
	Scene scene;
	std::vector<std::pair<int, const btTypedConstraint*>> polledStarted, polledBroken;
	std::map<const btTypedConstraint*, bool> wasYielding;
	for (gStep = 0; gStep < 200; gStep++)
	{
		std::vector<double> before;
		for (auto& j : scene.joints) before.push_back(j.rotation(j.constraint));
		std::vector<bool> enabled;
		for (auto& j : scene.joints) enabled.push_back(j.constraint->isEnabled());
		scene.step(gStep);
		for (size_t i = 0; i < scene.joints.size(); i++)
		{
			const Loaded& j = scene.joints[i];
			if (!enabled[i]) continue;  // broken before this step: not solved
			const bool yielded = j.rotation(j.constraint) != before[i];
			if (yielded && !wasYielding[j.constraint]) polledStarted.emplace_back(gStep, j.constraint);
			wasYielding[j.constraint] = yielded;
			if (!j.constraint->isEnabled()) polledBroken.emplace_back(gStep, j.constraint);
		}
	}
	gPlasticYieldStartedCallback = 0;
	gPlasticConstraintBrokenCallback = 0;
	EXPECT_EQ(gYieldStarted, polledStarted);
	EXPECT_EQ(gBroken, polledBroken);
	// what the loads must do, per class: always and startStopStart start yielding at step 0, startStopStart again
	// after its pause, late at step 40; all three break (0.5 rad), never neither
	EXPECT_EQ(polledBroken.size(), 9u) << "always, startStopStart and late break, for each of the three classes";
	EXPECT_GE(polledStarted.size(), 12u) << "4 yield starts per class at least";
}

// The callbacks only report: the same world steps bit for bit with and without them.
TEST(PlasticEvents, CallbacksDoNotChangeTheSimulation)
{
	std::vector<btScalar> result[2];
	for (int withCallbacks = 0; withCallbacks < 2; withCallbacks++)
	{
		gPlasticYieldStartedCallback = withCallbacks ? onYieldStarted : 0;
		gPlasticConstraintBrokenCallback = withCallbacks ? onBroken : 0;
		Scene scene;
		for (gStep = 0; gStep < 200; gStep++) scene.step(gStep);
		for (auto& j : scene.joints)
		{
			const btTransform& t = j.body->getWorldTransform();
			for (int r = 0; r < 3; r++)
				for (int c = 0; c < 3; c++) result[withCallbacks].push_back(t.getBasis()[r][c]);
			result[withCallbacks].push_back(btScalar(j.rotation(j.constraint)));
		}
	}
	gPlasticYieldStartedCallback = 0;
	gPlasticConstraintBrokenCallback = 0;
	EXPECT_EQ(result[0], result[1]);
}
