// The paper clip's parameters checked, and its answer from Coffin-Manson and Miner's rule on the driven angle.
#include <cmath>
#include <limits>
#include <sstream>

#include "PaperClip.h"

namespace structures
{
namespace
{
const double kPi = 3.14159265358979323846;
}

std::vector<std::string> validatePaperClipParameters(const PaperClipParameters& p)
{
	std::vector<std::string> errors = scene::validateSolverSettings(p.solver);
	auto check = [&errors](bool ok, const char* name, double value, const char* range)
	{
		if (ok) return;
		std::ostringstream out;
		out << name << ": " << value << " is not in " << range;
		errors.push_back(out.str());
	};
	auto positive = [](double v) { return v > 0 && std::isfinite(v); };
	check(positive(p.wire_diameter_m), "wire diameter", p.wire_diameter_m, "(0, inf) m");
	check(positive(p.leg_length_m) && p.leg_length_m > p.wire_diameter_m, "leg length", p.leg_length_m, "(wire diameter, inf) m");
	check(positive(p.yield_stress_pa), "yield stress", p.yield_stress_pa, "(0, inf) Pa");
	check(positive(p.youngs_modulus_pa), "Young's modulus", p.youngs_modulus_pa, "(0, inf) Pa");
	check(positive(p.density_kg_m3), "density", p.density_kg_m3, "(0, inf) kg/m^3");
	check(p.bend_amplitude_rad > 0 && p.bend_amplitude_rad <= kPi / 2, "bend amplitude", p.bend_amplitude_rad, "(0, pi/2] rad");
	check(positive(p.cycle_period_s) && p.cycle_period_s >= 20 * p.solver.world.internal_step_s, "cycle period", p.cycle_period_s,
		  "[20 internal steps, inf) s");
	check(p.reduction_of_area > 0 && p.reduction_of_area < 1, "reduction of area", p.reduction_of_area, "(0, 1)");
	check(positive(p.hinge_length_m), "hinge length", p.hinge_length_m, "(0, inf) m");
	check(positive(p.duration_s), "duration", p.duration_s, "(0, inf) s");
	if (errors.empty())
	{
		const std::vector<std::string> joint = plastic::validate(paperClipJointSpec(p));
		errors.insert(errors.end(), joint.begin(), joint.end());
	}
	return errors;
}

plastic::JointSpec paperClipJointSpec(const PaperClipParameters& p)
{
	plastic::JointSpec spec;
	spec.method = p.solver.method;
	spec.pivot_m = btVector3(0, 0, 0);
	// bending about z, the wire along x: columns z, -y, x (right-handed)
	spec.basis = btMatrix3x3(0, 0, 1, 0, -1, 0, 1, 0, 0);
	spec.section = plastic::roundBar(p.wire_diameter_m);
	spec.material.yield_stress_pa = p.yield_stress_pa;
	spec.material.youngs_modulus_pa = p.youngs_modulus_pa;
	spec.material.density_kg_m3 = p.density_kg_m3;
	spec.segment_length_m = p.hinge_length_m;  // the elastic joint's stiffness E I / Lp: the bend's own length
	spec.fatigue = plastic::universalSlopesFatigue(p.reduction_of_area, p.hinge_length_m);
	return spec;
}

PaperClipAnswer paperClipAnswer(const PaperClipParameters& p)
{
	PaperClipAnswer a;
	const plastic::JointSpec spec = paperClipJointSpec(p);
	a.plastic_moment_nm = p.yield_stress_pa * std::pow(p.wire_diameter_m, 3) / 6;
	a.ductility_rotation_rad = plastic::fatigueDuctilityRotation_rad(spec);
	a.ductility_exponent = spec.fatigue->ductility_exponent;
	const double A = p.bend_amplitude_rad, T = p.cycle_period_s;
	auto damage = [&a](double range) { return std::pow(range / (2 * a.ductility_rotation_rad), -1 / a.ductility_exponent); };
	// the first quarter period turns A, every half period after it 2A: the half-cycle that takes the sum to 1 turns
	// x = what is left of the life as a range, from an extreme where the angle is +-A cos(2 pi tau / T)
	double used = damage(A);
	double time_s = T / 4;
	if (used >= 1)
	{
		const double x = 2 * a.ductility_rotation_rad;  // damage(x) = 1
		a.break_time_s = std::asin(x / A) * T / (2 * kPi);
	}
	else
	{
		const double half = damage(2 * A);
		const double whole = std::floor((1 - used) / half);
		if (whole > 2e6)
			a.break_time_s = std::numeric_limits<double>::infinity();
		else
		{
			used += whole * half;
			time_s += whole * T / 2;
			const double x = 2 * a.ductility_rotation_rad * std::pow(1 - used, -a.ductility_exponent);
			a.break_time_s = time_s + std::acos(1 - x / A) * T / (2 * kPi);
		}
	}
	a.cycles_to_break = a.break_time_s / T;
	const double strainAmplitude = A * p.wire_diameter_m / (2 * p.hinge_length_m);
	a.constant_amplitude_cycles = 0.5 * std::pow(strainAmplitude / spec.fatigue->ductility_coefficient, 1 / a.ductility_exponent);
	return a;
}
}  // namespace structures
