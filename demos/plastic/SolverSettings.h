// Solver settings for jointed structures at game frame rates, in one small object with units in its names: the
// world's solver, its iterations and internal step, and what each joint asks of the solver (its own iteration
// count, warm starting of its rows, split position correction). The defaults are the ones report/GAME_SETTINGS.md
// measured best at four internal steps per 60 Hz frame and Bullet's 10 iterations (ci/game_settings.sh).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "btBulletDynamicsCommon.h"

class btMLCPSolverInterface;

namespace plastic
{
// What a joint asks of the solver; the joint factory applies it to every joint it makes. Only what the pull-request
// patches give (warm starting of a joint's rows, patch 0020, is not for upstream: the game-settings probe sets it).
struct JointSolverSettings
{
	// btTypedConstraint::setOverrideNumSolverIterations: 0 = the world's iterations
	int override_iterations = 0;
	// patch 0002, btTypedConstraint::setSplitPositionCorrection: only joints whose rows hold position errors alone
	// (the plastic hinge); the factory leaves it off for motors and springs
	bool split_position_correction = false;
};

// Upstream's behaviour for a joint: the world's iterations, Baumgarte correction (today the same as the default: the
// toolkit's default is in the world's solver).
JointSolverSettings upstreamJointSolverSettings();

enum class SolverKind
{
	SequentialImpulse,          // btSequentialImpulseConstraintSolver (upstream default)
	MlcpDantzig,                // btMLCPSolver with btDantzigSolver: a direct solve of the boxed LCP
	MlcpProjectedGaussSeidel,   // btMLCPSolver with btSolveProjectedGaussSeidel
	DirectJoint,                // btDirectJointSolver (patch 0019): joint rows solved directly, contacts by sequential impulse
};

// "sequential-impulse", "dantzig", "pgs", "direct" (command lines, JSON, reports)
const char* solverKindName(SolverKind kind);
// the kind of one of those names; false (kind untouched) for any other text
bool parseSolverKind(const std::string& name, SolverKind& kind);

struct WorldSolverSettings
{
	// the toolkit default: btDirectJointSolver, so a structure holds at 10 iterations (report/GAME_SETTINGS.md)
	SolverKind solver = SolverKind::DirectJoint;
	int iterations = 10;                     // btContactSolverInfo::m_numIterations (Bullet's default 10)
	double internal_step_s = 1.0 / 240.0;    // fixed internal step: four per 60 Hz frame
	double erp = 0.2;                        // btContactSolverInfo::m_erp (joints' Baumgarte factor), Bullet's default
	bool randomize_order = false;            // SOLVER_RANDMIZE_ORDER
};

// A constraint solver of a kind, constructed as Bullet's are (btMLCPSolver with upstream's btDantzigSolver or
// btSolveProjectedGaussSeidel, no setting); it owns the MLCP interface it needs.
class OwnedSolver
{
public:
	explicit OwnedSolver(SolverKind kind);
	~OwnedSolver();
	btConstraintSolver* get() { return m_solver.get(); }
	// steps in which the MLCP solver failed and fell back to sequential impulse (btMLCPSolver::getNumFallbacks, and
	// btDirectJointSolver::getNumFallbacks); 0 for SI
	int fallbacks() const;

private:
	std::unique_ptr<btMLCPSolverInterface> m_mlcp;
	std::unique_ptr<btConstraintSolver> m_solver;
};

// Bullet's own defaults: btSequentialImpulseConstraintSolver, 10 iterations, ERP 0.2, 1/240 s.
WorldSolverSettings upstreamWorldSolverSettings();

// A discrete dynamics world for a structure (collision configuration, dispatcher, broadphase, the settings' solver),
// zero gravity until the scene sets it. stepFrame advances one frame in fixed internal steps of the settings. Settings
// that validate refuses are not applied: the world is not configured, errors() says why, and it does not step.
class StructureWorld
{
public:
	explicit StructureWorld(const WorldSolverSettings& settings = WorldSolverSettings());
	~StructureWorld();
	StructureWorld(const StructureWorld&) = delete;
	StructureWorld& operator=(const StructureWorld&) = delete;
	btDiscreteDynamicsWorld& world() { return *m_world; }
	int solverFallbacks() const { return m_solver.fallbacks(); }
	const WorldSolverSettings& settings() const { return m_settings; }
	const std::vector<std::string>& errors() const { return m_errors; }  // validate(settings): empty when it steps
	// stepSimulation(frame, enough substeps, internal step); returns the internal steps taken (0 when errors())
	int stepFrame(double frame_s);
	// exactly one internal step of the settings (stepSimulation(internal step, 0)), for scenes that act before and
	// after every internal step
	void stepOnce();

private:
	WorldSolverSettings m_settings;
	std::vector<std::string> m_errors;
	std::unique_ptr<btDefaultCollisionConfiguration> m_configuration;
	std::unique_ptr<btCollisionDispatcher> m_dispatcher;
	std::unique_ptr<btDbvtBroadphase> m_broadphase;
	OwnedSolver m_solver;
	std::unique_ptr<btDiscreteDynamicsWorld> m_world;
};

// The world's solver info from the settings (iterations, ERP, solver mode); false, and the world untouched, when
// validate(settings) is not empty.
bool configureWorld(btDynamicsWorld& world, const WorldSolverSettings& settings);

// The one check of a WorldSolverSettings (every scene and runner uses it): internal step in [1e-6, 0.05] s,
// iterations in [1, 100000], erp in (0, 1]. One message per bad field, naming it (the internal step as
// internalStepName, the runners' flag: "dt", "internal-step"); empty when every field is valid.
std::vector<std::string> validate(const WorldSolverSettings& settings, const char* internalStepName = "internal step");
// The one check of a JointSolverSettings: override iterations in [0, inf). Empty when valid.
std::vector<std::string> validate(const JointSolverSettings& settings);
// A joint's solver settings; split_position_correction only where allowSplitPositionCorrection. False, and the joint
// untouched, when validate(settings) is not empty.
bool configureJoint(btTypedConstraint& joint, const JointSolverSettings& settings, bool allowSplitPositionCorrection);
}  // namespace plastic
