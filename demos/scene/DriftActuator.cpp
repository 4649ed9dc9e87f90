#include "DriftActuator.h"

#include <algorithm>
#include <cmath>

namespace scene
{
DriftActuator::DriftActuator(btRigidBody& body, const btVector3& localPoint_m, const btVector3& direction, const btVector3& restPoint_m, DriftPath path,
							 double stiffness_n_m, double mass_kg)
	: m_body(body),
	  m_load(body, localPoint_m, direction),
	  m_direction(direction),
	  m_rest_m(restPoint_m),
	  m_path(std::move(path)),
	  m_stiffness_n_m(stiffness_n_m),
	  m_damping_n_s_m(2.0 * std::sqrt(stiffness_n_m * mass_kg)),
	  m_forceSum_n(m_path.drifts.size(), 0.0),
	  m_driftSum(m_path.drifts.size(), 0.0),
	  m_samples(m_path.drifts.size(), 0)
{
	double t = m_path.start_s, from = 0;
	for (double d : m_path.drifts)
	{
		t += std::fabs(d - from) / m_path.rate_per_s;
		m_reach_s.push_back(t);
		from = d;
	}
	m_load.setFactor(0.0);
}

double DriftActuator::stableStiffness_n_m(double structureStiffness_n_m, double mass_kg, double step_s)
{
	return std::min(100.0 * structureStiffness_n_m, 0.25 * mass_kg / (step_s * step_s));
}

double DriftActuator::targetDrift(double time_s) const
{
	if (time_s < m_path.start_s) return 0.0;
	double start = m_path.start_s, from = 0;
	for (size_t i = 0; i < m_path.drifts.size(); i++)
	{
		const double travel = m_path.rate_per_s * (time_s - start);
		if (travel < std::fabs(m_path.drifts[i] - from)) return from + (m_path.drifts[i] > from ? travel : -travel);
		start = m_reach_s[i];
		from = m_path.drifts[i];
	}
	return from;
}

double DriftActuator::drift() const { return double((m_load.point_m() - m_rest_m).dot(m_direction)) / m_path.length_m; }

void DriftActuator::beforeStep(double time_s, double step_s)
{
	if (active())
	{
		const btVector3 point = m_load.point_m();
		const double displacement_m = double((point - m_rest_m).dot(m_direction));
		const double velocity_m_s = double(m_body.getVelocityInLocalPoint(point - m_body.getCenterOfMassPosition()).dot(m_direction));
		const double error_m = m_path.length_m * targetDrift(time_s) - displacement_m;
		m_integral_n += 5.0 * step_s * m_stiffness_n_m * error_m;
		const double force_n = m_stiffness_n_m * error_m - m_damping_n_s_m * velocity_m_s + m_integral_n;
		m_load.setFactor(force_n);
		const double window_s = std::min(m_path.window_max_s, m_path.window_drift / m_path.rate_per_s);
		for (size_t k = 0; k < m_reach_s.size(); k++)
		{
			if (time_s >= m_reach_s[k] - window_s && time_s < m_reach_s[k])
			{
				m_forceSum_n[k] += force_n;
				m_driftSum[k] += displacement_m / m_path.length_m;
				m_samples[k]++;
			}
		}
	}
	m_load.apply();
}

std::vector<double> DriftActuator::meanForces_n() const
{
	std::vector<double> f;
	for (size_t k = 0; k < m_samples.size(); k++) f.push_back(m_samples[k] ? m_forceSum_n[k] / m_samples[k] : 0.0);
	return f;
}

std::vector<double> DriftActuator::meanDrifts() const
{
	std::vector<double> d;
	for (size_t k = 0; k < m_samples.size(); k++) d.push_back(m_samples[k] ? m_driftSum[k] / m_samples[k] : 0.0);
	return d;
}
}  // namespace scene
