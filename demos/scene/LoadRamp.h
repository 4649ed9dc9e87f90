// The load factor of a quasi-static collapse test: it rises at a fast rate up to slow_from, then at the slow
// rate, until the scene says the structure has collapsed; from then on it is held.
#pragma once

namespace scene
{
class LoadRamp
{
public:
	LoadRamp(double slowRate_per_s, double fastRate_per_s, double slowFrom) : m_slow(slowRate_per_s), m_fast(fastRate_per_s), m_slowFrom(slowFrom) {}
	double factor() const { return m_factor; }
	void advance(double step_s)
	{
		if (m_held) return;
		m_factor += (m_factor < m_slowFrom ? m_fast : m_slow) * step_s;
	}
	void hold() { m_held = true; }
	void resume() { m_held = false; }
	// how much faster the load rises now than in the slow part (1 once held or slow)
	double speedRatio() const { return !m_held && m_factor < m_slowFrom ? m_fast / m_slow : 1.0; }
	bool held() const { return m_held; }

private:
	double m_slow, m_fast, m_slowFrom;
	double m_factor = 0;
	bool m_held = false;
};
}  // namespace scene
