// Areas of Boolean results: exact_area (a reduced rational) and rounded_area (the nearest
// double, decided by a filtered sum, exactly where the filter cannot).
// [MK89 §2.2] (islands add their area, holes subtract it)
// Preconditions: see api/area_exact.hpp and api/area_rounded.hpp.
#pragma once

#include "api/area_exact.hpp"
#include "api/area_rounded.hpp"
