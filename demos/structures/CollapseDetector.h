// Finds the collapse in a quasi-static load ramp from the joint rotations measured on the bodies: the structure
// has collapsed when a joint turns faster than rate_rad_s on average over the last window_s (a mechanism runs
// away; elastic joints turn with the load, slowly, and their vibrations average out over the window). While the
// load rises fast, the rate that counts is scaled by the ramp's fast/slow ratio (elastic joints turn faster
// then; a structure that collapses early is still caught, later). After the
// collapse it keeps the rotations at that moment, so a scene can tell which joints form the mechanism.
#pragma once

#include <deque>
#include <utility>
#include <vector>

namespace structures
{
class CollapseDetector
{
public:
	CollapseDetector(double rate_rad_s, double window_s) : m_rate(rate_rad_s), m_window(window_s) {}
	// returns true at the step the collapse is first seen; rateScale multiplies the rate (a change starts a new window)
	bool feed(double time_s, const std::vector<double>& rotations_rad, double rateScale = 1.0);
	bool collapsed() const { return m_collapsed; }
	// rotation of each joint since the collapse was seen (the mechanism's motion), rad
	std::vector<double> sinceCollapse(const std::vector<double>& rotations_rad) const;
	// indices of the joints that turned at least `fraction` of the largest rotation since the collapse
	std::vector<int> mechanism(const std::vector<double>& rotations_rad, double fraction = 0.2) const;

private:
	double m_rate, m_window;
	std::deque<std::pair<double, std::vector<double>>> m_history;
	double m_scale = 1.0;
	bool m_collapsed = false;
	std::vector<double> m_atCollapse;
};
}  // namespace structures
