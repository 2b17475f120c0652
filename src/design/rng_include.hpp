#pragma once
// core/rng.hpp uses unsigned __int128, which -Wpedantic flags; silence that one warning for the
// include only (reported to the lead: `__extension__` in core/rng.hpp would make this unneeded).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#include "core/rng.hpp"
#pragma GCC diagnostic pop
