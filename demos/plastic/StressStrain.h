// A material's stress-strain curve as (strain, stress) pairs (thesis 4.1.4: "material definition should be defined so
// that stress-strain curve can be defined as array of pairs"), the same in tension and compression. Elastic-perfectly
// plastic and bilinear (hardening) materials are special cases. Curves are checked, not trusted: validate() names the
// first bad pair.
#pragma once

#include <string>
#include <vector>

#include "Material.h"

namespace plastic
{
struct StressStrainPair
{
	double strain = 0;     // engineering strain (m/m)
	double stress_pa = 0;  // at that strain
};

// The curve through the origin and its pairs, in order of strain; between them stress is linear in strain, past the
// last pair it stays at the last stress (the material does not break here: a rotation or damage limit breaks joints).
struct StressStrainCurve
{
	std::vector<StressStrainPair> pairs;
};

// One message per bad curve, naming the pair (counted from 1) and what is wrong: at least one pair; strains finite,
// above 0 and increasing; stresses finite, above 0 and not decreasing (a monotonic curve); the first pair's slope (its
// Young's modulus) the steepest, so that the first pair is where yielding starts.
std::vector<std::string> validate(const StressStrainCurve& curve);

// stress (Pa) at a strain, of either sign (odd: -strain gives -stress)
double stress_pa(const StressStrainCurve& curve, double strain);

// the yield stress (Pa) and strain of the curve: its first pair
double yieldStress_pa(const StressStrainCurve& curve);
double yieldStrain(const StressStrainCurve& curve);

// E up to fy, then flat: the toolkit's Material as a curve (to ultimate_strain)
StressStrainCurve elasticPerfectlyPlastic(double youngs_modulus_pa, double yield_stress_pa, double ultimate_strain = 0.2);
inline StressStrainCurve elasticPerfectlyPlastic(const Material& m, double ultimate_strain = 0.2)
{
	return elasticPerfectlyPlastic(m.youngs_modulus_pa, m.yield_stress_pa, ultimate_strain);
}
// E up to fy, then hardening_ratio x E to ultimate_strain (hardening_ratio in [0, 1))
StressStrainCurve bilinear(double youngs_modulus_pa, double yield_stress_pa, double hardening_ratio, double ultimate_strain = 0.2);

// A curve from CSV text (a file's contents): one pair a line, "strain,stress_pa" (SI: strain in m/m, stress in Pa), a
// header line of names first if any, '#' comments and blank lines skipped. A line that is not two numbers is an error
// naming its line; the curve is then checked by validate (errors name the pair). No pairs kept when there are errors.
StressStrainCurve parseStressStrainCsv(const std::string& text, std::vector<std::string>& errors);
}  // namespace plastic
