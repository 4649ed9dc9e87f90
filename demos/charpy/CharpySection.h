// Section properties and the analytic energy loss of the Charpy specimen (thesis 2.2.3).
#pragma once

#include "CharpyParameters.h"

struct CharpySection
{
	double ligament_m;           // h = b - notch: the section depth left at the notch
	double plastic_modulus_m3;   // W = b * h^2 / 4
	double plastic_moment_nm;    // Mp = fy * W
	double hinge_offset_m;       // distance of the hinge axis from the specimen's back (anvil) side
	double theta_pass_rad;       // bend angle at which the halves slip past the anvil edges
	double analytic_loss_j;      // Mp * theta_pass
};

// The hinge sits at mid-ligament: the notch removes the back notch_depth of the section at mid-span and the
// fully plastic ligament rotates about its own centre, notch + h / 2 from the back side (6 mm by default).
// theta_pass: each half (length L/2) pivots on an anvil edge (gap g) with the hinge at offset d from the
// back side; it slips off the edge when g/2 - d sin(phi) = L/2 cos(phi), phi = half the bend angle.
CharpySection computeCharpySection(const CharpyParameters& parameters);
