#include "CityControls.h"

#include <cmath>
#include <stdexcept>

namespace game
{
CityParameters cityFromSliders(const std::vector<float>& v, const std::string& mode)
{
	if (v.size() != 7) throw std::invalid_argument("city sliders: " + std::to_string(v.size()) + " values, expected 7");
	CityParameters p;
	if (!parseCityMode(mode, p.mode)) throw std::invalid_argument("city mode: " + mode + " is not jit, jointed or rigid");
	p.buildings = int(std::lround(double(v[0])));
	p.hit = int(std::lround(double(v[1])));
	p.spacing_m = double(v[2]);
	p.building.storeys = int(std::lround(double(v[3])));
	p.building.bays = int(std::lround(double(v[4])));
	p.building.release_angle_rad = double(v[5]);
	p.building.ball_mass_kg = double(v[6]);
	// the example runs until it is closed: as long as the runner's longest run
	p.building.duration_s = 60;
	return p;
}

scene::ControlledScene cityControls()
{
	scene::ControlledScene c;
	c.name = "city";
	c.methods = {cityModeName(CityMode::JustInTime), cityModeName(CityMode::Jointed), cityModeName(CityMode::Rigid)};
	c.method = cityModeName(CityMode::JustInTime);
	c.sliders = {{"buildings", 1, 100, true, 9},
				 {"hit", 0, 100, true, 3},
				 {"spacing (m)", 10, 30, false, 12},
				 {"storeys", 1, 5, true, 1},
				 {"bays", 1, 2, true, 1},
				 {"release angle (rad)", 0, 1.5f, false, 1.0f},
				 {"ball mass (kg)", 100, 10000, false, 2000}};
	c.build = [](const std::vector<float>& v, const std::string& m) -> std::unique_ptr<scene::SteppedScene>
	{ return std::make_unique<CityScene>(cityFromSliders(v, m)); };
	// from the front left (-z, -x) and above: the hit buildings (the first row) in front, the rows behind them
	c.camera_yaw_deg = 30;
	c.camera_pitch_deg = -20;
	c.joint_marker_px = 3;  // many small frames
	c.time_scale = 1;
	return c;
}
}  // namespace game
