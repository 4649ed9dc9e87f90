// The Charpy example's controls: slider values in the units their names say, their ranges, and the
// CharpyParameters they stand for. No GUI code here, so the tests can check every range.
#pragma once

#include "LinearMath/btScalar.h"

#include "CharpyParameters.h"

struct CharpyControls
{
	btScalar yieldStress_MPa = 400;
	btScalar friction = 0;
	btScalar releaseAngle_rad = btScalar(2.8);
	btScalar strikerRadius_mm = 0;
	btScalar maxPlasticRotation_rad = 3;
	btScalar frameStep_ms = btScalar(0.1);
	btScalar solverIterations = 10;
	btScalar partPairs = 1;
	btScalar anvilGap_mm = 40;
};

bool operator==(const CharpyControls& a, const CharpyControls& b);
inline bool operator!=(const CharpyControls& a, const CharpyControls& b) { return !(a == b); }

// One slider: its label, the value it moves, its range.
struct CharpySlider
{
	const char* label;
	btScalar CharpyControls::*value;
	float min;
	float max;
	bool integers;
};
constexpr int kCharpySliderCount = 9;
extern const CharpySlider kCharpySliders[kCharpySliderCount];

// The scene parameters of the controls for a method; the rest stays at CharpyParameters' defaults.
CharpyParameters charpyParametersFromControls(const CharpyControls& controls, CharpyMethod method);
