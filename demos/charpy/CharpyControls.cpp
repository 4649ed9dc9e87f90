#include "CharpyControls.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "CharpyScene.h"

CharpyControls charpyControlsFromSliders(const std::vector<float>& v)
{
	if (v.size() != 9) throw std::invalid_argument("charpy sliders: " + std::to_string(v.size()) + " values, expected 9");
	CharpyControls c;
	c.yieldStress_MPa = double(v[0]);
	c.friction = double(v[1]);
	c.releaseAngle_rad = double(v[2]);
	c.strikerRadius_mm = double(v[3]);
	c.maxPlasticRotation_rad = double(v[4]);
	c.frameStep_ms = double(v[5]);
	c.solverIterations = double(v[6]);
	c.partPairs = double(v[7]);
	c.anvilGap_mm = double(v[8]);
	return c;
}

CharpyParameters charpyParametersFromControls(const CharpyControls& c, CharpyMethod method)
{
	CharpyParameters p;
	p.method = method;
	p.yield_stress_pa = c.yieldStress_MPa * 1e6;
	p.friction = c.friction;
	p.release_angle_rad = c.releaseAngle_rad;
	p.striker_radius_m = c.strikerRadius_mm * 1e-3;
	p.max_plastic_rotation_rad = c.maxPlasticRotation_rad;
	p.dt_s = c.frameStep_ms * 1e-3;
	p.solver_iterations = int(std::lround(c.solverIterations));
	// the rigid method builds one body whatever this says; parts must still be a valid even number
	p.parts = 2 * int(std::lround(c.partPairs));
	p.anvil_gap_m = c.anvilGap_mm * 1e-3;
	return p;
}

scene::ControlledScene charpyControls()
{
	const CharpyControls d;
	scene::ControlledScene c;
	c.name = "charpy";
	c.sliders = {{"yield stress (MPa)", 50, 2000, false, float(d.yieldStress_MPa)},
				 {"friction", 0, 1, false, float(d.friction)},
				 {"release angle (rad)", 0.5f, 3.0f, false, float(d.releaseAngle_rad)},
				 {"striker edge radius (mm), 0 = flat", 0, 8, false, float(d.strikerRadius_mm)},
				 {"max plastic rotation (rad)", 0.5f, 6, false, float(d.maxPlasticRotation_rad)},
				 {"frame step (ms)", 0.01f, 2, false, float(d.frameStep_ms)},
				 {"solver iterations", 1, 100, true, float(d.solverIterations)},
				 {"specimen part pairs", 1, 8, true, float(d.partPairs)},
				 {"anvil gap (mm)", 23, 50, false, float(d.anvilGap_mm)}};  // above the 20 mm hammer / 0.9
	for (int n = 1; n <= kCharpyMethodCount; n++) c.methods.push_back(std::string(charpyMethodName(charpyMethodByNumber(n))));
	c.method = std::string(charpyMethodName(CharpyMethod::PlasticHinge));
	c.build = [](const std::vector<float>& v, const std::string& m) -> std::unique_ptr<scene::SteppedScene>
	{
		const std::optional<CharpyMethod> method = parseCharpyMethod(m);
		if (!method) throw std::invalid_argument("method: '" + m + "' is not a Charpy method");
		return std::make_unique<CharpyScene>(charpyParametersFromControls(charpyControlsFromSliders(v), *method));
	};
	// looking along -x from the hammer's side, from above: the specimen bends away, towards the far side
	c.camera_yaw_deg = 90;
	c.camera_pitch_deg = -60;
	c.time_scale = 0.01f;  // the test is over in 10 ms
	return c;
}
