#include "SolverSettings.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "BulletDynamics/MLCPSolvers/btDantzigSolver.h"
#include "BulletDynamics/MLCPSolvers/btMLCPSolver.h"
#include "BulletDynamics/MLCPSolvers/btSolveProjectedGaussSeidel.h"

namespace plastic
{
JointSolverSettings upstreamJointSolverSettings()
{
	JointSolverSettings s;
	s.warm_starting_factor = 0;
	s.override_iterations = 0;
	s.split_position_correction = false;
	return s;
}

const char* solverKindName(SolverKind kind)
{
	switch (kind)
	{
		case SolverKind::SequentialImpulse:
			return "sequential-impulse";
		case SolverKind::MlcpDantzig:
			return "dantzig";
		case SolverKind::MlcpProjectedGaussSeidel:
			return "pgs";
		case SolverKind::DirectJoint:
			return "direct";
	}
	return "?";
}

bool parseSolverKind(const std::string& name, SolverKind& kind)
{
	for (SolverKind k : {SolverKind::SequentialImpulse, SolverKind::MlcpDantzig, SolverKind::MlcpProjectedGaussSeidel, SolverKind::DirectJoint})
		if (name == solverKindName(k))
		{
			kind = k;
			return true;
		}
	return false;
}

WorldSolverSettings upstreamWorldSolverSettings()
{
	WorldSolverSettings s;
	s.solver = SolverKind::SequentialImpulse;
	s.iterations = 10;
	s.internal_step_s = 1.0 / 240.0;
	s.erp = 0.2;
	s.randomize_order = false;
	s.mlcp_cfm = 0;
	s.mlcp_retry_cfm_factor = 0;
	s.mlcp_max_impulse_ns = 1000;
	return s;
}

StructureWorld::StructureWorld(const WorldSolverSettings& settings)
	: m_settings(settings),
	  m_configuration(std::make_unique<btDefaultCollisionConfiguration>()),
	  m_dispatcher(std::make_unique<btCollisionDispatcher>(m_configuration.get())),
	  m_broadphase(std::make_unique<btDbvtBroadphase>()),
	  m_solver(settings.solver, settings.mlcp_max_impulse_ns, settings.mlcp_cfm, settings.mlcp_retry_cfm_factor)
{
	if (!(settings.internal_step_s > 0 && settings.internal_step_s <= 0.1))
	{
		throw std::invalid_argument("internal step: " + std::to_string(settings.internal_step_s) + " is not in (0, 0.1] s");
	}
	m_world = std::make_unique<btDiscreteDynamicsWorld>(m_dispatcher.get(), m_broadphase.get(), m_solver.get(), m_configuration.get());
	m_world->setGravity(btVector3(0, 0, 0));
	configureWorld(*m_world, settings);
}

StructureWorld::~StructureWorld() = default;

int StructureWorld::stepFrame(double frame_s)
{
	const int substeps = static_cast<int>(frame_s / m_settings.internal_step_s) + 2;
	return m_world->stepSimulation(btScalar(frame_s), substeps, btScalar(m_settings.internal_step_s));
}

void StructureWorld::stepOnce() { m_world->stepSimulation(btScalar(m_settings.internal_step_s), 0); }

namespace
{
// btDantzigSolver whose acceptable impulse (upstream a fixed 1000 N s) is set
class LimitedDantzigSolver : public btDantzigSolver
{
public:
	explicit LimitedDantzigSolver(double maxImpulse_ns) { m_acceptableUpperLimitSolution = btScalar(maxImpulse_ns); }
};

// btMLCPSolver whose LCP matrix gets cfm / dt more on its diagonal before the direct solve; when the solve fails
// (Dantzig's pivoting stalls, s <= 0, on degenerate rows at their bounds), it is tried once more with retryFactor
// times that CFM before btMLCPSolver falls back to sequential impulse for the step
class RegularizedMLCPSolver : public btMLCPSolver
{
public:
	RegularizedMLCPSolver(btMLCPSolverInterface* solver, double cfm, double retryFactor)
		: btMLCPSolver(solver), m_cfm(btScalar(cfm)), m_retryFactor(btScalar(retryFactor))
	{
	}
	int retries() const { return m_retries; }

protected:
	bool solveMLCP(const btContactSolverInfo& infoGlobal) override
	{
		addToDiagonal(m_cfm / infoGlobal.m_timeStep);
		const bool solved = btMLCPSolver::solveMLCP(infoGlobal);
		if (solved || !(m_cfm > 0 && m_retryFactor > 1)) return solved;
		m_retries++;
		addToDiagonal((m_retryFactor - 1) * m_cfm / infoGlobal.m_timeStep);
		return btMLCPSolver::solveMLCP(infoGlobal);
	}

private:
	void addToDiagonal(btScalar value)
	{
		if (value > 0)
			for (int i = 0; i < m_A.rows(); ++i) m_A.setElem(i, i, m_A(i, i) + value);
	}
	btScalar m_cfm, m_retryFactor;
	int m_retries = 0;
};
}  // namespace

OwnedSolver::OwnedSolver(SolverKind kind, double mlcpMaxImpulse_ns, double mlcpCfm, double mlcpRetryCfmFactor)
{
	switch (kind)
	{
		case SolverKind::SequentialImpulse:
			m_solver = std::make_unique<btSequentialImpulseConstraintSolver>();
			return;
		case SolverKind::DirectJoint:
			m_solver = std::make_unique<btDirectJointSolver>();
			return;
		case SolverKind::MlcpDantzig:
			m_mlcp = std::make_unique<LimitedDantzigSolver>(mlcpMaxImpulse_ns);
			break;
		case SolverKind::MlcpProjectedGaussSeidel:
			m_mlcp = std::make_unique<btSolveProjectedGaussSeidel>();
			break;
	}
	m_solver = std::make_unique<RegularizedMLCPSolver>(m_mlcp.get(), mlcpCfm, mlcpRetryCfmFactor);
}

OwnedSolver::~OwnedSolver() = default;

int OwnedSolver::retries() const { return m_mlcp ? static_cast<const RegularizedMLCPSolver*>(m_solver.get())->retries() : 0; }

int OwnedSolver::fallbacks() const
{
	if (const btDirectJointSolver* direct = dynamic_cast<const btDirectJointSolver*>(m_solver.get()))
		return direct->getNumFallbacks();
	return m_mlcp ? static_cast<const btMLCPSolver*>(m_solver.get())->getNumFallbacks() : 0;
}

void configureWorld(btDynamicsWorld& world, const WorldSolverSettings& settings)
{
	if (settings.iterations < 1 || settings.iterations > 100000)
	{
		throw std::invalid_argument("iterations: " + std::to_string(settings.iterations) + " is not in [1, 100000]");
	}
	if (!(settings.erp > 0 && settings.erp <= 1))
	{
		throw std::invalid_argument("erp: " + std::to_string(settings.erp) + " is not in (0, 1]");
	}
	if (!(settings.mlcp_cfm >= 0 && settings.mlcp_cfm <= 1))
	{
		throw std::invalid_argument("mlcp cfm: " + std::to_string(settings.mlcp_cfm) + " is not in [0, 1]");
	}
	if (!(settings.mlcp_retry_cfm_factor >= 0 && settings.mlcp_retry_cfm_factor <= 1e6))
	{
		throw std::invalid_argument("mlcp retry cfm factor: " + std::to_string(settings.mlcp_retry_cfm_factor) + " is not in [0, 1e6]");
	}
	if (!(settings.mlcp_max_impulse_ns > 0))
	{
		throw std::invalid_argument("mlcp max impulse: " + std::to_string(settings.mlcp_max_impulse_ns) + " N s is not > 0");
	}
	btContactSolverInfo& info = world.getSolverInfo();
	info.m_numIterations = settings.iterations;
	info.m_erp = btScalar(settings.erp);
	if (settings.randomize_order)
		info.m_solverMode |= SOLVER_RANDMIZE_ORDER;
	else
		info.m_solverMode &= ~SOLVER_RANDMIZE_ORDER;
}

void configureJoint(btTypedConstraint& joint, const JointSolverSettings& settings, bool allowSplitPositionCorrection)
{
	if (!(settings.warm_starting_factor >= 0 && settings.warm_starting_factor <= 1))
	{
		throw std::invalid_argument("warm starting factor: " + std::to_string(settings.warm_starting_factor) + " is not in [0, 1]");
	}
	if (settings.override_iterations < 0)
	{
		throw std::invalid_argument("override iterations: " + std::to_string(settings.override_iterations) + " is not in [0, inf)");
	}
	joint.setWarmStartingFactor(btScalar(settings.warm_starting_factor));
	joint.setOverrideNumSolverIterations(settings.override_iterations > 0 ? settings.override_iterations : -1);
	joint.setSplitPositionCorrection(settings.split_position_correction && allowSplitPositionCorrection);
}
}  // namespace plastic
