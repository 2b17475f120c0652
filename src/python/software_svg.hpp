#pragma once
// Control software drawn as a standalone SVG (ControlSoftware.svg() in Python): a finite-state
// machine as its states on a ring (the initial one with a double border) joined by labelled
// transitions, a behaviour tree top-down, an EvoStick network as one box. The labels are
// describe()'s (control/describe.hpp), so the drawing and the text never disagree.
#include <string>

#include "control/control_software.hpp"

namespace sd::python {

std::string software_svg(const ControlSoftware& software);

}  // namespace sd::python
