// The three moments of a Charpy run the thesis' figures 3.1-3.7 show, found from the physics only:
// before impact, mid-bend and after the specimen passes the anvils (or stops the hammer).
#pragma once

#include <string>

class CharpyScene;

enum class CharpyMoment
{
	BeforeImpact,
	MidBend,
	After,
};
constexpr int kCharpyMomentCount = 3;

const char* charpyMomentName(CharpyMoment moment);

// Tells, after each scene step, which moment (if any) the scene has just reached. Reads the scene only.
class CharpyMomentTracker
{
public:
	explicit CharpyMomentTracker(const CharpyScene& scene);
	// true once for each moment, in order; the first call (before any step) reports BeforeImpact.
	bool reached(const CharpyScene& scene, CharpyMoment& moment);
	bool done() const { return m_next > int(CharpyMoment::After); }

private:
	double m_halfPassAngle_rad;
	double m_passTime_s = -1;  // time the specimen passed the anvils, -1 until it has
	double m_fallbackMidTime_s;
	int m_next = 0;
};
