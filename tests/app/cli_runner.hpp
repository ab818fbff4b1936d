#pragma once
// Kept for the tests that still include it by this name; the runner and the
// temporary directory live in tests/support/.
#include "support/cli.hpp"
