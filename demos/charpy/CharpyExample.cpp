// The Charpy example: sliders and a method choice build CharpyParameters, CharpyScene does the
// physics, the browser draws the world. Rendering only reads the world.
#include "CharpyExample.h"

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "btBulletDynamicsCommon.h"
#include "CommonInterfaces/CommonExampleInterface.h"
#include "CommonInterfaces/CommonGUIHelperInterface.h"
#include "CommonInterfaces/CommonGraphicsAppInterface.h"
#include "CommonInterfaces/CommonParameterInterface.h"
#include "CommonInterfaces/CommonRenderInterface.h"

#include "CharpyControls.h"
#include "CharpyScene.h"
#include "CharpyView.h"

namespace
{
const char* kMethodNames[kCharpyMethodCount];

class CharpyExample : public CommonExampleInterface
{
public:
	CharpyExample(GUIHelperInterface* guiHelper, int methodNumber)
		: m_guiHelper(guiHelper), m_method(methodNumber >= 1 && methodNumber <= kCharpyMethodCount ? methodNumber : 6)
	{
	}

	void initPhysics() override
	{
		m_guiHelper->setUpAxis(1);
		registerControls();
		rebuild();
	}

	void exitPhysics() override
	{
		m_guiHelper->removeAllGraphicsInstances();
		m_scene.reset();
	}

	// deltaTime_s of browser time advances slow_motion * deltaTime_s of simulated time.
	void stepSimulation(float deltaTime_s) override
	{
		if (controlsChanged()) rebuild();
		if (!m_scene) return;
		m_targetTime_s += double(deltaTime_s) * m_simulatedPerRealSecond;
		const double end_s = m_scene->parameters().duration_s;
		while (m_scene->time_s() < m_targetTime_s && m_scene->time_s() < end_s && m_scene->finite()) m_scene->step();
	}

	void renderScene() override
	{
		if (m_scene) m_guiHelper->syncPhysicsToGraphics(m_scene->world());
		if (m_scene) m_guiHelper->render(m_scene->world());
		drawEnergyPanel();
	}

	void physicsDebugDraw(int debugFlags) override
	{
		if (m_scene && m_scene->world()->getDebugDrawer())
		{
			m_scene->world()->getDebugDrawer()->setDebugMode(debugFlags);
			m_scene->world()->debugDrawWorld();
		}
	}

	void resetCamera() override { resetCharpyCamera(m_guiHelper, m_parameters); }

	bool mouseMoveCallback(float, float) override { return false; }
	bool mouseButtonCallback(int, int, float, float) override { return false; }
	bool keyboardCallback(int, int) override { return false; }

private:
	void registerControls()
	{
		CommonParameterInterface* parameters = m_guiHelper->getParameterInterface();
		if (!parameters) return;
		for (int i = 0; i < kCharpyMethodCount; i++) kMethodNames[i] = charpyMethodName(charpyMethodByNumber(i + 1)).data();
		ComboBoxParams combo;
		combo.m_numItems = kCharpyMethodCount;
		combo.m_items = kMethodNames;
		combo.m_startItem = m_method - 1;
		combo.m_userPointer = this;
		combo.m_callback = [](int, const char* item, void* self) {
			if (auto method = parseCharpyMethod(item)) static_cast<CharpyExample*>(self)->m_method = int(*method);
		};
		parameters->registerComboBox(combo);
		for (const CharpySlider& s : kCharpySliders) slider(parameters, s.label, &(m_controls.*s.value), s.min, s.max, s.integers);
		slider(parameters, "slow motion (sim s per s)", &m_simulatedPerRealSecond, 0.001f, 0.1f, false);
	}

	static void slider(CommonParameterInterface* parameters, const char* name, btScalar* value, float min, float max, bool integers)
	{
		SliderParams params(name, value);
		params.m_minVal = min;
		params.m_maxVal = max;
		params.m_clampToIntegers = integers;
		parameters->registerSliderFloatParameter(params);
	}

	bool controlsChanged() const { return m_controls != m_applied || m_method != int(m_parameters.method); }

	void rebuild()
	{
		m_applied = m_controls;
		const CharpyParameters p = charpyParametersFromControls(m_controls, charpyMethodByNumber(m_method));
		m_parameters = p;
		m_guiHelper->removeAllGraphicsInstances();
		m_scene.reset();
		m_error.clear();
		m_targetTime_s = 0;
		try
		{
			m_scene = std::make_unique<CharpyScene>(p);
		}
		catch (const std::invalid_argument& e)
		{
			m_error = e.what();  // shown on screen; the previous scene is gone, nothing is simulated
			return;
		}
		showCharpyScene(m_guiHelper, *m_scene);
	}

	void drawEnergyPanel()
	{
		CommonGraphicsApp* app = m_guiHelper->getAppInterface();
		if (!app) return;
		const std::string text = m_scene ? charpyEnergyPanel(*m_scene) : "invalid parameters:\n" + m_error;
		drawCharpyPanel(app, text);
	}

	GUIHelperInterface* m_guiHelper;
	int m_method;
	CharpyControls m_controls;  // moved by the sliders
	CharpyControls m_applied;   // what the current scene was built from
	btScalar m_simulatedPerRealSecond = 0.01;
	CharpyParameters m_parameters;
	std::unique_ptr<CharpyScene> m_scene;
	std::string m_error;
	double m_targetTime_s = 0;
};
}  // namespace

CommonExampleInterface* CharpyExampleCreateFunc(CommonExampleOptions& options)
{
	return new CharpyExample(options.m_guiHelper, options.m_option);
}
