// A displacement-controlled actuator for a pushover: a stiff spring and damper on a point of a body, along one
// direction, with integral action, whose target is driven at a rate through drifts (displacements as fractions of a
// reference length) in order and then held. It measures its force and the point's drift over a window before the
// target reaches each drift: the loading branch just before it (a rigid-plastic hinge held still carries any moment
// up to its cap, so only a loading branch has a load).
#pragma once

#include <vector>

#include "btBulletDynamicsCommon.h"
#include "plastic/PointLoad.h"

namespace scene
{
struct DriftPath
{
	std::vector<double> drifts;   // the targets in order (of length_m; negative: against the direction); none: no force
	double length_m = 1;          // the drift's reference length
	double rate_per_s = 0.02;     // the target's drift per second
	double start_s = 0;           // the target leaves 0 then
	double window_drift = 0.002;  // the measuring window before each target is reached (at most window_max_s)
	double window_max_s = 0.1;
};

class DriftActuator
{
public:
	// restPoint_m: the point's world position at zero drift (the drift is measured from it along direction, a unit
	// vector); stiffness: the spring's (N/m, see stableStiffness_n_m), critically damped for mass_kg at the point
	DriftActuator(btRigidBody& body, const btVector3& localPoint_m, const btVector3& direction, const btVector3& restPoint_m, DriftPath path,
				  double stiffness_n_m, double mass_kg);
	// the stiffest spring on a point of the given mass that is stable at the step (k dt^2 / m <= 1/4), at most
	// 100 times the structure's own stiffness there
	static double stableStiffness_n_m(double structureStiffness_n_m, double mass_kg, double step_s);
	// sets the force for the step starting at time_s and applies it (no drifts: a zero force)
	void beforeStep(double time_s, double step_s);
	void afterStep() { m_load.afterStep(); }
	bool active() const { return !m_path.drifts.empty(); }
	// the target's drift at time t: along the drifts at the rate from start_s, then held at the last one
	double targetDrift(double time_s) const;
	double end_s() const { return m_reach_s.empty() ? m_path.start_s : m_reach_s.back(); }  // the target reaches the last drift
	double force_n() const { return m_load.factor(); }
	double drift() const;  // the point's now
	double work_j() const { return m_load.work_j(); }
	// over each target's window: the mean force (N, along the direction) and the point's mean drift (0 if none)
	std::vector<double> meanForces_n() const;
	std::vector<double> meanDrifts() const;

private:
	btRigidBody& m_body;
	plastic::PointLoad m_load;  // its factor is the force along the direction
	btVector3 m_direction;
	btVector3 m_rest_m;
	DriftPath m_path;
	std::vector<double> m_reach_s;  // when the target reaches each drift
	double m_stiffness_n_m, m_damping_n_s_m;
	double m_integral_n = 0;  // what the spring's lag leaves, driven to zero at 5 rad/s
	std::vector<double> m_forceSum_n, m_driftSum;
	std::vector<int> m_samples;
};
}  // namespace scene
