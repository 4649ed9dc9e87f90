// Contact substeps: how a scene splits a frame into internal steps so that only the part of the frame in or near
// contact is cut into short steps. The scene owns one; the world is stepped through it.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

class btCollisionObject;
class btDispatcher;

namespace plastic
{
// A bound of the speed of any point of `mover` against the material of `other` at that point [m/s]: in `other`'s
// moving frame, the mover's centre of mass moves at v_m - v_o - w_o x (c_m - c_o), and its points turn about it at
// w_m - w_o within its reach (the farthest corner of its box from its centre of mass). Static objects do not move.
double relativeSpeedBound_m_s(const btCollisionObject* mover, const btCollisionObject* other);
// The magnitude of the difference of the two bodies' gravity [m/s^2] (a static object's is 0): a body falling beside
// a static one closes by 1/2 g h^2 more than its velocity says (1.4 mm in a 1/60 s frame).
double relativeGravity_m_s2(const btCollisionObject* mover, const btCollisionObject* other);

// Whether some body of `movers` can touch some object of `others` within horizon_s. For each pair, the mover's
// reach against the other's material in that time (their speed bound times horizon_s, plus 1/2 their difference in
// gravity and the other's turning frame's acceleration times horizon_s squared), plus clearance_m, is compared with
// the distance between their shapes: their boxes first, then, for boxes within reach, the shapes' own distance (GJK;
// the box of a turned box reaches well past its faces). Against that distance only the mover's closing speed along
// the normal GJK found counts, with its spin's and the accelerations' part: the shapes' gap along a fixed direction n
// bounds their distance from below and changes by the mover's velocity along n times the time, give or take what the
// spin and the accelerations move its points, so a body sliding past another at a constant gap does not close on it.
// The distance taken is the smaller of GJK's and that gap along n. A compound shape's children are taken one by one
// (up to 16 children; a larger compound is one box), so the air between a hammer's arm and its striker is no contact,
// and a non-convex shape stands as its box. GJK's tolerances follow gVoronoiSimplexLengthScale (patch 0018): a scene
// of millimetre bodies sets it around the call, and the gap along n bounds its answer from below if it does not. The
// velocities are taken as they are: what forces add within the horizon (joints between moving bodies, contacts) is
// left to clearance_m. A body that a hinge holds to a body that does not move turns about the hinge's axis: its
// centre's acceleration is at most |w|^2 |c - p| + |g| from its gravity (a swinging hammer's, 31 m/s^2; the hinge's
// motor and limit left out), and that is added to the pair's gravity difference (Bullet records the joint on the body
// when the world adds it with collisions between the linked bodies disabled).
// With speculative contacts (speculativeReach_m > 0, the distance within which the pair's contacts are made before
// they touch: the shapes' contact breaking threshold), a pair already that close is left to them: it counts only if
// its motion within the horizon (closing speed, spin and accelerations, without clearance_m) is more than half of
// that reach. A part sliding along an anvil's wall 30-80 um away no longer holds the world at the substep for as long
// as it slides. Whether such a pair's contacts carry load is not seen here (pressedContact). A box mover is then taken
// vertex by vertex: the other (each convex piece of it) lies behind the plane through its nearest point normal to n,
// and each vertex comes towards that plane by its own velocity in the other's frame (v + w x r along n, plus 1/2 (a +
// (|w|^2 + |w x w_o|) |r|) t^2, w the relative spin and w_o the other's); the pair counts if a vertex within the reach
// can move more than half of it, or one past the reach can reach the plane (with clearance_m). A box turning about
// its contact, or spinning flat on a face, moves its far corners along or away from the other, where the spin's bound
// at the farthest corner counted them as closing. Where the bodies turn a quarter revolution or more within the
// horizon the spin's bound is kept.
// A pair of convex pieces that these bounds count as near over the whole horizon, and that is not within the
// speculative reach, is tested again along its path: the horizon in eight equal parts, the mover put where its
// velocity and spin in the other's frame take it by the start of each and tested over that part alone (whether it can
// touch), with clearance_m grown by how far its points can be from that prediction by then (the accelerations and the
// turn's second order, as above). A body passing another a millimetre away no longer counts because its closing speed
// now would close the gap within the horizon.
bool mayTouchWithin(const std::vector<const btCollisionObject*>& movers, const std::vector<const btCollisionObject*>& others,
					double horizon_s, double clearance_m = 0.001, double speculativeReach_m = 0);

// The time within horizon_s at which the first pair of a body of `movers` and an object of `others` that is now more
// than minGap_m apart closes its gap at its present velocities [s]: the distance between their shapes (GJK, a compound
// child by child as mayTouchWithin) over the closing speed, along the normal between them, of the mover's point
// nearest the other in the other's moving frame; horizon_s when no pair closes within it. Pairs that touch (within
// minGap_m), that close nothing, or whose shapes are not both convex are left out. With speculative contacts a scene
// steps to that time so that a contact's first step starts touching: a speculative contact met within a step carries
// its load for the whole step while the bodies still cross the gap, and the work of that force over the gap is lost
// (the Charpy striker meeting the specimen: the section's collapse load, 6.4 kN, times up to the 0.31 mm a 0.06 ms
// step closes).
double timeToTouch_s(const std::vector<const btCollisionObject*>& movers, const std::vector<const btCollisionObject*>& others,
					 double horizon_s, double minGap_m);

// The time within horizon_s at which the first pressed contact between a box of `movers` and a box of `others` runs
// off the mover's face [s]: for each manifold of such a pair of which a point carried an impulse in the world's last
// step, each point that did or that touches (within 1 % of the breaking threshold) is taken where the other's point of
// it now is in the mover's frame, on the mover's face nearest the contact's normal, and slides over that face at the
// other's material velocity there; it reaches the face's edge after the distance to that edge over its speed along
// the face (an edge of the face it already lies on is where the manifold clipped a contact reaching past the face, and
// does not count); the contact ends when its last point has; horizon_s when none ends within it. A Charpy half held
// on an anvil's edge while the striker folds the specimen is let go as its end passes the edge: met within a step, the
// anvil held it to the step's end and the joint bent on past the pass angle (thesis, 60 us: 2.037 rad against 1.991).
// Pairs whose other is not a box (a rounded edge) are left out.
double timeToRelease_s(btDispatcher& dispatcher, const std::vector<const btCollisionObject*>& movers,
					   const std::vector<const btCollisionObject*>& others, double horizon_s);

// The fastest speed [m/s] of a body of `movers` against an object of `others` within horizon_s among the pairs in or
// near contact: pairs whose manifold (as the dispatcher holds them) has a point, and pairs that mayTouchWithin
// horizon_s (with the same clearance and speculative reach); 0 when there is none, +inf when a speed is not finite.
// A pair's speed is relativeSpeedBound_m_s grown by the accelerations mayTouchWithin takes (their gravity difference,
// the other's turning frame, a hinge to a fixed body) times horizon_s. What contact and joint forces add within the
// horizon is not in it, as mayTouchWithin leaves it to its clearance: a step of d over this speed moves such a pair
// about d, not at most d (a scene keeps the substep where such forces work: CharpyScene, while a joint flows).
double contactSpeed_m_s(btDispatcher& dispatcher, const std::vector<const btCollisionObject*>& movers,
						const std::vector<const btCollisionObject*>& others, double horizon_s, double clearance_m = 0.001,
						double speculativeReach_m = 0);

// Whether a contact point between a body of `movers` and one of `others` carried an impulse in the world's last
// step (their manifolds as the dispatcher holds them): a pair pressed together, whose forces a longer step would
// change, as against one that touches only through speculative points that hold nothing. A point without friction
// whose bodies slide past each other there faster than frictionlessSlide_m_s does not count: its force does no work
// along the slide (a Charpy specimen riding over the anvils after its fold), while a point at rest under a load (a
// specimen lying on its supports) or one with friction does.
bool pressedContact(btDispatcher& dispatcher, const std::vector<const btCollisionObject*>& movers,
					const std::vector<const btCollisionObject*>& others,
					double frictionlessSlide_m_s = std::numeric_limits<double>::infinity());

struct ContactSubstepSettings
{
	double contact_substep_s = 1e-5;  // internal step while in or near contact; 0 = no substeps
	// out of contact, no internal step turns a body more than this (with substeps on, and when advance is given the
	// bodies' spin): a pair of joined bodies spinning at 250 rad/s loses 0.9 % of its energy in 1/60 s steps and
	// 0.02 % in 1 ms steps (the Charpy halves after the test); 0 = no bound
	double max_turn_per_step_rad = 0.25;
	// out of contact, frames shorter than this are gathered into one internal step of about this length [s] (up to it
	// and a frame): the world lags the frames by less than it (as upstream's fixed-step stepSimulation lags its frames
	// by less than its step), so the internal steps a test takes do not grow with the frame rate. The rest of a frame
	// is owed while no contact is near within the shortest of this step's halves that is longer than the rest; needs
	// contact substeps, and is at least one. 0 = a step every frame
	double free_step_s = 0;
	// in or near contact, a piece longer than the substep within which the pairs in or near contact move at most this
	// far against each other (given `contactSpeed`: their fastest speed times the piece) is one step [m]: a slow
	// contact (a hammer stalled in a specimen, a specimen at rest on its supports) is stepped as far as its motion
	// allows, not at the substep. At most the speculative contacts' reach, such a step closes no more than the contacts
	// hold (as far as the speed bound holds). 0 = every step in or near contact is the substep
	double contact_travel_m = 0;
};

// Every violated setting as "name: value is not in range" text; empty when valid.
std::vector<std::string> validate(const ContactSubstepSettings& settings);

class ContactSubstepPolicy
{
public:
	using NearContact = std::function<bool(double horizon_s)>;  // can a contact happen within horizon_s?
	using Step = std::function<void(double step_s)>;           // one internal step of the world
	using Spin = std::function<double()>;                      // the fastest angular speed of the bodies [rad/s]
	using TimeToTouch = std::function<double(double horizon_s)>;  // when the first pair now apart touches [s]
	using TimeToRelease = std::function<double(double horizon_s)>;  // when the first pressed contact ends [s]
	using Done = std::function<bool()>;                              // is the scene's run over?
	using ContactSpeed = std::function<double(double horizon_s)>;   // fastest pair in or near contact [m/s]

	// settings that validate refuses are kept out: errors() says why, and advance steps nothing
	explicit ContactSubstepPolicy(const ContactSubstepSettings& settings);

	// Advances one frame: the part of the frame that reaches no contact within its own length is one step (or a
	// few halves); in or near contact the world steps at contact_substep_s on a clock of its own, whose ticks are the
	// multiples of contact_substep_s from the policy's start (a contact met between two ticks is stepped to the next
	// one first, in one step or two of at least half a substep), and what is left of the frame, less than a substep,
	// is owed to the next frame (owed_s; as upstream's fixed-step stepSimulation lags its frames), so the frame step
	// changes the steps the contacts see only up to the first tick, and not the phase of an impact within them. A rest
	// of the frame that is a whole number of substeps is taken in that many equal steps. Out of contact, what is owed
	// is stepped with the frame, and, given `spin`, a step is cut so that it turns no body more than
	// max_turn_per_step_rad. The contact test is made again after every internal step. Given `timeToTouch`, a pair
	// that comes into touch within two substeps in contact is stepped to its touch (in one step of at least half a
	// substep, or two equal ones), and the clock's ticks then count from the touch: the contact's first step starts
	// touching and is a whole substep. A rest of a frame shorter than half a substep after steps in contact, out of
	// contact, is owed to the next frame rather than stepped (the ticks counted from a touch leave such rests, and a
	// step of a fraction of a microsecond after the substeps threw an elastic-plastic Charpy specimen apart). Returns
	// the number of internal steps; -1, with no step, for a frame that is not a positive finite time or when errors()
	// is not empty.
	// Given `timeToRelease`, a step in contact within which a pressed contact ends, at least a quarter of a substep in,
	// ends there, and a contact that ends within the next step is met in two equal steps (once in a row: the
	// prediction is linear); the ticks count from there. With a free step, a frame (with what is owed) shorter than it
	// is owed, not stepped, while no contact is near within the free step's shortest half longer than that time (one
	// contact test per such frame), and is stepped as above once contact is near or the free step is reached.
	// Given `done`, asked after every internal step: once it holds, the rest of the frame is owed and advance returns (a
	// test that ends within a frame ends there). A caller whose `done` holds frame after frame owes more each frame:
	// pass it until it first holds (CharpyScene does), not after. With `gather` false the frame and what is
	// owed are stepped whatever the free step (a run's last frame: the world reaches its end, not past it later).
	// With contact_travel_m and `contactSpeed`, a piece longer than a substep that is near contact is one step when the
	// pairs move at most contact_travel_m in it (the halving stops there); such a step ends two substeps before a
	// touch predicted within it or the two substeps after it (one nearer than three substeps is met by substeps, not
	// by such a step), and at a release within it (at least a quarter of a substep in), and the clock's ticks count
	// from its end: the steps then depend on the frame step, as steps out of contact do.
	int advance(double frame_s, const NearContact& nearContact, const Step& step, const Spin& spin = Spin(),
				const TimeToTouch& timeToTouch = TimeToTouch(), const TimeToRelease& timeToRelease = TimeToRelease(),
				const Done& done = Done(), bool gather = true, const ContactSpeed& contactSpeed = ContactSpeed());

	// frame time not yet stepped: the world lags the frames by this much, less than one contact substep, or, out of
	// contact, than the free step, and after `done` by the rest of that frame [s]
	double owed_s() const { return m_owed_s; }

	const ContactSubstepSettings& settings() const { return m_settings; }
	const std::vector<std::string>& errors() const { return m_errors; }

private:
	// the time to the contacts' clock's next tick, 0 on a tick [s]
	double toNextTick_s() const;

	ContactSubstepSettings m_settings;
	std::vector<std::string> m_errors;
	double m_owed_s = 0;
	double m_phase_s = 0;  // the time the world has been stepped through this policy, modulo the contact substep
	bool m_splitForRelease = false;  // the last step was the first of two to a contact's end
};
}  // namespace plastic
