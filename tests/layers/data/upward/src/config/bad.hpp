#pragma once
// Fixture: a foundation header that includes the run machinery, which check_layers.py must reject.
#include "run/progress.hpp"
