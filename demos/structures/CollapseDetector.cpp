#include "CollapseDetector.h"

#include <algorithm>
#include <cmath>

namespace structures
{
bool CollapseDetector::feed(double time_s, const std::vector<double>& rotations, double rateScale)
{
	if (m_collapsed) return false;
	if (rateScale != m_scale)
	{
		m_history.clear();
		m_scale = rateScale;
	}
	m_history.emplace_back(time_s, rotations);
	while (m_history.size() > 2 && m_history[1].first <= time_s - m_window) m_history.pop_front();
	const auto& [then_s, before] = m_history.front();
	if (time_s - then_s < m_window * 0.999) return false;
	for (size_t i = 0; i < rotations.size(); i++)
	{
		if (std::fabs(rotations[i] - before[i]) > m_rate * m_scale * (time_s - then_s))
		{
			m_collapsed = true;
			m_atCollapse = rotations;
			m_history.clear();
			return true;
		}
	}
	return false;
}

std::vector<double> CollapseDetector::sinceCollapse(const std::vector<double>& rotations) const
{
	std::vector<double> d(rotations.size(), 0.0);
	if (!m_collapsed) return d;
	for (size_t i = 0; i < rotations.size(); i++) d[i] = rotations[i] - m_atCollapse[i];
	return d;
}

std::vector<int> CollapseDetector::mechanism(const std::vector<double>& rotations, double fraction) const
{
	const std::vector<double> d = sinceCollapse(rotations);
	double largest = 0;
	for (double x : d) largest = std::max(largest, std::fabs(x));
	std::vector<int> joints;
	for (size_t i = 0; i < d.size(); i++)
		if (largest > 0 && std::fabs(d[i]) >= fraction * largest) joints.push_back(int(i));
	return joints;
}
}  // namespace structures
