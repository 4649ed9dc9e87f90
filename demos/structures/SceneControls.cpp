#include "SceneControls.h"

#include <cmath>
#include <stdexcept>

namespace structures
{
namespace
{
int whole(float v) { return int(std::lround(double(v))); }

void requireValid(const std::vector<std::string>& errors)
{
	if (!errors.empty()) throw std::invalid_argument(errors.front());
}

void requireCount(const std::vector<float>& values, size_t n, const char* scene)
{
	if (values.size() != n)
		throw std::invalid_argument(std::string(scene) + " sliders: " + std::to_string(values.size()) + " values, expected " + std::to_string(n));
}

// the solver sliders every structure example ends with: internal step (ms) and iterations
void solverFrom(const std::vector<float>& v, size_t at, scene::SolverSettings& s, plastic::JointMethod method)
{
	s.method = method;
	s.world.internal_step_s = double(v[at]) * 1e-3;
	s.world.iterations = whole(v[at + 1]);
}

// the runner's defaults: the toolkit's game settings (four internal steps per 60 Hz frame, 10 iterations)
const scene::SliderSpec kStep = {"internal step (ms)", 0.1f, 16.7f, false, float(1000.0 / 240.0)};
const scene::SliderSpec kIterations = {"solver iterations", 1, 1000, true, 10};
}  // namespace

CantileverParameters cantileverFromSliders(const std::vector<float>& v, plastic::JointMethod method)
{
	requireCount(v, 9, "cantilever");
	CantileverParameters p;
	p.load_ratio = double(v[0]);
	p.segments = whole(v[1]);
	p.length_m = double(v[2]);
	p.section_depth_m = double(v[3]) * 1e-3;
	p.yield_stress_pa = double(v[4]) * 1e6;
	p.follower_load = whole(v[5]) != 0;
	p.tip_drift = double(v[6]) / 100;
	solverFrom(v, 7, p.solver, method);
	return p;
}

PortalParameters portalFromSliders(const std::vector<float>& v, plastic::JointMethod method)
{
	requireCount(v, 9, "portal");
	PortalParameters p;
	p.horizontal_load_n = double(v[0]) * 1e3;
	p.vertical_load_n = double(v[1]) * 1e3;
	p.span_m = double(v[2]);
	p.height_m = double(v[3]);
	p.ramp_rate_per_s = double(v[4]);
	p.knee_load_n = double(v[5]) * 1e3;
	if (v[6] > 0) p.sway_drifts = {double(v[6]) / 100};
	solverFrom(v, 7, p.solver, method);
	return p;
}

DropWeightParameters dropWeightFromSliders(const std::vector<float>& v, plastic::JointMethod method)
{
	requireCount(v, 8, "drop weight");
	DropWeightParameters p;
	p.weight_mass_kg = double(v[0]);
	p.impact_speed_m_s = double(v[1]);
	p.span_m = double(v[2]);
	p.segments = 2 * whole(v[3]);
	p.clamped = whole(v[4]) != 0;
	p.section_depth_m = double(v[5]) * 1e-3;
	solverFrom(v, 6, p.solver, method);
	return p;
}

PaperClipParameters paperClipFromSliders(const std::vector<float>& v, plastic::JointMethod method)
{
	requireCount(v, 7, "paper clip");
	PaperClipParameters p;
	p.bend_amplitude_rad = double(v[0]) * 3.14159265358979323846 / 180;
	p.cycle_period_s = double(v[1]);
	p.wire_diameter_m = double(v[2]) * 1e-3;
	p.hinge_length_m = double(v[3]) * 1e-3;
	p.reduction_of_area = double(v[4]);
	solverFrom(v, 5, p.solver, method);
	return p;
}

scene::ControlledScene cantileverControls()
{
	scene::ControlledScene c;
	c.name = "cantilever";
	c.methods = scene::structureMethodNames();
	c.method = "plastic-hinge";
	c.sliders = {{"tip load P L / Mp", 0, 3, false, 1.5f},
				 {"segments", 1, 8, true, 4},
				 {"length (m)", 0.5f, 5, false, 2},
				 {"section depth (mm)", 20, 300, false, 100},
				 {"yield stress (MPa)", 100, 1000, false, 400},
				 {"follower load (0/1)", 0, 1, true, 0},
				 {"pushover tip drift (% of L, 0: the load)", 0, 20, false, 0},
				 kStep,
				 kIterations};
	c.build = [](const std::vector<float>& v, const std::string& m) -> std::unique_ptr<scene::SteppedScene>
	{
		const CantileverParameters p = cantileverFromSliders(v, scene::structureMethod(m));
		requireValid(validateCantileverParameters(p));
		return std::make_unique<CantileverScene>(p);
	};
	// from +z, level: the beam and the arc it turns through (its view envelope)
	c.time_scale = 0.1f;  // it turns 1.5 rad in 0.15 s
	return c;
}

scene::ControlledScene portalControls()
{
	scene::ControlledScene c;
	c.name = "portal frame";
	c.methods = scene::structureMethodNames();
	c.method = "plastic-hinge";
	c.sliders = {{"horizontal load H (kN) at factor 1", 0, 200, false, 50},
				 {"vertical load V (kN) at factor 1", 0, 200, false, 75},
				 {"span (m)", 1, 10, false, 4},
				 {"height (m)", 1, 10, false, 3},
				 {"load factor ramp (1/s)", 0.005f, 0.2f, false, 0.02f},
				 {"gravity on each knee (kN)", 0, 300, false, 0},
				 {"sway pushover drift (% of h, 0: the loads)", 0, 30, false, 0},
				 kStep,
				 kIterations};
	c.build = [](const std::vector<float>& v, const std::string& m) -> std::unique_ptr<scene::SteppedScene>
	{
		const PortalParameters p = portalFromSliders(v, scene::structureMethod(m));
		requireValid(validatePortalParameters(p));
		return std::make_unique<PortalScene>(p);
	};
	// from +z, a little above: the frame in its plane, the beam's top face showing
	c.camera_pitch_deg = -8;
	c.time_scale = 2;
	return c;
}

scene::ControlledScene dropWeightControls()
{
	scene::ControlledScene c;
	c.name = "drop weight";
	c.methods = scene::structureMethodNames();
	c.method = "plastic-hinge";
	c.sliders = {{"weight mass (kg)", 10, 5000, false, 1000},
				 {"impact speed (m/s)", 0.5f, 20, false, 4.5f},
				 {"span (m)", 0.5f, 10, false, 2},
				 {"segment pairs", 1, 8, true, 1},
				 {"clamped ends (0/1)", 0, 1, true, 0},
				 {"section depth (mm)", 20, 300, false, 100},
				 kStep,
				 kIterations};
	c.build = [](const std::vector<float>& v, const std::string& m) -> std::unique_ptr<scene::SteppedScene>
	{
		const DropWeightParameters p = dropWeightFromSliders(v, scene::structureMethod(m));
		requireValid(validateDropWeightParameters(p));
		return std::make_unique<DropWeightScene>(p);
	};
	// from +z, level: the beam, the weight on it and the depth it is pushed to
	c.time_scale = 0.05f;  // the impact is over in 0.05 s
	return c;
}

scene::ControlledScene paperClipControls()
{
	scene::ControlledScene c;
	c.name = "paper clip";
	c.methods = {"plastic-hinge", "elastic-plastic", "elastic-plastic2"};  // the methods that break by fatigue
	c.method = "plastic-hinge";
	c.sliders = {{"bend amplitude (degrees)", 5, 90, false, 45},
				 {"cycle period (s)", 0.2f, 5, false, 1},
				 {"wire diameter (mm)", 0.3f, 3, false, 1},
				 {"hinge length (mm)", 0.5f, 10, false, 2},
				 {"reduction of area", 0.1f, 0.9f, false, 0.6f},
				 kStep,
				 kIterations};
	c.build = [](const std::vector<float>& v, const std::string& m) -> std::unique_ptr<scene::SteppedScene>
	{
		const PaperClipParameters p = paperClipFromSliders(v, scene::structureMethod(m));
		requireValid(validatePaperClipParameters(p));
		return std::make_unique<PaperClipScene>(p);
	};
	// from +z, level: the leg and the arc it is bent through; in real time (a cycle a second)
	c.time_scale = 1;
	return c;
}
}  // namespace structures
