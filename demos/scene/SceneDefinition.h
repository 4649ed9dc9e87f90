// scene::Scene's members (scene/Scene.h), each handing on to the scene's State. Only a scene's .cpp includes this,
// and instantiates the class at its end, once its State is defined:
//   template class scene::Scene<XParameters, XResult>;
// No other file sees these definitions, so the class is made once, where its State is complete.
#pragma once

#include <memory>
#include <vector>

#include "Scene.h"

namespace scene
{
template <class Parameters, class Result>
Scene<Parameters, Result>::Scene(const Parameters& p) : m(std::make_unique<State>(p))
{
}

// here, where State is complete: the unique_ptr deletes it
template <class Parameters, class Result>
Scene<Parameters, Result>::~Scene() = default;

template <class Parameters, class Result>
void Scene<Parameters, Result>::step()
{
	m->step();
}

template <class Parameters, class Result>
bool Scene<Parameters, Result>::done() const
{
	return m->done();
}

template <class Parameters, class Result>
double Scene<Parameters, Result>::time_s() const
{
	return m->time_s();
}

template <class Parameters, class Result>
btDiscreteDynamicsWorld& Scene<Parameters, Result>::world()
{
	return m->world();
}

template <class Parameters, class Result>
std::vector<JointView> Scene<Parameters, Result>::joints() const
{
	return m->joints();
}

template <class Parameters, class Result>
SceneLedger Scene<Parameters, Result>::ledger() const
{
	return m->ledger();
}

template <class Parameters, class Result>
WorldBox Scene<Parameters, Result>::viewEnvelope() const
{
	return m->viewEnvelope();
}

template <class Parameters, class Result>
Result Scene<Parameters, Result>::result() const
{
	return m->result();
}

template <class Parameters, class Result>
const typename Scene<Parameters, Result>::State& Scene<Parameters, Result>::state() const
{
	return *m;
}
}  // namespace scene
