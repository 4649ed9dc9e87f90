// A section's response to a stress-strain curve (issue 23): the section cut into layers across its depth (bending
// about y, the depth along z, as Section.h names it), each layer's stress from the curve at its strain, summed to the
// axial force and the bending moment. Plane sections stay plane: strain = axial strain + curvature x z.
#pragma once

#include <vector>

#include "Section.h"
#include "StressStrain.h"

namespace plastic
{
struct SectionLayer
{
	double z_m = 0;      // of its middle, from the section's centre
	double area_m2 = 0;  // its thickness times the shape's width there
};

// count layers of equal thickness across the depth (rectangle, notched rectangle, round bar, tube, I section); none for
// a refused section or count < 1
std::vector<SectionLayer> sectionLayers(const SectionProperties& section, int count = 2000);

struct SectionForces
{
	double axial_n = 0;     // tension positive
	double moment_nm = 0;   // about y, positive for positive curvature
};

// the layers' forces at an axial strain and a curvature (1/m)
SectionForces sectionForces(const std::vector<SectionLayer>& layers, const StressStrainCurve& curve, double axial_strain, double curvature_1_m);

struct MomentCurvaturePoint
{
	double curvature_1_m = 0;
	double moment_nm = 0;
};

// M(kappa) without axial force at count + 1 curvatures from 0 to max_curvature_1_m, evenly spaced
std::vector<MomentCurvaturePoint> momentCurvature(const SectionProperties& section, const StressStrainCurve& curve, double max_curvature_1_m,
												  int count = 100, int layers = 2000);
}  // namespace plastic
