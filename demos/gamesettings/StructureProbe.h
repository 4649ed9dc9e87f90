// Jointed structures under a static point load, run with a solver setting, for the game-settings comparison
// (game_settings_main.cpp, report/GAME_SETTINGS.md) and its tests: a cantilever of n segments under a tip load,
// and an L-frame (a stronger column fixed at its base, a beam from its top, a load at the beam's tip). The answers
// come from plastic analysis, not from the joints: collapse at P = Mp / L with one hinge, at the root of the
// cantilever and at the knee (the beam's end) of the L-frame; every other joint stays locked.
#pragma once

#include <string>

#include "plastic/JointFactory.h"
#include "plastic/SolverSettings.h"

namespace plastic
{
enum class Structure
{
	Cantilever,  // 2 m, 50 x 100 mm steel, fixed at its start, tip load across it
	LFrame,      // column 2 m 50 x 140 mm (Mp 1.96x), beam 2 m 50 x 100 mm, 4 + 4 segments, load at the beam tip
};

struct ProbeCase
{
	Structure structure = Structure::Cantilever;
	int segments = 4;  // per member
	std::string name() const;
};

// How the structure is built and solved: rigid bodies and joints of a method with world and joint settings, or
// (reduced coordinates) one btMultiBody with revolute joints whose motors are capped at Mp * dt.
struct ProbeSetting
{
	std::string name;
	bool multibody = false;
	WorldSolverSettings world;
	JointSolverSettings joint;
	// every joint's rows start each step at this factor times their previous impulses (patch 0020, not for upstream:
	// btTypedConstraint::setWarmStartingFactor); 0 = off, as upstream
	double warm_starting_factor = 0.0;
};

struct ProbeRun
{
	double hinge_rotation_rad = 0;      // |rotation| of the joint plastic analysis puts the hinge in, at the end
	double max_other_rotation_rad = 0;  // largest |rotation| of every other joint
	double max_rotation_rad = 0;        // largest |rotation| of any joint, at the end
	double max_rotation_after_1s_rad = 0;  // the same one second in (creep: what it grows after that)
	double load_work_j = 0;
	double kinetic_j = 0;
	double plastic_j = 0;               // booked by the joints (0 for motors)
	double elastic_j = 0;
	bool books = false;                 // the method books its plastic work (energy gain is meaningful)
	double wall_s_per_step = 0;         // measured over the whole run
	int internal_steps = 0;
	int solver_fallbacks = 0;           // MLCP steps that fell back to sequential impulse
	bool finite = true;
};

// The collapse load P_c = Mp / L of the case (N): Mp of the member that carries the hinge, L its lever.
double collapseLoad_n(const ProbeCase& c);

// Where a rigid-plastic mechanism with one hinge under a dead load factor * Mp / L across its lever stops, starting
// from rest (rad): the load's work P L sin(theta) equals the plastic work Mp theta, factor sin(theta) = theta.
// 0.5384 rad at 1.05. 0 at or below 1.
double restRotation_rad(double loadFactor);

// The load factor * P_c applied at the tip for the time, in 60 Hz frames split into internal steps of the
// setting's internal step.
ProbeRun runProbe(const ProbeCase& c, JointMethod method, const ProbeSetting& setting, double loadFactor, double seconds);

// The smallest load factor in [lo, hi] at which some joint rotates more than threshold_rad in one second, by
// bisection to within tolerance (of the factor).
double collapseFactor(const ProbeCase& c, JointMethod method, const ProbeSetting& setting, double lo = 0.3, double hi = 1.6,
					  double tolerance = 0.0025, double threshold_rad = 0.05);
}  // namespace plastic
