// Numerical-stability verdict of one Charpy run (the stability matrix of the stiff and extreme
// cases): the first of these that applies, in this order.
#pragma once

#include <string>
#include <string_view>

#include "CharpyRun.h"

enum class CharpyVerdict
{
	NotFinite,   // a NaN or infinity in a body state
	BlowUp,      // a body faster than max(100 m/s, 20 x impact speed) or farther from the origin than that
	             // speed carries it in the run's time (end_time_s), and than 20 m
	EnergyGain,  // total energy, or total energy plus the plastic work booked, rose more than 1 % of E0 above E0
	Tunnelling,  // the unbroken specimen got past the anvils bent less than it must be to fit the gap (through
	             // them), or the hammer swung on past the specimen (more than 0.05 rad) losing less than 5 % of
	             // Mp * theta_pass: through the specimen, or the specimen through the anvils, without the work
	CameApart,   // a specimen whose joints book their work (methods 6-8) got past the anvils unbroken, its end
	             // parts turned less than half of theta_pass relative to each other, and its joints booked less
	             // than half of the energy lost as plastic work: neither bent nor sheared plastically, so its
	             // joints let go in the solver (an unconverged chain, e.g. many light parts under the hammer);
	             // or, when it got behind the anvils, its end parts had turned more than a quarter of theta_pass
	             // beyond the plastic rotation its joints had booked (in all their angular DOFs): a bend no joint
	             // yielded for
	Stable,
};

// Name used in the JSON and the stability report: "nan", "blow-up", "energy-gain", "tunnelling",
// "came-apart", "stable".
std::string_view charpyVerdictName(CharpyVerdict verdict);

// why: the numbers behind the verdict, e.g. "max speed 412 m/s > 100 m/s".
CharpyVerdict classifyCharpyRun(const CharpyResult& result, std::string* why = nullptr);

// Accuracy of a stable run, which stability alone does not tell: the first of these that applies.
enum class CharpyAccuracy
{
	Unstable,     // the stability verdict is not "stable"
	DidNotPass,   // the unbroken specimen is still in front of the anvils at the end (jammed, or too little energy)
	OverTheTop,   // it got behind the anvils over their top, not through the gap
	Penetrated,   // a contact penetrated more than 10 % of the specimen's width (the loss is then not the bending's)
	Accurate,
};

// Name used in the JSON and the stability report: "unstable", "did-not-pass", "over-the-top", "penetrated",
// "accurate".
std::string_view charpyAccuracyName(CharpyAccuracy accuracy);

// why: the numbers behind it, e.g. "max penetration 3.5 mm > 1 mm (10 % of the specimen width)".
CharpyAccuracy classifyCharpyAccuracy(const CharpyResult& result, std::string* why = nullptr);
