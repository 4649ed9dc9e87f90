#include "CollapseTest.h"

#include <algorithm>
#include <cmath>

#include "scene/Ranges.h"

namespace structures
{
void validateCollapseRamp(const CollapseRamp& ramp, std::vector<std::string>& e)
{
	scene::requireRange(e, "fast-ramp-rate", ramp.fast_ramp_rate_per_s, 1e-6, 1000, "1/s");
	scene::requireRange(e, "slow-from", ramp.slow_from_fraction, 0, 1, "(of the plastic-analysis collapse factor)");
	scene::requireRange(e, "collapse-rate", ramp.collapse_rate_rad_s, 1e-6, 100, "rad/s");
	scene::requireRange(e, "rate-window", ramp.rate_window_s, 1e-3, 10, "s");
	scene::requireRange(e, "mechanism-rotation", ramp.mechanism_rotation_rad, 1e-4, 3, "rad");
	scene::requireRange(e, "hold", ramp.hold_s, 1e-3, 100, "s");
}

CollapseTest::CollapseTest(const CollapseRamp& ramp, double slowRate_per_s, double collapseFactor)
	: m_s(ramp),
	  m_ramp(slowRate_per_s, ramp.fast_ramp_rate_per_s, ramp.slow_from_fraction * collapseFactor),
	  m_detector(ramp.collapse_rate_rad_s, ramp.rate_window_s)
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
