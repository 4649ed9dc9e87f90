#include "CollapseTest.h"

#include <algorithm>
#include <cmath>

namespace structures
{
CollapseTest::CollapseTest(const CollapseTestSettings& s)
	: m_s(s), m_ramp(s.slow_rate_per_s, s.fast_rate_per_s, s.slow_from_factor), m_detector(s.collapse_rate_rad_s, s.rate_window_s)
{
}

void CollapseTest::update(double time_s, const std::vector<double>& rotations)
{
	if (m_done) return;
	if (!m_ramp.held())
	{
		if (m_detector.feed(time_s, rotations, m_ramp.speedRatio()))
		{
			m_ramp.hold();
			m_heldSince_s = time_s;
			m_holds++;
		}
		return;
	}
	double largest = 0;
	for (double d : m_detector.sinceCollapse(rotations)) largest = std::max(largest, std::fabs(d));
	if (largest > m_s.mechanism_rotation_rad)
	{
		m_collapseFactor = m_ramp.factor();
		m_done = true;
	}
	else if (time_s - m_heldSince_s > m_s.hold_s)
	{
		m_ramp.resume();
		m_detector = CollapseDetector(m_s.collapse_rate_rad_s, m_s.rate_window_s);
	}
}
}  // namespace structures
