#include "StructuresCommandLine.h"

#include <fstream>
#include <sstream>

#include "scene/FlagTable.h"

namespace structures
{
namespace
{
using scene::parseInteger;
using scene::parseNumber;

bool parseMethod(const std::string& text, plastic::JointMethod& method)
{
	for (plastic::JointMethod m : {plastic::JointMethod::HingeMotor, plastic::JointMethod::PlasticHinge, plastic::JointMethod::ElasticPlastic,
								   plastic::JointMethod::ElasticPlastic2})
		if (text == plastic::jointMethodName(m))
		{
			method = m;
			return true;
		}
	return false;
}

using scene::Flags;
using scene::numberFlag;
using scene::switchFlag;
using scene::wholeFlag;

// the joint method and the world's solver settings
template <class P>
Flags<P> solverFlags()
{
	Flags<P> f;
	f["method"] = {[](P& p, const std::string& t)
				   { return parseMethod(t, p.solver.method); },
				   "NAME  joint method: hinge-motor, plastic-hinge, elastic-plastic, elastic-plastic2; default plastic-hinge"};
	f["solver"] = {[](P& p, const std::string& t)
				   { return plastic::parseSolverKind(t, p.solver.world.solver); },
				   "NAME  constraint solver: direct (btDirectJointSolver, patch 0019: joint rows solved directly along the joint graph; the toolkit default), "
				   "dantzig (btMLCPSolver + btDantzigSolver as upstream constructs them), "
				   "sequential-impulse (upstream's btSequentialImpulseConstraintSolver), pgs (btMLCPSolver + projected Gauss-Seidel)"};
	f["dt"] = {[](P& p, const std::string& t)
			   { return parseNumber(t, p.solver.world.internal_step_s); },
			   "SECONDS  internal step, default 1/240 (four per 60 Hz frame)"};
	f["iterations"] = {[](P& p, const std::string& t)
					   { return parseInteger(t, p.solver.world.iterations); },
					   "N  solver iterations, default 10 (sequential impulse and pgs; direct: the friction passes; dantzig and direct use them only in a step where the direct solve fails)"};
	f["erp"] = {[](P& p, const std::string& t)
				{ return parseNumber(t, p.solver.world.erp); },
				"FRACTION  the joints' error reduction parameter, default 0.2 (Bullet's)"};
	return f;
}

template <class P>
Flags<P> commonFlags()
{
	Flags<P> f = solverFlags<P>();
	f["section-width"] = numberFlag<P>(&P::section_width_m, "M  rectangle along the bending axis, default 0.05");
	f["section-depth"] = numberFlag<P>(&P::section_depth_m, "M  rectangle in the bending plane, default 0.1");
	f["fy"] = numberFlag<P>(&P::yield_stress_pa, "PA  yield stress, default 400e6 (Mp = fy b d^2 / 4 = 50 kN m)");
	f["youngs-modulus"] = numberFlag<P>(&P::youngs_modulus_pa, "PA  default 200e9");
	f["density"] = numberFlag<P>(&P::density_kg_m3, "KG_M3  default 7800");
	f["duration"] = numberFlag(&P::duration_s, "SECONDS  simulated time at most");
	return f;
}

// a comma-separated list of drifts (at least one)
template <class P>
scene::Flag<P> driftListFlag(std::vector<double> P::*member, const char* help)
{
	return {[member](P& p, const std::string& t)
			{
				std::vector<double>& drifts = p.*member;
				drifts.clear();
				std::string item;
				std::istringstream in(t);
				while (std::getline(in, item, ','))
				{
					double d = 0;
					if (!parseNumber(item, d)) return false;
					drifts.push_back(d);
				}
				return !drifts.empty();
			},
			help};
}

template <class P>
void addRampFlags(Flags<P>& f, const char* rateHelp)
{
	f["ramp-rate"] = numberFlag(&P::ramp_rate_per_s, rateHelp);
	f["fast-ramp-rate"] = numberFlag<P>(&P::fast_ramp_rate_per_s, "1/S  load factor rate up to --slow-from, default 0.2");
	f["slow-from"] = numberFlag<P>(&P::slow_from_fraction, "FRACTION  of the plastic-analysis collapse factor where the slow ramp starts, default 0.9");
	f["collapse-rate"] = numberFlag<P>(&P::collapse_rate_rad_s, "RAD_S  a joint turning faster (over --rate-window) is the collapse, default 0.05");
	f["rate-window"] = numberFlag<P>(&P::rate_window_s, "SECONDS  default 0.1");
	f["mechanism-rotation"] = numberFlag<P>(&P::mechanism_rotation_rad, "RAD  a held load that turns the mechanism this far is the collapse, default 0.05");
	f["hold"] = numberFlag<P>(&P::hold_s, "SECONDS  how long the load is held before it rises again, default 2");
}

const Flags<CantileverParameters>& cantileverFlags()
{
	static const Flags<CantileverParameters> flags = []
	{
		using P = CantileverParameters;
		Flags<P> f = commonFlags<P>();
		addRampFlags(f, "1/S  > 0: ramp the load ratio and find the collapse; 0 (default): constant --load-ratio");
		f["length"] = numberFlag(&P::length_m, "M  default 2");
		f["segments"] = wholeFlag(&P::segments, "N  default 4");
		f["load-ratio"] = numberFlag(&P::load_ratio, "P_L_OVER_MP  constant tip load, default 1.5");
		f["follower"] = switchFlag(&P::follower_load, "the load turns with the tip (default: dead load along -y)");
		f["tip-drift"] = numberFlag(&P::tip_drift, "FRACTION  > 0: a pushover, the tip driven down to this times the length (load_ratio in --json: P L / Mp there); default 0");
		f["cyclic-drifts"] = driftListFlag(&P::cyclic_drifts, "D1,D2,...  a cyclic pushover: the tip driven through these drifts (of the length, negative up) in order; cyclic_load_ratios in --json");
		f["drift-rate"] = numberFlag(&P::drift_rate_per_s, "1/S  the pushover's drift per second, default 0.02");
		f["settle"] = numberFlag(&P::settle_s, "SECONDS  the pushover holds its drift this long, default 1");
		f["half-length-support"] = switchFlag(&P::support_joint_half_length, "the support's joint stands for half a segment (elastic stiffness 2 E I / L)");
		// --stress-strain=FILE is read by parseStructuresCommandLine
		f["stress-strain"] = {[](P&, const std::string&) { return true; },
							  "FILE  CSV of (strain, stress in Pa) pairs: elastic-plastic2 joints harden as the section does (its first pair sets E and fy)"};
		return f;
	}();
	return flags;
}

const Flags<PortalParameters>& portalFlags()
{
	static const Flags<PortalParameters> flags = []
	{
		using P = PortalParameters;
		Flags<P> f = commonFlags<P>();
		addRampFlags(f, "1/S  load factor rate from --slow-from on, default 0.02; 0: constant --load-factor");
		f["load-factor"] = numberFlag(&P::load_factor, "LAMBDA  constant load factor when --ramp-rate=0, default 0.9");
		f["span"] = numberFlag(&P::span_m, "M  L, default 4");
		f["height"] = numberFlag(&P::height_m, "M  h, default 3");
		f["column-segments"] = wholeFlag(&P::column_segments, "N  default 2");
		f["beam-segments"] = wholeFlag(&P::beam_segments, "N  even, default 2");
		f["horizontal-load"] = numberFlag(&P::horizontal_load_n, "N  H at the left knee at load factor 1, default 50e3");
		f["vertical-load"] = numberFlag(&P::vertical_load_n, "N  V at mid-span at load factor 1, default 75e3");
		f["knee-load"] = numberFlag(&P::knee_load_n, "N  gravity: a dead load down at each knee, raised over --knee-load-ramp, then held; default 0");
		f["knee-load-ramp"] = numberFlag(&P::knee_load_ramp_s, "SECONDS  default 1");
		f["sway-drifts"] = driftListFlag(&P::sway_drifts, "D1,D2,...  a sway pushover instead of H and V: the left knee driven along x through these drifts (of h) once the knee loads are on; sway_load_ratios (H h / 4 Mp) in --json");
		f["drift-rate"] = numberFlag(&P::drift_rate_per_s, "1/S  the sway pushover's drift per second, default 0.02");
		f["settle"] = numberFlag(&P::settle_s, "SECONDS  the sway pushover holds its last drift this long, default 1");
		return f;
	}();
	return flags;
}

const Flags<DropWeightParameters>& dropWeightFlags()
{
	static const Flags<DropWeightParameters> flags = []
	{
		using P = DropWeightParameters;
		Flags<P> f = commonFlags<P>();
		f["clamped"] = switchFlag(&P::clamped, "both ends clamped by plastic joints (default: simply supported)");
		f["span"] = numberFlag(&P::span_m, "M  L, default 2");
		f["segments"] = wholeFlag(&P::segments, "N  even, default 2");
		f["weight-mass"] = numberFlag(&P::weight_mass_kg, "KG  G, default 1000");
		f["weight-radius"] = numberFlag(&P::weight_radius_m, "M  default 0.05");
		f["impact-speed"] = numberFlag(&P::impact_speed_m_s, "M_S  v0, default 4.5");
		f["full-duration"] = switchFlag(&P::run_to_duration, "runs to --duration after the beam has stopped (default: the run ends there)");
		return f;
	}();
	return flags;
}

const Flags<PaperClipParameters>& paperClipFlags()
{
	static const Flags<PaperClipParameters> flags = []
	{
		using P = PaperClipParameters;
		Flags<P> f = solverFlags<P>();
		f["fy"] = numberFlag(&P::yield_stress_pa, "PA  yield stress, default 400e6 (Mp = fy d^3 / 6)");
		f["youngs-modulus"] = numberFlag(&P::youngs_modulus_pa, "PA  default 200e9");
		f["density"] = numberFlag(&P::density_kg_m3, "KG_M3  default 7800");
		f["duration"] = numberFlag(&P::duration_s, "SECONDS  simulated time at most, default 30");
		f["wire-diameter"] = numberFlag(&P::wire_diameter_m, "M  d, default 1e-3");
		f["leg-length"] = numberFlag(&P::leg_length_m, "M  the bent leg, default 0.03");
		f["amplitude"] = numberFlag(&P::bend_amplitude_rad, "RAD  A: bent to +-A, in (0, pi/2], default 0.785398 (45 degrees)");
		f["period"] = numberFlag(&P::cycle_period_s, "SECONDS  T of one full cycle, default 1");
		f["reduction-of-area"] = numberFlag(&P::reduction_of_area, "FRACTION  the wire's, in (0, 1): Coffin-Manson by universal slopes, default 0.6");
		f["hinge-length"] = numberFlag(&P::hinge_length_m, "M  Lp, the bend's plastic length, default 2e-3");
		// --hysteresis=FILE is read by parseStructuresCommandLine
		f["hysteresis"] = {[](P&, const std::string&) { return true; }, "FILE  write the moment-rotation loops as an SVG plot (whole or not at all)"};
		return f;
	}();
	return flags;
}

}  // namespace

StructuresCommandLine parseStructuresCommandLine(const std::vector<std::string>& arguments)
{
	StructuresCommandLine cl;
	std::vector<scene::FlagArgument> flags;
	for (const scene::FlagArgument& flag : scene::splitFlagArguments(arguments, cl.errors))
	{
		if (scene::takeSwitch(flag, {{"help", &cl.help}, {"json", &cl.json}}, cl.errors))
			continue;
		if (flag.name != "scene")
			flags.push_back(flag);
		else if (flag.value == "cantilever" || flag.value == "portal" || flag.value == "drop-weight" || flag.value == "paper-clip")
			cl.scene = flag.value;
		else
			cl.errors.push_back("--scene: '" + flag.value + "' is not valid; expected one of cantilever, portal, drop-weight, paper-clip");
	}
	if (cl.help) return cl;
	if (cl.scene.empty() && cl.errors.empty())
	{
		cl.errors.push_back("--scene: missing; expected one of cantilever, portal, drop-weight, paper-clip");
		return cl;
	}
	const std::string context = " for --scene=" + cl.scene;
	for (const scene::FlagArgument& flag : flags)
	{
		if (cl.scene == "cantilever") scene::applyFlag(cantileverFlags(), cl.cantilever, flag, cl.errors, context);
		if (cl.scene == "cantilever" && flag.name == "stress-strain" && flag.hasValue)
		{
			std::ifstream file(flag.value);
			std::ostringstream text;
			text << file.rdbuf();
			if (!file)
			{
				cl.errors.push_back("--stress-strain: cannot read '" + flag.value + "'");
				continue;
			}
			std::vector<std::string> curveErrors;
			const plastic::StressStrainCurve curve = plastic::parseStressStrainCsv(text.str(), curveErrors);
			for (const std::string& e : curveErrors) cl.errors.push_back("--stress-strain " + flag.value + ": " + e);
			if (curveErrors.empty()) cl.cantilever.stress_strain = curve;
		}
		if (cl.scene == "portal") scene::applyFlag(portalFlags(), cl.portal, flag, cl.errors, context);
		if (cl.scene == "drop-weight") scene::applyFlag(dropWeightFlags(), cl.dropWeight, flag, cl.errors, context);
		if (cl.scene == "paper-clip")
		{
			scene::applyFlag(paperClipFlags(), cl.paperClip, flag, cl.errors, context);
			if (flag.name == "hysteresis")
			{
				if (flag.value.empty())
					cl.errors.push_back("--hysteresis: needs a file name (--hysteresis=FILE.svg)");
				else
					cl.hysteresisPath = flag.value;
			}
		}
	}
	if (!cl.errors.empty()) return cl;
	std::vector<std::string> invalid;
	if (cl.scene == "cantilever") invalid = validateCantileverParameters(cl.cantilever);
	if (cl.scene == "portal") invalid = validatePortalParameters(cl.portal);
	if (cl.scene == "drop-weight") invalid = validateDropWeightParameters(cl.dropWeight);
	if (cl.scene == "paper-clip") invalid = validatePaperClipParameters(cl.paperClip);
	cl.errors.insert(cl.errors.end(), invalid.begin(), invalid.end());
	return cl;
}

std::string structuresUsage()
{
	return "usage: structures --scene=cantilever|portal|drop-weight|paper-clip [--json] [flags]\n"
		   "Runs a structure with a textbook answer headless and prints the simulated result beside the answer.\n"
		   "--scene=cantilever: a tip-loaded cantilever (collapse at P = Mp / L; a dead load above it stops where\n"
		   "P L sin(theta) = Mp theta)\n" +
		   scene::usageOf(cantileverFlags()) +
		   "--scene=portal: a fixed-base portal frame under H at the left knee and V at mid-span, the load factor\n"
		   "ramped until it collapses (beam V L/2 = 4 Mp, sway H h = 4 Mp, combined H h + V L/2 = 6 Mp); or, with\n"
		   "--sway-drifts, a sway pushover under --knee-load against the second-order rigid-plastic\n"
		   "H h / 4 Mp = (1 - 2 P h d / 4 Mp) / sqrt(1 - d^2)\n" +
		   scene::usageOf(portalFlags()) +
		   "--scene=drop-weight: a ball strikes a simply supported or clamped beam at mid-span (kinetic energy\n"
		   "after the impact = Mp x sum of hinge rotations)\n" +
		   scene::usageOf(dropWeightFlags()) +
		   "--scene=paper-clip: a steel wire bent back and forth through +-A by a hand until it breaks by low-cycle\n"
		   "fatigue (Coffin-Manson with Miner's rule over the joint's plastic half-cycles; the answer is the\n"
		   "rigid-plastic joint's, whose plastic rotation is the driven one)\n" +
		   scene::usageOf(paperClipFlags());
}
}  // namespace structures
