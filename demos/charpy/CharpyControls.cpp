#include "CharpyControls.h"

#include <cmath>

const CharpySlider kCharpySliders[kCharpySliderCount] = {
	{"yield stress (MPa)", &CharpyControls::yieldStress_MPa, 50, 2000, false},
	{"friction", &CharpyControls::friction, 0, 1, false},
	{"release angle (rad)", &CharpyControls::releaseAngle_rad, 0.5f, 3.0f, false},
	{"striker edge radius (mm), 0 = flat", &CharpyControls::strikerRadius_mm, 0, 8, false},
	{"max plastic rotation (rad)", &CharpyControls::maxPlasticRotation_rad, 0.5f, 6, false},
	{"frame step (ms)", &CharpyControls::frameStep_ms, 0.01f, 2, false},
	{"solver iterations", &CharpyControls::solverIterations, 1, 100, true},
	{"specimen part pairs", &CharpyControls::partPairs, 1, 8, true},
	{"anvil gap (mm)", &CharpyControls::anvilGap_mm, 23, 50, false},  // above the 20 mm hammer / 0.9
};

bool operator==(const CharpyControls& a, const CharpyControls& b)
{
	for (const CharpySlider& s : kCharpySliders)
		if (a.*s.value != b.*s.value) return false;
	return true;
}

CharpyParameters charpyParametersFromControls(const CharpyControls& c, CharpyMethod method)
{
	CharpyParameters p;
	p.method = method;
	p.yield_stress_pa = double(c.yieldStress_MPa) * 1e6;
	p.friction = double(c.friction);
	p.release_angle_rad = double(c.releaseAngle_rad);
	p.striker_radius_m = double(c.strikerRadius_mm) * 1e-3;
	p.max_plastic_rotation_rad = double(c.maxPlasticRotation_rad);
	p.dt_s = double(c.frameStep_ms) * 1e-3;
	p.solver_iterations = int(std::lround(double(c.solverIterations)));
	// the rigid method builds one body whatever this says; parts must still be a valid even number
	p.parts = 2 * int(std::lround(double(c.partPairs)));
	p.anvil_gap_m = double(c.anvilGap_mm) * 1e-3;
	return p;
}
