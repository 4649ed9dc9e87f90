// On-screen text as the ExampleBrowser examples draw it: lines kTextLine_px apart, app->drawText at size 0.4.
#pragma once

#include <string>

class CommonGraphicsApp;

constexpr int kTextLine_px = 17;

// Draws text lines from (left_px, top_px), kTextLine_px apart.
void drawTextLines(CommonGraphicsApp* app, const std::string& text, int left_px, int top_px);
