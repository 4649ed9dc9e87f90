// The moment-rotation law of a plastic hinge from a section and a stress-strain curve (issue 23, "joints that
// harden"): the section's moment-curvature relation (SectionResponse) turned into rotation by a hinge length,
// theta = kappa x L_p, and cut into parallel elastic-perfectly plastic layers for
// bt6DofElasticPlastic2Constraint::setHardeningLayers. Loaded, the layers yield one after the other and follow the
// section's curve (the rounding between first yield and the plastic moment, then the curve's hardening); reversed,
// they follow Masing's rule, the cyclic response of a section whose fibres yield from the outside in (kinematic
// hardening, the Bauschinger effect).
//
// The hinge length: a joint of a jointed member stands for the curvature of the length of member around it, the same
// length its elastic stiffness E I / L uses (JointSpec::segment_length_m): a whole segment between two segments, half
// of one at a support (BeamSpec::support_joint_half_length). Nothing is fitted: the plastic zone of a moment gradient
// is spread over the joints the member has, and the joints' laws converge to the member's as its segments get shorter.
#pragma once

#include <string>
#include <vector>

#include "Section.h"
#include "StressStrain.h"

namespace plastic
{
struct HingeLayer
{
	double stiffness_nm_rad = 0;
	double max_moment_nm = 0;  // infinite for the layer that stays elastic (the curve's last tangent)
};

struct HingeLaw
{
	double hinge_length_m = 0;
	std::vector<HingeLayer> layers;
	double max_error_fraction = 0;  // of the layers' moment from the section's, at the curvatures sampled, over its largest
	std::string error;              // empty for a law that can be used; else why not
};

// The layers (at most max_layers, 2 to 16, bt6DofElasticPlastic2Constraint::MAX_HARDENING_LAYERS) of the section's
// moment about y under the curve, for a hinge of hinge_length_m: the moment-curvature curve sampled from first yield to
// 100 times its curvature and reduced to the corners that keep it closest, the last tangent an elastic layer. Refused
// (error set, no layers): a refused section or curve, a hinge length <= 0, a curve whose moment-curvature tangents
// rise somewhere (a yield plateau followed by hardening: layers can only soften).
HingeLaw hingeLaw(const SectionProperties& section, const StressStrainCurve& curve, double hinge_length_m, int max_layers = 16);

// the law's moment (N m) at a rotation (rad) loaded monotonically from rest
double hingeMoment_nm(const HingeLaw& law, double rotation_rad);
}  // namespace plastic
