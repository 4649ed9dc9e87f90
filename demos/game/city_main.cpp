// build/bin/city: a city of steel frames, some hit by wrecking balls, simulated just in time, always jointed or rigid
// (issue 24). No OpenGL. See --help.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "City.h"
#include "scene/FlagTable.h"
#include "scene/JsonNumber.h"

namespace
{
using game::CityParameters;

scene::Flags<CityParameters> cityFlags()
{
	using P = CityParameters;
	scene::Flags<P> f;
	f["buildings"] = scene::wholeFlag(&P::buildings, "N  steel frames on a square grid, default 10");
	f["hit"] = scene::wholeFlag(&P::hit, "N  the first N buildings are hit, each by its own wrecking ball, default 1");
	f["spacing"] = scene::numberFlag(&P::spacing_m, "M  grid pitch, default 12");
	f["mode"] = {[](P& p, const std::string& t) { return t == "all" || game::parseCityMode(t, p.mode); },
				 "jit|jointed|rigid|all  default jit; all: the three in one run, one after the other, and the ratios of their costs"};
	f["storeys"] = {[](P& p, const std::string& t) { return scene::parseInteger(t, p.building.storeys); }, "N  of every building, default 1"};
	f["bays"] = {[](P& p, const std::string& t) { return scene::parseInteger(t, p.building.bays); }, "N  of every building, default 1"};
	f["duration"] = {[](P& p, const std::string& t) { return scene::parseNumber(t, p.building.duration_s); }, "SECONDS  simulated, default 3"};
	f["release-angle"] = {[](P& p, const std::string& t) { return scene::parseNumber(t, p.building.release_angle_rad); }, "RAD  the balls' release from the vertical, default 1"};
	f["json"] = {[](P&, const std::string&) { return true; }, "print the result as one JSON object", false};
	f["help"] = {[](P&, const std::string&) { return true; }, "this text", false};
	return f;
}

}  // namespace

int main(int argc, char** argv)
{
	CityParameters p;
	std::vector<std::string> errors;
	bool json = false, help = false;
	const scene::Flags<CityParameters> flags = cityFlags();
	for (const scene::FlagArgument& flag : scene::splitFlagArguments(std::vector<std::string>(argv + 1, argv + argc), errors))
	{
		if (flag.name == "json") json = true;
		if (flag.name == "help") help = true;
		scene::applyFlag(flags, p, flag, errors);
	}
	if (help)
	{
		std::cout << "usage: city [--json] [flags]\n" << scene::usageOf(flags);
		return 0;
	}
	for (const std::string& e : game::validateCityParameters(p)) errors.push_back(e);
	if (!errors.empty())
	{
		for (const std::string& e : errors) std::cerr << "city: " << e << "\n";
		return 2;
	}
	bool all = false;
	for (int i = 1; i < argc; i++) all = all || std::string(argv[i]) == "--mode=all";
	std::vector<game::CityMode> modes = {p.mode};
	if (all) modes = {game::CityMode::JustInTime, game::CityMode::Jointed, game::CityMode::Rigid};
	std::vector<game::CityResult> results;
	for (game::CityMode mode : modes)
	{
		p.mode = mode;
		results.push_back(game::runCity(p));
	}
	std::ostringstream o;
	bool finite = true;
	for (size_t k = 0; k < modes.size(); k++)
	{
		const game::CityResult& r = results[k];
		finite = finite && r.finite;
		if (json)
			o << (k ? "," : "") << "{\"mode\":\"" << game::cityModeName(modes[k]) << "\",\"buildings\":" << p.buildings << ",\"hit\":" << p.hit
			  << ",\"idle_step_us\":" << scene::jsonNumber(r.idle_step_us) << ",\"step_us\":" << scene::jsonNumber(r.step_us) << ",\"impact_energy_J\":" << scene::jsonNumber(r.impact_energy_j)
			  << ",\"plastic_energy_J\":" << scene::jsonNumber(r.plastic_energy_j) << ",\"bodies_max\":" << r.bodies_max << ",\"joints_max\":" << r.joints_max
			  << ",\"idle_bodies_max\":" << r.idle_bodies_max << ",\"idle_joints_max\":" << r.idle_joints_max << ",\"subdivisions\":" << r.subdivisions
			  << ",\"merges\":" << r.merges << ",\"first_impact_s\":" << scene::jsonNumber(r.first_impact_s) << ",\"internal_steps\":" << r.internal_steps
			  << ",\"simulated_s\":" << scene::jsonNumber(r.simulated_s) << ",\"wall_s\":" << scene::jsonNumber(r.wall_s) << ",\"finite\":" << (r.finite ? "true" : "false") << "}";
		else
			o << "city, " << game::cityModeName(modes[k]) << ": " << p.buildings << " buildings, " << p.hit << " hit; " << r.internal_steps << " internal steps in "
			  << r.wall_s << " s (median step " << r.step_us << " us, before the first impact " << r.idle_step_us << " us)\n  balls' energy " << r.impact_energy_j
			  << " J, plastic work " << r.plastic_energy_j << " J; at most " << r.bodies_max << " bodies and " << r.joints_max << " joints in the world; "
			  << r.subdivisions << " member subdivisions, " << r.merges << " member merges\n";
	}
	if (all)
	{
		// the targets, in this run: idle jit / rigid, whole run jit / jointed, plastic work jit / jointed
		const double idle = results[0].idle_step_us / results[2].idle_step_us, whole = results[0].wall_s / results[1].wall_s;
		const double plastic = results[0].plastic_energy_j / results[1].plastic_energy_j;
		if (json)
			o << ",{\"idle_jit_over_rigid\":" << scene::jsonNumber(idle) << ",\"run_jit_over_jointed\":" << scene::jsonNumber(whole) << ",\"plastic_jit_over_jointed\":" << scene::jsonNumber(plastic) << "}";
		else
			o << "ratios: before the first impact jit / rigid " << idle << "; the whole run jit / jointed " << whole << "; plastic work jit / jointed " << plastic << "\n";
	}
	std::cout << (json ? (all ? "[" + o.str() + "]\n" : o.str() + "\n") : o.str());
	return finite ? 0 : 3;
}
