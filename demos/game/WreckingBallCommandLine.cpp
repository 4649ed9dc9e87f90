#include "WreckingBallCommandLine.h"

#include "scene/FlagTable.h"

namespace game
{
namespace
{
using scene::parseInteger;
using scene::parseNumber;

using scene::numberFlag;
using scene::wholeFlag;

const scene::Flags<WreckingBallParameters>& flags()
{
	using P = WreckingBallParameters;
	static const scene::Flags<WreckingBallParameters> f = {
		{"method", {[](P& p, const std::string& t)
					{
						for (plastic::JointMethod m : {plastic::JointMethod::HingeMotor, plastic::JointMethod::PlasticHinge, plastic::JointMethod::ElasticPlastic,
													   plastic::JointMethod::ElasticPlastic2})
							if (t == plastic::jointMethodName(m))
							{
								p.method = m;
								return true;
							}
						return false;
					},
					"NAME  joint method: hinge-motor, plastic-hinge, elastic-plastic, elastic-plastic2; default plastic-hinge"}},
		{"solver", {[](P& p, const std::string& t)
					{ return plastic::parseSolverKind(t, p.solver.solver); },
					"NAME  direct (btDirectJointSolver: joint rows solved directly; the toolkit default), dantzig (btMLCPSolver + btDantzigSolver as upstream), pgs (btMLCPSolver, projected Gauss-Seidel), sequential-impulse (upstream)"}},
		{"internal-step", {[](P& p, const std::string& t)
						   { return parseNumber(t, p.solver.internal_step_s); },
						   "SECONDS  fixed internal step, default 1/240"}},
		{"iterations", {[](P& p, const std::string& t)
						{ return parseInteger(t, p.solver.iterations); },
						"N  solver iterations, default 10"}},
		{"frame-rate", numberFlag(&P::frame_rate_hz, "HZ  frames per second, default 60")},
		{"duration", numberFlag(&P::duration_s, "SECONDS  simulated, default 3")},
		{"gravity", numberFlag(&P::gravity_m_s2, "M_S2  default 9.81")},
		{"span", numberFlag(&P::span_m, "M  default 4")},
		{"height", numberFlag(&P::height_m, "M  default 3")},
		{"storeys", wholeFlag(&P::storeys, "N  storeys of the frame, default 1")},
		{"bays", wholeFlag(&P::bays, "N  bays of the frame, default 1")},
		{"column-segments", wholeFlag(&P::column_segments, "N  default 4")},
		{"beam-segments", wholeFlag(&P::beam_segments, "N  default 4")},
		{"section-depth", numberFlag(&P::section_depth_m, "M  I section depth, default 0.2")},
		{"flange-width", numberFlag(&P::flange_width_m, "M  default 0.1")},
		{"web-thickness", numberFlag(&P::web_thickness_m, "M  default 0.0056")},
		{"flange-thickness", numberFlag(&P::flange_thickness_m, "M  default 0.0085")},
		{"fy", numberFlag(&P::yield_stress_pa, "PA  yield stress, default 355e6 (Mp = 74.4 kN m)")},
		{"youngs-modulus", numberFlag(&P::youngs_modulus_pa, "PA  default 210e9")},
		{"density", numberFlag(&P::density_kg_m3, "KG_M3  default 7850")},
		{"max-plastic-rotation", numberFlag(&P::max_plastic_rotation_rad, "RAD  a joint breaks past this accumulated plastic rotation, default 0.2")},
		{"ball-mass", numberFlag(&P::ball_mass_kg, "KG  default 2000")},
		{"ball-radius", numberFlag(&P::ball_radius_m, "M  default 0.4")},
		{"chain-length", numberFlag(&P::chain_length_m, "M  pivot to the ball's surface, default 5")},
		{"chain-links", wholeFlag(&P::chain_links, "N  default 8")},
		{"chain-mass", numberFlag(&P::chain_mass_kg, "KG  default 80")},
		{"release-angle", numberFlag(&P::release_angle_rad, "RAD  from the vertical, default 1")},
		{"impact-height", numberFlag(&P::impact_height_m, "M  where the ball meets the left column, default 1.5")},
		{"ball-friction", numberFlag(&P::ball_friction, "COEFFICIENT  default 0.5")},
	};
	return f;
}
}  // namespace

WreckingBallCommandLine parseWreckingBallCommandLine(const std::vector<std::string>& arguments)
{
	WreckingBallCommandLine cl;
	for (const scene::FlagArgument& flag : scene::splitFlagArguments(arguments, cl.errors))
	{
		if (!scene::takeSwitch(flag, {{"help", &cl.help}, {"json", &cl.json}}, cl.errors) && !scene::takePath(flag, "joints-csv", cl.joints_csv, cl.errors) &&
			!scene::takePath(flag, "history", cl.history_csv, cl.errors))
			scene::applyFlag(flags(), cl.parameters, flag, cl.errors);
	}
	if (cl.help || !cl.errors.empty()) return cl;
	const std::vector<std::string> invalid = validateWreckingBallParameters(cl.parameters);
	cl.errors.insert(cl.errors.end(), invalid.begin(), invalid.end());
	return cl;
}

std::string wreckingBallUsage()
{
	std::string text =
		"usage: wrecking_ball [--json] [--joints-csv=PATH] [--history=PATH] [flags]\n"
		"A steel portal frame of plastic joints hit by a wrecking ball on a chain, at 60 Hz frames (the toolkit's game\n"
		"solver settings). Prints the energy balance measured from the bodies, the joints' plastic energies, the broken\n"
		"joints and the real-time factor (simulated time / wall time of the stepping).\n"
		"  --json  one JSON object on stdout\n"
		"  --joints-csv=PATH  per-joint plastic rotations and energies (CSV)\n"
		"  --history=PATH  energies per frame (CSV)\n";
	return text + scene::usageOf(flags());
}
}  // namespace game
