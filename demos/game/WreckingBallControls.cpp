#include "WreckingBallControls.h"

#include <cmath>
#include <stdexcept>

namespace game
{
WreckingBallParameters wreckingBallFromSliders(const std::vector<float>& v, plastic::JointMethod method)
{
	if (v.size() != 8) throw std::invalid_argument("wrecking ball sliders: " + std::to_string(v.size()) + " values, expected 8");
	WreckingBallParameters p;
	p.method = method;
	p.release_angle_rad = double(v[0]);
	p.ball_mass_kg = double(v[1]);
	p.yield_stress_pa = double(v[2]) * 1e6;
	p.max_plastic_rotation_rad = double(v[3]);
	p.chain_length_m = double(v[4]);
	p.impact_height_m = double(v[5]);
	p.solver.solver = std::lround(double(v[6])) ? plastic::SolverKind::DirectJoint : plastic::SolverKind::SequentialImpulse;
	p.solver.iterations = int(std::lround(double(v[7])));
	return p;
}

scene::ControlledScene wreckingBallControls()
{
	scene::ControlledScene c;
	c.name = "wrecking ball";
	c.methods = scene::structureMethodNames();
	c.method = "plastic-hinge";
	c.sliders = {{"release angle (rad)", 0, 1.5f, false, 1.0f},
				 {"ball mass (kg)", 100, 10000, false, 2000},
				 {"yield stress (MPa)", 100, 800, false, 355},
				 {"max plastic rotation (rad)", 0.02f, 2, false, 0.2f},
				 {"chain length (m)", 1, 10, false, 5},
				 {"impact height (m)", 0.6f, 3, false, 1.5f},
				 {"direct solver (1) or upstream SI (0)", 0, 1, true, 1},
				 {"solver iterations", 1, 100, true, 10}};
	c.build = [](const std::vector<float>& v, const std::string& m) -> std::unique_ptr<scene::SteppedScene>
	{ return std::make_unique<WreckingBallScene>(wreckingBallFromSliders(v, scene::structureMethod(m))); };
	// from +z, a little above: the frame in its plane, the ball coming from the left
	c.camera_pitch_deg = -8;
	c.time_scale = 1;
	return c;
}

WreckingBallParameters buildingFromSliders(const std::vector<float>& v, plastic::JointMethod method)
{
	if (v.size() != 10) throw std::invalid_argument("building sliders: " + std::to_string(v.size()) + " values, expected 10");
	WreckingBallParameters p = wreckingBallFromSliders(std::vector<float>(v.begin(), v.begin() + 8), method);
	p.storeys = int(std::lround(double(v[8])));
	p.bays = int(std::lround(double(v[9])));
	return p;
}

scene::ControlledScene buildingControls()
{
	scene::ControlledScene c = wreckingBallControls();
	c.name = "building";
	c.sliders.push_back({"storeys", 1, 10, true, 5});
	c.sliders.push_back({"bays", 1, 8, true, 4});
	c.build = [](const std::vector<float>& v, const std::string& m) -> std::unique_ptr<scene::SteppedScene>
	{ return std::make_unique<WreckingBallScene>(buildingFromSliders(v, scene::structureMethod(m))); };
	// the wrecking ball's view direction (from +z, a little above)
	return c;
}
}  // namespace game
