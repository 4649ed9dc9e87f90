#include "SubstepPolicy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h"
#include "BulletCollision/NarrowPhaseCollision/btPointCollector.h"
#include "BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h"
#include "LinearMath/btTransformUtil.h"
#include "btBulletDynamicsCommon.h"

namespace plastic
{
namespace
{
const btRigidBody* movingBody(const btCollisionObject* object)
{
	return object->isStaticObject() ? nullptr : btRigidBody::upcast(object);
}

// the velocity of a's material at the world point `at` against b's there (a null body is static)
btVector3 pointVelocityAgainst(const btRigidBody* a, const btRigidBody* b, const btVector3& at)
{
	btVector3 velocity(0, 0, 0);
	if (a)
	{
		velocity += a->getVelocityInLocalPoint(at - a->getCenterOfMassPosition());
	}
	if (b)
	{
		velocity -= b->getVelocityInLocalPoint(at - b->getCenterOfMassPosition());
	}
	return velocity;
}

bool overlap(const btVector3& aLo, const btVector3& aHi, const btVector3& bLo, const btVector3& bHi)
{
	return aLo.x() <= bHi.x() && bLo.x() <= aHi.x() && aLo.y() <= bHi.y() && bLo.y() <= aHi.y() && aLo.z() <= bHi.z() && bLo.z() <= aHi.z();
}

// The object's pieces: one per child of a compound shape (a hammer's arm, head and striker; the box of the whole
// compound would cover the air between them), else the shape itself. Each has its box, grown by `grow`, and, when it
// is convex, its shape and world transform for the distance test (else shape is null and its box stands for it).
struct Piece
{
	btVector3 lo, hi;
	const btConvexShape* shape;
	btTransform transform;
};

int pieces(const btCollisionObject* object, btScalar grow, Piece* out, int capacity)
{
	const btCollisionShape* shape = object->getCollisionShape();
	int count = 0;
	if (shape->isCompound())
	{
		const btCompoundShape* compound = static_cast<const btCompoundShape*>(shape);
		if (compound->getNumChildShapes() <= capacity)
		{
			for (int i = 0; i < compound->getNumChildShapes(); i++)
			{
				const btCollisionShape* child = compound->getChildShape(i);
				out[count].transform = object->getWorldTransform() * compound->getChildTransform(i);
				child->getAabb(out[count].transform, out[count].lo, out[count].hi);
				out[count].shape = child->isConvex() ? static_cast<const btConvexShape*>(child) : nullptr;
				count++;
			}
		}
	}
	if (count == 0)
	{
		out[0].transform = object->getWorldTransform();
		shape->getAabb(out[0].transform, out[0].lo, out[0].hi);
		out[0].shape = shape->isConvex() ? static_cast<const btConvexShape*>(shape) : nullptr;
		count = 1;
	}
	const btVector3 g(grow, grow, grow);
	for (int i = 0; i < count; i++)
	{
		out[i].lo -= g;
		out[i].hi += g;
	}
	return count;
}

// The mover's motion against the other (relativeMotion)
struct Motion
{
	btVector3 velocity;             // of the mover's centre of mass, in the other's moving frame [m/s]
	btVector3 spin;                 // the mover's spin in the other's frame, w_m - w_o [rad/s]
	btVector3 otherSpin;            // the other's spin w_o [rad/s]
	btVector3 centre;               // the mover's centre of mass
	double spinSpeed_m_s;           // the bound of the spin's speed at the mover's points
	double frameAcceleration_m_s2;  // the bound of the other's turning frame's acceleration at the mover's centre
};

// How far the mover can go against the other within the horizon: `grow` bounds it in every direction (its speed bound
// times the horizon, plus the accelerations' part and the clearance); along a normal n from the other towards the
// mover it is at most `fixed` (the spin's part, the accelerations' and the clearance) plus the horizon times the
// mover's closing speed along n, -motion.velocity . n.
struct Reach
{
	btScalar grow;
	btScalar fixed;
	Motion motion;
	btScalar horizon;
	btScalar clearance;
	btScalar speculativeReach;  // 0: no speculative contacts
	btScalar acceleration;      // the difference of their gravity and the other's frame's acceleration [m/s^2]
	bool touchOnly = false;     // near only if they can touch, whatever the speculative reach (withinAlongPath)
};

// How far a box mover's points can come towards the plane through `onOther` with normal n (from the other towards the
// mover) within the horizon, each vertex on its own: a box's points nearest to a plane after a rigid motion are among
// its vertices, and a vertex q moves along n by its velocity in the other's frame, v + w x (q - c), times the time,
// plus at most 1/2 (a + (|w|^2 + |w x w_o|) |q - c|) t^2: the accelerations, and the turn's second order, in which
// the relative spin w = w_m - w_o, fixed in the world, turns in the other's frame at w_o (an angular acceleration
// w x w_o there). A convex other lies behind
// the plane through its support point along n, so no point of the mover reaches it before crossing that plane. The
// pair counts as near if a vertex already within the speculative reach moves more than half of it towards the plane, or
// a vertex past the reach can cross its way to the plane (with the clearance). A part lying on the hammer's nose, or
// turning about its contact with it, has its far vertices moving along the plane or away from it, which the bound of
// its spin at its farthest corner counted as closing. The second-order expansion is kept to horizons in which the
// bodies turn less than a quarter revolution (|w| + |w_o|) t < pi / 2: returns -1 for a longer horizon, and for a mover
// that is not a box (the caller falls back to the bound of the spin at the farthest corner, an arc length that holds
// at any angle).
int boxVerticesNear(const Piece& mover, const btVector3& n, const btVector3& onOther, const Reach& reach)
{
	const Motion& motion = reach.motion;
	const btScalar h = reach.horizon;
	const btScalar turn = (motion.spin.length() + motion.otherSpin.length()) * h;
	if (!mover.shape || mover.shape->getShapeType() != BOX_SHAPE_PROXYTYPE || !(turn < SIMD_HALF_PI))
	{
		return -1;
	}
	const btScalar curvature = motion.spin.length2() + motion.spin.cross(motion.otherSpin).length();
	const btBoxShape* box = static_cast<const btBoxShape*>(mover.shape);
	for (int i = 0; i < 8; i++)
	{
		btVector3 vertex;
		box->getVertex(i, vertex);
		const btVector3 q = mover.transform(vertex);
		const btVector3 r = q - motion.centre;
		const btScalar height = n.dot(q - onOther);
		const btScalar along = (motion.velocity + motion.spin.cross(r)).dot(n);
		const btScalar moves = btMax(btScalar(0), -along) * h + btScalar(0.5) * (reach.acceleration + curvature * r.length()) * h * h;
		if (height <= reach.speculativeReach && !reach.touchOnly ? moves > reach.speculativeReach / 2 : moves + reach.clearance >= height)
		{
			return 1;
		}
	}
	return 0;
}

// GJK's closest points of two convex pieces (no penetration solver: overlapping shapes give no result), the normal
// from the other towards the mover
btPointCollector closestPoints(const Piece& mover, const Piece& other)
{
	btVoronoiSimplexSolver simplex;
	btGjkPairDetector gjk(mover.shape, other.shape, &simplex, nullptr);
	btDiscreteCollisionDetectorInterface::ClosestPointInput input;
	input.m_transformA = mover.transform;
	input.m_transformB = other.transform;
	btPointCollector closest;
	gjk.getClosestPoints(input, closest, nullptr);
	return closest;
}

// whether two pieces can touch within the horizon: their boxes overlap (the mover's grown by reach.grow) and, when both
// are convex, the distance between their shapes (GJK; 0 when they overlap) is at most what the mover can close along
// the normal between them. The shapes' gap along a fixed direction n bounds their distance from below; translated,
// the mover changes it by its velocity along n times the time, and its spin and the accelerations move none of its
// points more than reach.fixed. A body sliding past another closes nothing. With speculative contacts, a box mover's
// vertices are taken one by one against the plane that separates the other (boxVerticesNear); another mover's pair
// within their reach counts only if it can move more than half the reach against the other within the horizon. A pair
// that touches or overlaps is left to its contacts as well (whether they carry load is pressedContact's to tell).
bool within(const Piece& mover, const Piece& other, const Reach& reach, btScalar* gjkDistance = nullptr)
{
	const btScalar grow = reach.grow;
	if (!overlap(mover.lo, mover.hi, other.lo, other.hi))
	{
		return false;
	}
	if (!mover.shape || !other.shape)
	{
		return true;
	}
	const btPointCollector closest = closestPoints(mover, other);
	if (gjkDistance)
	{
		*gjkDistance = closest.m_hasResult ? closest.m_distance : btScalar(0);
	}
	// without a penetration solver an overlap gives no result (and so would a distance past the input's default
	// m_maximumDistanceSquared, 1e18 m^2)
	if (!closest.m_hasResult)
	{
		return true;
	}
	// GJK's answer is only as good as its tolerances: without gVoronoiSimplexLengthScale set to the shapes' size, or
	// at one of its early exits, it can give a positive distance for overlapping shapes. The shapes' gap along the
	// normal it found (their support points, margins included) is a lower bound of their distance that holds
	// whatever GJK did; the smaller of the two is taken.
	const btVector3 n = closest.m_normalOnBInWorld;  // from the other towards the mover
	const btVector3 moverNearest = mover.transform(mover.shape->localGetSupportingVertex(-n * mover.transform.getBasis()));
	const btVector3 otherNearest = other.transform(other.shape->localGetSupportingVertex(n * other.transform.getBasis()));
	const btScalar alongNormal = n.dot(moverNearest) - n.dot(otherNearest);
	const btScalar closes = reach.fixed + btMax(btScalar(0), -reach.motion.velocity.dot(n)) * reach.horizon;
	const btScalar distance = btMin(closest.m_distance, alongNormal);
	if (reach.speculativeReach > 0)
	{
		const int vertices = boxVerticesNear(mover, n, otherNearest, reach);
		if (vertices >= 0)
		{
			return vertices == 1;
		}
		if (distance <= reach.speculativeReach && !reach.touchOnly)
		{
			return closes - reach.clearance > reach.speculativeReach / 2;
		}
	}
	return distance <= btMin(grow, closes);
}

// whether a pair of convex pieces that within() counts as near over the whole horizon still is along the mover's
// path: the horizon in kPathParts equal parts, the mover put where its velocity and spin in the other's frame take it
// by the start of each (btTransformUtil::integrateTransform about its centre) and tested over that part alone, with
// the clearance grown by how far its points can be from that prediction by then, 1/2 (a + (|w|^2 + |w x w_o|) r) t^2
// (the accelerations and the turn's second order, as boxVerticesNear bounds them; r the farthest point from the
// centre). A bound over the whole horizon takes each point's closing speed at the start for all of it: a half flying
// past the hammer's nose spinning at 100 rad/s has corners whose tangent lines cross the nose's tangent plane within
// 0.2 ms, and passes it half a millimetre away. gjkDistance: the distance within() found between them now (0 for an
// overlap).
bool withinAlongPath(const Piece& mover, const Piece& other, const Reach& reach, btScalar gjkDistance)
{
	const int kPathParts = 8;
	const Motion& motion = reach.motion;
	const btScalar part = reach.horizon / kPathParts;
	const btTransform centreFrame(mover.transform.getBasis(), motion.centre);
	const btTransform local = centreFrame.inverseTimes(mover.transform);
	const btScalar spin = motion.spin.length();
	const btScalar farthest = spin > 0 ? btScalar(motion.spinSpeed_m_s) / spin : btScalar(0);
	const btScalar curvature = motion.spin.length2() + motion.spin.cross(motion.otherSpin).length();
	if (reach.speculativeReach > 0 && gjkDistance <= reach.speculativeReach)
	{
		// a pair within the speculative reach counts by how far it moves against the other over the whole horizon
		// (within): the parts would each move less
		return true;
	}
	for (int k = 0; k < kPathParts; k++)
	{
		const btScalar t = part * k;
		btTransform moved;
		btTransformUtil::integrateTransform(centreFrame, motion.velocity, motion.spin, t, moved);
		Piece at = mover;
		at.transform = moved * local;
		Reach along = reach;
		along.touchOnly = true;
		along.motion.centre = moved.getOrigin();
		along.horizon = part;
		along.clearance = reach.clearance + btScalar(0.5) * (reach.acceleration + curvature * farthest) * t * t;
		along.fixed = btScalar(motion.spinSpeed_m_s) * part + btScalar(0.5) * reach.acceleration * part * part + along.clearance;
		along.grow = motion.velocity.length() * part + along.fixed;
		at.shape->getAabb(at.transform, at.lo, at.hi);
		const btVector3 g(along.grow, along.grow, along.grow);
		at.lo -= g;
		at.hi += g;
		if (within(at, other, along))
		{
			return true;
		}
	}
	return false;
}
}  // namespace

namespace
{
// How far a body's centre's acceleration can be from its gravity because a hinge holds it to a body that does not move
// [m/s^2]: it turns about the hinge's fixed axis through the pivot p, its centre accelerating by at most |w|^2 |c - p|
// towards the axis, and by gravity's torque about the axis at most |g| across the arm (the body's moment of inertia
// about the axis is at least m |c - p|^2); the pivot takes the rest of its weight. A hammer swinging at 5.5 rad/s with
// its centre 0.7 m below its pivot is 31 m/s^2 from its gravity, 0.4 mm over 5 ms. A hinge's motor and limit are left
// out, as other forces are, and so are ball joints, whose body's gyroscopic turn this does not bound. 0 for a body no
// such hinge holds (and for an object that does not move); Bullet records a joint on its bodies when the world adds it
// with collisions between them disabled.
double heldAcceleration_m_s2(const btCollisionObject* object)
{
	const btRigidBody* body = movingBody(object);
	double held = 0;
	if (!body)
	{
		return held;
	}
	for (int i = 0; i < body->getNumConstraintRefs(); i++)
	{
		const btTypedConstraint* joint = const_cast<btRigidBody*>(body)->getConstraintRef(i);  // Bullet's getter is not const
		const bool isA = &joint->getRigidBodyA() == body;
		const btRigidBody& other = isA ? joint->getRigidBodyB() : joint->getRigidBodyA();
		if (!joint->isEnabled() || movingBody(&other))
		{
			continue;
		}
		if (joint->getConstraintType() != HINGE_CONSTRAINT_TYPE)
		{
			continue;
		}
		const btHingeConstraint* hinge = static_cast<const btHingeConstraint*>(joint);
		const btVector3 pivotInBody = (isA ? hinge->getAFrame() : hinge->getBFrame()).getOrigin();
		const btVector3 arm = body->getCenterOfMassPosition() - body->getCenterOfMassTransform() * pivotInBody;
		held = std::max(held, double(body->getAngularVelocity().length2()) * double(arm.length()) + double(body->getGravity().length()));
	}
	return held;
}
}  // namespace

double relativeGravity_m_s2(const btCollisionObject* mover, const btCollisionObject* other)
{
	const btRigidBody* m = movingBody(mover);
	const btRigidBody* o = movingBody(other);
	const btVector3 gm = m ? m->getGravity() : btVector3(0, 0, 0);
	const btVector3 go = o ? o->getGravity() : btVector3(0, 0, 0);
	return double((gm - go).length());
}

namespace
{
// The mover's centre's velocity in the other's moving frame and the bound of its spin's speed at its points. In a
// turning other's frame the mover's centre also accelerates with the frame's Coriolis and centripetal terms,
// 2 w_o x v and w_o x (w_o x r): frameAcceleration_m_s2 bounds them by 2 |w_o| |v| + |w_o|^2 |r| (r from the other's
// centre of mass). A ball 0.7 m from the centre of a wall turning at 2 rad/s slides along its face, closing nothing
// along the normal, and the wall's end sweeps into it after 0.64 s.
Motion relativeMotion(const btCollisionObject* mover, const btCollisionObject* other)
{
	const btRigidBody* m = movingBody(mover);
	const btRigidBody* o = movingBody(other);
	btVector3 lo, hi;
	mover->getCollisionShape()->getAabb(mover->getWorldTransform(), lo, hi);
	Motion motion;
	motion.centre = m ? m->getCenterOfMassPosition() : mover->getWorldTransform().getOrigin();
	const btVector3 up = (hi - motion.centre).absolute(), down = (motion.centre - lo).absolute();
	const double reach = double(btVector3(btMax(up.x(), down.x()), btMax(up.y(), down.y()), btMax(up.z(), down.z())).length());
	motion.velocity.setValue(0, 0, 0);
	motion.spin.setValue(0, 0, 0);
	motion.otherSpin.setValue(0, 0, 0);
	if (m)
	{
		motion.velocity = m->getLinearVelocity();
		motion.spin = m->getAngularVelocity();
	}
	motion.frameAcceleration_m_s2 = 0;
	if (o)
	{
		const btVector3 arm = motion.centre - o->getCenterOfMassPosition();
		const btVector3& w = o->getAngularVelocity();
		motion.velocity -= o->getLinearVelocity() + w.cross(arm);
		motion.spin -= w;
		motion.otherSpin = w;
		motion.frameAcceleration_m_s2 = double(w.length()) * (2 * double(motion.velocity.length()) + double(w.length()) * double(arm.length()));
	}
	motion.spinSpeed_m_s = double(motion.spin.length()) * reach;
	return motion;
}

// How far the pair's relative acceleration can be from none [m/s^2]: their gravity difference, the other's turning
// frame at the mover's centre (motion, relativeMotion's), and a hinge that holds either to a body that does not move
// (otherHeld_m_s2: heldAcceleration_m_s2(other), which a caller asking for many movers takes once)
double pairAcceleration_m_s2(const btCollisionObject* mover, const btCollisionObject* other, const Motion& motion, double otherHeld_m_s2)
{
	return relativeGravity_m_s2(mover, other) + motion.frameAcceleration_m_s2 + heldAcceleration_m_s2(mover) + otherHeld_m_s2;
}

// Whether the manifold lies between a body of `movers` and an object of `others`; moverIsBody0 says which of its
// bodies is the mover
bool betweenSets(const btPersistentManifold& manifold, const std::vector<const btCollisionObject*>& movers,
				 const std::vector<const btCollisionObject*>& others, bool& moverIsBody0)
{
	auto in = [](const std::vector<const btCollisionObject*>& set, const btCollisionObject* o)
	{
		return std::find(set.begin(), set.end(), o) != set.end();
	};
	const btCollisionObject* a = manifold.getBody0();
	const btCollisionObject* b = manifold.getBody1();
	moverIsBody0 = in(movers, a) && in(others, b);
	return moverIsBody0 || (in(movers, b) && in(others, a));
}

// Whether a point of the manifold carried an impulse in the world's last step; a point without friction whose bodies
// slide past each other there faster than frictionlessSlide_m_s does not count
bool carriedImpulse(const btPersistentManifold& manifold, double frictionlessSlide_m_s = std::numeric_limits<double>::infinity())
{
	const btRigidBody* body0 = movingBody(manifold.getBody0());
	const btRigidBody* body1 = movingBody(manifold.getBody1());
	for (int j = 0; j < manifold.getNumContacts(); j++)
	{
		const btManifoldPoint& point = manifold.getContactPoint(j);
		if (!(point.getAppliedImpulse() > 0))
		{
			continue;
		}
		if (point.m_combinedFriction > 0 || std::isinf(frictionlessSlide_m_s))
		{
			return true;
		}
		const btVector3 at = (point.getPositionWorldOnA() + point.getPositionWorldOnB()) * btScalar(0.5);
		const btVector3 relative = pointVelocityAgainst(body0, body1, at);
		const btVector3 slide = relative - point.m_normalWorldOnB * relative.dot(point.m_normalWorldOnB);
		if (!(double(slide.length()) > frictionlessSlide_m_s))
		{
			return true;
		}
	}
	return false;
}
}  // namespace

double timeToTouch_s(const std::vector<const btCollisionObject*>& movers, const std::vector<const btCollisionObject*>& others,
					 double horizon_s, double minGap_m)
{
	const int kCapacity = 16;  // as mayTouchWithin
	Piece mine[kCapacity], theirs[kCapacity];
	double first = horizon_s;
	for (const btCollisionObject* other : others)
	{
		const int numOther = pieces(other, btScalar(0), theirs, kCapacity);
		for (const btCollisionObject* mover : movers)
		{
			if (other == mover)
			{
				continue;
			}
			const Motion motion = relativeMotion(mover, other);
			// a pair whose boxes stay apart over the horizon at the mover's speed bound cannot touch within it
			const btScalar grow = btScalar((double(motion.velocity.length()) + motion.spinSpeed_m_s) * first + minGap_m);
			const int numMover = pieces(mover, grow, mine, kCapacity);
			for (int i = 0; i < numMover; i++)
			{
				for (int j = 0; j < numOther; j++)
				{
					if (!mine[i].shape || !theirs[j].shape || !overlap(mine[i].lo, mine[i].hi, theirs[j].lo, theirs[j].hi))
					{
						continue;
					}
					const btPointCollector closest = closestPoints(mine[i], theirs[j]);
					if (!closest.m_hasResult || !(double(closest.m_distance) > minGap_m))
					{
						continue;
					}
					// the mover's point nearest the other, and its velocity in the other's frame along the normal
					// (from the other towards the mover)
					const btVector3 n = closest.m_normalOnBInWorld;
					const btVector3 nearest = closest.m_pointInWorld + n * closest.m_distance;
					const double closing = -double((motion.velocity + motion.spin.cross(nearest - motion.centre)).dot(n));
					if (closing > 0 && double(closest.m_distance) < closing * first)
					{
						first = double(closest.m_distance) / closing;
					}
				}
			}
		}
	}
	return first;
}

double relativeSpeedBound_m_s(const btCollisionObject* mover, const btCollisionObject* other)
{
	const Motion motion = relativeMotion(mover, other);
	return double(motion.velocity.length()) + motion.spinSpeed_m_s;
}

bool mayTouchWithin(const std::vector<const btCollisionObject*>& movers, const std::vector<const btCollisionObject*>& others,
					double horizon_s, double clearance_m, double speculativeReach_m)
{
	// no allocation: a scene asks this several times per frame
	const int kCapacity = 16;  // children of a compound tested one by one; a larger compound is one box
	Piece mine[kCapacity], theirs[kCapacity];
	// an other's pieces do not grow: they are taken once, each mover's are grown by its reach against that other
	for (const btCollisionObject* other : others)
	{
		const int numOther = pieces(other, btScalar(0), theirs, kCapacity);
		const double otherHeld_m_s2 = heldAcceleration_m_s2(other);
		for (const btCollisionObject* mover : movers)
		{
			if (other == mover)
			{
				continue;
			}
			Reach reach;
			reach.motion = relativeMotion(mover, other);
			const double acceleration_m_s2 = pairAcceleration_m_s2(mover, other, reach.motion, otherHeld_m_s2);
			const double fixed_m = reach.motion.spinSpeed_m_s * horizon_s + 0.5 * acceleration_m_s2 * horizon_s * horizon_s + clearance_m;
			reach.grow = btScalar(double(reach.motion.velocity.length()) * horizon_s + fixed_m);
			reach.fixed = btScalar(fixed_m);
			reach.horizon = btScalar(horizon_s);
			reach.clearance = btScalar(clearance_m);
			reach.speculativeReach = btScalar(speculativeReach_m);
			reach.acceleration = btScalar(acceleration_m_s2);
			const int numMover = pieces(mover, reach.grow, mine, kCapacity);
			for (int i = 0; i < numMover; i++)
			{
				for (int j = 0; j < numOther; j++)
				{
					btScalar gjkDistance = 0;
					if (within(mine[i], theirs[j], reach, &gjkDistance) &&
						(!mine[i].shape || !theirs[j].shape || withinAlongPath(mine[i], theirs[j], reach, gjkDistance)))
					{
						return true;
					}
				}
			}
		}
	}
	return false;
}

double timeToRelease_s(btDispatcher& dispatcher, const std::vector<const btCollisionObject*>& movers,
					   const std::vector<const btCollisionObject*>& others, double horizon_s)
{
	double first = horizon_s;
	for (int i = 0; i < dispatcher.getNumManifolds(); i++)
	{
		const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
		bool boxIsA = false;
		if (!betweenSets(*manifold, movers, others, boxIsA))
		{
			continue;
		}
		const btCollisionObject* box = boxIsA ? manifold->getBody0() : manifold->getBody1();
		const btCollisionObject* other = boxIsA ? manifold->getBody1() : manifold->getBody0();
		// a box's face running off another box's edge lets go at once; round a rounded edge (an ISO anvil's, a capsule
		// child of a compound) the contact fades as the face rolls off it, and its manifold's points, found one a step
		// by GJK, do not give the face's end (stepping to their predictions put the standard striker's ISO runs +1 %
		// further from the friction model and 4 more of 50 past 100 steps)
		if (box->getCollisionShape()->getShapeType() != BOX_SHAPE_PROXYTYPE || other->getCollisionShape()->getShapeType() != BOX_SHAPE_PROXYTYPE)
		{
			continue;
		}
		// a pressed contact (a point of it carried an impulse) ends when the last of its points that touch has run off
		// the face: the load of a face's points is statically indeterminate, and one that carried none still touches
		if (!carriedImpulse(*manifold))
		{
			continue;
		}
		const btVector3 half = static_cast<const btBoxShape*>(box->getCollisionShape())->getHalfExtentsWithMargin();
		const btMatrix3x3& basis = box->getWorldTransform().getBasis();
		const btRigidBody* boxBody = movingBody(box);
		const btRigidBody* otherBody = movingBody(other);
		const btScalar touching = btScalar(0.01) * manifold->getContactBreakingThreshold();
		double last = -1;
		for (int j = 0; j < manifold->getNumContacts(); j++)
		{
			const btManifoldPoint& point = manifold->getContactPoint(j);
			if (!(point.getAppliedImpulse() > 0) && !(point.getDistance() <= touching))
			{
				continue;
			}
			// the other's point of the contact where the step left it, in the box's frame (the manifold's points are
			// where the last collision detection, at the step's start, found them: a step's slide behind)
			const btVector3 world = other->getWorldTransform() * (boxIsA ? point.m_localPointB : point.m_localPointA);
			const btVector3 local = box->getWorldTransform().invXform(world);
			const btVector3 slide = pointVelocityAgainst(otherBody, boxBody, world) * basis;  // in the box's frame
			// the face the point lies on: the box's axis nearest the contact's normal
			const btVector3 normal = point.m_normalWorldOnB * basis;
			int face = 0;
			for (int k = 1; k < 3; k++)
			{
				if (btFabs(normal[k]) > btFabs(normal[face]))
				{
					face = k;
				}
			}
			double off = horizon_s;
			for (int k = 0; k < 3; k++)
			{
				// a point on the face's edge along k is where the manifold clipped a contact that reaches past the face
				// (an anvil's edge lying across the whole of a part's face): sliding along k does not end it
				if (k == face || slide[k] == 0 || btFabs(local[k]) >= half[k] * btScalar(1 - 1e-3))
				{
					continue;
				}
				const double toEdge = double(half[k]) - double(slide[k] > 0 ? local[k] : -local[k]);
				off = std::min(off, std::max(0.0, toEdge) / double(btFabs(slide[k])));
			}
			last = std::max(last, off);
		}
		if (last >= 0)
		{
			first = std::min(first, last);
		}
	}
	return first;
}

namespace
{
// relativeSpeedBound_m_s grown by what the accelerations mayTouchWithin takes (the pair's gravity difference, the
// other's turning frame, a body a hinge holds to a fixed one) add within the horizon
double speedWithin_m_s(const btCollisionObject* mover, const btCollisionObject* other, double horizon_s)
{
	const Motion motion = relativeMotion(mover, other);
	const double acceleration_m_s2 = pairAcceleration_m_s2(mover, other, motion, heldAcceleration_m_s2(other));
	return double(motion.velocity.length()) + motion.spinSpeed_m_s + acceleration_m_s2 * horizon_s;
}
}  // namespace

double contactSpeed_m_s(btDispatcher& dispatcher, const std::vector<const btCollisionObject*>& movers,
						const std::vector<const btCollisionObject*>& others, double horizon_s, double clearance_m,
						double speculativeReach_m)
{
	double fastest = 0;
	for (int i = 0; i < dispatcher.getNumManifolds(); i++)
	{
		const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
		bool moverIsBody0 = false;
		if (manifold->getNumContacts() > 0 && betweenSets(*manifold, movers, others, moverIsBody0))
		{
			const btCollisionObject* mover = moverIsBody0 ? manifold->getBody0() : manifold->getBody1();
			const btCollisionObject* other = moverIsBody0 ? manifold->getBody1() : manifold->getBody0();
			const double speed = speedWithin_m_s(mover, other, horizon_s);
			if (!std::isfinite(speed))
			{
				return std::numeric_limits<double>::infinity();
			}
			fastest = std::max(fastest, speed);
		}
	}
	std::vector<const btCollisionObject*> mover(1), other(1);
	for (const btCollisionObject* o : others)
	{
		for (const btCollisionObject* m : movers)
		{
			if (m == o)
			{
				continue;
			}
			const double speed = speedWithin_m_s(m, o, horizon_s);
			if (!std::isfinite(speed))
			{
				return std::numeric_limits<double>::infinity();
			}
			if (speed <= fastest)
			{
				continue;
			}
			mover[0] = m;
			other[0] = o;
			if (mayTouchWithin(mover, other, horizon_s, clearance_m, speculativeReach_m))
			{
				fastest = speed;
			}
		}
	}
	return fastest;
}

bool pressedContact(btDispatcher& dispatcher, const std::vector<const btCollisionObject*>& movers,
					const std::vector<const btCollisionObject*>& others, double frictionlessSlide_m_s)
{
	for (int i = 0; i < dispatcher.getNumManifolds(); i++)
	{
		const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(i);
		bool moverIsBody0 = false;
		if (betweenSets(*manifold, movers, others, moverIsBody0) && carriedImpulse(*manifold, frictionlessSlide_m_s))
		{
			return true;
		}
	}
	return false;
}

std::vector<std::string> validate(const ContactSubstepSettings& settings)
{
	std::vector<std::string> errors;
	const double h = settings.contact_substep_s;
	if (!(std::isfinite(h) && (h == 0 || (h >= 1e-7 && h <= 0.05))))
	{
		std::ostringstream out;
		out << "contact-substep: " << h << " is not in [1e-07, 0.05] s (or 0 = off)";
		errors.push_back(out.str());
	}
	const double turn = settings.max_turn_per_step_rad;
	if (!(std::isfinite(turn) && turn >= 0 && turn <= SIMD_PI))
	{
		std::ostringstream out;
		out << "max_turn_per_step_rad: " << turn << " is not in [0, pi] rad (0 = no bound)";
		errors.push_back(out.str());
	}
	const double travel = settings.contact_travel_m;
	if (!(std::isfinite(travel) && travel >= 0 && travel <= 1))
	{
		std::ostringstream out;
		out << "contact_travel_m: " << travel << " is not in [0, 1] m (0 = every step in contact is the substep)";
		errors.push_back(out.str());
	}
	const double free = settings.free_step_s;
	if (!(std::isfinite(free) && (free == 0 || (h > 0 && free >= h && free <= 1))))
	{
		std::ostringstream out;
		out << "free_step_s: " << free;
		if (h > 0)
		{
			out << " is not in [" << h << ", 1] s (the contact substep to 1 s; or 0 = a step every frame)";
		}
		else
		{
			out << " needs contact substeps (contact_substep_s > 0; or 0 = a step every frame)";
		}
		errors.push_back(out.str());
	}
	return errors;
}

ContactSubstepPolicy::ContactSubstepPolicy(const ContactSubstepSettings& settings) : m_settings(settings), m_errors(validate(settings)) {}

double ContactSubstepPolicy::toNextTick_s() const
{
	const double h = m_settings.contact_substep_s;
	return m_phase_s > 1e-6 * h && h - m_phase_s > 1e-6 * h ? h - m_phase_s : 0;
}

int ContactSubstepPolicy::advance(double frame_s, const NearContact& nearContact, const Step& step, const Spin& spin,
								  const TimeToTouch& timeToTouch, const TimeToRelease& timeToRelease, const Done& done,
								  bool gather, const ContactSpeed& contactSpeed)
{
	if (!(std::isfinite(frame_s) && frame_s > 0) || !m_errors.empty())
	{
		return -1;
	}
	const double h = m_settings.contact_substep_s;
	// with contact_travel_m and contactSpeed: whether the pairs in or near contact move no more than the travel within
	// a time
	const auto slowWithin = [&](double time_s)
	{ return m_settings.contact_travel_m > 0 && contactSpeed && contactSpeed(time_s) * time_s <= m_settings.contact_travel_m; };
	int steps = 0;
	double remaining = frame_s + m_owed_s;
	m_owed_s = 0;
	bool steppedInContact = false;
	while (remaining > 1e-12 * frame_s)
	{
		double piece = remaining;
		bool touching = false;
		if (gather && h > 0 && m_settings.free_step_s > remaining)
		{
			// out of contact a frame shorter than the free step is gathered with the next ones: owed while no contact
			// is near within the shortest of the free step's halves longer than it, so that one step of about the free
			// step is taken where a step a frame took ten (0.1 ms frames after a Charpy test's fold). Asked after steps
			// in contact too (a second contact test a step there), so that a rest whose contact ended is gathered: not
			// asking it there took a step more in some Charpy runs
			double horizon = m_settings.free_step_s;
			while (horizon / 2 > remaining && horizon / 2 > h)
			{
				horizon /= 2;
			}
			// (with contact_travel_m, a contact whose pairs move no more than that within the horizon is gathered
			// too: a hammer stalled in a specimen)
			if (!nearContact(horizon) || slowWithin(horizon))
			{
				m_owed_s = remaining;
				break;
			}
		}
		if (h > 0)
		{
			// cut in halves until a piece reaches no contact within its own length; a rest of at most a substep is
			// asked once (far from contact it is stepped, not owed)
			// with contact_travel_m a piece near contact within which the pairs in or near contact move no more than
			// that against each other is one step: the halving stops there
			bool travelling = false;
			while (piece > h && nearContact(piece))
			{
				if (slowWithin(piece))
				{
					travelling = true;
					break;
				}
				piece /= 2;
			}
			if (travelling && timeToTouch)
			{
				// a pair that comes into touch within the piece or the two substeps after it is met from substeps, as
				// without the travel: the piece ends two substeps before the touch, or is a substep where that leaves
				// less than one. A touch predicted at the end of a long step is not where it happens: the Charpy
				// hammer's pivot, moved by the step's drift, is put back in the next one, and a step to the touch
				// after a 0.52 ms step met the specimen within it and braked the hammer by 1.5 J
				const double touch = timeToTouch(piece + 2 * h);
				if (touch < piece + 2 * h)
				{
					if (touch - 2 * h >= h)
					{
						piece = touch - 2 * h;
					}
					else
					{
						travelling = false;
						piece = std::min(h, remaining);
					}
				}
			}
			if (travelling)
			{
				// such a step ends on a tick of the contacts' clock (the next one, and whole substeps after it), so
				// that the ticks keep their phase and a contact met after it falls where it would in substeps, whatever
				// the frame step; a piece that holds no whole substep after the next tick is left to the substeps
				const double toTick = toNextTick_s();
				const double whole = std::floor((piece - toTick) / h * (1 + 1e-9));
				if (whole >= 1)
				{
					piece = toTick + whole * h;
				}
				else
				{
					travelling = false;
					piece = std::min(h, remaining);
				}
			}
			const bool inContact = !travelling && (piece < remaining ? piece <= h : (remaining <= h && nearContact(remaining)));
			if (travelling)
			{
				steppedInContact = true;
				// as a substep, a step that a release falls within ends there (at least a quarter of a substep in);
				// the ticks count from its end
				if (timeToRelease)
				{
					const double release = timeToRelease(piece);
					if (release >= h / 4 && release < piece)
					{
						piece = release;
						touching = true;
					}
				}
				m_splitForRelease = false;
			}
			else if (inContact)
			{
				steppedInContact = true;
				// in or near contact the world keeps a clock of its own, in steps of the contact substep: a rest of
				// the frame shorter than one is owed to the next frame (the world then lags the frame by less than a
				// substep, as in upstream's fixed-step stepSimulation), so no frame step cuts a short step into the
				// contacts; a rest that is a whole number of substeps is taken in equal steps.
				// The clock's ticks are the multiples of the substep from the policy's start, whatever steps the frames
				// took out of contact: a contact that begins between two ticks is met by the steps to the next one, so
				// the frame step does not move the phase of an impact within the substeps. Those are one step, or two
				// equal ones where one would be shorter than half a substep: a step of a few microseconds after a long
				// one gave a Charpy specimen's contacts the impulses of the long one (423 J made on a 365 J test).
				const double toTick = toNextTick_s();
				const double whole = std::round(remaining / h);
				if (toTick > 0)
				{
					const double alignment = toTick >= h / 2 ? toTick : (toTick + h) / 2;
					if (alignment > remaining + 1e-12 * frame_s)
					{
						m_owed_s = remaining;
						break;
					}
					piece = alignment;
				}
				else if (whole >= 1 && std::fabs(remaining - whole * h) <= 1e-9 * remaining)
				{
					piece = remaining / whole;
				}
				else if (remaining > h)
				{
					piece = h;
				}
				else
				{
					m_owed_s = remaining;
					break;
				}
				if (timeToTouch)
				{
					// a pair touching within this step or the next is stepped to its touch: in one step if that is at
					// least half a substep away, in two equal ones if it is past this step (a touch nearer than half a
					// substep is met within the step, as without timeToTouch)
					const double touch = timeToTouch(2 * h);
					const double toTouch = touch >= h / 2 && touch <= h ? touch : (touch > h && touch < 2 * h ? touch / 2 : 0);
					if (toTouch > remaining + 1e-12 * frame_s)
					{
						// as a tick past the frame's end: the steps to the touch do not depend on the frame step
						m_owed_s = remaining;
						break;
					}
					if (toTouch > 0)
					{
						piece = toTouch;
						touching = toTouch == touch;
					}
				}
				bool splitting = false;
				if (timeToRelease && !touching)
				{
					// a pressed contact that ends within this step, at least a quarter of a substep in, ends the step; one
					// that ends within the next is met in two equal steps, once (the linear prediction moves as the
					// contact turns: a half rolling round an ISO anvil's rounded edge). The ticks count from the end
					const double release = timeToRelease(2 * h);
					if (release >= h / 4 && release < piece)
					{
						piece = release;
						touching = true;
					}
					else if (!m_splitForRelease && release >= piece && release < 2 * h && release / 2 < piece && release / 2 >= h / 4)
					{
						piece = release / 2;
						touching = true;
						splitting = true;
					}
				}
				m_splitForRelease = splitting;
			}
			else if (steppedInContact && piece < h / 2)
			{
				// the rest of a frame whose contact ended within it, shorter than half a substep, is owed to the next
				// frame: a step of a fraction of a microsecond after the substeps threw an elastic-plastic Charpy
				// specimen apart (the ticks counted from a touch leave such rests)
				m_owed_s = remaining;
				break;
			}
			else if (spin && m_settings.max_turn_per_step_rad > 0)
			{
				// out of contact a long step is still an integration step: a fast spin turned too far in one loses
				// energy in the joints and the gyroscopic term. The piece is cut in equal steps, with no short rest:
				// a joint's position correction in a step of a few microseconds after a long one threw the Charpy
				// halves apart with 34 J
				const double w = spin();
				if (w * piece > m_settings.max_turn_per_step_rad)
				{
					// no step shorter than a substep, nor longer than the piece
					const double steps = std::min(std::ceil(w * piece / m_settings.max_turn_per_step_rad), std::max(1.0, std::floor(piece / h)));
					piece /= steps;
				}
			}
		}
		step(piece);
		steps++;
		remaining -= piece;
		if (h > 0)
		{
			// after a step to a touch the clock's ticks count from the touch
			m_phase_s = touching ? 0 : std::fmod(m_phase_s + piece, h);
		}
		if (done && done())
		{
			m_owed_s = remaining > 1e-12 * frame_s ? remaining : 0;
			break;
		}
	}
	return steps;
}
}  // namespace plastic
