#pragma once
// Fixture: the run machinery header that tests/layers/data/upward/src/config/bad.hpp includes.
