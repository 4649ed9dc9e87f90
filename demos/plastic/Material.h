// An isotropic elastic-perfectly-plastic material, with its units in every name.
#pragma once

#include <cmath>

namespace plastic
{
struct Material
{
	double youngs_modulus_pa = 200e9;
	double poisson_ratio = 0.3;
	double yield_stress_pa = 400e6;
	double density_kg_m3 = 7800.0;

	double shearModulus_pa() const { return youngs_modulus_pa / (2.0 * (1.0 + poisson_ratio)); }
	// von Mises: a section yields in pure shear at fy / sqrt(3)
	double shearYieldStress_pa() const { return yield_stress_pa / std::sqrt(3.0); }
};

// Steel as the thesis and the Charpy scene use it: E 200 GPa, nu 0.3, fy 400 MPa, 7800 kg/m^3.
inline Material steel() { return Material{}; }
}  // namespace plastic
