#include "SolverSettings.h"

#include <cstdlib>
#include <sstream>
#include <string>

#include "BulletDynamics/MLCPSolvers/btDantzigSolver.h"
#include "BulletDynamics/MLCPSolvers/btMLCPSolver.h"
#include "BulletDynamics/MLCPSolvers/btSolveProjectedGaussSeidel.h"

namespace plastic
{
JointSolverSettings upstreamJointSolverSettings()
{
	JointSolverSettings s;
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
	return s;
}

StructureWorld::StructureWorld(const WorldSolverSettings& settings)
	: m_settings(settings),
	  m_errors(validate(settings)),
	  m_configuration(std::make_unique<btDefaultCollisionConfiguration>()),
	  m_dispatcher(std::make_unique<btCollisionDispatcher>(m_configuration.get())),
	  m_broadphase(std::make_unique<btDbvtBroadphase>()),
	  m_solver(settings.solver)
{
	m_world = std::make_unique<btDiscreteDynamicsWorld>(m_dispatcher.get(), m_broadphase.get(), m_solver.get(), m_configuration.get());
	m_world->setGravity(btVector3(0, 0, 0));
	configureWorld(*m_world, settings);  // not when m_errors
}

StructureWorld::~StructureWorld() = default;

int StructureWorld::stepFrame(double frame_s)
{
	if (!m_errors.empty()) return 0;
	const int substeps = static_cast<int>(frame_s / m_settings.internal_step_s) + 2;
	return m_world->stepSimulation(btScalar(frame_s), substeps, btScalar(m_settings.internal_step_s));
}

void StructureWorld::stepOnce()
{
	if (m_errors.empty()) m_world->stepSimulation(btScalar(m_settings.internal_step_s), 0);
}

OwnedSolver::OwnedSolver(SolverKind kind)
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
			m_mlcp = std::make_unique<btDantzigSolver>();
			break;
		case SolverKind::MlcpProjectedGaussSeidel:
			m_mlcp = std::make_unique<btSolveProjectedGaussSeidel>();
			break;
	}
	m_solver = std::make_unique<btMLCPSolver>(m_mlcp.get());
}

OwnedSolver::~OwnedSolver() = default;

int OwnedSolver::fallbacks() const
{
	if (const btDirectJointSolver* direct = dynamic_cast<const btDirectJointSolver*>(m_solver.get()))
		return direct->getNumFallbacks();
	return m_mlcp ? static_cast<const btMLCPSolver*>(m_solver.get())->getNumFallbacks() : 0;
}

std::vector<std::string> validate(const WorldSolverSettings& settings, const char* internalStepName)
{
	std::vector<std::string> errors;
	if (!(settings.internal_step_s >= 1e-6 && settings.internal_step_s <= 0.05))
	{
		std::ostringstream out;
		out << internalStepName << ": " << settings.internal_step_s << " is not in [1e-06, 0.05] s";
		errors.push_back(out.str());
	}
	if (settings.iterations < 1 || settings.iterations > 100000)
	{
		errors.push_back("iterations: " + std::to_string(settings.iterations) + " is not in [1, 100000]");
	}
	if (!(settings.erp > 0 && settings.erp <= 1))
	{
		std::ostringstream out;
		out << "erp: " << settings.erp << " is not in (0, 1]";
		errors.push_back(out.str());
	}
	return errors;
}

bool configureWorld(btDynamicsWorld& world, const WorldSolverSettings& settings)
{
	if (!validate(settings).empty())
	{
		return false;
	}
	btContactSolverInfo& info = world.getSolverInfo();
	info.m_numIterations = settings.iterations;
	info.m_erp = btScalar(settings.erp);
	if (settings.randomize_order)
		info.m_solverMode |= SOLVER_RANDMIZE_ORDER;
	else
		info.m_solverMode &= ~SOLVER_RANDMIZE_ORDER;
	return true;
}

std::vector<std::string> validate(const JointSolverSettings& settings)
{
	if (settings.override_iterations < 0)
	{
		return {"override iterations: " + std::to_string(settings.override_iterations) + " is not in [0, inf)"};
	}
	return {};
}

bool configureJoint(btTypedConstraint& joint, const JointSolverSettings& settings, bool allowSplitPositionCorrection)
{
	if (!validate(settings).empty())
	{
		return false;
	}
	joint.setOverrideNumSolverIterations(settings.override_iterations > 0 ? settings.override_iterations : -1);
	joint.setSplitPositionCorrection(settings.split_position_correction && allowSplitPositionCorrection);
	return true;
}
}  // namespace plastic
