// Umbrella header for the cslice library.
#pragma once

#include "cslice/classify.hpp"
#include "cslice/geometry.hpp"
#include "cslice/pair.hpp"
#include "cslice/part.hpp"
#include "cslice/tolerance.hpp"
