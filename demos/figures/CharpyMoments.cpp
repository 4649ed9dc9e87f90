#include "CharpyMoments.h"

#include <cmath>

#include "CharpyScene.h"

namespace
{
const double kAfterPass_s = 2e-3;      // the "after" frame: this long after the specimen passed the anvils
const double kFallbackMid_s = 3e-3;    // mid-bend for methods that never bend half-way: 3 ms after the start
}  // namespace

const char* charpyMomentName(CharpyMoment moment)
{
	switch (moment)
	{
		case CharpyMoment::BeforeImpact:
			return "before impact";
		case CharpyMoment::MidBend:
			return "mid-bend";
		case CharpyMoment::After:
			return "after";
	}
	return "?";
}

CharpyMomentTracker::CharpyMomentTracker(const CharpyScene& scene)
	: m_halfPassAngle_rad(0.5 * scene.section().theta_pass_rad), m_fallbackMidTime_s(kFallbackMid_s)
{
}

bool CharpyMomentTracker::reached(const CharpyScene& scene, CharpyMoment& moment)
{
	const double t = scene.time_s();
	const double end = scene.parameters().duration_s;
	bool hit = false;
	switch (CharpyMoment(m_next))
	{
		case CharpyMoment::BeforeImpact:
			hit = true;
			break;
		case CharpyMoment::MidBend:
			hit = std::fabs(scene.bendAngle_rad()) >= m_halfPassAngle_rad || t >= m_fallbackMidTime_s;
			break;
		case CharpyMoment::After:
			if (m_passTime_s < 0 && scene.passedAnvils()) m_passTime_s = t;
			hit = (m_passTime_s >= 0 && t >= m_passTime_s + kAfterPass_s) || t >= end - 1e-12 || !scene.finite();
			break;
	}
	if (!hit || done()) return false;
	moment = CharpyMoment(m_next++);
	return true;
}
