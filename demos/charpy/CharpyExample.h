// The Charpy impact test as a Bullet example (CommonExampleInterface), for an ExampleBrowser.
// The scene is the one CharpyScene builds for the console runner and the tests; the example only
// draws it, shows its energy balance and turns sliders into CharpyParameters.
#pragma once

class CommonExampleInterface;
struct CommonExampleOptions;

// options.m_option: the method number 1-8 (thesis order) the example starts with.
CommonExampleInterface* CharpyExampleCreateFunc(CommonExampleOptions& options);
