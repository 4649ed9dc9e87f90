// What build/bin/wrecking_ball prints and writes: JSON, a summary, the per-joint CSV and the per-frame history CSV.
#pragma once

#include <string>

#include "WreckingBall.h"

namespace game
{
std::string toJson(const WreckingBallParameters& p, const WreckingBallResult& r);
std::string toSummary(const WreckingBallParameters& p, const WreckingBallResult& r);
std::string jointsCsv(const WreckingBallResult& r);
std::string historyHeader();
std::string historyRow(double time_s, const WreckingBallResult& r);
}  // namespace game
