// Numerical-stability verdict of one Charpy run (the stability matrix of the stiff and extreme
// cases): the first of these that applies, in this order.
#pragma once

#include <string>
#include <string_view>

#include "CharpyRun.h"

enum class CharpyVerdict
{
	NotFinite,   // a NaN or infinity in a body state
	BlowUp,      // a body faster than max(100 m/s, 20 x impact speed) or farther than 20 m from the origin
	EnergyGain,  // total energy rose more than 1 % of E0 above E0
	Tunnelling,  // a rigid specimen got past the anvils (it cannot without penetrating them), or the
	             // hammer swung on past the specimen (more than 0.05 rad) losing less than 5 % of
	             // Mp * theta_pass: through the specimen, or the specimen through the anvils, without the work
	CameApart,   // a specimen whose joints book their work (methods 6-8) got past the anvils unbroken, its end
	             // parts turned less than half of theta_pass relative to each other, and its joints booked less
	             // than half of the energy lost as plastic work: neither bent nor sheared plastically, so its
	             // joints let go in the solver (an unconverged chain, e.g. many light parts under the hammer)
	Stable,
};

// Name used in the JSON and the stability report: "nan", "blow-up", "energy-gain", "tunnelling",
// "came-apart", "stable".
std::string_view charpyVerdictName(CharpyVerdict verdict);

// why: the numbers behind the verdict, e.g. "max speed 412 m/s > 100 m/s".
CharpyVerdict classifyCharpyRun(const CharpyResult& result, std::string* why = nullptr);
