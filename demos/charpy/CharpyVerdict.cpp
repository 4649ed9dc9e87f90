#include "CharpyVerdict.h"

#include <algorithm>
#include <cstdio>

namespace
{
// farther from the origin than a body at the speed limit gets in the run's time, and at least this
const double kMinDistanceLimit_m = 20.0;
const double kMinSpeedLimit_m_s = 100.0;
const double kSpeedLimitPerImpactSpeed = 20.0;
const double kEnergyGainFraction = 0.01;
const double kTunnellingLossFraction = 0.05;
const double kHammerThroughAngle_rad = 0.05;  // about 30 mm of striker travel past the specimen's front face
const double kCameApartBendFraction = 0.5;    // of theta_pass, end to end
const double kCameApartWorkFraction = 0.5;    // of the energy lost
const double kUnbookedBendFraction = 0.25;    // of theta_pass: end-to-end bend beyond the joints' plastic rotation
const double kPenetrationWidthFraction = 0.1; // of the specimen's width

std::string format(const char* pattern, double a, double b)
{
	char text[160];
	std::snprintf(text, sizeof(text), pattern, a, b);
	return text;
}
}  // namespace

std::string_view charpyVerdictName(CharpyVerdict verdict)
{
	switch (verdict)
	{
		case CharpyVerdict::NotFinite:
			return "nan";
		case CharpyVerdict::BlowUp:
			return "blow-up";
		case CharpyVerdict::EnergyGain:
			return "energy-gain";
		case CharpyVerdict::Tunnelling:
			return "tunnelling";
		case CharpyVerdict::CameApart:
			return "came-apart";
		case CharpyVerdict::Stable:
			return "stable";
	}
	return "?";
}

CharpyVerdict classifyCharpyRun(const CharpyResult& r, std::string* why)
{
	std::string reason;
	CharpyVerdict verdict = CharpyVerdict::Stable;
	const double speedLimit_m_s = std::max(kMinSpeedLimit_m_s, kSpeedLimitPerImpactSpeed * r.impact_speed_m_s);
	// a half thrown from between the striker and an anvil at 54 m/s flies about 400 m/s, 24 m in 60 ms, in its converged
	// run too (2 us substeps with patch 0055's turn prediction): a fixed 20 m would call that a blow-up where the speed
	// limit (1078 m/s) does not
	const double distanceLimit_m = std::max(kMinDistanceLimit_m, speedLimit_m_s * r.end_time_s);
	if (!r.finite)
	{
		verdict = CharpyVerdict::NotFinite;
		reason = "a body state is NaN or infinite";
	}
	else if (r.max_speed_m_s > speedLimit_m_s)
	{
		verdict = CharpyVerdict::BlowUp;
		reason = format("max speed %.3g m/s > %.3g m/s", r.max_speed_m_s, speedLimit_m_s);
	}
	else if (r.max_distance_m > distanceLimit_m)
	{
		verdict = CharpyVerdict::BlowUp;
		reason = format("max distance %.3g m > %.3g m", r.max_distance_m, distanceLimit_m);
	}
	else if (r.max_energy_gain_J > kEnergyGainFraction * r.E0_J)
	{
		verdict = CharpyVerdict::EnergyGain;
		reason = format("energy rose %.3g J above E0 = %.4g J", r.max_energy_gain_J, r.E0_J);
	}
	else if (r.joints_book_work && r.max_booked_excess_J > kEnergyGainFraction * r.E0_J)
	{
		// the world's energy plus the plastic work its joints dissipated rose above E0: the joints booked flow that no
		// force paid for, energy made as surely as a body's
		verdict = CharpyVerdict::EnergyGain;
		reason = format("the joints booked %.3g J of plastic work beyond the energy lost (more than 1 %% of E0 = %.4g J)",
						r.max_booked_excess_J, r.E0_J);
	}
	else if (r.impact_speed_m_s > 0 && r.hammer_angle_end_rad < -kHammerThroughAngle_rad &&
			 r.energy_loss_J < kTunnellingLossFraction * r.analytic_J)
	{
		verdict = CharpyVerdict::Tunnelling;
		reason = format("the hammer swung through losing %.3g J < 5 %% of Mp*theta_pass = %.4g J", r.energy_loss_J, r.analytic_J);
	}
	else if (r.joints_book_work && r.passed_anvils && !r.broken && r.end_bend_angle_rad < kCameApartBendFraction * r.theta_pass_rad &&
			 r.plastic_work_J < kCameApartWorkFraction * r.energy_loss_J)
	{
		verdict = CharpyVerdict::CameApart;
		reason = format("the unbroken specimen passed the anvils bent %.3g rad end to end (theta_pass %.3g rad)",
						r.end_bend_angle_rad, r.theta_pass_rad) +
				 format(" with %.3g J of plastic work for %.4g J lost", r.plastic_work_J, r.energy_loss_J);
	}
	else if (r.joints_book_work && r.passed_anvils && !r.broken &&
			 r.pass_end_bend_angle_rad - r.pass_plastic_rotation_rad > kUnbookedBendFraction * r.theta_pass_rad)
	{
		// the joints' elastic turn at their caps is a few hundredths of a radian end to end; taken when the specimen got
		// behind the anvils, not after its flight
		verdict = CharpyVerdict::CameApart;
		reason = format("the unbroken specimen got behind the anvils bent %.3g rad end to end, but its joints had booked %.3g rad of plastic rotation",
						r.pass_end_bend_angle_rad, r.pass_plastic_rotation_rad) +
				 format(" (%.3g J of plastic work for %.4g J lost)", r.plastic_work_J, r.energy_loss_J);
	}
	else if (r.tunnelled)
	{
		verdict = CharpyVerdict::Tunnelling;
		reason = format("the unbroken specimen passed the anvils bent at most %.3g rad, below the %.3g rad it needs to fit the gap",
						r.max_bend_rad, r.min_pass_bend_rad) +
				 format(" (max penetration %.3g mm, loss %.4g J)", r.max_penetration_m * 1e3, r.energy_loss_J);
	}
	else
	{
		reason = format("energy loss %.4g J, max energy gain %.3g J", r.energy_loss_J, r.max_energy_gain_J);
	}
	if (why) *why = reason;
	return verdict;
}

std::string_view charpyAccuracyName(CharpyAccuracy accuracy)
{
	switch (accuracy)
	{
		case CharpyAccuracy::Unstable:
			return "unstable";
		case CharpyAccuracy::DidNotPass:
			return "did-not-pass";
		case CharpyAccuracy::OverTheTop:
			return "over-the-top";
		case CharpyAccuracy::Penetrated:
			return "penetrated";
		case CharpyAccuracy::Accurate:
			return "accurate";
	}
	return "?";
}

CharpyAccuracy classifyCharpyAccuracy(const CharpyResult& r, std::string* why)
{
	std::string stability;
	std::string reason;
	CharpyAccuracy accuracy = CharpyAccuracy::Accurate;
	const double penetrationLimit_m = kPenetrationWidthFraction * r.specimen_width_m;
	if (classifyCharpyRun(r, &stability) != CharpyVerdict::Stable)
	{
		accuracy = CharpyAccuracy::Unstable;
		reason = stability;
	}
	else if (!r.passed_anvils && !r.broken)
	{
		accuracy = CharpyAccuracy::DidNotPass;
		reason = format("the specimen is still in front of the anvils, bent at most %.3g rad (it needs %.3g rad)", r.max_bend_rad,
						r.min_pass_bend_rad);
	}
	else if (r.over_the_top)
	{
		accuracy = CharpyAccuracy::OverTheTop;
		reason = format("a part got behind the anvils above their top (loss %.4g J, max bend %.3g rad)", r.energy_loss_J, r.max_bend_rad);
	}
	else if (r.max_penetration_m > penetrationLimit_m)
	{
		accuracy = CharpyAccuracy::Penetrated;
		reason = format("max penetration %.3g mm > %.3g mm (10 %% of the specimen width)", r.max_penetration_m * 1e3, penetrationLimit_m * 1e3);
	}
	else
	{
		reason = format("max penetration %.3g mm, max bend %.3g rad", r.max_penetration_m * 1e3, r.max_bend_rad);
	}
	if (why) *why = reason;
	return accuracy;
}
