#include "CharpySection.h"

#include <cmath>

CharpySection computeCharpySection(const CharpyParameters& p)
{
	CharpySection s{};
	const double b = p.specimen_width_m;
	s.ligament_m = b - p.notch_depth_m;
	s.plastic_modulus_m3 = b * s.ligament_m * s.ligament_m / 4.0;
	s.plastic_moment_nm = p.yield_stress_pa * s.plastic_modulus_m3;
	s.hinge_offset_m = p.notch_depth_m + s.ligament_m / 2.0;

	const double halfGap = p.anvil_gap_m / 2.0;
	const double halfLength = p.specimen_length_m / 2.0;
	const double d = s.hinge_offset_m;
	// f(phi) = halfGap - d sin(phi) - halfLength cos(phi) rises from halfGap - halfLength < 0 at phi = 0
	// to halfGap - d > 0 at phi = pi/2 (d < halfGap): bisect for its root.
	double lo = 0.0, hi = M_PI / 2.0;
	for (int i = 0; i < 100; i++)
	{
		double mid = 0.5 * (lo + hi);
		double f = halfGap - d * std::sin(mid) - halfLength * std::cos(mid);
		(f < 0 ? lo : hi) = mid;
	}
	s.theta_pass_rad = lo + hi;  // 2 * phi
	s.analytic_loss_j = s.plastic_moment_nm * s.theta_pass_rad;
	return s;
}
