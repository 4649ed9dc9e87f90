// The one class of the scenes that are built from a parameter struct and measured into a result struct (the
// structures and the wrecking ball), declared once here instead of by each scene: what the runners, the browser's
// examples and the tests hold and step. A scene's header names it, using XScene = scene::Scene<XParameters, XResult>;
// its .cpp defines the State (the scene itself: its bodies, loads and measures, and the methods that the members below
// hand on to, scene/SceneDefinition.h) and makes the class there, once:
//   template <> struct scene::Scene<XParameters, XResult>::State { ... };
//   template class scene::Scene<XParameters, XResult>;
// Only that .cpp sees the members' definitions and the State, so no other file can instantiate them. (The headers do
// not declare the instantiation extern: that would also name the State, which a specialization may not follow, and
// Clang rejects it; declaring the specialization first, as the standard asks, makes GCC 12 warn that it declares
// nothing.)
#pragma once

#include <memory>
#include <vector>

#include "SteppedScene.h"

namespace scene
{
template <class Parameters, class Result>
class Scene final : public SteppedScene
{
public:
	explicit Scene(const Parameters& p);  // may throw std::invalid_argument naming a bad parameter
	~Scene() override;
	void step() override;
	bool done() const override;
	double time_s() const override;
	btDiscreteDynamicsWorld& world() override;
	std::vector<JointView> joints() const override;
	SceneLedger ledger() const override;
	WorldBox viewEnvelope() const override;
	Result result() const;  // measured now

	// the scene itself, defined by each scene's .cpp (complete only there); state() is for that file's free functions
	struct State;
	const State& state() const;

private:
	std::unique_ptr<State> m;
};
}  // namespace scene
