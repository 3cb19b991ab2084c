#pragma once
// The comparison page's files, compiled into the program (embed.cmake):
// the HTML template, its script, and three.js with its orbit controls
// (npm's three@0.168.0, vendor/; viewer/package.json pins it).

#include <string_view>

namespace subdiv::compare {

extern const std::string_view kPageHtml;       // placeholders @TITLE@, @IMPORTMAP@, @DATA@, @SCRIPT@
extern const std::string_view kPageScript;     // an ES module importing 'three' and the orbit controls
extern const std::string_view kThreeModule;    // build/three.module.min.js
extern const std::string_view kOrbitControls;  // examples/jsm/controls/OrbitControls.js

}  // namespace subdiv::compare
