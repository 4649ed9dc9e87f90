// The runner's output of each scene: one JSON object on one line, or a few lines for people.
#pragma once

#include <string>

#include "Cantilever.h"
#include "DropWeight.h"
#include "PaperClip.h"
#include "Portal.h"

namespace structures
{
std::string toJson(const CantileverParameters& p, const CantileverResult& r);
std::string toJson(const PortalParameters& p, const PortalResult& r);
std::string toJson(const DropWeightParameters& p, const DropWeightResult& r);
std::string toSummary(const CantileverParameters& p, const CantileverResult& r);
std::string toSummary(const PortalParameters& p, const PortalResult& r);
std::string toSummary(const DropWeightParameters& p, const DropWeightResult& r);
std::string toJson(const PaperClipParameters& p, const PaperClipResult& r);
std::string toSummary(const PaperClipParameters& p, const PaperClipResult& r);
// The paper clip's moment-rotation loops as an SVG plot (moment / Mp against rotation, rad)
std::string hysteresisSvg(const PaperClipParameters& p, const PaperClipResult& r);
}  // namespace structures
