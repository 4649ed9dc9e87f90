// A quasi-static collapse test, as in a laboratory: the load factor rises (scene::LoadRamp); when a joint runs away
// (CollapseDetector) the load is held; if the structure keeps moving until its joints have turned
// mechanism_rotation_rad since then, it has collapsed at the held factor, otherwise (an elastic-plastic
// structure that only softened as its hinges formed one by one, or a vibration) the ramp resumes after hold_s.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "CollapseDetector.h"
#include "scene/LoadRamp.h"

namespace structures
{
// The ramp as a scene's parameters give it (the cantilever's and the portal's derive from it): the load factor rises
// at fast_ramp_rate_per_s up to slow_from_fraction of the plastic-analysis collapse factor, then at the scene's
// ramp_rate_per_s, until a joint turns faster than collapse_rate_rad_s (over rate_window_s); then it is held: a
// collapse if the mechanism turns mechanism_rotation_rad within hold_s, else the ramp resumes.
struct CollapseRamp
{
	double fast_ramp_rate_per_s = 0.2;
	double slow_from_fraction = 0.9;
	double collapse_rate_rad_s = 0.05;
	double rate_window_s = 0.1;
	double mechanism_rotation_rad = 0.05;
	double hold_s = 2.0;  // a held load that has not turned the mechanism that far by then is raised again
};

// Appends "name: value is not in range" for every field out of its range (named as the runners' flags).
void validateCollapseRamp(const CollapseRamp& ramp, std::vector<std::string>& errors);

class CollapseTest
{
public:
	// the ramp, the scene's slow rate (from slow_from_fraction x collapseFactor on) and its plastic-analysis collapse factor
	CollapseTest(const CollapseRamp& ramp, double slowRate_per_s, double collapseFactor);
	double factor() const { return m_ramp.factor(); }
	void advance(double step_s) { m_ramp.advance(step_s); }
	// after each step, with the joints' rotations measured on the bodies
	void update(double time_s, const std::vector<double>& rotations_rad);
	bool done() const { return m_done; }
	double collapseFactor() const { return m_collapseFactor; }  // NaN until a collapse is confirmed
	int holds() const { return m_holds; }                       // how many times the load was held
	// the mechanism: rotation of each joint since the (confirmed) hold began, and the joints that turned >= 20 %
	std::vector<double> mechanismRotations(const std::vector<double>& rotations_rad) const { return m_detector.sinceCollapse(rotations_rad); }
	std::vector<int> mechanism(const std::vector<double>& rotations_rad) const { return m_detector.mechanism(rotations_rad); }

private:
	CollapseRamp m_s;
	scene::LoadRamp m_ramp;
	CollapseDetector m_detector;
	double m_heldSince_s = 0;
	double m_collapseFactor = std::numeric_limits<double>::quiet_NaN();
	int m_holds = 0;
	bool m_done = false;
};
}  // namespace structures
