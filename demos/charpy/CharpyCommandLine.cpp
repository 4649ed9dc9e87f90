#include "CharpyCommandLine.h"

#include "scene/FlagTable.h"

namespace
{
using scene::parseNumber;

using scene::numberFlag;
using scene::wholeFlag;

const scene::Flags<CharpyParameters>& valueFlags()
{
	static const scene::Flags<CharpyParameters> flags = {
		{"method", {[](CharpyParameters& p, const std::string& text) {
						auto m = parseCharpyMethod(text);
						if (m) p.method = *m;
						return m.has_value();
					},
					"NAME  joining method (see --list-methods), default plastic-hinge"}},
		{"solver", {[](CharpyParameters& p, const std::string& text) { return plastic::parseSolverKind(text, p.solver); },
					"NAME  constraint solver: sequential-impulse (upstream; default), direct (btDirectJointSolver, patch 0019: "
					"the specimen's joints and contacts solved together), dantzig, pgs (btMLCPSolver)"}},
		{"dt", numberFlag(&CharpyParameters::dt_s, "SECONDS  frame step, default 1e-4")},
		{"auto-dt-coarse", numberFlag(&CharpyParameters::auto_dt_coarse_s, "SECONDS  frame far from contact with --auto-dt (or the longest of its halves that reaches none), default 5e-3")},
		{"contact-substep", numberFlag(&CharpyParameters::contact_substep_s, "SECONDS  internal step in/near contact, 0 = off, default 1e-5")},
		{"free-step", numberFlag(&CharpyParameters::free_step_s,
								 "SECONDS  out of contact, gather frames shorter than this into one internal step of up to it (the "
								 "world lags them by less), 0 = a step every frame (default)")},
		{"contact-travel", numberFlag(&CharpyParameters::contact_travel_m,
									  "M  in/near contact, a step longer than the substep where the pairs there move at most this far "
									  "in it (a stalled hammer, a specimen at rest), 0 = off (default); needs --speculative-contacts and "
									  "--solver=direct; their reach, 3e-4, for the halves")},
		{"world-contact-travel", numberFlag(&CharpyParameters::world_contact_travel_m,
											"M  the world cuts each internal step into its own, within which no pair in or near "
											"contact moves more than this (patch 0053; with --contact-substep=0, the world's steps "
											"alone), 0 = off (default); the speculative reach, 3e-4, for the halves")},
		{"world-step", numberFlag(&CharpyParameters::world_step_s,
								  "SECONDS  with --world-contact-travel, the world's fixed step (stepSimulation's fixedTimeStep): "
								  "shorter frames are gathered into it, the world lagging them by less, and the world cuts it by "
								  "its contacts; 0 = each frame is one step (default)")},
		{"ccd-motion-threshold", numberFlag(&CharpyParameters::ccd_motion_threshold_m,
											"M  Bullet's CCD on the specimen's parts: sweep a part moving more than this in a step, 0 = off (default)")},
		{"ccd-swept-radius", numberFlag(&CharpyParameters::ccd_swept_sphere_radius_m, "M  radius of the sphere Bullet's CCD sweeps, default 0")},
		{"iterations", wholeFlag(&CharpyParameters::solver_iterations, "N  solver iterations, default 10")},
		{"duration", numberFlag(&CharpyParameters::duration_s, "SECONDS  simulated time, default 0.06")},
		{"fy", numberFlag(&CharpyParameters::yield_stress_pa, "PA  yield stress, default 400e6")},
		{"youngs-modulus", numberFlag(&CharpyParameters::youngs_modulus_pa, "PA  default 200e9")},
		{"density", numberFlag(&CharpyParameters::density_kg_m3, "KG_M3  default 7800")},
		{"friction", numberFlag(&CharpyParameters::friction, "MU  combined friction of specimen contacts, default 0")},
		{"max-plastic-rotation", numberFlag(&CharpyParameters::max_plastic_rotation_rad, "RAD  breaks plastic joints, default 3")},
		{"parts", wholeFlag(&CharpyParameters::parts, "N  even number of specimen parts, default 2")},
		{"specimen-width", numberFlag(&CharpyParameters::specimen_width_m, "M  default 0.01")},
		{"specimen-length", numberFlag(&CharpyParameters::specimen_length_m, "M  default 0.055")},
		{"notch-depth", numberFlag(&CharpyParameters::notch_depth_m, "M  default 0.002")},
		{"anvil-gap", numberFlag(&CharpyParameters::anvil_gap_m, "M  default 0.04")},
		{"anvil-width", numberFlag(&CharpyParameters::anvil_width_m, "M  default 0.04")},
		{"anvil-radius", numberFlag(&CharpyParameters::anvil_radius_m, "M  radius of the anvils' inner edges (ISO 148-1: 0.001), 0 = sharp (default)")},
		{"anvil-taper", numberFlag(&CharpyParameters::anvil_taper_rad, "RAD  taper of the gap behind rounded edges (ISO 148-1: 0.192), default 0")},
		{"striker-radius", numberFlag(&CharpyParameters::striker_radius_m, "M  striker edge radius, 0 = flat nose (default)")},
		{"hammer-mass", numberFlag(&CharpyParameters::hammer_mass_kg, "KG  default 19.5")},
		{"hammer-thickness", numberFlag(&CharpyParameters::hammer_thickness_m, "M  0 = no hammer, default 0.02")},
		{"draft", numberFlag(&CharpyParameters::hammer_draft_m, "M  striker nose, default 0.04")},
		{"impact-speed", numberFlag(&CharpyParameters::impact_speed_m_s, "M_S  striker speed at impact, 0 = from --release-angle (default)")},
		{"release-angle", {[](CharpyParameters& p, const std::string& text) {
							   p.impact_speed_m_s = 0;  // the hammer starts from this angle instead
							   return parseNumber(text, p.release_angle_rad);
						   },
						   "RAD  release from this angle (instead of --impact-speed), default 2.8"}},
		{"initial-energy", numberFlag(&CharpyParameters::initial_energy_j, "J  hammer energy, overrides --impact-speed and --release-angle")},
		{"brittle-force", numberFlag(&CharpyParameters::brittle_breaking_force_n, "N  breaking force of method brittle, default 2e4")},
		{"min-steps-per-period", numberFlag(&CharpyParameters::min_steps_per_period, "STEPS  per period for elastic DOFs, default 25")},
	};
	return flags;
}
}  // namespace

CharpyCommandLine parseCharpyCommandLine(const std::vector<std::string>& arguments)
{
	CharpyCommandLine cl;
	// --geometry sets several parameters; it is applied first so that other flags refine it in any order
	for (const std::string& argument : arguments)
	{
		if (argument.rfind("--geometry=", 0) != 0)
		{
			continue;
		}
		const std::string value = argument.substr(11);
		if (value == "thesis")
			applyThesisGeometry(cl.parameters);
		else if (value == "standard")
			applyStandardGeometry(cl.parameters);
		else
			cl.errors.push_back("--geometry: '" + value + "' is not valid; expected standard or thesis");
	}
	bool fullDuration = false;
	for (const scene::FlagArgument& flag : scene::splitFlagArguments(arguments, cl.errors))
	{
		if (scene::takeSwitch(flag,
							  {{"help", &cl.help}, {"list-methods", &cl.listMethods}, {"json", &cl.json}, {"auto-dt", &cl.parameters.auto_dt},
							   {"full-duration", &fullDuration}, {"speculative-contacts", &cl.parameters.speculative_contacts},
							   {"box-edges-across-faces", &cl.parameters.box_edges_across_faces},
							   {"contact-turn-prediction", &cl.parameters.contact_turn_prediction}},
							  cl.errors) ||
			scene::takePath(flag, "history", cl.historyPath, cl.errors))
			continue;
		if (flag.name == "geometry")
		{
			if (!flag.hasValue)
				cl.errors.push_back("--geometry needs a value: --geometry=standard|thesis");
		}
		else
			scene::applyFlag(valueFlags(), cl.parameters, flag, cl.errors);
	}
	cl.parameters.end_when_clear = cl.parameters.end_when_clear && !fullDuration;
	if (cl.errors.empty() && !cl.help && !cl.listMethods)
	{
		for (const std::string& e : validateCharpyParameters(cl.parameters))
		{
			cl.errors.push_back(e);
		}
	}
	return cl;
}

std::string charpyUsage()
{
	std::string text =
		"usage: charpy [--method=NAME] [--geometry=standard|thesis] [--json] [--history=FILE.csv] [--auto-dt] [--full-duration] [--speculative-contacts] [--box-edges-across-faces] [--contact-turn-prediction] [--list-methods] [flags]\n"
		"Runs the Charpy impact test scene headless and prints the energy balance. The test ends once the specimen is clear\n"
		"(every part behind the anvils, none able to touch an anvil within a frame), or at --duration;\n"
		"  --full-duration      runs to --duration even after the specimen is clear\n"
		"  --speculative-contacts  box pairs touch before they overlap (patch 0036), so parts do not sink in at coarse steps;\n"
		"                       a step in which the hammer closes more than their reach is warned about (predicted from the settings);\n"
		"                       with them an edge across a face touches it at both ends (as --box-edges-across-faces), so does a\n"
		"                       capsule lying on a face (the striker's edge, an ISO anvil's rounded edge; patch 0051), and the\n"
		"                       world is stepped to the time the striker or a part touches, so a contact's first step starts touching,\n"
		"                       and to the time a part runs off a sharp anvil's edge, so the anvil holds it no longer\n"
		"  --box-edges-across-faces  an edge of a box lying nearly across another's face touches it at both ends (patch 0042),\n"
		"                       not at its deeper end alone as upstream has it (on with --speculative-contacts)\n"
		"  --contact-turn-prediction  contact rows aim at the gap the bodies' turns leave at the step's end (patch 0055),\n"
		"                       not at its linear prediction (on with --world-contact-travel)\n"
		"  --geometry=thesis    (default) the thesis' scene: a flat striker nose as thick as the hammer, released from 2.8 rad\n"
		"  --geometry=standard  the standard machine's striker (ISO 148-1): a 2 mm edge at mid-span, 5.2 m/s\n";
	return text + scene::usageOf(valueFlags());
}
